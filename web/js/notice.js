// @ts-check
// The notice over the canvas: what just happened — a refused goal, a bad map file, a loaded
// scenario, or a state of the system (a component in Error, a bump, a planning failure,
// arrival).
//
// A notice about a state is tied to it: `show(text, level, { until })` hides it as
// soon as `until()` says the state has ended (checked every frame), and `endState()` — called
// by Reset and Activate, and by loading a scenario — ends it at once. Other notices fade after
// a few seconds; a refusal stays longer, so it can be read. The notice keeps off the robot and
// the goal: each frame it is placed at the top of the map, or at the bottom, or along a side,
// or at a height in between, the first of these where it covers neither (else where it covers
// fewest). It never takes more than a quarter of the map: a notice that would is made compact
// (smaller, at most three lines; its whole text stays its title and what a screen reader
// reads) and, if it must, narrower. Clicks pass through it to the map (its text is no
// control); only its button takes them (style.css: `pointer-events`). A screen reader hears a
// notice once, when it is shown, from a polite live region beside the map (`said`); the box
// itself is no live region, so placing it again each frame says nothing.
/** @type {Record<string, number>} */
const FADE_MS = { info: 5000, success: 5000, warn: 12000, error: 20000 };
/** Room kept around the robot's body and the goal, CSS pixels. */
const CLEARANCE_PX = 6;
/** The notice's offsets from the map's top and bottom edge, rem (style.css `.notice`). */
const TOP_REM = 2.6;
const BOTTOM_REM = 2.3;
/** Its offset from the map's side when it keeps to the left or right, rem (`data-align`). */
const EDGE_REM = 0.45;
/**
 * Where it may go, in order of preference: [top or bottom, centre or side]; then heights in between.
 * @type {Array<['top' | 'bottom', 'center' | 'left' | 'right']>}
 */
const PLACES = [['top', 'center'], ['bottom', 'center'], ['top', 'left'], ['top', 'right'], ['bottom', 'left'], ['bottom', 'right']];
/** @type {Array<'center' | 'left' | 'right'>} */
const ALIGNS = ['center', 'left', 'right'];
/** The step between the heights in between, CSS pixels. */
const STEP_PX = 8;
/** The most of the map's area a notice may cover. */
const MOST_OF_MAP = 0.25;

/** @param {ClientBox} a @param {ClientBox} b */
const overlaps = (a, b) =>
  a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;

/**
 * @param {HTMLElement} box the notice
 * @param {HTMLElement} text its words
 * @param {HTMLElement} close its button
 * @param {HTMLElement} said where a screen reader hears it (a polite live region)
 */
export function createNotice(box, text, close, said) {
  /** @type {ReturnType<typeof setTimeout> | undefined} */
  let timer;
  /** @type {(() => boolean) | null} */
  let until = null;
  /**
   * What to keep clear (a function giving client boxes: the robot, the goal), from the last frame.
   * @type {() => Array<ClientBox | null>}
   */
  let keepClear = () => [];
  const hide = () => {
    box.hidden = true;
    until = null;
    delete box.dataset.tied;
    clearTimeout(timer);
  };
  close.addEventListener('click', hide);

  /**
   * Keeps the notice within a quarter of the map `wrap` (its client box): compact if it is
   * larger, and narrower if it still is.
   */
  let fitted = '';
  /** @param {DOMRect} wrap */
  function fit(wrap) {
    // Measured again only when the text or the map's size changed.
    const key = `${Math.round(wrap.width)}×${Math.round(wrap.height)} ${text.textContent}`;
    if (key === fitted) return;
    fitted = key;
    const most = MOST_OF_MAP * wrap.width * wrap.height;
    const area = () => box.offsetWidth * box.offsetHeight;
    if (box.dataset.compact !== undefined || box.style.maxWidth) {
      delete box.dataset.compact;
      box.style.maxWidth = '';
    }
    if (area() <= most) return;
    box.dataset.compact = 'true';
    if (area() > most) box.style.maxWidth = `${Math.floor(most / box.offsetHeight)}px`;
  }

  /**
   * Puts the notice where none of `clear` (client boxes: the robot, the goal) is under it:
   * the first of `PLACES` (its `top` or `bottom` offset from the map's edge, centred or
   * `EDGE_REM` from a side: `data-place`, `data-align` in the style), else the first height in
   * between (`data-place="middle"`, from the top down) and alignment; where every place
   * covers one, the first place that covers fewest.
   * @param {Array<ClientBox | null>} boxes
   */
  function place(boxes) {
    const clear = /** @type {ClientBox[]} */ (boxes.filter(Boolean));
    if (box.hidden) return;
    const wrap = /** @type {HTMLElement | null} */ (box.offsetParent)?.getBoundingClientRect();
    if (!wrap) return;
    if (box.title !== text.textContent) box.title = text.textContent ?? '';
    fit(wrap);
    /** @type {[string, string, number | null]} */
    let best = ['top', 'center', null];
    if (clear.length) {
      const now = { width: box.offsetWidth, height: box.offsetHeight };
      const rem = parseFloat(getComputedStyle(document.documentElement).fontSize) || 16;
      const tops = { top: wrap.top + TOP_REM * rem, bottom: wrap.bottom - BOTTOM_REM * rem - now.height };
      const lefts = {
        center: wrap.left + (wrap.width - now.width) / 2,
        left: wrap.left + EDGE_REM * rem,
        right: wrap.right - EDGE_REM * rem - now.width,
      };
      const under = (/** @type {number} */ top, /** @type {'center' | 'left' | 'right'} */ h) => clear.filter((c) => overlaps(
        { left: lefts[h], right: lefts[h] + now.width, top, bottom: top + now.height },
        { left: c.left - CLEARANCE_PX, right: c.right + CLEARANCE_PX, top: c.top - CLEARANCE_PX, bottom: c.bottom + CLEARANCE_PX },
      )).length;
      /** @type {Array<[string, 'center' | 'left' | 'right', number | null, number]>} */
      const candidates = PLACES.map(([v, h]) => [v, h, null, tops[v]]);
      for (let y = tops.top + STEP_PX; y < tops.bottom; y += STEP_PX) {
        for (const h of ALIGNS) candidates.push(['middle', h, y - wrap.top, y]);
      }
      let fewest = Infinity;
      for (const [v, h, offset, top] of candidates) {
        const n = under(top, h);
        if (n < fewest) [best, fewest] = [[v, h, offset], n];
        if (n === 0) break;
      }
    }
    if (box.dataset.place !== best[0]) box.dataset.place = best[0];
    if (box.dataset.align !== best[1]) box.dataset.align = best[1];
    const top = best[2] === null ? '' : `${Math.round(best[2])}px`;
    if (box.style.top !== top) box.style.top = top;
  }

  return {
    /**
     * Shows `message`; `level` is `info`, `success`, `warn` or `error`. With `until`, the
     * notice is about a state and stays until `until()` is true (or the state is ended);
     * with `stays`, it stays until its button closes it or another notice takes its place.
     * @param {string} message
     * @param {string} [level]
     * @param {{ until?: () => boolean, stays?: boolean }} [options]
     */
    show(message, level = 'info', { until: ends, stays = false } = {}) {
      text.textContent = message;
      said.textContent = message;
      box.dataset.level = level;
      box.hidden = false;
      clearTimeout(timer);
      until = ends ?? null;
      if (until) box.dataset.tied = 'true';
      else delete box.dataset.tied;
      if (!until && !stays) timer = setTimeout(hide, FADE_MS[level] ?? FADE_MS.info);
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
    /** @param {() => Array<ClientBox | null>} clear */
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
