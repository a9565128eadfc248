// The notice over the canvas: what just happened to a request — a refused goal, a bad map
// file, a loaded scenario. Information fades after a few seconds; a refusal stays until it
// is dismissed or replaced, so it can be read.
const FADE_MS = { info: 5000, success: 5000, warn: 12000, error: 20000 };

export function createNotice(box, text, close) {
  let timer = 0;
  const hide = () => {
    box.hidden = true;
    clearTimeout(timer);
  };
  close.addEventListener('click', hide);
  return {
    /** Shows `message`; `level` is `info`, `success`, `warn` or `error`. */
    show(message, level = 'info') {
      text.textContent = message;
      box.dataset.level = level;
      box.hidden = false;
      clearTimeout(timer);
      timer = setTimeout(hide, FADE_MS[level] ?? FADE_MS.info);
    },
    hide,
  };
}
