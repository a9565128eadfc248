// @ts-check
// The system bar, seen from every tab: the whole system's lifecycle state in the
// RT System Editor's colours, and the requests on all components at once — Activate all,
// Deactivate all, Reset all — which start and stop the robot. What the robot is doing is
// the core's `Status` (the telemetry's status), never guessed here.
import { el, setText, textOn } from '../dom.js';
import { t } from '../i18n.js';

/** @type {Record<string, string>} */
const EDITOR = { Inactive: '#0000ff', Active: '#00ff00', Error: '#ff0000' };

/**
 * @param {HTMLElement} root
 * @param {App} app
 */
export function createSystemBar(root, app) {
  const { demo } = app;

  const request = app.request;

  const badge = el('span', { id: 'system-state', class: 'state-badge', title: t('system.badge.title') });
  const buttons = {
    activate: el('button', {
      type: 'button', id: 'activate-all', title: t('system.activate_all.title'),
      onclick: () => request(t('system.activate_all'), () => demo.activate_all(), true),
    }, t('system.activate_all')),
    deactivate: el('button', {
      type: 'button', id: 'deactivate-all', class: 'secondary', title: t('system.deactivate_all.title'),
      onclick: () => request(t('system.deactivate_all'), () => demo.deactivate_all(), false),
    }, t('system.deactivate_all')),
    reset: el('button', {
      type: 'button', id: 'reset-all', class: 'secondary', title: t('system.reset_all.title'),
      onclick: () => request(t('system.reset_all'), () => demo.reset_all(), true),
    }, t('system.reset_all')),
  };
  root.append(
    el('span', { class: 'system-label' }, t('system.label')),
    badge,
    el('span', { class: 'all-buttons' }, buttons.activate, buttons.deactivate, buttons.reset),
  );

  return {
    /**
     * Every frame: the state and which requests make sense now.
     * @param {SystemState} s the system's state
     * @param {ComponentView[]} components
     * @param {boolean} placed whether the robot has a pose (a start was placed): before, the
     *   core refuses to activate PhysicsSim, and Activate all says so (spec §5 Decision 0.4)
     */
    update(s, components, placed) {
      const active = components.filter((c) => c.state === 'Active').length;
      const error = components.filter((c) => c.state === 'Error').length;
      if (badge.dataset.state !== s) {
        badge.dataset.state = s;
        const colour = EDITOR[s] ?? '#dee2e6';
        badge.style.background = colour;
        badge.style.color = textOn(colour);
      }
      setText(badge, s === 'Partial' ? t('system.partial', { active, total: components.length }) : s);
      buttons.activate.disabled = !components.some((c) => c.state === 'Inactive');
      const missing = !placed && components.some((c) => c.name === 'PhysicsSim' && c.state === 'Inactive');
      if (buttons.activate.dataset.unplaced !== String(missing)) {
        buttons.activate.dataset.unplaced = String(missing);
        buttons.activate.title = t(missing ? 'system.activate_all.unplaced' : 'system.activate_all.title');
      }
      buttons.deactivate.disabled = active === 0;
      buttons.reset.disabled = error === 0 && active === 0;
    },
  };
}
