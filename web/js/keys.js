// @ts-check
// The keyboard guide: a short list of the page's keys, in a modal dialog opened with `?` (or
// its button in the toolbar). Escape or its Close button closes it, and the focus goes back to
// where it was. The keys themselves are handled where they act: the map's in js/stage.js, the
// tools', the clock's and the zoom's in js/panels/toolbar.js.
import { el } from './dom.js';
import { t } from './i18n.js';

/** The guide's rows: the keys (as shown) and the catalogue key of what they do. */
const ROWS = [
  ['Tab', 'keys.tab'],
  ['G · S · O · E · P', 'keys.tools'],
  ['← ↑ → ↓', 'keys.arrows'],
  ['Shift + ← ↑ → ↓', 'keys.shift_arrows'],
  ['[ · ]', 'keys.turn'],
  ['Enter', 'keys.enter'],
  ['Space', 'keys.space'],
  ['.', 'keys.step'],
  ['+ · − · 0', 'keys.zoom'],
  ['?', 'keys.help'],
  ['Esc', 'keys.escape'],
];

/**
 * @param {HTMLButtonElement} opener the toolbar's button that opens it
 */
export function createKeyGuide(opener) {
  const close = el('button', { type: 'button', class: 'plain', id: 'keys-close' }, t('keys.close'));
  const dialog = el('dialog', { class: 'keys-dialog', id: 'keys', 'aria-labelledby': 'keys-title' },
    el('h2', { id: 'keys-title' }, t('keys.title')),
    el('dl', { class: 'keys-list' }, ...ROWS.map(([keys, what]) =>
      el('div', {}, el('dt', {}, el('kbd', {}, keys)), el('dd', {}, t(what))))),
    el('div', { class: 'keys-foot' }, close));
  document.body.append(dialog);
  /** @type {HTMLElement | null} */
  let back = null;

  function open() {
    if (dialog.open) return;
    back = document.activeElement instanceof HTMLElement ? document.activeElement : null;
    dialog.showModal();
    close.focus();
  }
  close.addEventListener('click', () => dialog.close());
  // Escape closes a modal dialog by itself; either way the focus goes back.
  dialog.addEventListener('close', () => {
    back?.focus();
    back = null;
  });
  opener.addEventListener('click', open);

  window.addEventListener('keydown', (e) => {
    const target = e.target;
    if (e.key !== '?' || e.ctrlKey || e.metaKey || e.altKey) return;
    if (target instanceof HTMLInputElement || target instanceof HTMLSelectElement || target instanceof HTMLTextAreaElement) return;
    e.preventDefault();
    open();
  });

  return {
    open,
    get isOpen() {
      return dialog.open;
    },
  };
}
