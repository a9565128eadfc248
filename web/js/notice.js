// The notice over the canvas: what just happened — a refused goal, a bad map file, a loaded
// scenario, or a state of the system (a component in Error, a bump, a planning failure,
// arrival).
//
// A notice about a state is tied to it (issue 15): `show(text, level, { until })` hides it as
// soon as `until()` says the state has ended (checked every frame), and `endState()` — called
// by Reset and Activate, and by loading a scenario — ends it at once. Other notices fade after
// a few seconds; a refusal stays longer, so it can be read. The notice keeps off the robot and
// the goal: each frame it is placed at the top of the map, or at the bottom, or along a side,
// wherever it covers fewest of them. Clicks pass through it to the map (its text is no
// control); only its button takes them (style.css: `pointer-events`).
const FADE_MS = { info: 5000, success: 5000, warn: 12000, error: 20000 };
/** Room kept around the robot's body and the goal, CSS pixels. */
const CLEARANCE_PX = 6;
/** The notice's offsets from the map's top and bottom edge, rem (style.css `.notice`). */
const TOP_REM = 2.6;
const BOTTOM_REM = 2.3;
/** Its offset from the map's side when it keeps to the left or right, rem (`data-align`). */
const EDGE_REM = 0.45;
/** Where it may go, in order of preference: [top or bottom, centre or side]. */
const PLACES = [['top', 'center'], ['bottom', 'center'], ['top', 'left'], ['top', 'right'], ['bottom', 'left'], ['bottom', 'right']];

const overlaps = (a, b) =>
  a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;

export function createNotice(box, text, close) {
  let timer = 0;
  let until = null;
  /** What to keep clear (a function giving client boxes: the robot, the goal), from the last frame. */
  let keepClear = () => [];
  const hide = () => {
    box.hidden = true;
    until = null;
    delete box.dataset.tied;
    clearTimeout(timer);
  };
  close.addEventListener('click', hide);

  /**
   * Puts the notice where fewest of `clear` (client boxes: the robot, the goal) are under it:
   * at the top of the map or at the bottom, in the middle or along the left or right edge —
   * the first of these places, in that order of preference, with the fewest. The places are
   * where the style puts it (`data-place`, `data-align`): its `top` or `bottom` offset from
   * the map's edge, centred or `EDGE_REM` from a side.
   */
  function place(clear) {
    if (box.hidden) return;
    let best = ['top', 'center'];
    const wrap = box.offsetParent?.getBoundingClientRect();
    if (clear.length && wrap) {
      const now = box.getBoundingClientRect();
      const rem = parseFloat(getComputedStyle(document.documentElement).fontSize) || 16;
      const tops = { top: wrap.top + TOP_REM * rem, bottom: wrap.bottom - BOTTOM_REM * rem - now.height };
      const lefts = {
        center: wrap.left + (wrap.width - now.width) / 2,
        left: wrap.left + EDGE_REM * rem,
        right: wrap.right - EDGE_REM * rem - now.width,
      };
      const under = ([v, h]) => clear.filter((c) => overlaps(
        { left: lefts[h], right: lefts[h] + now.width, top: tops[v], bottom: tops[v] + now.height },
        { left: c.left - CLEARANCE_PX, right: c.right + CLEARANCE_PX, top: c.top - CLEARANCE_PX, bottom: c.bottom + CLEARANCE_PX },
      )).length;
      let fewest = Infinity;
      for (const candidate of PLACES) {
        const n = under(candidate);
        if (n < fewest) [best, fewest] = [candidate, n];
      }
    }
    if (box.dataset.place !== best[0]) box.dataset.place = best[0];
    if (box.dataset.align !== best[1]) box.dataset.align = best[1];
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
      place(keepClear());
    },
    hide,
    /** Ends a notice about a state (Reset, Activate, a new scenario); others stay. */
    endState() {
      if (until) hide();
    },
    /**
     * Every frame: hides a notice whose state has ended; keeps it off the robot and the goal
     * (`clear()` gives their client boxes; it is asked only while a notice is up).
     */
    update(clear) {
      keepClear = clear;
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
      place(clear());
    },
    get visible() {
      return !box.hidden;
    },
  };
}
