// @ts-check
// The page's words in English and Japanese: one catalogue per language (`i18n/en.json`,
// `i18n/ja.json`, flat `key → text` with `{name}` placeholders); `tests/e2e/i18n.test.mjs`
// fails if a key is missing in either. The Japanese catalogue also holds the scenarios'
// texts (`scenario.NAME.description|lesson|task`); their English is the scenario files'.
//
// The language: `?lang=` in the address (a share link carries it) first, then the choice
// kept in local storage, then the browser's language. Switching reloads the page in the
// other language, so every string is drawn anew; the run goes with it (`carry.js`).
export const LANGUAGES = ['en', 'ja'];
const STORAGE_KEY = 'rtnav.lang';

/** A catalogue: key → text with `{name}` placeholders. @typedef {Record<string, string>} Catalogue */

let lang = 'en';
/** @type {Catalogue} */
let words = {};
/** @type {Catalogue} */
let english = {};

/** Whether `l` is a language the page has a catalogue for. @param {string | null | undefined} l @returns {l is string} */
const known = (l) => typeof l === 'string' && LANGUAGES.includes(l);

/**
 * The language to use: the address's `lang`, the stored choice, the browser's.
 * @param {string} [search]
 * @param {Storage | undefined} [storage]
 * @param {readonly string[] | undefined} [browser]
 * @returns {string}
 */
export function chooseLanguage(search = location.search, storage = globalThis.localStorage,
  browser = navigator.languages ?? [navigator.language]) {
  const asked = new URLSearchParams(search).get('lang');
  if (known(asked)) return asked;
  let kept = null;
  try { kept = storage?.getItem(STORAGE_KEY); } catch { /* storage blocked: not kept */ }
  if (known(kept)) return kept;
  return (browser ?? []).some((l) => String(l).toLowerCase().startsWith('ja')) ? 'ja' : 'en';
}

/**
 * Loads the catalogues (English always: the fallback) and sets the document's language.
 * @param {string} chosen
 * @returns {Promise<string>}
 */
export async function loadLanguage(chosen) {
  lang = known(chosen) ? chosen : 'en';
  /** @param {string} l @returns {Promise<Catalogue>} */
  const get = async (l) => {
    const r = await fetch(`i18n/${l}.json`);
    if (!r.ok) throw new Error(`i18n/${l}.json: HTTP ${r.status}`);
    return r.json();
  };
  english = await get('en');
  words = lang === 'en' ? english : await get(lang);
  document.documentElement.lang = lang;
  return lang;
}

/** The language in use. */
export function language() {
  return lang;
}

/**
 * `v` with six significant digits, without trailing zeros: the core's `present::number`.
 * @param {number | null | undefined} v
 * @returns {string}
 */
export function number(v) {
  if (v === null || v === undefined) return 'NaN';
  if (!Number.isFinite(v)) return String(v).replace('Infinity', 'inf');
  if (v === 0) return '0';
  const a = Math.abs(v);
  /** @param {string} s */
  const trim = (s) => (s.includes('.') ? s.replace(/0+$/, '').replace(/\.$/, '') : s);
  if (a < 1e-4 || a >= 1e9) {
    const [m, e] = v.toExponential(5).split('e');
    return `${trim(m)}e${e.replace('+', '')}`;
  }
  const decimals = Math.min(12, Math.max(0, 5 - Math.floor(Math.log10(a))));
  return trim(v.toFixed(decimals));
}

/**
 * A placeholder's value as text: `fmt` is empty (a whole number as it is, any other as
 * [`number`]; a list joined with ", "), `.N`
 * (N decimals, no minus on a zero), `n` ([`number`]), `deg.N` (radians in degrees, N decimals)
 * or `link` (a connection's id with an arrow for its `->`).
 * @param {unknown} v
 * @param {string | undefined} fmt
 * @returns {string}
 */
function show(v, fmt) {
  if (Array.isArray(v)) return v.map((x) => show(x, fmt)).join(', ');
  if (v === null || v === undefined) return fmt ? 'NaN' : '';
  // A data connection's id (`A.out->B.in`) as people read it: an arrow, not ASCII "->".
  if (fmt === 'link') return String(v).replace('->', ' → ');
  if (typeof v !== 'number') return String(v);
  // A whole number as it is; any other to six significant digits (`number`), never the 17
  // of a float's shortest form ("0.30000000000000004 m").
  if (!fmt) return Number.isInteger(v) ? String(v) : number(v);
  if (fmt === 'n') return number(v);
  const deg = fmt.startsWith('deg');
  const digits = Number(fmt.replace(/^deg/, '').replace(/^\./, ''));
  const shown = (deg ? (v * 180) / Math.PI : v).toFixed(digits);
  // Never "-0.00" (a heading of −1e-17 rad is 0.0°), as the core's `present::fixed`.
  return /^-[0.]+$/.test(shown) ? shown.slice(1) : shown;
}

/**
 * `vars`' value at a dotted path (`pose.x`, `cell.0`), or undefined.
 * @param {object} vars
 * @param {string} path
 * @returns {unknown}
 */
function at(vars, path) {
  /** @type {unknown} */
  let v = vars;
  for (const part of path.split('.')) {
    if (v === null || typeof v !== 'object' || !(part in v)) return undefined;
    v = /** @type {Record<string, unknown>} */ (v)[part];
  }
  return v;
}

/**
 * The text of `key` with placeholders filled from `vars`: `{name}`, a dotted path
 * `{pose.x}` / `{cell.0}`, and a format after a colon (`{speed:.3}`, `{value:n}`,
 * `{theta:deg.1}`, see `show`). A placeholder without a value stays as written.
 * @param {string} key
 * @param {object} [vars]
 * @returns {string}
 */
export function t(key, vars = {}) {
  return fill(words[key] ?? english[key] ?? key, vars);
}

/**
 * `text` with its placeholders filled from `vars` (see `t`).
 * @param {string} text
 * @param {object} [vars]
 * @returns {string}
 */
export function fill(text, vars = {}) {
  return text.replace(/\{([\w.]+)(?::([\w.]+))?\}/g, (/** @type {string} */ m, /** @type {string} */ path, /** @type {string | undefined} */ fmt) => {
    const v = at(vars, path);
    return v === undefined ? m : show(v, fmt);
  });
}

/**
 * The English catalogue (the one English of the page and the command line).
 * @returns {Readonly<Catalogue>}
 */
export function englishWords() {
  return english;
}

/**
 * Whether the catalogue has `key` (the scenarios' Japanese texts are optional lookups).
 * @param {string} key
 */
export function has(key) {
  return key in words;
}

/**
 * Fills `[data-i18n]` (text), `[data-i18n-title]`, `[data-i18n-label]` (a tab's label) and
 * `[data-i18n-aria-label]` under `root` (the selectors guarantee each attribute is there).
 * @param {ParentNode} [root]
 */
export function translateStatic(root = document) {
  /** The page's elements that match (all of them HTML). @param {string} selector */
  const all = (selector) => /** @type {NodeListOf<HTMLElement>} */ (root.querySelectorAll(selector));
  for (const node of all('[data-i18n]')) node.textContent = t(node.dataset.i18n ?? '');
  for (const node of all('[data-i18n-title]')) node.title = t(node.dataset.i18nTitle ?? '');
  for (const node of all('[data-i18n-label]')) node.dataset.label = t(node.dataset.i18nLabel ?? '');
  for (const node of all('[data-i18n-aria-label]')) {
    node.setAttribute('aria-label', t(node.dataset.i18nAriaLabel ?? ''));
  }
  document.title = t('page.title');
}

/**
 * Keeps `next` and reloads the page in it, with `share` (a set-up token) if given; without
 * one, the address names no set-up (the run itself is carried: `carry.js`).
 * @param {string} next
 * @param {string | null} [share]
 */
export function switchLanguage(next, share = null) {
  try { localStorage.setItem(STORAGE_KEY, next); } catch { /* not kept: the address says it */ }
  const params = new URLSearchParams(location.search);
  params.set('lang', next);
  if (share) params.set('share', share);
  else params.delete('share');
  location.search = params.toString();
}

/**
 * A number as the language writes it (the core's own numbers are already text); one that
 * rounds to zero is "0", never "-0".
 * @param {number | string} value
 * @param {number} digits
 * @returns {string}
 */
export function num(value, digits) {
  return Number(value).toLocaleString(lang === 'ja' ? 'ja-JP' : 'en-GB', {
    maximumFractionDigits: digits, minimumFractionDigits: 0, useGrouping: false, signDisplay: 'negative',
  });
}

/**
 * `v` with `digits` decimals (`toFixed`), but "0.00" for a value that rounds to zero, never "-0.00".
 * @param {number | string} v
 * @param {number} digits
 * @returns {string}
 */
export function fixed(v, digits) {
  const s = Number(v).toFixed(digits);
  return /^-0(\.0*)?$/.test(s) ? s.slice(1) : s;
}

// The catalogues are loaded before any module that imports this one runs (top-level await):
// the modules' own tables of labels are made in the chosen language.
try {
  await loadLanguage(chooseLanguage());
} catch (e) {
  // Without catalogues the page shows the keys; the crash box says why.
  console.error(`rtnav: the language catalogues did not load: ${e}`);
}
