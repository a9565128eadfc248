// End-to-end: the teaching tools and the sensor glitch, through the
// page's own panels, mouse and canvas.
//
// Proves: a planning parameter changed while the robot stands re-plans and redraws the path
// (PostureConsiderationLevel 0 → 100); PGainL changed while driving changes the torques
// (against the same run without the change, tick for tick) and their plot; an
// on-activation parameter (lengthOfAxle) waits, marked pending, until MotorControl is
// activated again; the inspector shows exactly the numbers the native core computes
// (`rtnav inspect`); a share link reproduces the set-up (first frame byte for byte, the
// parameters) and a bad one falls back to the default scenario; an exported .conf
// re-imported restores the configuration, refused values and a bad .conf change nothing;
// the exports download; a sensor glitch puts Localization in Error with the port named,
// and Reset → Activate recovers.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFile } from 'node:child_process';
import { existsSync } from 'node:fs';
import { readFile } from 'node:fs/promises';
import { join } from 'node:path';
import { promisify } from 'node:util';
import {
  REPO, WAIT, launch, openPage, screenshot, json, plan, cellToPage, showTab, expectState,
  activateAll, frames, canvasHash, keepCanvas, canvasDiff, logged, shownLogged, shownDriven,
  shownText, clockRuns, paramRow, typeParam, shownParam,
} from './helpers.mjs';

const run = promisify(execFile);

let browser;
before(async () => {
  browser = await launch();
});
after(async () => {
  await browser?.close();
});

const open = (query = '') => openPage(browser.context, query);
const params = (page) => json(page, 'params_json');
const param = (list, component, name) =>
  list.find((c) => c.component === component).params.find((p) => p.name === name);
const row = paramRow;


/** The `[x0, y0, x1, y1]` canvas-pixel box around the cells of `paths`, padded. */
const pathBox = (page, paths, pad = 12) =>
  page.evaluate(([paths, pad]) => {
    const { demo } = window.rtnav;
    const m = JSON.parse(demo.map_json());
    const box = [Infinity, Infinity, -Infinity, -Infinity];
    for (const [x, y] of paths.flat()) {
      const [px, py] = demo.world_to_pixel(m.origin[0] + (x + 0.5) * m.grid_size, m.origin[1] + (y + 0.5) * m.grid_size);
      box[0] = Math.min(box[0], px - pad);
      box[1] = Math.min(box[1], py - pad);
      box[2] = Math.max(box[2], px + pad);
      box[3] = Math.max(box[3], py + pad);
    }
    return box;
  }, [paths, pad]);

test('PostureConsiderationLevel 0 → 100 while the robot stands: re-planned, the drawn path changes', { timeout: 60_000 }, async () => {
  const { page, problems } = await open();
  await expectState(page, 'DriveControl', 'Inactive');
  await page.evaluate(() => window.rtnav.setFrameSize(960, 600));

  /**
   * Sets the level and waits until the page has logged the plan made with it, a second of
   * simulated time has passed (no plan comes later) and the page has drawn since.
   */
  const level = async (value) => {
    const plans = (await logged(page, 'LocalPlanSent')).length;
    await typeParam(page, 'LocalPathPlanning', 'PostureConsiderationLevel', value);
    await shownParam(page, 'LocalPathPlanning', 'PostureConsiderationLevel', value);
    await shownLogged(page, 'LocalPlanSent', plans + 1);
    await clockRuns(page, 1);
    await frames(page, 3);
  };
  await level(0);
  let list = await params(page);
  assert.equal(param(list, 'LocalPathPlanning', 'PostureConsiderationLevel').effective, 0);
  const raw0 = await page.evaluate(() => window.rtnav.demo.plan_json());
  await keepCanvas(page, 'level0');

  // The next plan is made with the new value: at once, since the robot stands.
  await level(100);
  assert.notEqual(await page.evaluate(() => window.rtnav.demo.plan_json()), raw0);
  await keepCanvas(page, 'level100');
  list = await params(page);
  const p = param(list, 'LocalPathPlanning', 'PostureConsiderationLevel');
  assert.deepEqual([p.value, p.effective, p.pending, p.reflection, p.unit, p.range], [100, 100, false, 'always', '%', '[0, 100]']);

  const plan0 = JSON.parse(raw0);
  const plan100 = await plan(page);
  assert.notDeepEqual(plan100.local_path, plan0.local_path, 'the local path follows the posture level');
  const box = await pathBox(page, [plan0.local_path, plan100.local_path]);
  const diff = await canvasDiff(page, 'level0', 'level100', box);
  console.log(`PostureConsiderationLevel 0 → 100: ${diff.differing} of ${diff.pixels} pixels differ over the path's box`);
  assert.ok(diff.differing > 500, `${diff.differing} pixels changed over the path`);
  await screenshot(page, 'teach-params.png', { docs: false });
  assert.deepEqual(problems, []);
  await page.close();
});

test('PGainL while driving changes the torques and their plot; lengthOfAxle waits for the next activation', { timeout: 90_000 }, async () => {
  const { page, problems } = await open();
  await page.click('#pause');
  /** A run from the scenario's start, paused, stepped tick by tick; `change` after 1.5 s. */
  const drive = async (change) => {
    await page.evaluate(() => window.rtnav.scenarios.load('open_field'));
    const t0 = await page.evaluate(() => window.rtnav.demo.time_s());
    await showTab(page, 'rtc');
    await activateAll(page);
    await page.evaluate(() => window.rtnav.demo.step_ticks(1500));
    const tc = await page.evaluate(() => window.rtnav.demo.time_s());
    if (change) {
      await typeParam(page, 'MotorControl', 'PGainL', 40);
      await shownParam(page, 'MotorControl', 'PGainL', 40);
    }
    await page.evaluate(() => window.rtnav.demo.step_ticks(1000));
    await showTab(page, 'plots');
    const data = await page.evaluate(() => JSON.parse(window.rtnav.demo.plot_json(10)));
    await page.waitForFunction((t) => document.getElementById('plots-panel').dataset.t === String(t), data.t.at(-1), WAIT);
    return { t0, tc, data, plot: (await canvasHash(page, '#plot-torques')).sha256 };
  };
  const plain = await drive(false);
  const changed = await drive(true);
  assert.equal(changed.t0, plain.t0, 'both runs start at the same simulated time');
  assert.deepEqual(changed.data.t, plain.data.t, 'the same samples');
  const n = plain.data.t.length;
  for (const key of ['t', 'torque_l', 'torque_r', 'rate_l', 'target_rate_l', 'v', 'w', 'deviation']) {
    assert.equal(plain.data[key].length, n, key);
  }
  let before = 0;
  let after = 0;
  let most = 0;
  for (let i = 0; i < n; i++) {
    const same = changed.data.torque_l[i] === plain.data.torque_l[i];
    if (plain.data.t[i] <= plain.tc + 1e-9) {
      assert.ok(same, `torque_l at t = ${plain.data.t[i]} s, before the change, is the same`);
      before++;
    } else {
      if (!same) after++;
      most = Math.max(most, Math.abs(changed.data.torque_l[i] - plain.data.torque_l[i]));
    }
  }
  console.log(`PGainL 5 → 40 at ${plain.tc} s: ${before} samples equal before, ${after} differ after (largest ${most.toFixed(3)} N·m)`);
  assert.ok(before > 10 && after > 10, `${before} samples before, ${after} changed after`);
  assert.ok(most > 0.01, `the left torque changed by up to ${most} N·m`);
  assert.notEqual(changed.plot, plain.plot, 'the torque plot is drawn differently');
  assert.ok(plain.data.replans.length > 0 && plain.data.replans.every(Number.isFinite), 'the plans are marked');

  // lengthOfAxle (on activation): pending while MotorControl stays Active.
  await page.click('#pause');
  await typeParam(page, 'MotorControl', 'lengthOfAxle', 0.5);
  await page.waitForSelector(`${row('MotorControl', 'lengthOfAxle')}.pending`, WAIT);
  assert.match(await page.textContent(`${row('MotorControl', 'lengthOfAxle')} .pending-tag`), /^pending \(next activation\)/);
  let axle = param(await params(page), 'MotorControl', 'lengthOfAxle');
  assert.deepEqual([axle.value, axle.effective, axle.pending, axle.reflection], [0.5, 0.441, true, 'on_activation']);
  await clockRuns(page, 0.5);
  axle = param(await params(page), 'MotorControl', 'lengthOfAxle');
  assert.deepEqual([axle.effective, axle.pending], [0.441, true], 'still waiting while Active');
  await page.$eval(row('MotorControl', 'lengthOfAxle'), (e) => e.scrollIntoView({ block: 'center' }));
  await screenshot(page, 'teach-pending.png', { docs: false });
  const mc = '#components li[data-component="MotorControl"]';
  await showTab(page, 'rtc');
  await page.click(`${mc} .act`);
  await expectState(page, 'MotorControl', 'Inactive');
  axle = param(await params(page), 'MotorControl', 'lengthOfAxle');
  assert.deepEqual([axle.effective, axle.pending], [0.441, true], 'still waiting while Inactive');
  await page.click(`${mc} .act`);
  await expectState(page, 'MotorControl', 'Active');
  axle = param(await params(page), 'MotorControl', 'lengthOfAxle');
  assert.deepEqual([axle.value, axle.effective, axle.pending], [0.5, 0.5, false], 'in use after the activation');
  await showTab(page, 'params');
  await page.waitForSelector(`${row('MotorControl', 'lengthOfAxle')}[data-pending="false"]:not(.pending)`, WAIT);
  assert.equal(await page.isVisible(`${row('MotorControl', 'lengthOfAxle')} .pending-tag`), false);
  await showTab(page, 'plots');
  // Drawn again since the tab was shown (it redraws while shown and the clock runs).
  const drawn = await page.getAttribute('#plots-panel', 'data-draws');
  await page.waitForFunction((n) => document.getElementById('plots-panel').dataset.draws !== n, drawn, WAIT);
  await screenshot(page, 'teach-plots.png');
  assert.deepEqual(problems, []);
  await page.close();
});

/** The native core's answer for `cell` of open_field (`rtnav inspect`, after the page's preview). */
async function nativeInspect([x, y]) {
  const args = ['inspect', 'fixtures/scenarios/open_field.json', '--cell', `${x},${y}`];
  const built = join(REPO, 'target', 'debug', 'rtnav');
  const [program, argv] = process.env.RTNAV_CLI
    ? [process.env.RTNAV_CLI, args]
    : existsSync(built) && !process.env.RTNAV_CLI_CARGO
      ? [built, args]
      : ['cargo', ['run', '-q', '-p', 'rtnav-cli', '--', ...args]];
  const { stdout } = await run(program, argv, { cwd: REPO, maxBuffer: 1 << 20, timeout: 600_000 });
  return { text: stdout.trim(), json: JSON.parse(stdout) };
}

test('the inspector shows, for the cell under the mouse, exactly what the native core computes', { timeout: 600_000 }, async () => {
  const { page, problems } = await open();
  await showTab(page, 'inspector');
  // Three kinds of cell: on the planned path (in the field), an obstacle, free but within dmin.
  const cells = await page.evaluate(() => {
    const { demo } = window.rtnav;
    const m = JSON.parse(demo.map_json());
    const path = JSON.parse(demo.plan_json()).local_path;
    const onPath = path[Math.floor(path.length * 0.3)];
    let obstacle = null;
    let near = null;
    for (let y = 5; y < m.height - 5 && !(obstacle && near); y++) {
      for (let x = 5; x < m.width - 5 && !(obstacle && near); x++) {
        const j = JSON.parse(demo.inspect_cell(x, y));
        if (!obstacle && j.occupancy === 1 && x > m.width / 3) obstacle = [x, y];
        if (!near && j.occupancy === 0 && j.impassable && x > m.width / 3 && y > m.height / 3) near = [x, y];
      }
    }
    return [onPath, obstacle, near];
  });
  for (const cell of cells) assert.ok(cell, JSON.stringify(cells));
  console.log(`inspected cells: on the path ${cells[0]}, obstacle ${cells[1]}, within dmin ${cells[2]}`);
  for (const cell of cells) {
    const [x, y] = await cellToPage(page, cell);
    await page.mouse.move(x - 3, y);
    await page.mouse.move(x, y);
    await page.waitForSelector(`#inspector-panel[data-cell="${cell[0]},${cell[1]}"]`, { state: 'attached', ...WAIT });
    const shownJson = JSON.parse(await page.getAttribute('#inspector-panel', 'data-json'));
    const native = await nativeInspect(cell);
    assert.deepEqual(shownJson, native.json, `cell ${cell}: page ${JSON.stringify(shownJson)} vs native ${native.text}`);
    // Every row carries its exact value; the text shows it rounded.
    const rows = await page.$$eval('#inspector dd', (dds) => Object.fromEntries(dds.map((d) => [d.dataset.key, [d.dataset.value, d.textContent]])));
    assert.equal(JSON.parse(rows.obstacle_distance[0]), native.json.obstacle_distance);
    assert.equal(rows.obstacle_distance[1], `${native.json.obstacle_distance.toFixed(3)} m`);
    assert.equal(JSON.parse(rows.occupancy[0]), native.json.occupancy);
    assert.equal(JSON.parse(rows.impassable[0]), native.json.impassable);
    assert.deepEqual(JSON.parse(rows.cell[0]), cell);
    for (const k of ['potential', 'repulsion', 'attraction', 'posture', 'state']) {
      assert.deepEqual(JSON.parse(rows[k][0]), native.json.field === null ? null : native.json.field[k], k);
    }
  }
  const [onPath, obstacle, near] = await Promise.all(cells.map((c) => nativeInspect(c).then((r) => r.json)));
  assert.equal(onPath.occupancy, 0);
  assert.ok(onPath.field && typeof onPath.field.potential === 'number', JSON.stringify(onPath));
  assert.deepEqual([obstacle.occupancy, obstacle.obstacle_distance, obstacle.impassable], [1, 0, true]);
  assert.deepEqual([near.occupancy, near.impassable], [0, true]);
  await screenshot(page, 'teach-inspector.png', { docs: false });
  assert.deepEqual(problems, []);
  await page.close();
});

test('a share link reproduces the scenario, its edits and parameters; a bad link falls back to the default', { timeout: 90_000 }, async () => {
  const { page, problems } = await open();
  // The lesson is shown beside the scenario.
  assert.match(await page.textContent('#about-lesson'), /^Try this \S/);
  assert.equal(await page.isVisible('#about-lesson'), true);
  // Edits: a 3×3 block of obstacle cells on the path, two parameters.
  const { local_path: path } = await plan(page);
  const at = path[Math.floor(path.length * 0.6)];
  await page.click('#tool-paint');
  await page.selectOption('#brush', '3');
  const [px, py] = await cellToPage(page, at);
  await page.mouse.click(px, py);
  await page.waitForFunction(([x, y]) => window.rtnav.demo.cell(x, y) === 1, at, WAIT);
  await typeParam(page, 'LocalPathPlanning', 'PostureConsiderationLevel', 40);
  await shownParam(page, 'LocalPathPlanning', 'PostureConsiderationLevel', 40);
  await typeParam(page, 'DriveControl', 'MaxVelocity', 0.3);
  await shownParam(page, 'DriveControl', 'MaxVelocity', 0.3);
  // The clock is paused, so the frame stays the set-up's first one (its caption carries the
  // simulated time); making the link restarts the set-up from it while the robot stands.
  await page.click('#pause');
  await shownText(page, '#pause', 'Run');
  await page.click('#share-copy');
  await page.waitForSelector('#share-link:not([hidden])', WAIT);
  const link = await page.inputValue('#share-link');
  const list = await params(page);
  const planned = await plan(page);
  const token = new URL(link).searchParams.get('share');
  assert.equal(link, `${new URL(page.url()).origin}${new URL(page.url()).pathname}?lang=en&share=${token}`, "the link carries the language");
  assert.match(token, /^[A-Za-z0-9_-]+$/, 'URL-safe');

  // The fresh page keeps a copy of the first frame it puts on the canvas.
  const { page: other, problems: otherProblems } = await openPage(browser.context, new URL(link).search, {
    init: () => {
      const put = CanvasRenderingContext2D.prototype.putImageData;
      CanvasRenderingContext2D.prototype.putImageData = function (image, ...rest) {
        if (!window.__firstFrame && this.canvas.id === 'view') {
          window.__firstFrame = { width: image.width, height: image.height, data: new Uint8ClampedArray(image.data) };
        }
        return put.call(this, image, ...rest);
      };
    },
  });
  assert.equal(await other.inputValue('#scenario'), 'open_field');
  assert.equal(await other.evaluate(([x, y]) => window.rtnav.demo.cell(x, y), at), 1, 'the painted cells');
  assert.deepEqual(await params(other), list, 'the same parameters');
  const otherPlan = await plan(other);
  assert.deepEqual([otherPlan.start, otherPlan.goal, otherPlan.direction], [planned.start, planned.goal, planned.direction]);
  assert.equal((await json(other, 'telemetry_json')).driving, false, 'the robot has not started');
  const first = await other.evaluate(async () => {
    const f = window.__firstFrame;
    const h = new Uint8Array(await crypto.subtle.digest('SHA-256', f.data));
    return { width: f.width, height: f.height, sha256: Array.from(h, (b) => b.toString(16).padStart(2, '0')).join('') };
  });
  // The page that made the link, still paused at its set-up, drawn at the same size.
  await page.evaluate(([w, h]) => window.rtnav.setFrameSize(w, h), [first.width, first.height]);
  await frames(page, 3);
  assert.deepEqual(await canvasHash(page), first, 'the same first frame, byte for byte (caption and all)');
  assert.deepEqual(otherProblems, []);
  await other.close();

  // A broken link: explained, and the default scenario instead.
  const { page: bad, problems: badProblems } = await open('?share=not-a-token');
  await bad.waitForSelector('#notice[data-level="error"]:not([hidden])', WAIT);
  assert.match(await bad.textContent('#notice-text'), /^This share link cannot be used: .+\. The default scenario is shown instead\.$/);
  assert.equal(await bad.inputValue('#scenario'), 'open_field');
  assert.equal(param(await params(bad), 'LocalPathPlanning', 'PostureConsiderationLevel').value, 85);
  assert.deepEqual(badProblems, []);
  await bad.close();
  assert.deepEqual(problems, []);
  await page.close();
});

test('an exported .conf imported again restores the configuration; refused values change nothing', { timeout: 60_000 }, async () => {
  const { page, problems } = await open();
  await showTab(page, 'params');
  const original = await params(page);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#conf-export')]);
  assert.equal(download.suggestedFilename(), 'rtnav.conf');
  const text = await readFile(await download.path(), 'utf8');
  assert.equal(text, await page.evaluate(() => window.rtnav.demo.conf_export()));
  assert.match(text, /PostureConsiderationLevel/);

  // A refused value: explained beside the field, the field back to the value held.
  await typeParam(page, 'LocalPathPlanning', 'PostureConsiderationLevel', 250);
  const error = `${row('LocalPathPlanning', 'PostureConsiderationLevel')} .param-error`;
  await page.waitForSelector(error, WAIT);
  const why = await page.textContent(error);
  assert.match(why, /PostureConsiderationLevel/);
  assert.match(why, /250/);
  assert.match(why, /\[0, 100\]/);
  assert.equal(await page.inputValue(`${row('LocalPathPlanning', 'PostureConsiderationLevel')} input`), '85');
  await typeParam(page, 'DriveControl', 'MaxVelocity', 'fast');
  await page.waitForSelector(`${row('DriveControl', 'MaxVelocity')} .param-error`, WAIT);
  assert.deepEqual(await params(page), original, 'nothing changed');

  // Changes: one parameter, and the four gains through SetPDGain.
  await typeParam(page, 'DriveControl', 'MaxVelocity', 0.25);
  await shownParam(page, 'DriveControl', 'MaxVelocity', 0.25);
  for (const [name, v] of [['PGainL', 7], ['PGainR', 8], ['DGainL', 1.5], ['DGainR', 2.5]]) await page.fill(`#pd-${name}`, String(v));
  await page.click('#pd-send');
  await shownParam(page, 'MotorControl', 'DGainR', 2.5);
  let list = await params(page);
  assert.deepEqual(['PGainL', 'PGainR', 'DGainL', 'DGainR'].map((n) => param(list, 'MotorControl', n).effective), [7, 8, 1.5, 2.5]);
  assert.equal(param(list, 'DriveControl', 'MaxVelocity').effective, 0.25);
  // A refused SetPDGain changes nothing.
  await page.fill('#pd-PGainL', '-1');
  await page.click('#pd-send');
  await page.waitForSelector('#pd-form .param-error:not([hidden])', WAIT);
  assert.deepEqual(await params(page), list);

  // A broken .conf: refused with the line, nothing changed.
  await page.setInputFiles('#conf-import', { name: 'broken.conf', mimeType: 'text/plain', buffer: Buffer.from('this line is not a configuration\n') });
  await page.waitForSelector('#conf-message[data-level="error"]:not([hidden])', WAIT);
  assert.match(await page.textContent('#conf-message'), /^broken\.conf not imported \(nothing changed\): /);
  assert.deepEqual(await params(page), list);

  // The exported file: everything as it was.
  await page.setInputFiles('#conf-import', { name: 'rtnav.conf', mimeType: 'text/plain', buffer: Buffer.from(text) });
  await page.waitForSelector('#conf-message[data-level="success"]:not([hidden])', WAIT);
  list = await params(page);
  assert.deepEqual(list, original);
  assert.equal(await page.evaluate(() => window.rtnav.demo.conf_export()), text, 'export → import → export is identical');
  const velocity = param(original, 'DriveControl', 'MaxVelocity').value;
  await page.waitForSelector(`${row('DriveControl', 'MaxVelocity')}[data-value="${velocity}"]`, { state: 'attached', ...WAIT });
  assert.deepEqual(problems, []);
  await page.close();
});

test('Telemetry CSV and Frame PNG download', { timeout: 60_000 }, async () => {
  const { page, problems } = await open();
  await activateAll(page);
  await shownDriven(page, 0.2);
  const [csv] = await Promise.all([page.waitForEvent('download'), page.click('#export-csv')]);
  assert.equal(csv.suggestedFilename(), 'rtnav-telemetry.csv');
  const lines = (await readFile(await csv.path(), 'utf8')).trim().split('\n');
  assert.match(lines[0], /^t,/);
  assert.ok(lines.length > 10, `${lines.length} lines`);
  assert.equal(lines[1].split(',').length, lines[0].split(',').length);
  const [png] = await Promise.all([page.waitForEvent('download'), page.click('#export-png')]);
  assert.equal(png.suggestedFilename(), 'rtnav-frame.png');
  const bytes = await readFile(await png.path());
  assert.deepEqual([...bytes.subarray(0, 8)], [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
  const [w, h] = await page.evaluate(() => [document.getElementById('view').width, document.getElementById('view').height]);
  assert.deepEqual([bytes.readUInt32BE(16), bytes.readUInt32BE(20)], [w, h]);
  assert.deepEqual(problems, []);
  await page.close();
});

test('Sensor glitch → Localization in Error naming the port → Reset → Inactive → Activate', { timeout: 60_000 }, async () => {
  const { page, problems } = await open();
  const loc = '#components li[data-component="Localization"]';
  assert.equal(await page.isDisabled(`${loc} .glitch`), true, 'only while Active');
  assert.match(await page.getAttribute(`${loc} .glitch`, 'title'), /NaN.*InSimulatedPosition.*rtinject/s);
  await activateAll(page);
  await page.click(`${loc} .glitch`);
  await expectState(page, 'Localization', 'Error');
  const reason = await page.textContent(`${loc} .rtc-reason`);
  assert.match(reason, /^Reason: .*InSimulatedPosition/);
  const components = await page.evaluate(() => window.rtnav.demo.components());
  assert.match(JSON.stringify(components.find((c) => c.name === 'Localization').last_error), /InSimulatedPosition/);
  await screenshot(page, 'teach-glitch.png', { docs: false });
  await page.click(`${loc} .act`);
  await expectState(page, 'Localization', 'Inactive');
  assert.equal(await page.isVisible(`${loc} .rtc-reason`), false);
  await page.click(`${loc} .act`);
  await expectState(page, 'Localization', 'Active');
  assert.deepEqual(problems, []);
  await page.close();
});
