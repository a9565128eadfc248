// @ts-check
// Small DOM helpers shared by the panels.

// `el('button', { class: 'x', onclick }, 'text', child…)`
/**
 * @template {keyof HTMLElementTagNameMap} K
 * @param {K} tag
 * @param {Record<string, any>} [attrs]
 * @param {...(Node | string | null | undefined)} children
 * @returns {HTMLElementTagNameMap[K]}
 */
export function el(tag, attrs = {}, ...children) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (v === undefined || v === null || v === false) continue;
    if (k.startsWith('on')) node.addEventListener(k.slice(2), v);
    else if (k === 'dataset') Object.assign(node.dataset, v);
    else node.setAttribute(k, v === true ? '' : String(v));
  }
  node.append(.../** @type {Array<Node | string>} */ (children.filter((c) => c !== null && c !== undefined)));
  return node;
}

// Black or white text, whichever has the higher contrast on `#rrggbb` (WCAG's relative
// luminance: black wins from 0.179 up, where both ratios are equal).
/** @param {string} hex */
export function textOn(hex) {
  const n = parseInt(hex.slice(1), 16);
  const linear = (/** @type {number} */ c) => {
    const s = c / 255;
    return s <= 0.04045 ? s / 12.92 : ((s + 0.055) / 1.055) ** 2.4;
  };
  const [r, g, b] = [(n >> 16) & 255, (n >> 8) & 255, n & 255].map(linear);
  return 0.2126 * r + 0.7152 * g + 0.0722 * b > 0.179 ? '#000000' : '#ffffff';
}

// Sets text only when it changed (panels update every frame).
/**
 * @param {Node | null | undefined} node
 * @param {string} text
 */
export function setText(node, text) {
  if (!node) return;
  if (node.textContent !== text) node.textContent = text;
}
