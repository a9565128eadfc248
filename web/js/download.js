// @ts-check
// Saving something the page made (a .conf, the telemetry CSV, the frame PNG) as a file.

/** Offers `blob` for download as `name` (an <a download> click; the URL is freed after). */
/** @param {Blob} blob @param {string} name */
export function download(blob, name) {
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  a.hidden = true;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

/** Offers `text` for download as `name`. */
/** @param {string} text @param {string} name @param {string} [type] */
export function downloadText(text, name, type = 'text/plain') {
  download(new Blob([text], { type: `${type};charset=utf-8` }), name);
}
