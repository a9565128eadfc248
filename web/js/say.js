// @ts-check
// The core's facts in the page's words. The core hands every fact over as data — a kind and
// its fields — and this module says it from the catalogue (`i18n/<lang>.json`), in English
// as in Japanese, never by reading the core's English back:
//   - an event (`{kind, data}`)                → `event.<Kind>` (and its forms);
//   - a reason (`{kind, …}`, `rtnav::Reason`)   → `reason.<kind>`, a nested error through
//     `error.<Area>.<Kind>`;
//   - a refusal (an `Error` with its `detail`)  → `error.<Area>.<Kind>`;
//   - a request (`rtnav::system::InputSummary`) → `input.<Kind>`;
//   - the robot's status (`Status`)             → `status.<kind>`;
//   - a component's activity (`ComponentActivity`, the RTC panel's status column)
//                                               → `rtcstatus.<kind>`;
//   - a parameter's warning (`ParameterWarning`) → `warning.<kind>`.
// Words that arrive as given (a fault's reason typed in a scenario, a parse problem's text
// inside an error) are shown as given, or through `word.<text>` when the catalogue has them.
import { t, has, language } from './i18n.js';

/** A text of the catalogue: a key and its placeholders' values. @typedef {(key: string, vars?: object) => string} Say */
/** A catalogue key and the words its placeholders take beyond the fields. @typedef {[key: string, vars: object]} Form */

/**
 * The sayings of one catalogue: `t` (a key and its placeholders' values → text) and `has`
 * (whether the catalogue has a key). The page's are exported below; a test makes them over
 * the English catalogue to compare with the core's own English.
 * @param {Say} t
 * @param {(key: string) => boolean} has
 */
export function sayer(t, has) {
  /** `key`, or its `.one` form when the count is one (English's singular). @param {string} key @param {number} n */
  function counted(key, n) {
    return n === 1 && has(`${key}.one`) ? `${key}.one` : key;
  }

  /**
   * Words that arrive as given, in the catalogue's words when it has them.
   * @template T
   * @param {T} text
   * @returns {T | string}
   */
  function given(text) {
    return typeof text === 'string' && has(`word.${text}`) ? t(`word.${text}`) : text;
  }

  // ---------------------------------------------------------------------------- errors

  /** Fields that hold a number which is NaN when the core sends null. */
  const OPTIONAL = new Set(['line', 'index']);

  /**
   * The fields of an error (`{area, kind, fields}`, the core's `ErrorDetail` or the wasm
   * layer's `Page` errors) as the catalogue's `error.<Area>.<Kind>` placeholders want them:
   * requests and the core's words (`start`, `goal`, …) in the page's language, a nested error
   * said in words, the optional " (line N)" part.
   * @param {ErrorDetail} d
   * @returns {Record<string, unknown>}
   */
  function errorVars(d) {
    const fields = d.fields ?? {};
    /** @type {Record<string, unknown>} */
    const vars = {};
    for (const [k, v] of Object.entries(fields)) {
      if (v === null && !OPTIONAL.has(k)) vars[k] = 'NaN';
      else if (v && typeof v === 'object' && !Array.isArray(v) && 'area' in v && 'kind' in v) vars[k] = detailText(/** @type {ErrorDetail} */ (v)) ?? '';
      else vars[k] = given(v);
    }
    if (typeof fields.request === 'string') vars.request = t(`request.${fields.request}`);
    if (typeof fields.type === 'string' && has(`params.type.${fields.type}`)) vars.type = t(`params.type.${fields.type}`);
    if ('line' in fields) vars.at_line = fields.line === null ? '' : t('error.at_line', { line: fields.line });
    if ('index' in fields) vars.at_index = fields.index === null ? '' : t('error.at_index', { index: fields.index });
    if (typeof fields.index === 'number') vars.previous = fields.index - 1;
    if ('non_negative' in fields) vars.non_negative = fields.non_negative ? t('error.System.non_negative') : '';
    return vars;
  }

  /**
   * An error's detail (a refusal's names the file or scenario it is about) in the page's
   * language, or null when the catalogue has no words.
   * @param {Refusal} d
   * @returns {string | null}
   */
  function detailText(d) {
    const key = `error.${d.area}.${d.kind}`;
    if (!has(key)) return null;
    let text = t(key, errorVars(d));
    if (d.file) text = t('error.in_file', { file: d.file, error: text });
    if (d.scenario) text = t('error.in_scenario', { scenario: d.scenario, error: text });
    return text;
  }

  // ---------------------------------------------------------------------------- reasons

  /**
   * The fields of a reason, said, for `reason.<kind>` (a kind not here: its fields as they are).
   * @type {{ [K in Reason['kind']]?: (r: Extract<Reason, { kind: K }>) => object }}
   */
  const REASON_VARS = {
    error: (r) => ({ error: detailText(r.error) ?? '' }),
    course_refused: (r) => ({ error: detailText(r.error) ?? '' }),
    map_update_refused: (r) => ({ component: r.component, error: detailText(r.error) ?? '' }),
    bump: (r) => ({ ...r.report, t: (r.report?.tm?.sec ?? 0) + (r.report?.tm?.nsec ?? 0) * 1e-9 }),
    injected_fault: (r) => ({ words: given(r.words) }),
    words: (r) => ({ words: r.words }),
  };

  /**
   * A reason of the core (`rtnav::Reason`: `{kind, …fields}`) in the page's language.
   * @param {Reason | null | undefined} r
   * @returns {string}
   */
  function reasonText(r) {
    if (!r || typeof r !== 'object') return '';
    const vars = /** @type {((r: Reason) => object) | undefined} */ (REASON_VARS[r.kind]);
    return t(`reason.${r.kind}`, vars?.(r) ?? r);
  }

  /**
   * A parameter's warning (`rtnav::system::ParameterWarning`) in the page's language.
   * @param {ParameterWarning} w
   * @returns {string}
   */
  function warningText(w) {
    return t(`warning.${w.kind}`, w.kind === 'clearance' ? { ...w, half: w.grid_size / 2 } : w);
  }

  // ---------------------------------------------------------------------------- requests

  /**
   * A request (`rtnav::system::InputSummary`: `{kind, …fields}`, the fields the catalogue's
   * placeholders) in the page's language.
   * @param {{ kind: string }} request
   * @returns {string}
   */
  function inputText(request) {
    return t(`input.${request.kind}`, request);
  }

  // ---------------------------------------------------------------------------- events

  /** ", escaping the dmin zone in N steps" when a plan starts inside it. */
  const escape = (/** @type {number} */ steps) => (steps > 0 ? t('event.escape', { steps }) : '');

  /**
   * For each kind with more than its fields: the catalogue key of its form, and its words.
   * An event's fields (`EventView.data`) are the core's event enum as it serializes, one
   * shape per kind: each form names the types of the fields it reads.
   * @type {Record<string, (d: Record<string, unknown>) => Form>}
   */
  const EVENT_FORMS = {
    GoalSet: (d) => [d.placed ? 'event.GoalSet' : 'event.GoalSet.new',
      { dir: t(d.direction === 'Backward' ? 'dir.backward' : 'dir.forward') }],
    GlobalPlan: (d) => ['event.GlobalPlan', {
      why: has(`event.GlobalPlan.${d.reason}`) ? t(`event.GlobalPlan.${d.reason}`) : '',
      escape: escape(/** @type {number} */ (d.escaped)),
    }],
    LocalPlanSent: (d) => [
      d.cells === 0 ? 'event.LocalPlanSent.empty' : d.replanned ? 'event.LocalPlanSent' : 'event.LocalPlanSent.global',
      { escape: escape(/** @type {number} */ (d.escaped)) }],
    PlanningFailed: (d) => ['event.PlanningFailed', { reason: reasonText(/** @type {Reason} */ (d.reason)) }],
    Bump: (d) => {
      const report = /** @type {BumpReport | undefined} */ (d.report);
      return ['event.Bump', { t_s: (report?.tm?.sec ?? 0) + (report?.tm?.nsec ?? 0) * 1e-9 }];
    },
    ComponentError: (d) => ['event.ComponentError', { reason: reasonText(/** @type {Reason | null} */ (d.reason)) }],
    SafetyStop: (d) => [d.replanning ? 'event.SafetyStop.replanning' : 'event.SafetyStop', {}],
    FaultInjected: (d) => ['event.FaultInjected', { reason: given(d.reason) }],
    ClearanceWarning: (d) => ['event.ClearanceWarning', { half: /** @type {number} */ (d.grid_size) / 2 }],
    RequestRefused: (d) => ['event.RequestRefused', {
      source: t(`source.${d.source}`),
      request: inputText(/** @type {{ kind: string }} */ (d.request)),
      reason: reasonText(/** @type {Reason} */ (d.reason)),
    }],
  };

  /**
   * An event of the core (`{kind, data}`) in the page's language, from its fields through
   * `event.<Kind>` (and its forms). `tests/e2e/ja.test.mjs` says every event of a run with the
   * English catalogue and compares the result with the core's own English text.
   * @param {{ kind: string, data?: EventView['data'] }} e an `EventView` (its kind and fields)
   * @returns {string}
   */
  function eventText(e) {
    const d = e.data ?? {};
    const [key, extra] = EVENT_FORMS[e.kind]?.(d) ?? [`event.${e.kind}`, {}];
    return t(key, { ...d, ...extra });
  }

  // ---------------------------------------------------------------------------- status

  /**
   * What the robot is doing (the core's `Status`: its `kind` and fields, the telemetry's
   * `status_kind` and `status_fields`) said through `status.<kind>` with its details — which
   * component, why, and `status.paused` while the clock is paused — in the page's language.
   * @param {string} kind
   * @param {Record<string, unknown>} [fields]
   * @returns {string}
   */
  function statusText(kind, fields = {}) {
    /** @type {Record<string, unknown>} */
    const vars = { ...fields };
    if (fields.reason && typeof fields.reason === 'object') vars.reason = reasonText(/** @type {Reason} */ (fields.reason));
    if (fields.retrying && typeof fields.retrying === 'object') vars.retrying = reasonText(/** @type {Reason} */ (fields.retrying));
    if (typeof fields.direction === 'string') vars.direction = t(`status.direction.${fields.direction}`);
    if (typeof fields.motion === 'string') vars.motion = t(`status.motion.${fields.motion}`);
    let key = `status.${kind}`;
    if (kind === 'waiting_for_plan' && fields.retrying) key = 'status.waiting_for_plan.retrying';
    if (kind === 'component_error' && !fields.reason) key = 'status.component_error.no_reason';
    const said = t(key, vars);
    // The session's clock stands still: the cause is said with the status.
    return fields.paused === true ? t('status.paused', { status: said }) : said;
  }

  // ---------------------------------------------------------------------------- components

  /**
   * The fields of an activity, said, for `rtcstatus.<kind>` (and its forms).
   * @type {{ [K in ComponentActivity['kind']]?: (a: Extract<ComponentActivity, { kind: K }>) => Form }}
   */
  const ACTIVITY_FORMS = {
    in_error: (/** @type {{ reason?: Reason | null }} */ a) => a.reason ? ['rtcstatus.in_error.because', { reason: reasonText(a.reason) }] : ['rtcstatus.in_error', {}],
    updates_sent: (a) => [counted('rtcstatus.updates_sent', a.updates), {}],
    bumps: (a) => [counted('rtcstatus.bumps', a.bumps), { touching: a.touching ? t('rtcstatus.touching') : '' }],
    waiting_for: (a) => ['rtcstatus.waiting_for', { inputs: a.inputs.join(t('rtcstatus.waiting_for.and')) }],
    safe_stop: (a) => ['rtcstatus.safe_stop', { output: t(`rtcstatus.zero.${a.output}`), reason: reasonText(a.reason) }],
    route_failed: (a) => ['rtcstatus.route_failed', { reason: reasonText(a.reason) }],
    local_planning: (a) => [counted('rtcstatus.local_planning', a.made), {
      holds: a.holds.length ? a.holds.map((h) => t(`held.${h}`)).join(t('held.separator')) : t('held.nothing'),
      retrying: a.retrying ? t('rtcstatus.retrying') : '',
    }],
  };

  /**
   * What a component is doing or holds (`ComponentInfo.status`, the core's
   * `ComponentActivity`: `{kind, …fields}`) in the page's language. `{kind: 'in_error'}`
   * without its reason says only that it is in Error (the RTC panel says why on a line of its own).
   * @param {ComponentActivity | { kind: 'in_error' }} a
   * @returns {string}
   */
  function activityText(a) {
    const form = /** @type {((a: ComponentActivity | { kind: 'in_error' }) => Form) | undefined} */ (ACTIVITY_FORMS[a.kind]);
    const [key, extra] = form?.(a) ?? [`rtcstatus.${a.kind}`, {}];
    return t(key, { ...a, ...extra });
  }

  return { errorDetail: detailText, reasonText, warningText, inputText, eventText, statusText, activityText };
}

const page = sayer(t, has);
export const { reasonText, warningText, inputText, eventText, statusText, activityText } = page;

/**
 * The status line (the telemetry's, and the scene's words): the robot's status as a sentence
 * (with the clock's pause, which the status's fields carry).
 * @param {Pick<TelemetryView, 'status_kind' | 'status_fields'>} v
 * @returns {string}
 */
export function statusLine(v) {
  const said = statusText(v.status_kind, v.status_fields);
  return said.charAt(0).toUpperCase() + said.slice(1);
}

/**
 * A refusal (an `Error` thrown by the wasm layer, or a message) in the page's language: said
 * from its `detail` (`{area, kind, fields}`) through `error.<Area>.<Kind>`; in English, and
 * where there is no detail or no words for it, the core's own `message`.
 * @param {unknown} e
 * @returns {string}
 */
export function errorText(e) {
  // What the wasm layer throws: an `Error` whose `detail` is the core's `Refusal`.
  const thrown = /** @type {{ message?: string, detail?: Refusal }} */ (typeof e === 'object' && e !== null ? e : {});
  const message = thrown.message ?? String(e);
  if (language() === 'en' || !thrown.detail) return message;
  return page.errorDetail(thrown.detail) ?? message;
}

