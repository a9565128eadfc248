// @ts-check
// The event log (InventGUI's log): plans, planning failures with their reasons, bumps,
// arrival, component errors and state changes, map changes — newest first, in simulated-time
// order — and the page's own notes (a refused goal, a bad map file). The texts are the
// core's (`rtnav::system::EventKind`), numbers already written for people; the page only
// writes the time.
import { el } from '../dom.js';
import { t } from '../i18n.js';
import { eventText } from '../words.js';

const MAX_ENTRIES = 300;

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

  /** Adds one entry where its time puts it (newest first; equal times keep their order). */
  /**
   * @param {{time_s: number, kind: string, level: string, text: string, data?: EventView['data']}} e
   */
  function add(e) {
    const item = el('li', { dataset: { kind: e.kind, level: e.level, t: String(e.time_s) } },
      el('time', {}, seconds(e.time_s)),
      el('span', { class: 'text' }, eventText(e)));
    Object.assign(item, { rtnavEvent: e }); // what the core sent (the end-to-end test reads it back)
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
