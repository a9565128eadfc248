// The core's short status lines of the components (RT System Editor's status column,
// `ComponentInfo.status`) in the page's language: each form the core writes is matched and
// rewritten through the catalogue (`rtcstatus.*`); a line of another form is shown as the
// core wrote it. English needs no rewriting.
import { t, language } from './i18n.js';

/** [pattern, key, names of the captured parts]. */
const FORMS = [
  [/^map (\d+)×(\d+) at ([\d.]+) m$/, 'rtcstatus.map', ['w', 'h', 'g']],
  [/^no map$/, 'rtcstatus.no_map', []],
  [/^(\d+) updates? sent$/, 'rtcstatus.updates', ['n']],
  [/^(\d+) bumps?(, touching an obstacle)?$/, 'rtcstatus.bumps', ['n', 'touching']],
  [/^inactive$/, 'rtcstatus.inactive', []],
  [/^waiting for (.+)$/, 'rtcstatus.waiting', ['what']],
  [/^running$/, 'rtcstatus.running', []],
  [/^stopped \(Stop\): braking to zero velocity$/, 'rtcstatus.stopped', []],
  [/^finished \(Finish\): zero torque$/, 'rtcstatus.finished', []],
  [/^safe stop, zero (torque|velocity): (.+)$/, 'rtcstatus.safe_stop', ['what', 'reason']],
  [/^(Odometry|SimulatedPose)$/, 'rtcstatus.mode', ['mode']],
  [/^failed: (.+)$/, 'rtcstatus.failed', ['reason']],
  [/^route of ([\d.]+) m$/, 'rtcstatus.route', ['l']],
  [/^no route$/, 'rtcstatus.no_route', []],
  [/^holds: (.+); (\d+) plans? made(; retrying)?$/, 'rtcstatus.holds', ['held', 'n', 'retrying']],
  [/^idle \(no path\)$/, 'rtcstatus.idle', []],
  [/^turning on the spot$/, 'rtcstatus.turning', []],
  [/^following the path$/, 'rtcstatus.following', []],
  [/^turning to the goal heading$/, 'rtcstatus.final_turn', []],
  [/^arrived$/, 'rtcstatus.arrived', []],
  [/^safety stop: obstacle ([\d.]+) m ahead, a new plan asked for$/, 'rtcstatus.safety_stop', ['d']],
];
/** The parts of LocalPathPlanning's "holds" list. */
const HELD = { nothing: 'held.nothing', map: 'held.map', 'start and goal': 'held.start_goal', path: 'held.path', arrived: 'held.arrived' };

/** The reasons the core gives that the page can say in its language: [pattern, key, parts]. */
const REASONS = [
  [/^no path from cell \((-?\d+), (-?\d+)\) to cell \((-?\d+), (-?\d+)\)$/, 'reason.no_path', ['x0', 'y0', 'x1', 'y1']],
];

/** `text`, a reason the core gave, in the page's language (as given when not known). */
export function reasonText(text) {
  if (language() === 'en') return text;
  for (const [pattern, key, names] of REASONS) {
    const m = pattern.exec(text);
    if (m) return t(key, Object.fromEntries(names.map((n, i) => [n, m[i + 1]])));
  }
  return text;
}

/**
 * An event of the core (`{kind, text, data}`) in the page's language: the kinds a notice
 * shows over the map are said from their fields; the others as the core wrote them.
 */
export function eventText(e) {
  if (language() === 'en' || !e.data) return e.text;
  const d = e.data;
  const n = (v, digits) => (typeof v === 'number' ? v.toFixed(digits) : String(v));
  switch (e.kind) {
    case 'PlanningFailed':
      return t('event.planning_failed', { planner: d.planner, reason: reasonText(d.reason) });
    case 'Arrived':
      return t('event.arrived', {
        x: n(d.pose?.x, 3), y: n(d.pose?.y, 3), error: n(d.position_error, 3),
      });
    case 'ComponentError':
      return t('event.component_error', { component: d.component, callback: d.callback, reason: reasonText(d.reason) });
    case 'FaultInjected':
      return t('event.fault_injected', { component: d.component });
    default:
      return e.text;
  }
}

/** `text`, a component's status line from the core, in the page's language. */
export function componentStatus(text) {
  if (language() === 'en') return text;
  for (const [pattern, key, names] of FORMS) {
    const m = pattern.exec(text);
    if (!m) continue;
    const vars = Object.fromEntries(names.map((n, i) => [n, m[i + 1] ?? '']));
    if ('touching' in vars) vars.touching = vars.touching ? t('rtcstatus.touching') : '';
    if ('retrying' in vars) vars.retrying = vars.retrying ? t('rtcstatus.retrying') : '';
    if ('what' in vars && key === 'rtcstatus.safe_stop') vars.what = t(`rtcstatus.zero_${vars.what}`);
    if ('what' in vars && key === 'rtcstatus.waiting') vars.what = vars.what.replace(' and ', '・');
    if ('reason' in vars) vars.reason = reasonText(vars.reason);
    if ('held' in vars) vars.held = vars.held.split(', ').map((h) => (HELD[h] ? t(HELD[h]) : h)).join('・');
    return t(key, vars);
  }
  return text;
}
