// The notice over the canvas: what just happened — a refused goal, a bad map file, a loaded
// scenario, or a state of the system (a component in Error, a bump, a planning failure,
// arrival).
//
// A notice about a state is tied to it (issue 15): `show(text, level, { until })` hides it as
// soon as `until()` says the state has ended (checked every frame), and `endState()` — called
// by Reset and Activate, and by loading a scenario — ends it at once. Other notices fade after
// a few seconds; a refusal stays longer, so it can be read. The notice never covers the robot:
// each frame it is placed at the top of the map, or at the bottom when the robot is under it.
const FADE_MS = { info: 5000, success: 5000, warn: 12000, error: 20000 };
/** Room kept around the robot's body, CSS pixels. */
const CLEARANCE_PX = 6;

const overlaps = (a, b) =>
  a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;

export function createNotice(box, text, close) {
  let timer = 0;
  let until = null;
  /** Where the robot is (a function giving its client box, or null), from the last frame. */
  let robotBox = () => null;
  const hide = () => {
    box.hidden = true;
    until = null;
    delete box.dataset.tied;
    clearTimeout(timer);
  };
  close.addEventListener('click', hide);

  /** Puts the notice at the top of the map, or at the bottom when the robot is under the top. */
  function place(robot) {
    if (box.hidden) return;
    let where = 'top';
    if (robot) {
      const r = {
        left: robot.left - CLEARANCE_PX,
        right: robot.right + CLEARANCE_PX,
        top: robot.top - CLEARANCE_PX,
        bottom: robot.bottom + CLEARANCE_PX,
      };
      const now = box.getBoundingClientRect();
      const wrap = box.offsetParent?.getBoundingClientRect();
      if (wrap) {
        // The same distance from the top edge as it keeps from whichever edge it is at.
        const gap = box.dataset.place === 'bottom' ? wrap.bottom - now.bottom : now.top - wrap.top;
        const top = { left: now.left, right: now.right, top: wrap.top + gap, bottom: wrap.top + gap + now.height };
        if (overlaps(top, r)) where = 'bottom';
      }
    }
    if (box.dataset.place !== where) box.dataset.place = where;
  }

  return {
    /**
     * Shows `message`; `level` is `info`, `success`, `warn` or `error`. With `until`, the
     * notice is about a state and stays until `until()` is true (or the state is ended).
     */
    show(message, level = 'info', { until: ends } = {}) {
      text.textContent = message;
      box.dataset.level = level;
      box.hidden = false;
      clearTimeout(timer);
      until = ends ?? null;
      if (until) box.dataset.tied = 'true';
      else delete box.dataset.tied;
      if (!until) timer = setTimeout(hide, FADE_MS[level] ?? FADE_MS.info);
      place(robotBox());
    },
    hide,
    /** Ends a notice about a state (Reset, Activate, a new scenario); others stay. */
    endState() {
      if (until) hide();
    },
    /**
     * Every frame: hides a notice whose state has ended; keeps it off the robot (`robot()`
     * gives the robot's client box; it is asked only while a notice is up).
     */
    update(robot) {
      robotBox = robot;
      if (box.hidden) return;
      if (until) {
        let ended = true;
        try {
          ended = until();
        } catch {
          // The state cannot be read (e.g. a crash): the notice goes.
        }
        if (ended) {
          hide();
          return;
        }
      }
      place(robot());
    },
    get visible() {
      return !box.hidden;
    },
  };
}
