// @ts-check
// The telemetry readout under the canvas: where the robot is, how fast it goes, how far the
// goal is, what the planners have done. `data-*` attributes carry the raw values (the
// end-to-end test reads them).
import { el, setText } from '../dom.js';
import { t, fixed } from '../i18n.js';
import { statusText } from '../say.js';

const FIELDS = [
  ['status', t('telemetry.status')],
  ['pose', t('telemetry.pose')],
  ['speed', 'v · ω'],
  ['goal', t('telemetry.goal')],
  ['driven', t('telemetry.driven')],
  ['plans', t('telemetry.plans')],
];

/**
 * @param {HTMLElement} root
 * @param {App} app
 */
export function createTelemetry(root, app) {
  /** @type {Map<string, HTMLElement>} */
  const values = new Map();
  for (const [key, label] of FIELDS) {
    const dd = el('dd', { dataset: { key } });
    values.set(key, dd);
    root.append(el('div', { class: 'field', dataset: { field: key } }, el('dt', {}, label), dd));
  }
  /** @param {string} key @param {string} text */
  const set = (key, text) => setText(values.get(key), text);

  return {
    /** Every frame. @param {TelemetryView} v */
    update(v) {
      root.dataset.arrived = String(v.arrived);
      root.dataset.driving = String(v.driving);
      root.dataset.state = v.state;
      root.dataset.distance = String(v.distance_to_goal ?? '');
      root.dataset.bumps = String(v.bumps);
      root.dataset.localPlans = String(v.local_plans);
      set('pose', `${fixed(v.pose.x, 2)}, ${fixed(v.pose.y, 2)} m · ${fixed(v.pose.theta_deg, 0)}°`);
      set('speed', `${fixed(v.v, 2)} m/s · ${fixed(v.w, 2)} rad/s`);
      set('goal', v.distance_to_goal === null ? '—' : `${fixed(v.distance_to_goal, 2)} m`);
      set('driven', `${fixed(v.path_length, 2)} m`);
      root.dataset.status = v.status_kind;
      set('plans', t('telemetry.plans.value', { global: v.global_plans, local: v.local_plans }));
      // What the core says is true (rtnav::system::Status), not guessed here: said from the
      // catalogue's words for the status's kind, with its fields (which component, why).
      const said = statusText(v.status_kind, v.status_fields);
      const status = said.charAt(0).toUpperCase() + said.slice(1);
      set('status', status);
      const shown = /** @type {HTMLElement} */ (values.get('status'));
      if (shown.title !== status) shown.title = status;
      shown.dataset.arrived = String(v.arrived);
    },
  };
}
