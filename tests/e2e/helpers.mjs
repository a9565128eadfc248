// What the end-to-end tests share: Debian's Chromium (driven by playwright-core, never a
// downloaded browser) against the page served by `cargo xtask test` at $RTNAV_URL, and small
// readers of the page's state.
import assert from 'node:assert/strict';
import { statSync } from 'node:fs';
import { mkdtemp, mkdir, rm, copyFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

export const URL = process.env.RTNAV_URL ?? 'http://127.0.0.1:8080/';
export const CHROMIUM = process.env.RTNAV_CHROMIUM ?? '/usr/bin/chromium';
export const HERE = dirname(fileURLToPath(import.meta.url));
export const REPO = join(HERE, '..', '..');

/**
 * The external data folder (real maps nobody on the project wrote): $RTNAV_DATA, else
 * ../shared/data beside the repository, as `rtnav::data` finds it. `DATA_MISSING` is why
 * there is none (a test that needs it is skipped with that reason), or null.
 */
export const DATA = process.env.RTNAV_DATA ?? join(REPO, '..', 'shared', 'data');
const isDir = (p) => { try { return statSync(p).isDirectory(); } catch { return false; } };
export const DATA_MISSING = process.env.RTNAV_DATA === ''
  ? 'external data not found: RTNAV_DATA is set but empty'
  : isDir(DATA)
    ? null
    : `external data not found: ${process.env.RTNAV_DATA === undefined ? `RTNAV_DATA is unset and ${DATA}` : `RTNAV_DATA=${DATA}`} is not a folder`;
const ARGS = [
  '--headless',
  '--no-sandbox',
  '--disable-gpu',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
  '--disable-quic',
];
/**
 * How long a test waits for the page to show something that follows at once from what it
 * did (a click's state, a panel's refresh, a few simulated seconds at 1×). Sized for a
 * loaded 2-core machine (other builds beside the browser), where the page may draw only a
 * few frames a second: generous, but bounded, so a page that never shows it fails.
 */
export const WAIT = { timeout: 30_000 };
/** How long a test waits for a whole drive (an arrival, an exercise's verdict) at 16×. */
export const DRIVE = { timeout: 150_000 };
export const COLOURS = { Inactive: 'rgb(0, 0, 255)', Active: 'rgb(0, 255, 0)', Error: 'rgb(255, 0, 0)' };

/**
 * Chromium with a fresh profile at 1280×800 (or `options`: another viewport, a phone's
 * `isMobile`, `hasTouch`, `deviceScaleFactor`); `close()` ends it and removes the profile.
 */
export async function launch(options = {}) {
  const profile = await mkdtemp(join(tmpdir(), 'rtnav-e2e-profile-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM,
    headless: true,
    args: ARGS,
    viewport: { width: 1280, height: 800 },
    acceptDownloads: true,
    ...options,
  });
  return {
    context,
    async close() {
      await context.close();
      await rm(profile, { recursive: true, force: true });
    },
  };
}

/**
 * A fresh page at `URL + query`, loaded and ready; `problems` collects page errors and
 * console errors.
 */
export async function openPage(context, query = '', { init } = {}) {
  const page = await context.newPage();
  if (init) await page.addInitScript(init);
  const problems = [];
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  page.on('console', (m) => {
    if (m.type() === 'error') problems.push(`console.error: ${m.text()}`);
  });
  await page.goto(URL + query, { waitUntil: 'domcontentloaded', timeout: 60_000 });
  await page.waitForSelector('body[data-ready="true"], #crash:not([hidden])', { timeout: 60_000 });
  if (await page.isVisible('#crash')) {
    assert.fail(`the page did not start: ${await page.innerText('#crash')}\n${problems.join('\n')}`);
  }
  // Ready is set when the scenario has loaded; the panels show it from the next frame on.
  await frames(page, 2);
  return { page, problems };
}

let polls = 0;

/**
 * Waits until the page shows what `check` looks for, as Playwright's auto-waiting
 * assertions do: `check(arg)` runs in the page at every animation frame and returns
 * `{ ok, shown, value }` — whether it is shown, what the page shows (for the message when
 * it never is) and what to return. It may read the DOM and the core (`window.rtnav`) in the
 * same call, so a shown value is compared with the core's as they are at one moment.
 * After `timeout` ms it fails, saying what was awaited (`what`) and what was shown last.
 */
export async function until(page, what, check, arg = null, { timeout = WAIT.timeout } = {}) {
  const slot = `__e2eShown${++polls}`;
  const expression = `(() => {
    const r = (${check})(${JSON.stringify(arg)});
    window[${JSON.stringify(slot)}] = r.shown;
    return r.ok ? { value: r.value ?? null } : false;
  })()`;
  try {
    const handle = await page.waitForFunction(expression, null, { timeout, polling: 'raf' });
    return (await handle.jsonValue()).value;
  } catch (e) {
    if (!/Timeout .*exceeded/.test(e.message)) throw e;
    const shown = await page.evaluate((s) => window[s], slot).catch((err) => `nothing readable (${err.message})`);
    assert.fail(`waited ${timeout / 1000} s for ${what}; the page shows ${typeof shown === 'string' ? shown : JSON.stringify(shown)}`);
  }
}

/**
 * Waits until the element `selector` shows `text` (a string: exactly; a RegExp: matching)
 * and returns its text.
 */
export function shownText(page, selector, text, options = {}) {
  const want = text instanceof RegExp ? { re: text.source, flags: text.flags } : { exact: text };
  return until(page, `${selector} to show ${text instanceof RegExp ? text : JSON.stringify(text)}`, (a) => {
    const e = document.querySelector(a.selector);
    const t = e?.textContent ?? null;
    const ok = t !== null && ('exact' in a ? t === a.exact : new RegExp(a.re, a.flags).test(t));
    return { ok, value: t, shown: e ? JSON.stringify(t) : `no ${a.selector}` };
  }, { selector, ...want }, options);
}

/**
 * Waits until the telemetry's status line shows text matching `re` for a status of one of
 * `kinds` (the core's `status_kind`s, any if null), and the core's status is still the one
 * the page drew: the words shown are the truth now. Returns `{ text, kind }`.
 */
export function shownStatus(page, re, kinds = null, options = {}) {
  return until(page, `the status to read /${re.source}/${kinds ? ` (${kinds.join(' or ')})` : ''}`, (a) => {
    const tel = document.getElementById('telemetry');
    const text = tel.querySelector('dd[data-key="status"]').textContent;
    const drawn = tel.dataset.status;
    const core = JSON.parse(window.rtnav.demo.telemetry_json()).status_kind;
    const ok = new RegExp(a.re).test(text) && (a.kinds === null || a.kinds.includes(drawn)) && drawn === core;
    return { ok, value: { text, kind: drawn }, shown: `the status "${text}" (drawn for ${drawn}; the core's status now ${core})` };
  }, { re: re.source, kinds }, options);
}

/** The distance driven as the telemetry shows it [m]. */
export const driven = (page) =>
  page.$eval('#telemetry dd[data-key="driven"]', (e) => parseFloat(e.textContent));

/** Waits until the telemetry shows more than `metres` driven; returns what it shows. */
export function shownDriven(page, metres, options = {}) {
  return until(page, `the telemetry to show more than ${metres} m driven`, (m) => {
    const t = document.querySelector('#telemetry dd[data-key="driven"]').textContent;
    return { ok: parseFloat(t) > m, value: parseFloat(t), shown: `driven ${t}, the status "${document.querySelector('#telemetry dd[data-key="status"]').textContent}"` };
  }, metres, options);
}

/** The simulated time the clock shows [s]. */
export const clock = (page) => page.$eval('#sim-time', (e) => parseFloat(e.textContent));

/**
 * Waits until the clock shows at least `seconds` of simulated time (the clock must run);
 * returns what it shows.
 */
export function shownClock(page, seconds, options = {}) {
  return until(page, `the clock to show ${seconds.toFixed(3)} s`, (s) => {
    const t = document.getElementById('sim-time').textContent;
    return { ok: parseFloat(t) >= s - 1e-9, value: parseFloat(t), shown: `the clock at ${t}${window.rtnav.demo.paused() ? ', paused' : ''}` };
  }, seconds, options);
}

/** Waits until the clock shows `seconds` more simulated time than it does now. */
export async function clockRuns(page, seconds, options = {}) {
  return shownClock(page, (await clock(page)) + seconds, options);
}

/**
 * Waits until the log shows at least `n` entries of `kind`; returns their texts, oldest
 * first.
 */
export function shownLogged(page, kind, n = 1, options = {}) {
  return until(page, `${n} ${kind} line(s) in the log`, (a) => {
    const lines = [...document.querySelectorAll(`#events li[data-kind="${a.kind}"] .text`)].map((i) => i.textContent).reverse();
    return { ok: lines.length >= a.n, value: lines, shown: `${lines.length}: ${JSON.stringify(lines.slice(-5))}` };
  }, { kind, n }, options);
}

/**
 * `promise`, or a failure saying what was awaited (`what`) if it has not settled within
 * `timeout` ms (for what the test itself awaits: a dialog, a download).
 */
export async function within(promise, what, { timeout = WAIT.timeout } = {}) {
  let timer;
  const late = new Promise((_, fail) => {
    timer = setTimeout(() => fail(new assert.AssertionError({ message: `waited ${timeout / 1000} s for ${what}` })), timeout);
  });
  try {
    return await Promise.race([promise, late]);
  } finally {
    clearTimeout(timer);
  }
}

/** Waits until the parameter panel shows its rows (it fills them in the first frame it is shown). */
export function shownParams(page, options = {}) {
  return until(page, 'the parameter panel\'s rows', () => {
    const n = document.querySelectorAll('#params-panel .param').length;
    return { ok: n >= 30 && document.getElementById('pd-explain') !== null, value: n, shown: `${n} parameters` };
  }, null, options);
}

/** Saves a screenshot in tests/e2e/out/ (and, for the README's and the docs' pictures, docs/ with UPDATE_SCREENSHOTS=1). */
export async function screenshot(page, name, { docs = true, fullPage = false } = {}) {
  await mkdir(join(HERE, 'out'), { recursive: true });
  const shot = join(HERE, 'out', name);
  await page.evaluate(() => document.activeElement?.blur());
  await page.screenshot({ path: shot, fullPage });
  if (docs && process.env.UPDATE_SCREENSHOTS === '1') {
    await mkdir(join(REPO, 'docs'), { recursive: true });
    await copyFile(shot, join(REPO, 'docs', name));
  }
  return shot;
}

export const json = (page, call) => page.evaluate((c) => JSON.parse(window.rtnav.demo[c]()), call);
export const plan = (page) => json(page, 'plan_json');
export const telemetry = (page) => json(page, 'telemetry_json');
export const mapInfo = (page) => json(page, 'map_json');

/** Page coordinates of the centre of map cell (x, y). */
export function cellToPage(page, [x, y]) {
  return page.evaluate(([x, y]) => {
    const m = JSON.parse(window.rtnav.demo.map_json());
    const wx = m.origin[0] + (x + 0.5) * m.grid_size;
    const wy = m.origin[1] + (y + 0.5) * m.grid_size;
    const [px, py] = window.rtnav.demo.world_to_pixel(wx, wy);
    const c = document.getElementById('overlay');
    const r = c.getBoundingClientRect();
    return [r.left + (px * r.width) / c.width, r.top + (py * r.height) / c.height];
  }, [x, y]);
}

/**
 * Shows the side panel's tab `name` (rtc, system, params, inspector, plots, log); for the
 * parameters, waits for their rows too.
 */
export async function showTab(page, name) {
  await page.click(`#tab-${name}`);
  await page.waitForSelector(`#panel-tabs [aria-selected="true"]#tab-${name}`, WAIT);
  if (name === 'params') await shownParams(page);
}

/** The Parameters tab's row of `component`'s parameter `name`. */
export const paramRow = (component, name) => `#params-panel .param[data-component="${component}"][data-name="${name}"]`;

/** Types `value` into the parameter's field in the Parameters tab and presses Enter, as a person does. */
export async function typeParam(page, component, name, value) {
  await showTab(page, 'params');
  const input = `${paramRow(component, name)} input`;
  await page.waitForSelector(input, WAIT);
  await page.fill(input, String(value));
  await page.press(input, 'Enter');
}

/** Waits until the Parameters tab shows `value` as the parameter's requested value. */
export const shownParam = (page, component, name, value) =>
  page.waitForSelector(`${paramRow(component, name)}[data-value="${value}"]`, { state: 'attached', ...WAIT });

/** Types `value` as {@link typeParam} does and waits until the tab shows it. */
export async function setParam(page, component, name, value) {
  await typeParam(page, component, name, value);
  await shownParam(page, component, name, value);
}

/** Waits until component `name`'s row shows `state`, in the RT System Editor's colour. */
export async function expectState(page, name, state, options = {}) {
  const badge = await until(page, `${name}'s row to show ${state}`, (a) => {
    const row = document.querySelector(`#components li[data-component="${a.name}"]`);
    const b = row?.querySelector('.state-badge');
    const value = b ? [row.dataset.state, b.textContent, getComputedStyle(b).backgroundColor] : null;
    return { ok: value?.[0] === a.state, value, shown: JSON.stringify(value) };
  }, { name, state }, options);
  assert.deepEqual(badge, [state, state, COLOURS[state]], `${name} in ${state}`);
}

/** Waits until the system bar shows the whole system in `state`. */
export function systemShows(page, state, options = {}) {
  return until(page, `the system bar to show ${state}`, (s) => {
    const e = document.getElementById('system-state');
    return { ok: e.dataset.state === s, shown: `${e.dataset.state}: "${e.textContent}"` };
  }, state, options);
}

export async function activateAll(page) {
  await page.click('#activate-all');
  await systemShows(page, 'Active');
}

/** The log entries of `kind`, oldest first. */
export const logged = (page, kind) =>
  page.$$eval(`#events li[data-kind="${kind}"] .text`, (items) => items.map((i) => i.textContent).reverse());

/** Resolves after the page has drawn `n` more animation frames. */
export const frames = (page, n = 2) =>
  page.evaluate((n) => new Promise((done) => {
    const next = (k) => (k === 0 ? done() : requestAnimationFrame(() => next(k - 1)));
    next(n);
  }), n);

/** SHA-256 (hex) of the RGBA bytes of a canvas (the main one, `#view`, unless told) and its size. */
export const canvasHash = (page, selector = '#view') =>
  page.evaluate(async (selector) => {
    const c = document.querySelector(selector);
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    const h = new Uint8Array(await crypto.subtle.digest('SHA-256', d));
    return { width: c.width, height: c.height, sha256: Array.from(h, (b) => b.toString(16).padStart(2, '0')).join('') };
  }, selector);

/** Keeps a copy of the main canvas's pixels in the page, as `name`. */
export const keepCanvas = (page, name) =>
  page.evaluate((name) => {
    const c = document.getElementById('view');
    window.__kept = window.__kept ?? {};
    window.__kept[name] = c.getContext('2d').getImageData(0, 0, c.width, c.height);
  }, name);

/**
 * How many pixels differ between the kept canvases `a` and `b` inside the box
 * `[x0, y0, x1, y1]` (canvas pixels, clipped to the canvas), and how many the box holds.
 */
export const canvasDiff = (page, a, b, box) =>
  page.evaluate(([a, b, box]) => {
    const A = window.__kept[a];
    const B = window.__kept[b];
    if (A.width !== B.width || A.height !== B.height) throw new Error('the canvases differ in size');
    const [x0, y0, x1, y1] = [Math.max(0, Math.floor(box[0])), Math.max(0, Math.floor(box[1])),
      Math.min(A.width, Math.ceil(box[2])), Math.min(A.height, Math.ceil(box[3]))];
    let differing = 0;
    for (let y = y0; y < y1; y++) {
      for (let x = x0; x < x1; x++) {
        const i = 4 * (y * A.width + x);
        if (A.data[i] !== B.data[i] || A.data[i + 1] !== B.data[i + 1] || A.data[i + 2] !== B.data[i + 2]) differing++;
      }
    }
    return { differing, pixels: Math.max(0, x1 - x0) * Math.max(0, y1 - y0) };
  }, [a, b, box]);

/**
 * In the page: every visible control and text block, and what is wrong with the layout —
 * wider than the window, a control outside the window or clipped by a box that hides
 * overflow, two overlapping, or one whose centre another element covers (a tap there would
 * not reach it).
 */
export function layoutProblems() {
  const scrollers = [...document.querySelectorAll('*')].filter((e) => /auto|scroll/.test(getComputedStyle(e).overflowY));
  const home = () => {
    for (const e of scrollers) e.scrollTop = 0;
    window.scrollTo(0, 0);
  };
  home();
  const vw = document.documentElement.clientWidth;
  const problems = [];
  if (document.documentElement.scrollWidth > vw + 1) {
    problems.push(`the page is wider than the window: ${document.documentElement.scrollWidth} > ${vw}`);
  }
  const name = (e) => (e.id ? `#${e.id}` : `${e.tagName.toLowerCase()}.${[...e.classList].join('.')} "${e.textContent.trim().slice(0, 24)}"`);
  const shown = (e) => e.checkVisibility({ checkOpacity: true, checkVisibilityCSS: true })
    && e.getBoundingClientRect().width > 0 && e.getBoundingClientRect().height > 0;
  const CONTROLS = 'button, select, input:not([type="file"]), label.file-button, summary, [role="tab"]';
  const BLOCKS = '.telemetry .field, .lesson, #tool-hint, .legend-box, .map-controls, #notice, #system-state';
  const controls = [...document.querySelectorAll(CONTROLS)].filter(shown);
  const items = [...new Set([...controls, ...document.querySelectorAll(BLOCKS)])].filter(shown);
  /** The part of `e` its scrolling boxes show (null: scrolled out of sight, reachable by scrolling). */
  const seen = new Map();
  for (const e of items) {
    const r = e.getBoundingClientRect();
    let v = { left: r.left, right: r.right, top: r.top, bottom: r.bottom };
    let inScroller = false;
    if (r.left < -0.5 || r.right > vw + 0.5) problems.push(`${name(e)} is off-screen (${Math.round(r.left)}–${Math.round(r.right)} of ${vw})`);
    for (let a = e.parentElement; a && a !== document.body; a = a.parentElement) {
      const cs = getComputedStyle(a);
      const over = `${cs.overflowX} ${cs.overflowY}`;
      if (!/hidden|clip|auto|scroll/.test(over)) continue;
      const ar = a.getBoundingClientRect();
      if (/auto|scroll/.test(over)) {
        inScroller = true;
      } else if (r.left < ar.left - 0.5 || r.right > ar.right + 0.5 || r.top < ar.top - 0.5 || r.bottom > ar.bottom + 0.5) {
        problems.push(`${name(e)} is cut off by ${name(a)}`);
      }
      v = { left: Math.max(v.left, ar.left), right: Math.min(v.right, ar.right), top: Math.max(v.top, ar.top), bottom: Math.min(v.bottom, ar.bottom) };
    }
    if (!inScroller && r.top + window.scrollY < -0.5) problems.push(`${name(e)} is above the page`);
    seen.set(e, v.right - v.left > 1 && v.bottom - v.top > 1 ? v : null);
  }
  for (let i = 0; i < items.length; i++) {
    for (let j = i + 1; j < items.length; j++) {
      const [a, b] = [items[i], items[j]];
      if (a.contains(b) || b.contains(a)) continue;
      const p = seen.get(a);
      const q = seen.get(b);
      if (!p || !q) continue;
      const w = Math.min(p.right, q.right) - Math.max(p.left, q.left);
      const h = Math.min(p.bottom, q.bottom) - Math.max(p.top, q.top);
      if (w > 1 && h > 1) problems.push(`${name(a)} overlaps ${name(b)} (${Math.round(w)}×${Math.round(h)} px)`);
    }
  }
  // A tap at each control's centre reaches it.
  for (const e of controls) {
    e.scrollIntoView({ block: 'center', inline: 'center' });
    const r = e.getBoundingClientRect();
    const hit = document.elementFromPoint(r.left + r.width / 2, r.top + r.height / 2);
    if (!hit || !(hit === e || e.contains(hit) || hit.contains(e) && hit.tagName === 'LABEL')) {
      problems.push(`a tap on ${name(e)} reaches ${hit ? name(hit) : 'nothing'}`);
    }
  }
  home();
  return problems;
}

/**
 * A cell of the page's map inside an obstacle: it and every cell within `margin` cells of it
 * are obstacles (null if the map has none).
 */
export function solidObstacleCell(page, margin = 1) {
  return page.evaluate((margin) => {
    const { demo } = window.rtnav;
    const m = JSON.parse(demo.map_json());
    for (let y = margin + 1; y < m.height - margin - 1; y++) {
      for (let x = margin + 1; x < m.width - margin - 1; x++) {
        let solid = true;
        for (let dy = -margin; dy <= margin && solid; dy++) {
          for (let dx = -margin; dx <= margin && solid; dx++) solid = demo.cell(x + dx, y + dy) === 1;
        }
        if (solid) return [x, y];
      }
    }
    return null;
  }, margin);
}
