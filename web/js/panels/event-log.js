// The event log (InventGUI's log): plans, planning failures with their reasons, bumps,
// arrival, component errors and state changes, map changes — newest first, with simulated
// time — and the page's own notes (a refused goal, a bad map file).
import { el } from '../dom.js';

const MAX_ENTRIES = 300;
/** Events important enough to be shown over the canvas too. */
const NOTICE = new Set(['Bump', 'ComponentError', 'PlanningFailed', 'Arrived']);

export function createEventLog(root, app) {
  const { demo } = app;
  const list = el('ol', { id: 'events', class: 'events', reversed: true });
  const clear = el('button', { type: 'button', class: 'link', id: 'clear-log', onclick: () => list.replaceChildren() }, 'clear');
  root.append(el('div', { class: 'panel-head' }, el('h2', {}, 'Event log'), clear), list);

  function add(e) {
    const item = el('li', { dataset: { kind: e.kind, level: e.level } },
      el('time', {}, `${e.time_s.toFixed(3)} s`),
      el('span', { class: 'text' }, e.text));
    list.prepend(item);
    while (list.children.length > MAX_ENTRIES) list.lastElementChild.remove();
  }

  return {
    clear() {
      list.replaceChildren();
    },
    update() {
      const events = JSON.parse(app.guard.call(() => demo.take_events()) ?? '[]');
      for (const e of events) add(e);
      const loud = events.filter((e) => NOTICE.has(e.kind)).at(-1);
      if (loud) app.notice.show(loud.text, loud.level);
    },
    /** A note of the page's own (`level`: info, success, warn, error). */
    page(text, level = 'info') {
      add({ time_s: demo.time_s(), kind: 'Page', level, text });
    },
  };
}
