// @ts-check
// The event log (InventGUI's log): plans, planning failures with their reasons, bumps,
// arrival, component errors and state changes, map changes — newest first, in simulated-time
// order — and the page's own notes (a refused goal, a bad map file). Each event is said from
// its kind and fields (`say.js`); the page writes the time.
//
// A condition that repeats (spec §7 "repeats": a safety stop every second, a planning
// failure retried every second) is one entry with a count and the time of its last repeat;
// the core's recorded event stream keeps every occurrence.
import { el } from '../dom.js';
import { t } from '../i18n.js';
import { eventText } from '../say.js';

const MAX_ENTRIES = 300;
/**
 * The kinds whose occurrences fold into one entry when they say the same thing within
 * `REPEAT_WINDOW_S` of simulated time of the last one (the condition still holds).
 */
const REPEATING = new Set(['SafetyStop', 'PlanningFailed', 'RequestRefused', 'LocalPlanSent']);
const REPEAT_WINDOW_S = 2.5;

/** Simulated time as a person reads it: seconds with three decimals. */
/** @param {number} t */
export const seconds = (t) => `${t.toFixed(3)} s`;

/**
 * @param {HTMLElement} root
 * @param {App} app
 */
export function createEventLog(root, app) {
  const { demo } = app;
  const list = el('ol', { id: 'events', class: 'events', reversed: true });
  const clear = el('button', { type: 'button', class: 'link', id: 'clear-log', onclick: () => list.replaceChildren() }, t('log.clear'));
  root.append(el('div', { class: 'panel-head' }, el('h2', {}, t('log.title')), clear), list);

  /** The component an instance name names (`MotorControl0` → `MotorControl`). */
  /** @param {string} instance */
  const componentOf = (instance) => instance.replace(/\d+$/, '');
  /** A component's state in the last frame read. @param {string} name */
  const stateOf = (name) => app.frame?.components.find((c) => c.name === name)?.state;
  /** The telemetry of the last frame read. */
  const telemetry = () => app.frame?.telemetry;

  /**
   * The events shown over the canvas too, each tied to the state it describes: the notice
   * goes when `until` is true (or on Reset, Activate, a new scenario).
   */
  /** @type {Record<string, (e: EventView) => () => boolean>} */
  const NOTICE = {
    Bump: () => () => stateOf('PhysicsSim') !== 'Error',
    ComponentError: (e) => {
      const name = componentOf(String(e.data?.component ?? ''));
      return () => stateOf(name) !== 'Error';
    },
    PlanningFailed: () => () => !['waiting_for_plan', 'no_route'].includes(telemetry()?.status_kind ?? ''),
    Arrived: () => () => !telemetry()?.arrived,
  };

  /**
   * What makes two occurrences the same condition: the kind and the words (a safety stop's
   * distance ahead changes from one stop to the next; whether it replans does not).
   * @param {{kind: string, data?: EventView['data']}} e
   * @param {string} text
   * @returns {string | null}
   */
  const condition = (e, text) => {
    if (!REPEATING.has(e.kind)) return null;
    if (e.kind === 'SafetyStop') return `SafetyStop ${Boolean(e.data?.replanning)}`;
    if (e.kind === 'LocalPlanSent' && e.data?.cells !== 0) return null;
    return `${e.kind} ${text}`;
  };

  /**
   * The entry `e` repeats (its condition, said last within the window), if any.
   * @param {string | null} key
   * @param {{time_s: number}} e
   * @returns {HTMLElement | null}
   */
  function repeated(key, e) {
    if (!key) return null;
    for (const item of list.children) {
      if (!(item instanceof HTMLElement)) continue;
      if (e.time_s - Number(item.dataset.last) > REPEAT_WINDOW_S) continue;
      if (/** @type {{rtnavCondition?: string}} */ (/** @type {unknown} */ (item)).rtnavCondition === key) return item;
    }
    return null;
  }

  /**
   * Counts one more occurrence of `item`'s condition, at `time_s`.
   * @param {HTMLElement} item
   * @param {number} time_s
   */
  function repeat(item, time_s) {
    const count = Number(item.dataset.count) + 1;
    item.dataset.count = String(count);
    item.dataset.last = String(time_s);
    const repeats = item.querySelector('.repeats');
    if (repeats) repeats.textContent = t('log.repeats', { count, last: seconds(time_s) });
  }

  /**
   * Adds one entry where its time puts it (newest first; equal times keep their order), or
   * counts a repeat of the condition an entry shows.
   *
   * @param {{time_s: number, kind: string, level: string, text?: string, data?: EventView['data']}} e
   */
  function add(e) {
    const text = e.kind === 'Page' ? e.text ?? '' : eventText(e);
    const key = condition(e, text);
    const again = repeated(key, e);
    if (again) {
      repeat(again, e.time_s);
      return;
    }
    const item = el('li', { dataset: { kind: e.kind, level: e.level, t: String(e.time_s), last: String(e.time_s), count: '1' } },
      el('time', {}, seconds(e.time_s)),
      el('span', { class: 'text' }, text),
      el('span', { class: 'repeats' }));
    // What the core sent (the end-to-end test reads it back), and the condition it shows.
    Object.assign(item, { rtnavEvent: e, rtnavCondition: key });
    let before = list.firstElementChild;
    while (before instanceof HTMLElement && Number(before.dataset.t) > e.time_s) before = before.nextElementSibling;
    list.insertBefore(item, before);
    while (list.children.length > MAX_ENTRIES) list.lastElementChild?.remove();
  }

  /**
   * Adds the events read: a frame's, or (without any given) those since the last read —
   * before a note of the page's, or after a change that cleared the log.
   * @param {EventView[]} [events]
   */
  function update(events = app.guard.call(() => demo.take_events()) ?? []) {
    for (const e of events) add(e);
    const loud = events.filter((e) => e.kind in NOTICE).at(-1);
    if (loud) app.notice.show(eventText(loud), loud.level, { until: NOTICE[loud.kind](loud) });
  }

  return {
    clear() {
      list.replaceChildren();
    },
    update,
    /**
     * A note of the page's own (`level`: info, success, warn, error), after the core's
     * events so far (a request may have run the clock: its events come first).
     */
    /** @param {string} text @param {string} [level] */
    page(text, level = 'info') {
      update();
      add({ time_s: demo.time_s(), kind: 'Page', level, text });
    },
  };
}
