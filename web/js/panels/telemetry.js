// The telemetry readout under the canvas: where the robot is, how fast it goes, how far the
// goal is, what the planners have done. `data-*` attributes carry the raw values (the
// end-to-end test reads them).
import { el, setText } from '../dom.js';

const FIELDS = [
  ['status', 'Status'],
  ['pose', 'Robot'],
  ['speed', 'v · ω'],
  ['goal', 'To goal'],
  ['driven', 'Driven'],
  ['plans', 'Plans'],
];

export function createTelemetry(root, app) {
  const { demo } = app;
  const values = new Map();
  for (const [key, label] of FIELDS) {
    const dd = el('dd', { dataset: { key } });
    values.set(key, dd);
    root.append(el('div', { class: 'field', dataset: { field: key } }, el('dt', {}, label), dd));
  }
  const set = (key, text) => setText(values.get(key), text);

  return {
    update() {
      const t = JSON.parse(demo.telemetry_json());
      root.dataset.arrived = String(t.arrived);
      root.dataset.driving = String(t.driving);
      root.dataset.state = t.state;
      root.dataset.distance = t.distance_to_goal ?? '';
      root.dataset.bumps = t.bumps;
      root.dataset.localPlans = t.local_plans;
      set('pose', `${t.pose.x.toFixed(2)}, ${t.pose.y.toFixed(2)} m · ${Math.round(t.pose.theta_deg)}°`);
      set('speed', `${t.v.toFixed(2)} m/s · ${t.w.toFixed(2)} rad/s`);
      set('goal', t.distance_to_goal === null ? '—' : `${t.distance_to_goal.toFixed(2)} m`);
      set('driven', `${t.path_length.toFixed(2)} m`);
      root.dataset.status = t.status_kind;
      set('plans', `${t.global_plans} global · ${t.local_plans} local`);
      // What the core says is true (rtnav::system::Status), not guessed here.
      let status = t.status.charAt(0).toUpperCase() + t.status.slice(1);
      if (t.paused) status += ' · paused';
      set('status', status);
      values.get('status').dataset.arrived = String(t.arrived);
    },
  };
}
