// End-to-end: a run of open_field with a map stroke and a parameter change is
// downloaded as a replay (< 20 KB), the page is reloaded, the replay loaded: the same trace
// hash and the same frame, byte for byte. The timeline seeks back and forth and steps one
// tick, back to the same hash; "compare with…" on parking_wall shows different arrival
// headings for PostureConsiderationLevel 85 (A) and 0 (B).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFile, stat } from 'node:fs/promises';
import {
  WAIT, launch, openPage, screenshot, activateAll, frames, canvasHash, showTab,
} from './helpers.mjs';

let browser;
before(async () => {
  browser = await launch();
});
after(async () => {
  await browser?.close();
});

const SIZE = [640, 400];

/** The run's trace hash now (the replay's own record of it). */
const traceHash = (page) => page.evaluate(() => JSON.parse(window.rtnav.demo.replay_json()).trace_hash);
const simTime = (page) => page.evaluate(() => window.rtnav.demo.time_s());

/** Runs the clock until simulated time reaches `t` seconds, then pauses it. */
async function runTo(page, t) {
  await page.waitForFunction((t) => window.rtnav.demo.time_s() >= t, t, { timeout: 60_000 });
  await page.evaluate(() => window.rtnav.demo.set_paused(true));
}

test('a downloaded replay, loaded after a reload, gives the same trace and frame; the timeline seeks both ways', { timeout: 180_000 }, async () => {
  const { page, problems } = await openPage(browser.context);
  await page.evaluate(([w, h]) => window.rtnav.setFrameSize(w, h), SIZE);
  await page.evaluate(() => window.rtnav.demo.set_speed(4));
  await activateAll(page);
  await runTo(page, 2);
  // A stroke across the route (sent at once when it ends, as the brush does) and a
  // parameter change, both while the clock runs.
  await page.evaluate(() => {
    const xs = [];
    const ys = [];
    for (let x = 150; x < 158; x++) for (let y = 100; y < 103; y++) { xs.push(x); ys.push(y); }
    window.rtnav.demo.set_cells(xs, ys, 1);
    window.rtnav.demo.set_paused(false);
  });
  await runTo(page, 4);
  await page.evaluate(() => {
    window.rtnav.demo.set_param('LocalPathPlanning', 'PostureConsiderationLevel', '85');
    window.rtnav.demo.set_paused(false);
  });
  await runTo(page, 12);
  await frames(page, 3);
  const hash = await traceHash(page);
  const frame = await canvasHash(page);
  const end = await simTime(page);

  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#replay-download')]);
  assert.match(download.suggestedFilename(), /^open_field-.*\.rtnav\.json$/);
  const file = await download.path();
  const size = (await stat(file)).size;
  assert.ok(size < 20 * 1024, `${size} bytes`);
  const replay = JSON.parse(await readFile(file, 'utf8'));
  assert.equal(replay.format, 'rtnav-replay');
  assert.equal(replay.trace_hash, hash);
  assert.deepEqual(replay.inputs.map((i) => i.input.type), ['activate_all', 'map_update', 'set_param']);

  // A fresh page: load the file through the file picker.
  await page.reload({ waitUntil: 'domcontentloaded' });
  await page.waitForSelector('body[data-ready="true"]', { timeout: 60_000 });
  await page.evaluate(([w, h]) => window.rtnav.setFrameSize(w, h), SIZE);
  await page.setInputFiles('#replay-file', file);
  await page.waitForSelector('#timeline[data-replay-matches="true"]', { timeout: 60_000 });
  assert.equal(await page.getAttribute('#timeline', 'data-replay-hash'), hash);
  assert.equal(await traceHash(page), hash);
  assert.equal(await simTime(page), end);
  await frames(page, 3);
  assert.deepEqual(await canvasHash(page), frame, 'the same frame, byte for byte');
  assert.ok(Number(await page.getAttribute('#timeline', 'data-checkpoints')) >= 3);
  const marks = await page.$$eval('#tl-marks .timeline-mark', (m) => m.map((e) => e.dataset.kind));
  assert.ok(marks.includes('plan'), `marks ${marks}`);

  // How long a seek takes in this build of the page (reported; the bound is the release
  // build's, checked natively by core/tests/replay.rs).
  const seekMs = await page.evaluate((end) => [1, end - 0.5, 5, end, 0.5].map((t) => {
    const t0 = performance.now();
    window.rtnav.demo.seek(t);
    return performance.now() - t0;
  }), end);
  console.log(`replay ${size} bytes; seeks in the page: ${seekMs.map((m) => m.toFixed(1)).join(', ')} ms`);
  // Back to 3 s: another frame; forth to the end: the recorded hash and frame again.
  await page.evaluate(() => window.rtnav.timeline.seek(3));
  assert.equal(await simTime(page), 3);
  await frames(page, 2);
  assert.notDeepEqual(await canvasHash(page), frame);
  await screenshot(page, 'timeline.png');
  await page.evaluate((t) => window.rtnav.timeline.seek(t), end);
  assert.equal(await traceHash(page), hash);
  await frames(page, 2);
  assert.deepEqual(await canvasHash(page), frame);
  // One tick back and one forth.
  await page.click('#tl-back');
  assert.ok(Math.abs((await simTime(page)) - (end - 0.001)) < 1e-9);
  await page.click('#tl-forth');
  assert.equal(await traceHash(page), hash);

  // A file of another version is refused with the reason, and the page keeps its run.
  await page.setInputFiles('#replay-file', {
    name: 'old.rtnav.json', mimeType: 'application/json',
    buffer: Buffer.from(JSON.stringify({ ...replay, version: 99 })),
  });
  await page.waitForSelector('#timeline-message[data-level="error"]', WAIT);
  assert.match(await page.innerText('#timeline-message'), /version 99/);
  assert.equal(await traceHash(page), hash);
  // A hand-in of a scenario changed since it was recorded, or of another behaviour version of
  // the core, is refused with which, and the page keeps its run.
  for (const [edit, words] of [
    [{ scenario_hash: '0'.repeat(64) }, 'has changed since the replay was recorded'],
    [{ behaviour: replay.behaviour - 1 }, `recorded by behaviour version ${replay.behaviour - 1}`],
  ]) {
    await page.setInputFiles('#replay-file', {
      name: 'changed.rtnav.json', mimeType: 'application/json',
      buffer: Buffer.from(JSON.stringify({ ...replay, ...edit })),
    });
    await page.waitForFunction(
      (words) => document.querySelector('#timeline-message[data-level="error"]')?.textContent?.includes(words),
      words, WAIT);
    assert.equal(await traceHash(page), hash);
  }
  assert.deepEqual(problems, []);
  await page.close();
});

test('compare with…: PostureConsiderationLevel 85 and 0 on parking_wall arrive at different headings', { timeout: 180_000 }, async () => {
  const { page, problems } = await openPage(browser.context);
  await page.evaluate(() => window.rtnav.scenarios.load('parking_wall'));
  await showTab(page, 'params');
  await page.click('#compare-form summary');
  await page.selectOption('#compare-param', 'LocalPathPlanning/PostureConsiderationLevel');
  await page.fill('#compare-value', '0');
  await page.click('#compare-run');
  await page.waitForSelector('#compare-view:not([hidden])', { timeout: 120_000 });
  const rows = await page.$$eval('#compare-table tbody tr', (trs) => Object.fromEntries(
    trs.map((tr) => [tr.dataset.measure, [...tr.querySelectorAll('td')].map((td) => td.textContent)]),
  ));
  for (const m of ['time to goal', 'path length', 'min clearance', 'arrival heading error', 'replans', 'energy Σ|τ·ω|·Δt']) {
    assert.ok(rows[m], `row ${m}`);
  }
  const [a, b] = rows['arrival heading error'].map(parseFloat);
  assert.ok(a < 55 && b > 70, `A ${a}°, B ${b}°`);
  assert.deepEqual(rows.outcome, ['Arrived', 'Arrived']);
  const picture = await canvasHash(page, '#compare-canvas');
  assert.equal(picture.width, 640);
  await screenshot(page, 'compare.png');
  await page.click('#compare-close');
  assert.equal(await page.isVisible('#compare-view'), false);
  assert.deepEqual(problems, []);
  await page.close();
});

test('the timeline and the compare view fit small screens', { timeout: 180_000 }, async () => {
  for (const [w, h, name] of [[768, 1024, 'tablet'], [390, 844, 'phone']]) {
    const small = await launch({ viewport: { width: w, height: h }, isMobile: w < 500, hasTouch: w < 500 });
    try {
      const { page, problems } = await openPage(small.context);
      const box = await page.$eval('#timeline', (e) => {
        const r = e.getBoundingClientRect();
        return [r.left, r.right, document.documentElement.clientWidth];
      });
      assert.ok(box[0] >= 0 && box[1] <= box[2] + 0.5, `timeline ${box} on ${name}`);
      await page.$eval('#timeline', (e) => e.scrollIntoView());
      await screenshot(page, `timeline-${name}.png`, { docs: false });
      // The compare view covers the page and fits it.
      await page.evaluate(() => window.rtnav.compare.start('LocalPathPlanning/PostureConsiderationLevel', '0'));
      await page.waitForSelector('#compare-view:not([hidden])', WAIT);
      const view = await page.$eval('#compare-view', (e) => {
        const r = e.getBoundingClientRect();
        return [r.left, r.right, e.scrollWidth <= e.clientWidth + 1, document.documentElement.clientWidth];
      });
      assert.ok(view[0] >= 0 && view[1] <= view[3] + 0.5 && view[2], `compare view ${view} on ${name}`);
      await screenshot(page, `compare-${name}.png`, { docs: false });
      assert.deepEqual(problems, []);
    } finally {
      await small.close();
    }
  }
});
