// @ts-check
// The RTC panel: every component of the system (spec §0) with its lifecycle state in the RT
// System Editor's colours, the reason when it is in Error, and the requests of spec §1 for
// each one (those for all at once are in the system bar) — plus "Inject fault", and for Localization
// a "Sensor glitch": one NaN pose written into its InSimulatedPosition port, as
// OpenRTM rtshell's `rtinject` writes into a port (`inject_input`).
import { el, setText, textOn } from '../dom.js';
import { t } from '../i18n.js';
import { activityText, reasonText } from '../say.js';

/** Each state's request: its name, its label, and its accessible name (which component). @type {Record<string, [string, string, string]>} */
const ACTIONS = {
  Inactive: ['activate', t('rtc.activate'), 'rtc.activate.aria'],
  Active: ['deactivate', t('rtc.deactivate'), 'rtc.deactivate.aria'],
  Error: ['reset', t('rtc.reset'), 'rtc.reset.aria'],
};
const EDITOR = { Inactive: '#0000ff', Active: '#00ff00', Error: '#ff0000' };
/** The sensor glitch: which component, which InPort, what sample (x, y, z, θ). */
const GLITCH = { component: 'Localization', port: 'InSimulatedPosition', sample: () => new Float64Array([Number.NaN, 0, 0, 0]) };
const GLITCH_TITLE = t('rtc.glitch.title');

/**
 * @param {HTMLElement} badge
 * @param {string} state
 * @param {string} colour
 */
function paint(badge, state, colour) {
  if (badge.dataset.state === state) return;
  badge.dataset.state = state;
  badge.style.background = colour;
  badge.style.color = textOn(colour);
}

/** Sets a control's accessible name when it changed. @param {HTMLElement} e @param {string} name */
function named(e, name) {
  if (e.getAttribute('aria-label') !== name) e.setAttribute('aria-label', name);
}

/**
 * @param {HTMLElement} root
 * @param {App} app
 */
export function createRtcPanel(root, app) {
  const { demo } = app;

  const request = app.request;

  const list = el('ol', { class: 'rtc-list', id: 'components' });
  const rows = new Map();

  /** @param {ComponentView} c */
  function row(c) {
    const badge = el('span', { class: 'state-badge small' });
    const name = el('span', { class: 'rtc-name' });
    const rate = el('span', { class: 'rate' });
    const status = el('div', { class: 'rtc-status' });
    const reason = el('div', { class: 'rtc-reason', hidden: true });
    const action = el('button', { type: 'button', class: 'act' });
    const fault = el('button', { type: 'button', class: 'fault danger', title: t('rtc.fault.title', { name: c.instance_name }) }, t('rtc.fault'));
    action.addEventListener('click', () => {
      const what = /** @type {'activate' | 'deactivate' | 'reset'} */ (action.dataset.action);
      request(t(`system.act.${what}`, { name: c.name }), () => demo[what](c.name), what === 'activate' || what === 'reset');
    });
    fault.addEventListener('click', () => request(t('rtc.fault.request', { name: c.name }), () => demo.inject_fault(c.name)));
    let glitch = null;
    if (c.name === GLITCH.component) {
      glitch = el('button', { type: 'button', class: 'glitch danger', title: GLITCH_TITLE, 'aria-label': t('rtc.glitch.aria', { name: c.instance_name }) }, t('rtc.glitch'));
      glitch.addEventListener('click', () => {
        const r = request(t('rtc.glitch'), () => demo.inject_input(GLITCH.component, GLITCH.port, GLITCH.sample()));
        if (r.ok) app.log.page(t('rtc.glitch.log', { port: `${GLITCH.component}.${GLITCH.port}` }), 'warn');
      });
    }
    const li = el('li', { class: 'rtc', dataset: { component: c.name } },
      badge,
      el('div', { class: 'rtc-main' }, el('div', { class: 'rtc-title' }, name, rate), status, reason),
      el('div', { class: 'rtc-actions' }, action, fault, glitch));
    list.append(li);
    const r = { li, badge, name, rate, status, reason, action, fault, glitch };
    rows.set(c.name, r);
    return r;
  }

  root.append(
    el('div', { class: 'panel-head' },
      el('h2', {}, t('rtc.title')),
      el('span', { class: 'legend' },
        ...Object.entries(EDITOR).flatMap(([s, c]) => [el('span', { class: 'swatch', style: `--c:${c}` }), s]))),
    el('p', { class: 'panel-hint' }, t('rtc.hint')),
    list,
  );

  return {
    /** Every frame. @param {ComponentView[]} components */
    update(components) {
      for (const c of components) {
        const r = rows.get(c.name) ?? row(c);
        r.li.dataset.state = c.state;
        paint(r.badge, c.state, c.colour);
        setText(r.badge, c.state);
        setText(r.name, c.instance_name);
        setText(r.rate, `${c.rate} Hz`);
        // What it does or holds, as the core decided it (in Error: that it does not execute;
        // why is the line under it).
        setText(r.status, activityText(c.status.kind === 'in_error' ? { kind: 'in_error' } : c.status));
        const why = c.state === 'Error' && c.last_error ? t('rtc.reason', { reason: reasonText(c.last_error) }) : '';
        setText(r.reason, why);
        r.reason.hidden = !why;
        const [action, label, aria] = ACTIONS[c.state] ?? ACTIONS.Inactive;
        r.action.dataset.action = action;
        setText(r.action, label);
        // The buttons' names say which component ("Activate MotorControl0"), as their
        // labels in a row do not.
        named(r.action, t(aria, { name: c.instance_name }));
        named(r.fault, t(c.fault_pending ? 'rtc.fault.pending.aria' : 'rtc.fault.aria', { name: c.instance_name }));
        r.action.disabled = !(c.state in ACTIONS);
        r.fault.disabled = !(c.state === 'Inactive' || c.state === 'Active') || c.fault_pending;
        setText(r.fault, c.fault_pending ? t('rtc.fault.pending') : t('rtc.fault'));
        // A sample only matters to a component that executes: Active only.
        if (r.glitch) r.glitch.disabled = c.state !== 'Active';
      }
    },
  };
}
