// The lifecycle panel: the component's state (coloured as in the RT System Editor), why it
// is in Error, the requests of SPEC §1 as buttons, and its counters.
import { el, setText, textOn } from '../dom.js';

export function createLifecyclePanel(root, host, guard) {
  const state = el('span', { id: 'state', class: 'state-badge' });
  const reason = el('p', { id: 'reason', class: 'reason', hidden: true });
  const refusal = el('p', { id: 'refusal', class: 'refusal', hidden: true });
  const executions = el('output', { id: 'executions' });
  const beats = el('output', { id: 'beats' });
  const rate = el('output', { id: 'rate' });

  // Each button sends one request; buttons for illegal requests are disabled, and if one
  // is refused anyway the error (a value, never a panic) is shown.
  const request = (fn) => () => {
    try {
      guard.call(fn);
      refusal.hidden = true;
    } catch (e) {
      refusal.textContent = e.message ?? String(e);
      refusal.hidden = false;
    }
  };
  const buttons = {
    activate: el('button', { id: 'activate', onclick: request(() => host.activate()) }, 'Activate'),
    deactivate: el('button', { id: 'deactivate', onclick: request(() => host.deactivate()) }, 'Deactivate'),
    reset: el('button', { id: 'reset', onclick: request(() => host.reset()) }, 'Reset'),
    fault: el('button', { id: 'inject-fault', class: 'danger', onclick: request(() => host.inject_fault()) }, 'Inject fault'),
  };

  root.append(
    el('h2', {}, 'Lifecycle'),
    el('div', { class: 'state-row' }, el('span', { id: 'component-name', class: 'name' }, host.name()), state),
    reason,
    el('div', { class: 'buttons' }, ...Object.values(buttons)),
    refusal,
    el('dl', { class: 'stats' },
      el('dt', {}, 'executions'), el('dd', {}, executions),
      el('dt', {}, 'beats'), el('dd', {}, beats),
      el('dt', {}, 'rate'), el('dd', {}, rate)),
  );

  return {
    update() {
      const s = host.state();
      if (state.dataset.state !== s) {
        const colour = host.state_colour();
        state.dataset.state = s;
        state.style.background = colour;
        state.style.color = textOn(colour);
      }
      setText(state, s);
      const why = s === 'Error' ? host.last_error() : undefined;
      reason.hidden = !why;
      setText(reason, why ? `Reason: ${why}` : '');
      const pending = host.fault_pending();
      buttons.activate.disabled = s !== 'Inactive';
      buttons.deactivate.disabled = s !== 'Active';
      buttons.reset.disabled = s !== 'Error';
      buttons.fault.disabled = !(s === 'Inactive' || s === 'Active') || pending;
      setText(buttons.fault, pending ? 'Fault pending…' : 'Inject fault');
      setText(executions, String(host.execution_count()));
      setText(beats, String(host.beats()));
      setText(rate, `${host.rate_hz()} Hz`);
    },
  };
}
