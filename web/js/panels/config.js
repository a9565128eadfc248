// The configuration panel (the RT System Editor's ConfigurationView): one row per
// parameter with its range, unit and reflection timing; a refused value shows why and the
// old value stays (SPEC §1 "Configuration parameters").
import { el } from '../dom.js';

export function createConfigPanel(root, host, guard) {
  const params = JSON.parse(guard.call(() => host.parameters_json()) ?? '[]');
  const message = el('p', { class: 'refusal', id: 'config-refusal', hidden: true });
  const rows = params.map((p) => {
    const range = `[${p.min ?? '-∞'}, ${p.max ?? '∞'}]`;
    const input = el('input', {
      type: 'number',
      id: `param-${p.name}`,
      value: p.value,
      min: p.min ?? undefined,
      max: p.max ?? undefined,
      step: p.kind === 'Int' ? 1 : 'any',
    });
    input.addEventListener('change', () => {
      try {
        guard.call(() => host.set_parameter(p.name, Number(input.value)));
        message.hidden = true;
      } catch (e) {
        message.textContent = e.message ?? String(e);
        message.hidden = false;
        input.value = currentValue(p.name);
      }
    });
    return el('div', { class: 'param', title: p.description },
      el('label', { for: input.id }, p.name),
      input,
      el('span', { class: 'unit' }, p.unit === '-' ? '' : p.unit),
      el('span', { class: 'meta' }, `${range} · ${p.reflection === 'Always' ? 'always' : 'on activation'}`),
      el('span', { class: 'description' }, p.description));
  });

  function currentValue(name) {
    const all = JSON.parse(guard.call(() => host.parameters_json()) ?? '[]');
    return all.find((p) => p.name === name)?.value ?? '';
  }

  root.append(el('h2', {}, 'Configuration'), ...rows, message);
  return { update() {} };
}
