// @ts-check
// The scene in words, for a screen reader: the map (its name and size), the robot's pose, the
// goal, the route's length and the status — what the canvas shows, said from the frame the page
// reads each frame (`Session::frame`: the telemetry, GlobalPathPlanning's route) and the map. The description is
// the map's `aria-describedby` and a paragraph a screen reader reaches by reading on; it is
// written only when its words change. The status is said again in a polite live region only
// when the status itself changes (its kind, or what it names), not when a number in it moves:
// nothing here speaks every frame.
import { t, fixed } from './i18n.js';
import { statusLine } from './say.js';
import { setText } from './dom.js';

/**
 * @param {HTMLElement} description the scene's words
 * @param {HTMLElement} status the status's live region
 * @param {App} app
 */
export function createScene(description, status, app) {
  const { demo } = app;
  /** @type {MapView | null} */
  let map = null;
  let spokenStatus = '';

  app.on('loaded', () => {
    map = demo.map();
  });

  /**
   * GlobalPathPlanning's route's length [m], as the component says it (its activity in the
   * frame: `route`), or null without a route.
   * @param {ComponentView[]} components
   */
  function routeLength(components) {
    for (const c of components) if (c.status.kind === 'route') return c.status.length;
    return null;
  }

  /** @param {PoseView} p */
  const at = (p) => ({ x: fixed(p.x, 1), y: fixed(p.y, 1), theta: fixed(p.theta_deg, 0) });

  /** What a change of status is: its kind and its fields' words (not its numbers). @param {TelemetryView} v */
  function statusKey(v) {
    const words = Object.entries(v.status_fields).filter(([, f]) => typeof f !== 'number');
    return `${v.status_kind} ${v.paused} ${JSON.stringify(words)}`;
  }

  return {
    /** Every frame. @param {FrameView} frame */
    update(frame) {
      const v = frame.telemetry;
      const parts = [];
      if (map) {
        parts.push(t('scene.map', {
          // The file's name, without its folders.
          name: map.name.split(/[\\/]/).pop() ?? map.name,
          w: fixed(map.width * map.grid_size, 1),
          h: fixed(map.height * map.grid_size, 1),
          cw: map.width,
          ch: map.height,
          grid: map.grid_size,
        }));
      } else {
        parts.push(t('scene.no_map'));
      }
      parts.push(v.start || v.driving ? t('scene.robot', at(v.pose)) : t('scene.robot.none'));
      if (v.goal) {
        parts.push(t('scene.goal', {
          ...at(v.goal),
          distance: v.distance_to_goal === null ? '—' : fixed(v.distance_to_goal, 1),
        }));
      } else {
        parts.push(t('scene.goal.none'));
      }
      const length = routeLength(frame.components);
      parts.push(length === null ? t('scene.route.none') : t('scene.route', { length: fixed(length, 1) }));
      const line = statusLine(v);
      parts.push(t('scene.status', { status: line }));
      setText(description, parts.join(' '));
      const key = statusKey(v);
      if (key !== spokenStatus) {
        spokenStatus = key;
        status.textContent = line;
      }
    },
  };
}
