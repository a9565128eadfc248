// The event log: every state change and failed callback the execution context recorded,
// newest first, with simulated time.
import { el } from '../dom.js';

const MAX_ENTRIES = 50;

export function createEventLog(root, host, guard) {
  const list = el('ol', { id: 'events', class: 'events', reversed: true });
  root.append(el('h2', {}, 'Event log'), list);
  return {
    update() {
      const events = JSON.parse(guard.call(() => host.take_events()) ?? '[]');
      for (const e of events) {
        const item = el('li', { dataset: { to: e.to } },
          el('time', {}, `${(e.time_ms / 1000).toFixed(3)} s`),
          el('span', { class: 'transition' }, e.from === e.to ? e.to : `${e.from} → ${e.to}`),
          el('code', {}, e.callback),
          e.reason ? el('span', { class: 'why' }, e.reason) : null);
        list.prepend(item);
      }
      while (list.children.length > MAX_ENTRIES) list.lastElementChild.remove();
    },
  };
}
