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

// Black or white text, whichever reads better on `#rrggbb`.
/** @param {string} hex */
export function textOn(hex) {
  const n = parseInt(hex.slice(1), 16);
  const [r, g, b] = [(n >> 16) & 255, (n >> 8) & 255, n & 255];
  return 0.299 * r + 0.587 * g + 0.114 * b > 150 ? '#000000' : '#ffffff';
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
