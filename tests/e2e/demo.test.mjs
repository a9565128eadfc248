// End-to-end: Debian's Chromium (driven by playwright-core, never a downloaded browser)
// against the page served by `cargo xtask test` at $RTNAV_URL.
//
// Proves, through the page's own canvas, mouse, buttons and readouts: the default scenario
// drawn on open; Activate all → the robot drives to the goal; an obstacle painted on the
// path while Active → a replan around it; a goal dropped in an obstacle → refused, the old
// goal and path kept; Inject fault → Error with its reason → Reset → Inactive → Activate;
// paint on the robot → refused, no bump; PhysicsSim in Error → Reset all; a bad map file →
// refused, the map kept; a MovingAI map of the external data (skipped without it); the frame budget at 1280×800 (printed); a Rust panic
// shown as a crash.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import {
  REPO, DATA, DATA_MISSING, WAIT, DRIVE, COLOURS, launch, openPage, screenshot, plan, telemetry, mapInfo,
  cellToPage, expectState, activateAll, logged, solidObstacleCell, frames, until, shownText, shownStatus,
  shownDriven, shownLogged, driven, systemShows } from './helpers.mjs';

/** The frame budget of one frame (simulation + render + blit), ms. */
const BUDGET_MS = 8;

let browser;
before(async () => {
  browser = await launch();
});
after(async () => {
  await browser?.close();
});

/** A fresh page, loaded and ready; `problems` collects page errors and console errors. */
const open = () => openPage(browser.context);

test('the default scenario is drawn, and Activate all drives the robot to the goal', { timeout: 300_000 }, async () => {
  const { page, problems } = await open();
  assert.equal(await page.inputValue('#scenario'), 'open_field');
  assert.match(await page.textContent('#about-title'), /open field/);
  // Drawn: map, field, paths, robot — many colours on the canvas, nothing transparent.
  const drawn = await page.evaluate(() => {
    const c = document.getElementById('view');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    const colours = new Set();
    for (let i = 0; i < d.length; i += 16) colours.add((d[i] << 16) | (d[i + 1] << 8) | d[i + 2]);
    return { colours: colours.size, opaque: d.every((v, i) => i % 4 !== 3 || v === 255) };
  });
  assert.ok(drawn.opaque, 'the frame is opaque');
  assert.ok(drawn.colours > 50, `the frame shows a drawing (${drawn.colours} colours)`);
  const p = await plan(page);
  assert.deepEqual(p.goal, { x: 23, y: 15.5, theta_deg: 90 });
  assert.ok(p.global_path.length > 20 && p.local_path.length > 20 && p.control_points.length > 2);
  // The planners run, the robot waits: Partial.
  for (const name of ['MapBuilder', 'MapMaintenance', 'GlobalPathPlanning', 'LocalPathPlanning']) {
    await expectState(page, name, 'Active');
  }
  for (const name of ['PhysicsSim', 'MotorControl', 'Localization', 'DriveControl']) {
    await expectState(page, name, 'Inactive');
  }
  await shownText(page, '#system-state', 'Partial · 4 of 8 Active');
  assert.deepEqual(await shownLogged(page, 'GlobalPlan'), ['global plan: 206 cells, 25.88 m']);

  await activateAll(page);
  for (const name of ['PhysicsSim', 'MotorControl', 'Localization', 'DriveControl']) {
    await expectState(page, name, 'Active');
  }
  // The README's screenshot: on the way, paused.
  await page.selectOption('#speed', '4');
  await shownDriven(page, 11);
  await page.click('#pause');
  await shownText(page, '#pause', 'Run');
  await frames(page, 3);
  await screenshot(page, 'screenshot-demo.png');
  await page.click('#pause');
  await page.selectOption('#speed', '16');
  await page.waitForSelector('#telemetry[data-arrived="true"]', DRIVE);
  await shownStatus(page, /^Arrived: the robot rests at the goal$/, ['arrived']);
  const t = await telemetry(page);
  assert.ok(t.distance_to_goal < 0.1, `arrived ${t.distance_to_goal} m from the goal`);
  assert.equal(t.bumps, 0);
  const arrived = await shownLogged(page, 'Arrived');
  assert.equal(arrived.length, 1);
  assert.match(arrived[0], /^arrived at \(2[23]\.\d{3}, 15\.\d{3}, \d+\.\d°\): 0\.0\d\d m and \d+\.\d\d° from the goal \(it came in \d+\.\d° off the goal heading\)$/);
  await screenshot(page, 'screenshot-arrived.png', { docs: false });
  assert.deepEqual(problems, []);
  await page.close();
});

test('an obstacle painted on the path while Active is planned around', { timeout: 180_000 }, async () => {
  const { page, problems } = await open();
  await activateAll(page);
  await shownDriven(page, 0.5);
  // A stroke of the 5×5 brush across the path, 40 % of the way along.
  const { local_path: path } = await plan(page);
  const at = path[Math.floor(path.length * 0.4)];
  const before = path.length;
  await page.click('#tool-paint');
  await page.selectOption('#brush', '5');
  const [x0, y0] = await cellToPage(page, [at[0] - 3, at[1] + 3]);
  const [x1, y1] = await cellToPage(page, [at[0] + 3, at[1] - 3]);
  await page.mouse.move(x0, y0);
  await page.mouse.down();
  await page.mouse.move(x1, y1, { steps: 8 });
  await page.mouse.up();
  // The MapUpdate reaches the planners; LocalPathPlanning replans around the block.
  await page.waitForFunction(() => {
    // Newest first: a replanned LocalPlanSent above (after) the MapUpdated entry.
    const items = [...document.querySelectorAll('#events li')];
    const update = items.findIndex((li) => li.dataset.kind === 'MapUpdated');
    return update > 0 && items.slice(0, update)
      .some((li) => li.dataset.kind === 'LocalPlanSent' && li.textContent.includes('local plan sent'));
  }, null, WAIT);
  // One MapUpdate for the stroke.
  const updated = await logged(page, 'MapUpdated');
  assert.equal(updated.length, 1);
  assert.match(updated[0], /^map updated: (\d+) cells listed, \1 changed$/);
  assert.equal(await page.evaluate(([x, y]) => window.rtnav.demo.cell(x, y), at), 1, 'the path cell is now an obstacle');
  const after = await plan(page);
  const blocked = await page.evaluate((cells) => cells.filter(([x, y]) => window.rtnav.demo.cell(x, y) !== 0).length, after.local_path);
  assert.equal(blocked, 0, 'the new local path avoids every obstacle cell');
  assert.notEqual(after.local_path.length, before);
  await page.selectOption('#speed', '4');
  await shownDriven(page, 9, { timeout: 60_000 });
  await page.click('#pause');
  await screenshot(page, 'screenshot-replan.png');
  assert.equal((await telemetry(page)).bumps, 0);
  assert.deepEqual(problems, []);
  await page.close();
});

test('a goal dropped inside an obstacle is refused; the previous goal and path stay', { timeout: 60_000 }, async () => {
  const { page, problems } = await open();
  const before = await plan(page);
  // An obstacle cell whose neighbours are obstacles too (inside the shed).
  const cell = await solidObstacleCell(page, 2);
  assert.ok(cell, 'the map has a solid obstacle');
  await page.click('#tool-goal');
  const [x, y] = await cellToPage(page, cell);
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x + 40, y - 40, { steps: 4 });
  await page.mouse.up();
  await page.waitForSelector('#notice[data-level="error"]:not([hidden])', WAIT);
  const notice = await page.textContent('#notice-text');
  assert.match(notice, /^Goal refused: .+\. The previous goal and its path are kept\.$/);
  assert.match(notice, /obstacle|dmin|inside/i, notice);
  assert.deepEqual(await plan(page), before);
  assert.deepEqual((await logged(page, 'Page')).filter((t) => t.startsWith('Goal refused')).length, 1);
  // A good goal (a cell on the path), dragged upward, backward: accepted and planned at once
  // (the planners are Active).
  await page.click('#dir-backward');
  await page.waitForSelector('#notice[data-level="success"]:not([hidden])', WAIT);
  assert.equal((await plan(page)).direction, 'backward');
  const goalsBefore = (await shownLogged(page, 'GoalSet')).length;
  const target = before.local_path[Math.floor(before.local_path.length / 2)];
  const [gx, gy] = await cellToPage(page, target);
  await page.mouse.move(gx, gy);
  await page.mouse.down();
  await page.mouse.move(gx, gy - 50, { steps: 4 });
  await page.mouse.up();
  await page.waitForFunction(() => document.getElementById('notice-text').textContent.startsWith('Goal set at'), null, WAIT);
  const moved = await plan(page);
  const m = await mapInfo(page);
  const centre = target.map((c, i) => m.origin[i] + (c + 0.5) * m.grid_size);
  assert.equal(moved.goal.theta_deg, 90);
  assert.ok(Math.hypot(moved.goal.x - centre[0], moved.goal.y - centre[1]) < m.grid_size, JSON.stringify([moved.goal, centre]));
  assert.equal(moved.direction, 'backward');
  assert.notDeepEqual(moved.local_path, before.local_path);
  const goals = await shownLogged(page, 'GoalSet', goalsBefore + 1);
  assert.match(goals.at(-1), /→ \(\d+\.\d\d, \d+\.\d\d, 90\.0°\), Backward$/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('Inject fault → Error with the reason → Reset → Inactive → Activate', { timeout: 60_000 }, async () => {
  const { page, problems } = await open();
  await activateAll(page);
  const row = '#components li[data-component="MotorControl"]';
  await page.click(`${row} .fault`);
  await expectState(page, 'MotorControl', 'Error');
  assert.equal(await page.textContent(`${row} .rtc-reason`), 'Reason: injected fault: requested from the page');
  await systemShows(page, 'Error');
  assert.equal(await page.$eval('#system-state', (e) => getComputedStyle(e).backgroundColor), COLOURS.Error);
  assert.deepEqual(await shownLogged(page, 'ComponentError'), ['MotorControl0: on_execute failed: injected fault: requested from the page']);
  assert.equal(await page.textContent(`${row} .act`), 'Reset');
  assert.equal(await page.isDisabled(`${row} .fault`), true);
  await page.click(`${row} .act`);
  await expectState(page, 'MotorControl', 'Inactive');
  assert.equal(await page.isVisible(`${row} .rtc-reason`), false);
  await page.click(`${row} .act`);
  await expectState(page, 'MotorControl', 'Active');
  await systemShows(page, 'Active');
  // The robot drives on.
  await shownDriven(page, (await driven(page)) + 0.3);
  const changes = await until(page, 'MotorControl0\'s five state changes in the log', () => {
    const lines = [...document.querySelectorAll('#events li[data-kind="StateChanged"] .text')]
      .map((i) => i.textContent).reverse().filter((t) => t.startsWith('MotorControl0'));
    return { ok: lines.length >= 5, value: lines, shown: JSON.stringify(lines) };
  });
  assert.deepEqual(changes, [
    'MotorControl0: Created → Inactive',
    'MotorControl0: Inactive → Active',
    'MotorControl0: Active → Error',
    'MotorControl0: Error → Inactive',
    'MotorControl0: Inactive → Active',
  ]);
  // Deactivate all: every component Inactive (blue).
  await page.click('#deactivate-all');
  for (const name of ['MapBuilder', 'PhysicsSim', 'DriveControl']) await expectState(page, name, 'Inactive');
  assert.deepEqual(problems, []);
  await page.close();
});

test('painting on the robot is refused, never a bump; a PhysicsSim in Error, then Reset all recovers and keeps the goal', { timeout: 60_000 }, async () => {
  const { page, problems } = await open();
  await activateAll(page);
  await shownDriven(page, 0.3);
  // Paint right where the robot is, with the clock paused (on a loaded machine the robot
  // would drive off the cell while the brush is chosen): refused, with the reason (spec §5
  // Decision 0.4: no obstacle under the body, so no bump at 0 m/s).
  await page.click('#pause');
  await shownText(page, '#pause', 'Run');
  const t = await telemetry(page);
  const m = await mapInfo(page);
  const cell = [Math.floor((t.pose.x - m.origin[0]) / m.grid_size), Math.floor((t.pose.y - m.origin[1]) / m.grid_size)];
  await page.click('#tool-paint');
  await page.selectOption('#brush', '5');
  const [x, y] = await cellToPage(page, cell);
  await page.mouse.click(x, y);
  await page.waitForSelector('#notice[data-level="error"]:not([hidden])', WAIT);
  assert.match(await page.textContent('#notice-text'), /^MapUpdate refused: cell \(\d+, \d+\) lies under the robot's body/);
  assert.equal(await page.evaluate(([cx, cy]) => window.rtnav.demo.cell(cx, cy), cell), 0);
  await page.click('#tool-pan');
  await page.click('#pause');
  await shownText(page, '#pause', 'Pause');
  await shownDriven(page, (await driven(page)) + 0.2);
  await expectState(page, 'PhysicsSim', 'Active');
  assert.equal((await telemetry(page)).bumps, 0);
  // A fault from the RTC panel puts PhysicsSim in Error; Reset all recovers it.
  await page.click('#components li[data-component="PhysicsSim"] button.fault');
  await expectState(page, 'PhysicsSim', 'Error');
  const reason = await page.textContent('#components li[data-component="PhysicsSim"] .rtc-reason');
  assert.match(reason, /^Reason: /);
  await shownStatus(page, /^PhysicsSim0 in Error: .+ \(Reset recovers\); the robot \w+$/);
  // The physics in Error moves nothing: the robot stands where it is.
  const goal = (await plan(page)).goal;
  const pose = (await telemetry(page)).pose;
  await page.click('#reset-all');
  await systemShows(page, 'Inactive');
  await expectState(page, 'PhysicsSim', 'Inactive');
  assert.equal(await page.isVisible('#components li[data-component="PhysicsSim"] .rtc-reason'), false);
  // Nothing held is lost: the goal, the robot's pose.
  assert.deepEqual((await plan(page)).goal, goal);
  assert.deepEqual((await telemetry(page)).pose, pose);
  // Activate: the robot drives on.
  const sent = (await logged(page, 'LocalPlanSent')).length;
  await activateAll(page);
  await shownDriven(page, (await driven(page)) + 0.3);
  // LocalPathPlanning plans afresh after its activation (spec §3 Decision 0.2, re-activation).
  assert.ok((await shownLogged(page, 'LocalPlanSent', sent + 1)).slice(sent).some((t) => t.startsWith('local plan sent')));
  assert.equal((await telemetry(page)).bumps, 0);
  assert.deepEqual(problems, []);
  await page.close();
});

test('a bad map file is refused with the reason; the current map stays', { timeout: 60_000 }, async () => {
  const { page, problems } = await open();
  const before = await mapInfo(page);
  await page.setInputFiles('#map-file', { name: 'broken.json', mimeType: 'application/json', buffer: Buffer.from('{"width": 3') });
  await page.waitForSelector('#notice[data-level="error"]:not([hidden])', WAIT);
  assert.match(
    await page.textContent('#notice-text'),
    /^Could not load the map: `broken\.json`: rtnav JSON.*\. The current map stays\.$/,
  );
  assert.deepEqual(await mapInfo(page), before);
  assert.equal(await page.inputValue('#scenario'), 'open_field');
  // An image without its YAML: the reason says what is missing.
  await page.setInputFiles('#map-file', { name: 'map.pgm', mimeType: 'image/x-portable-graymap', buffer: Buffer.from('P5 1 1 255\n\0') });
  await page.waitForFunction(() => document.getElementById('notice-text').textContent.includes('needs its .yaml'), null, WAIT);
  assert.deepEqual(await mapInfo(page), before);
  // A ROS map (YAML and image picked together) and a MovingAI map load.
  await page.setInputFiles('#map-file', [join(REPO, 'fixtures/maps/tiny.yaml'), join(REPO, 'fixtures/maps/tiny.pgm')]);
  await page.waitForFunction(() => JSON.parse(window.rtnav.demo.map_json()).name === 'tiny.yaml', null, WAIT);
  assert.equal((await mapInfo(page)).grid_size, 0.25);
  await page.setInputFiles('#map-file', join(REPO, 'fixtures/maps/yard.map'));
  await page.waitForFunction(() => JSON.parse(window.rtnav.demo.map_json()).name === 'yard.map', null, WAIT);
  assert.deepEqual(await mapInfo(page).then((m) => [m.width, m.height, m.grid_size]), [9, 6, 1]);
  // A good map file loads, with the planners Active and no goal yet.
  const rows = ['########', '#......#', '#......#', '#......#', '########'];
  await page.setInputFiles('#map-file', {
    name: 'room.json', mimeType: 'application/json',
    buffer: Buffer.from(JSON.stringify({ width: 8, height: 5, grid_size: 0.5, rows })),
  });
  // (The notice of the map before may still be up: the title says which map is shown.)
  await shownText(page, '#about-title', 'Map file: room.json');
  await shownText(page, '#notice:not([hidden])[data-level="success"] #notice-text', /room\.json/);
  const room = await mapInfo(page);
  assert.deepEqual([room.name, room.width, room.height, room.grid_size], ['room.json', 8, 5, 0.5]);
  assert.equal((await plan(page)).goal, null);
  // And a scenario from the picker replaces it.
  await page.selectOption('#scenario', 'backward_dock');
  await page.waitForFunction(() => document.getElementById('about-title').textContent.includes('backward dock'), null, WAIT);
  assert.equal((await mapInfo(page)).name, 'fixtures/maps/scenarios/backward_dock.json');
  assert.ok((await plan(page)).goal);
  assert.deepEqual(problems, []);
  await page.close();
});

test('a MovingAI benchmark map (external data) loads from the file picker', { timeout: 60_000, skip: DATA_MISSING ?? false }, async () => {
  const { page, problems } = await open();
  await page.setInputFiles('#map-file', join(DATA, 'movingai', 'dao', 'arena.map'));
  await page.waitForFunction(() => JSON.parse(window.rtnav.demo.map_json()).name === 'arena.map', null, WAIT);
  assert.deepEqual(await mapInfo(page).then((m) => [m.width, m.height, m.grid_size]), [49, 49, 1]);
  assert.deepEqual(problems, []);
  await page.close();
});

test('frame time: step + render + blit at 1280×800 (reported)', { timeout: 240_000 }, async () => {
  const { page, problems } = await open();
  await page.evaluate(() => window.rtnav.setFrameSize(1280, 800));
  assert.deepEqual(await page.evaluate(() => [document.getElementById('view').width, document.getElementById('view').height]), [1280, 800]);
  await activateAll(page);
  await shownDriven(page, 0.1);
  /** Median and 90th percentile of the page's own frame times over `n` frames of driving. */
  const measure = async (speed, n) => {
    await page.selectOption('#speed', speed);
    await page.evaluate(() => window.rtnav.clearFrameTimes());
    const t0 = Date.now();
    await until(page, `${n} frames drawn at ${speed}×`, (n) => {
      const k = window.rtnav.frameTimes().length;
      return { ok: k >= n, shown: `${k} frames` };
    }, n, { timeout: 60_000 });
    const times = (await page.evaluate(() => window.rtnav.frameTimes())).sort((a, b) => a - b);
    const at = (q) => times[Math.min(times.length - 1, Math.floor(times.length * q))];
    const line = `frame time at 1280×800, ${speed}× speed: median ${at(0.5).toFixed(2)} ms, ` +
      `90th percentile ${at(0.9).toFixed(2)} ms over ${times.length} frames in ${Date.now() - t0} ms`;
    console.log(line);
    return at(0.5);
  };
  // The machine is shared (other builds may run): the better of two windows counts.
  const median = Math.min(await measure('1', 150), await measure('1', 150));
  await measure('16', 150);
  assert.equal((await telemetry(page)).state, 'Active');
  // Speed is measured by the benchmarks, not asserted by a test (a shared machine's wall
  // time says little): the budget is reported beside the measurement.
  console.log(`frame budget ${BUDGET_MS} ms: median ${median.toFixed(2)} ms, ${median <= BUDGET_MS ? 'within' : 'over'} it`);
  assert.deepEqual(problems, []);
  await page.close();
});

test('a Rust panic is shown, not a frozen tab', { timeout: 60_000 }, async () => {
  const { page, problems } = await open();
  assert.equal(await page.isVisible('#crash'), false);
  await page.evaluate(() => window.rtnav.debugPanic());
  await page.waitForSelector('#crash', { state: 'visible', ...WAIT });
  assert.equal(await page.getAttribute('body', 'data-crashed'), 'true');
  const message = await page.textContent('#crash-message');
  assert.match(message, /debug_panic: deliberate panic requested by the page/);
  assert.match(message, /wasm\/src\/demo\.rs/);
  // The console's lines reach the test as messages of their own, after the page showed them.
  for (const t0 = Date.now(); problems.length === 0 && Date.now() - t0 < WAIT.timeout;) await new Promise((r) => setTimeout(r, 50));
  assert.ok(problems.length >= 1, 'the panic is logged');
  for (const p of problems) assert.match(p, /debug_panic/);
  await page.close();
});
