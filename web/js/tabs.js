// @ts-check
// The side panel's tabs: one button per `.tab-panel` section (its `data-tab` and
// `data-label`), one section shown at a time. The choice is announced as the app event
// `tab` (name) so a panel can work only while it is seen (the plots, the inspector).
import { el } from './dom.js';

/**
 * @param {HTMLElement} nav the tab list the buttons go into
 * @param {HTMLElement[]} panels the `.tab-panel` sections
 * @param {App} app
 * @param {string} [first] the tab shown first (else the first section's)
 */
export function createTabs(nav, panels, app, first) {
  /** @type {Map<string, HTMLButtonElement>} */
  const buttons = new Map();
  /** @type {string | null} */
  let current = null;

  /** Shows the section `name` (a name without a tab: nothing). @param {string | undefined} name */
  function show(name) {
    if (name === undefined) return;
    if (!buttons.has(name) || name === current) return;
    current = name;
    for (const p of panels) p.hidden = p.dataset.tab !== name;
    for (const [n, b] of buttons) {
      b.setAttribute('aria-selected', String(n === name));
      b.tabIndex = n === name ? 0 : -1;
    }
    nav.dataset.current = name;
    app.emit('tab', name);
  }

  for (const p of panels) {
    const name = p.dataset.tab ?? '';
    const b = el('button', {
      type: 'button', role: 'tab', class: 'tab', id: `tab-${name}`, 'aria-controls': p.id,
      onclick: () => show(name),
    }, p.dataset.label ?? name);
    p.setAttribute('aria-labelledby', b.id);
    buttons.set(name, b);
    nav.append(b);
  }
  // Arrow keys move between tabs (the WAI-ARIA tabs pattern).
  nav.addEventListener('keydown', (e) => {
    if (e.key !== 'ArrowRight' && e.key !== 'ArrowLeft') return;
    const names = [...buttons.keys()];
    const i = current === null ? -1 : names.indexOf(current);
    const next = names[(i + (e.key === 'ArrowRight' ? 1 : names.length - 1)) % names.length];
    show(next);
    buttons.get(next)?.focus();
    e.preventDefault();
  });
  show(first ?? panels[0]?.dataset.tab);

  return {
    show,
    get current() {
      return current;
    },
    /** Whether the panel `name` is the one shown. @param {string} name */
    visible: (name) => current === name,
  };
}
