// The core's short status lines of the components (RT System Editor's status column,
// `ComponentInfo.status`) in the page's language: each form the core writes is matched and
// rewritten through the catalogue (`rtcstatus.*`); a line of another form is shown as the
// core wrote it. English needs no rewriting.
import { t, has, language, englishWords } from './i18n.js';

/** [pattern, key, names of the captured parts]. */
const FORMS = [
  [/^in Error, not executing$/, 'rtcstatus.in_error', []],
  [/^in Error, not executing: (.+)$/, 'rtcstatus.in_error_because', ['reason']],
  [/^map (\d+)×(\d+) at ([\d.]+) m$/, 'rtcstatus.map', ['w', 'h', 'g']],
  [/^no map$/, 'rtcstatus.no_map', []],
  [/^(\d+) updates? sent$/, 'rtcstatus.updates', ['n']],
  [/^(\d+) bumps?(, touching an obstacle)?$/, 'rtcstatus.bumps', ['n', 'touching']],
  [/^inactive$/, 'rtcstatus.inactive', []],
  [/^waiting for (.+)$/, 'rtcstatus.waiting', ['what']],
  [/^running$/, 'rtcstatus.running', []],
  [/^stopped \(Stop\): braking to zero velocity$/, 'rtcstatus.stopped', []],
  [/^finished \(Finish\): zero torque$/, 'rtcstatus.finished', []],
  [/^safe stop, zero (torque|velocity): (.+)$/, 'rtcstatus.safe_stop', ['what', 'reason']],
  [/^(Odometry|SimulatedPose)$/, 'rtcstatus.mode', ['mode']],
  [/^failed: (.+)$/, 'rtcstatus.failed', ['reason']],
  [/^route of ([\d.]+) m$/, 'rtcstatus.route', ['l']],
  [/^no route$/, 'rtcstatus.no_route', []],
  [/^holds: (.+); (\d+) plans? made(; retrying)?$/, 'rtcstatus.holds', ['held', 'n', 'retrying']],
  [/^idle \(no path\)$/, 'rtcstatus.idle', []],
  [/^turning on the spot$/, 'rtcstatus.turning', []],
  [/^following the path$/, 'rtcstatus.following', []],
  [/^turning to the goal heading$/, 'rtcstatus.final_turn', []],
  [/^arrived$/, 'rtcstatus.arrived', []],
  [/^safety stop: obstacle ([\d.]+) m ahead, a new plan asked for$/, 'rtcstatus.safety_stop', ['d']],
];
/** The parts of LocalPathPlanning's "holds" list. */
const HELD = { nothing: 'held.nothing', map: 'held.map', 'start and goal': 'held.start_goal', path: 'held.path', arrived: 'held.arrived' };

// ---------------------------------------------------------------------------- errors

/** Fields that hold a number which is NaN when the core sends null. */
const OPTIONAL = new Set(['line', 'index']);

/**
 * The fields of an error (`{area, kind, fields}`, the core's `ErrorDetail` or the wasm
 * layer's `Page` errors) as the catalogue's `error.<Area>.<Kind>` placeholders want them:
 * requests and the core's words (`start`, `goal`, …) in the page's language, a nested error
 * said in words, the optional " (line N)" part.
 */
function errorVars(d) {
  const fields = d.fields ?? {};
  const vars = {};
  for (const [k, v] of Object.entries(fields)) {
    if (v === null && !OPTIONAL.has(k)) vars[k] = 'NaN';
    else if (typeof v === 'string' && has(`word.${v}`)) vars[k] = t(`word.${v}`);
    else if (v && typeof v === 'object' && !Array.isArray(v) && 'kind' in v) vars[k] = detailText(v) ?? '';
    // A reason given as text (a file's parse problem, a callback's): read back if it can be.
    else if (typeof v === 'string' && /[a-z]{3}/.test(v)) vars[k] = reasonText(v);
    else vars[k] = v;
  }
  if (typeof fields.request === 'string') vars.request = t(`request.${fields.request}`);
  if (typeof fields.type === 'string' && has(`params.type.${fields.type}`)) vars.type = t(`params.type.${fields.type}`);
  if ('line' in fields) vars.at_line = fields.line === null ? '' : t('error.at_line', { line: fields.line });
  if ('index' in fields) vars.at_index = fields.index === null ? '' : t('error.at_index', { index: fields.index });
  if (typeof fields.index === 'number') vars.previous = fields.index - 1;
  if ('non_negative' in fields) vars.non_negative = fields.non_negative ? t('error.System.non_negative') : '';
  if (d.area === 'Page') vars.expected = t('error.Page.expected');
  return vars;
}

/** An error's detail in the page's language, or null when the catalogue has no words. */
function detailText(d) {
  const key = `error.${d.area}.${d.kind}`;
  if (!has(key)) return null;
  let text = t(key, errorVars(d));
  if (d.file) text = t('error.in_file', { file: d.file, error: text });
  if (d.scenario) text = t('error.in_scenario', { scenario: d.scenario, error: text });
  return text;
}

/**
 * A refusal (an `Error` thrown by the wasm layer, or a message) in the page's language: said
 * from its `detail` (`{area, kind, fields}`) through `error.<Area>.<Kind>`; the English
 * `message` when there is no detail or no words for it.
 */
export function errorText(e) {
  const message = e?.message ?? String(e);
  if (language() === 'en' || !e?.detail) return message;
  return detailText(e.detail) ?? message;
}

/**
 * The English templates of the errors and reasons (`error.<Area>.<Kind>`, `reason.*` in
 * en.json) as patterns: a reason that reaches the page only as the core's text (inside an
 * event — a planning failure's, a callback's — or a component's last error) is read back
 * into its fields by the template it was written from, and said by the same key.
 */
let templates = null;
function errorTemplates() {
  if (templates) return templates;
  templates = [];
  for (const [key, text] of Object.entries(englishWords())) {
    if (!/^(error\.\w+\.[A-Z]\w*|reason\.\w+)$/.test(key)) continue;
    const names = [];
    const source = text.split(/(\{[\w.]+(?::[\w.]+)?\})/).map((part) => {
      const m = /^\{([\w.]+)(?::[\w.]+)?\}$/.exec(part);
      if (!m) return part.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
      names.push(m[1]);
      return '(.*?)';
    }).join('');
    templates.push({ key, names, pattern: new RegExp(`^${source}$`), fixed: text.replace(/\{[^}]*\}/g, '').length });
  }
  // The most specific template first: the one with the most fixed words.
  templates.sort((a, b) => b.fixed - a.fixed);
  return templates;
}

/** `text`, a reason the core gave as text, in the page's language (as given when not known). */
export function reasonText(text) {
  if (language() === 'en' || typeof text !== 'string') return text;
  if (has(`word.${text}`)) return t(`word.${text}`);
  for (const { key, names, pattern } of errorTemplates()) {
    const m = pattern.exec(text);
    if (!m) continue;
    const vars = {};
    names.forEach((name, i) => {
      const v = m[i + 1];
      const path = name.split('.');
      let into = vars;
      for (const p of path.slice(0, -1)) into = into[p] ??= {};
      into[path.at(-1)] = has(`word.${v}`) ? t(`word.${v}`) : /[a-z]{3}/.test(v) ? reasonText(v) : v;
    });
    if (typeof vars.request === 'string') {
      const r = Object.keys(englishWords()).find((k) => k.startsWith('request.') && englishWords()[k] === vars.request);
      if (r) vars.request = t(r);
    }
    return t(key, vars);
  }
  return text;
}

// ---------------------------------------------------------------------------- events

/** ", escaping the dmin zone in N steps" when a plan starts inside it. */
const escape = (steps, say) => (steps > 0 ? say('event.escape', { steps }) : '');

/**
 * For each kind: the catalogue key of its form, and the words its fields do not hold
 * (`say` is the catalogue's `t`, `reason` says a reason given as text).
 */
const EVENT_FORMS = {
  GoalSet: (d, say) => [d.placed ? 'event.GoalSet' : 'event.GoalSet.new',
    { dir: say(d.direction === 'Backward' ? 'dir.backward' : 'dir.forward') }],
  GlobalPlan: (d, say) => ['event.GlobalPlan', {
    why: has(`event.GlobalPlan.${d.reason}`) ? say(`event.GlobalPlan.${d.reason}`) : '',
    escape: escape(d.escaped, say),
  }],
  LocalPlanSent: (d, say) => [
    d.cells === 0 ? 'event.LocalPlanSent.empty' : d.replanned ? 'event.LocalPlanSent' : 'event.LocalPlanSent.global',
    { escape: escape(d.escaped, say) }],
  PlanningFailed: (d, say, reason) => ['event.PlanningFailed', { reason: reason(d.reason) }],
  Bump: (d) => ['event.Bump', { t_s: (d.report?.tm?.sec ?? 0) + (d.report?.tm?.nsec ?? 0) * 1e-9 }],
  ComponentError: (d, say, reason) => ['event.ComponentError', { reason: reason(d.reason) }],
  SafetyStop: (d) => [d.replanning ? 'event.SafetyStop.replanning' : 'event.SafetyStop', {}],
  FaultInjected: (d, say, reason) => ['event.FaultInjected', { reason: reason(d.reason) }],
  ClearanceWarning: (d) => ['event.ClearanceWarning', { half: d.grid_size / 2 }],
  RequestRefused: (d, say, reason) => ['event.RequestRefused', {
    request: reason === reasonText ? requestText(d.request) : d.request, reason: reason(d.reason),
  }],
};

/** The sources of requests the system makes on someone's behalf (`Input::describe`'s). */
const SOURCES = { "the scenario's timeline": 'source.timeline', 'the replay': 'source.replay' };
/** The forms of `Input::describe`: [pattern, key, names of the captured parts]. */
const REQUESTS = [
  [/^a new goal$/, 'input.SetGoal', []],
  [/^MapUpdate of (\d+) cells$/, 'input.MapUpdate', ['n']],
  [/^(activate|deactivate|reset) (all|\w+)$/, null, ['request', 'component']],
  [/^inject a fault into (\w+)$/, 'input.InjectFault', ['component']],
  [/^inject into (\w+)\.(\w+)$/, 'input.InjectInput', ['component', 'port']],
  [/^loading the configuration$/, 'input.LoadConf', []],
  [/^the rate of (\w+)$/, 'input.SetRate', ['component']],
  [/^(cut|restore) (.+)$/, null, ['request', 'connection']],
];

/** A refused request's description (`the scenario's timeline: a new goal`) in words. */
function requestText(text) {
  const at = (text ?? '').indexOf(': ');
  if (at < 0 || !SOURCES[text.slice(0, at)]) return text;
  const what = text.slice(at + 2);
  let said = what;
  for (const [pattern, key, names] of REQUESTS) {
    const m = pattern.exec(what);
    if (!m) continue;
    const vars = Object.fromEntries(names.map((n, i) => [n, m[i + 1]]));
    const form = key ?? (vars.component === 'all' ? `input.${vars.request}_all` : `input.${vars.request}`);
    said = t(form, vars);
    break;
  }
  return t('source.request', { source: t(SOURCES[text.slice(0, at)]), request: said });
}

/**
 * An event of the core (`{kind, text, data}`) in the page's language: every kind is said from
 * its fields through `event.<Kind>` (and its forms); the core's English `text` only when the
 * catalogue has no words for the kind.
 */
export function eventText(e) {
  if (language() === 'en' || !has(`event.${e.kind}`)) return e.text;
  return eventWords(e);
}

/**
 * An event said through the catalogue: `say` (`t`, or another language's lookup) and
 * `reason` (how a reason given as text is said). `tests/e2e/ja.test.mjs` says every event
 * of a run with the English catalogue and the reasons as given, and compares the result
 * with the core's own English text: the numbers are written as the core writes them.
 */
export function eventWords(e, say = t, reason = reasonText) {
  const d = e.data ?? {};
  const [key, extra] = EVENT_FORMS[e.kind]?.(d, say, reason) ?? [`event.${e.kind}`, {}];
  return say(key, { ...d, ...extra });
}

/**
 * What the robot is doing (the core's `Status`: its `kind` and fields, the telemetry's
 * `status_kind` and `status_fields`) said through `status.<kind>` with its details — which
 * component, why — in the page's language. `say` and `reason` as for `eventWords`: with the
 * English catalogue and the reasons as given, this is the core's own English text
 * (`tests/e2e/qa.test.mjs` compares them).
 */
export function statusText(kind, fields = {}, say = t, reason = reasonText) {
  const vars = { ...fields };
  for (const k of ['reason', 'retrying']) if (typeof vars[k] === 'string') vars[k] = reason(vars[k]);
  if (typeof fields.direction === 'string') vars.direction = say(`status.direction.${fields.direction}`);
  const key = kind === 'waiting_for_plan' && fields.retrying ? 'status.waiting_for_plan.retrying' : `status.${kind}`;
  return say(key, vars);
}

/** `text`, a component's status line from the core, in the page's language. */
export function componentStatus(text) {
  if (language() === 'en') return text;
  for (const [pattern, key, names] of FORMS) {
    const m = pattern.exec(text);
    if (!m) continue;
    const vars = Object.fromEntries(names.map((n, i) => [n, m[i + 1] ?? '']));
    if ('touching' in vars) vars.touching = vars.touching ? t('rtcstatus.touching') : '';
    if ('retrying' in vars) vars.retrying = vars.retrying ? t('rtcstatus.retrying') : '';
    if ('what' in vars && key === 'rtcstatus.safe_stop') vars.what = t(`rtcstatus.zero_${vars.what}`);
    if ('what' in vars && key === 'rtcstatus.waiting') vars.what = vars.what.replace(' and ', '・');
    if ('reason' in vars) vars.reason = reasonText(vars.reason);
    if ('held' in vars) vars.held = vars.held.split(', ').map((h) => (HELD[h] ? t(HELD[h]) : h)).join('・');
    return t(key, vars);
  }
  return text;
}
