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
export const WAIT = { timeout: 20_000 };
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
  return { page, problems };
}

/** Saves a screenshot in tests/e2e/out/ (and, for the README's, docs/ with UPDATE_SCREENSHOTS=1). */
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

/** Shows the side panel's tab `name` (rtc, params, inspector, plots, log). */
export async function showTab(page, name) {
  await page.click(`#tab-${name}`);
  await page.waitForSelector(`#panel-tabs [aria-selected="true"]#tab-${name}`, WAIT);
}

/** Waits until component `name`'s row shows `state`, in the RT System Editor's colour. */
export async function expectState(page, name, state) {
  const row = `#components li[data-component="${name}"]`;
  await page.waitForSelector(`${row}[data-state="${state}"]`, WAIT);
  const badge = await page.$eval(`${row} .state-badge`, (e) => [e.textContent, getComputedStyle(e).backgroundColor]);
  assert.deepEqual(badge, [state, COLOURS[state]], `${name} in ${state}`);
}

export async function activateAll(page) {
  await page.click('#activate-all');
  await page.waitForSelector('#system-state[data-state="Active"]', WAIT);
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
