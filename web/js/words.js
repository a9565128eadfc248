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
    if ('held' in vars) vars.held = vars.held.split(', ').map((h) => (HELD[h] ? t(HELD[h]) : h)).join('・');
    return t(key, vars);
  }
  return text;
}
