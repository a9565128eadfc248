// @ts-check
// The page's clock: requestAnimationFrame calls `frame(elapsedMs)` with the wall time since
// the previous frame (0 for the first). Simulated time is Rust's business: it turns the
// elapsed time into whole ticks. `frame` returns false to stop.
/**
 * @param {(elapsedMs: number) => boolean | void} frame
 */
export function startLoop(frame) {
  /** @type {number | null} */
  let last = null;
  let handle = 0;
  let running = true;
  /** @param {number} now */
  const tick = (now) => {
    const elapsed = last === null ? 0 : now - last;
    last = now;
    if (frame(elapsed) === false) running = false;
    if (running) handle = requestAnimationFrame(tick);
  };
  handle = requestAnimationFrame(tick);
  return {
    stop() {
      running = false;
      cancelAnimationFrame(handle);
    },
  };
}
