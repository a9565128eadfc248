// End-to-end: the page as a teacher meets it, one test per point,
// through the page's own buttons, mouse, fingers and canvas.
//
// Proves: (1) the status, the counters and the log come from the system's facts, numbers
// read as people write them, the log in time order; (2) the system bar (Activate all,
// Deactivate all, Reset all, the system's state) works from every tab; (3) at 1280×800,
// 768×1024 and 390×844 no control is off-screen, clipped or overlapping, and a tap or click
// at a control's centre reaches it — with real taps on Activate all in Chromium's mobile
// emulation (and a pinch); (4) zoom by wheel, buttons and pinch keeps the point under it,
// pan, Fit, a legend that folds and stays under 15 % of the map, brushes in metres, the hint
// outside the map; (5) notices end with the state they describe (Reset, a new scenario, a
// new goal) and never cover the robot; (6) one paint stroke is one MapUpdate, a stroke that
// changes nothing sends nothing; (7) parameters explained in English with the seed's
// Japanese, the gains' instability bound and its warning, applied torque against MaxTorque,
// one dmin with its clearance warning; (8) the inspector in metres and G = G(parent) + R + A
// + P; (9) the unreachable lesson done in the page; (10) the trail drawn over the paths; (11) the
// version of rtnav beside the title.
// Screenshots at the three sizes go to docs/ (UPDATE_SCREENSHOTS=1).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import {
  WAIT, DRIVE, launch, openPage, screenshot, plan, telemetry, mapInfo, cellToPage, showTab,
  expectState, activateAll, logged, frames, layoutProblems, until, shownText, shownStatus,
  shownDriven, shownLogged, clockRuns, systemShows, paramRow, setParam,
} from './helpers.mjs';

const SIZES = [[1280, 800], [768, 1024], [390, 844]];
const TABS = ['rtc', 'system', 'params', 'inspector', 'plots', 'log'];

let browser;
before(async () => {
  browser = await launch();
});
after(async () => {
  await browser?.close();
});

const open = (query = '') => openPage(browser.context, query);
const row = paramRow;


/** Waits until the log shows the line `text` (of any kind); returns every line, newest first. */
const shownLine = (page, text) => until(page, `the log line "${text}"`, (t) => {
  const lines = [...document.querySelectorAll('#events li')].map((li) => [li.querySelector('time').textContent, li.querySelector('.text').textContent]);
  return { ok: lines.some(([, x]) => x === t), value: lines, shown: `${lines.length} lines, newest ${JSON.stringify(lines.slice(0, 3))}` };
}, text);

/** Loads scenario `name` through the picker. */
async function pick(page, name) {
  await page.selectOption('#scenario', name);
  await page.waitForFunction((n) => window.rtnav.scenarios.current === n, name, WAIT);
  await frames(page, 2);
}

/** Hides a notice that is up (so it does not count in layout checks). */
const dismiss = (page) => page.evaluate(() => window.rtnav.app.notice.hide());

// ------------------------------------------------------------------------------------ (3)

test('(3) at 1280×800, 768×1024 and 390×844 nothing is off-screen, cut off or overlapping, and taps reach their controls', { timeout: 180_000 }, async () => {
  const { page, problems } = await open();
  await activateAll(page);
  await page.selectOption('#speed', '4');
  await shownDriven(page, 4);
  await page.click('#pause');
  for (const [width, height] of SIZES) {
    await page.setViewportSize({ width, height });
    await frames(page, 4);
    await dismiss(page);
    // The legend open: the most it takes.
    await page.evaluate(() => { document.getElementById('legend').open = true; });
    for (const tab of TABS) {
      await showTab(page, tab);
      await frames(page, 2);
      const found = await page.evaluate(layoutProblems);
      assert.deepEqual(found, [], `${width}×${height}, tab ${tab}`);
    }
    // The Layers menu open, too (placed by its `toggle` event, which comes as a task of its
    // own after the click).
    await page.click('#layers summary');
    await frames(page, 2);
    assert.deepEqual(await page.evaluate(() => {
      const r = document.querySelector('#layers .menu-body').getBoundingClientRect();
      return r.left >= 0 && r.right <= document.documentElement.clientWidth;
    }), true, `${width}×${height}: the Layers menu fits`);
    await page.click('#layers summary');
    // The legend covers at most 15 % of the map (on a narrow screen it is under it).
    const share = await page.evaluate(() => {
      const l = document.getElementById('legend').getBoundingClientRect();
      const m = document.getElementById('canvas-wrap').getBoundingClientRect();
      const w = Math.max(0, Math.min(l.right, m.right) - Math.max(l.left, m.left));
      const h = Math.max(0, Math.min(l.bottom, m.bottom) - Math.max(l.top, m.top));
      return (w * h) / (m.width * m.height);
    });
    console.log(`${width}×${height}: the open legend covers ${(100 * share).toFixed(1)} % of the map`);
    assert.ok(share <= 0.15, `${width}×${height}: the legend covers ${(100 * share).toFixed(1)} % of the map`);
    await showTab(page, 'rtc');
    if (width < 700) await page.evaluate(() => { document.getElementById('legend').open = false; });
    await frames(page, 2);
    await screenshot(page, `page-${width}x${height}.png`, { fullPage: width < 1000 });
  }
  assert.deepEqual(problems, []);
  await page.close();
});

test('(3) real taps on Activate all in Chromium\'s mobile emulation at 390×844, and a pinch zooms', { timeout: 120_000 }, async () => {
  const phone = await launch({
    viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true, deviceScaleFactor: 3,
  });
  try {
    const { page, problems } = await openPage(phone.context);
    // Playwright's tap checks that the element itself receives it (nothing covers it).
    await page.tap('#activate-all');
    await systemShows(page, 'Active');
    await shownDriven(page, 0.1);
    await page.tap('#tab-params');
    await page.tap('#deactivate-all');
    await systemShows(page, 'Inactive');
    await page.tap('#tab-plots');
    await page.tap('#activate-all');
    await systemShows(page, 'Active');
    assert.deepEqual(await page.evaluate(layoutProblems), [], 'the phone layout');

    // Two fingers spread apart on the map: zoom about their middle.
    const box = await page.$eval('#overlay', (e) => { e.scrollIntoView({ block: 'center' }); const r = e.getBoundingClientRect(); return { x: r.left, y: r.top, w: r.width, h: r.height }; });
    const cx = Math.round(box.x + box.w / 2);
    const cy = Math.round(box.y + box.h / 2);
    const under = await page.evaluate(([x, y]) => {
      const c = document.getElementById('overlay');
      const r = c.getBoundingClientRect();
      return window.rtnav.demo.pixel_to_world(((x - r.left) * c.width) / r.width, ((y - r.top) * c.height) / r.height);
    }, [cx, cy]);
    const cdp = await phone.context.newCDPSession(page);
    const touch = (type, d) => cdp.send('Input.dispatchTouchEvent', {
      type,
      touchPoints: type === 'touchEnd' ? [] : [{ x: cx - d, y: cy, id: 1 }, { x: cx + d, y: cy, id: 2 }],
    });
    await touch('touchStart', 30);
    for (let d = 35; d <= 90; d += 5) await touch('touchMove', d);
    await touch('touchEnd', 0);
    await frames(page, 2);
    const zoom = await page.evaluate(() => window.rtnav.demo.zoom());
    assert.ok(zoom > 2.5 && zoom < 3.5, `a pinch from 60 to 180 px zooms about 3× (${zoom})`);
    const after = await page.evaluate(([x, y]) => {
      const c = document.getElementById('overlay');
      const r = c.getBoundingClientRect();
      return window.rtnav.demo.pixel_to_world(((x - r.left) * c.width) / r.width, ((y - r.top) * c.height) / r.height);
    }, [cx, cy]);
    assert.ok(Math.hypot(after[0] - under[0], after[1] - under[1]) < 0.05, `the point between the fingers stays (${under} → ${after})`);
    assert.deepEqual(problems, []);
  } finally {
    await phone.close();
  }
});

// ------------------------------------------------------------------------------------ (2)

test('(2) the system bar — state, Activate all, Deactivate all, Reset all — is there on every tab', { timeout: 60_000 }, async () => {
  const { page, problems } = await open();
  for (const tab of TABS) {
    await showTab(page, tab);
    for (const id of ['system-state', 'activate-all', 'deactivate-all', 'reset-all']) {
      assert.equal(await page.isVisible(`#${id}`), true, `#${id} on tab ${tab}`);
    }
  }
  await shownText(page, '#system-state', 'Partial · 4 of 8 Active');
  await showTab(page, 'plots');
  await page.click('#activate-all');
  await systemShows(page, 'Active');
  await showTab(page, 'inspector');
  await page.click('#deactivate-all');
  await systemShows(page, 'Inactive');
  // Reset all after an error, from the Log tab.
  await page.click('#activate-all');
  await showTab(page, 'rtc');
  await page.click('#components li[data-component="MotorControl"] .fault');
  await systemShows(page, 'Error');
  await showTab(page, 'log');
  await page.click('#reset-all');
  await systemShows(page, 'Inactive');
  assert.deepEqual(problems, []);
  await page.close();
});

// ------------------------------------------------------------------------------------ (1)

test('(1) the status and the counters say what is true; the log is in time order with numbers for people', { timeout: 180_000 }, async () => {
  const { page, problems } = await open();
  // The plans the load made are in the log a second of simulated time later.
  await clockRuns(page, 1);
  const mapBox = () => page.$eval('#canvas-wrap', (e) => JSON.stringify(e.getBoundingClientRect()));
  const box0 = await mapBox();
  await shownStatus(page, /^Plan ready: activate the robot's components$/);
  // A parameter changed while the robot stands: planned again at once, no empty path.
  const before = (await logged(page, 'LocalPlanSent')).length;
  await setParam(page, 'LocalPathPlanning', 'PostureConsiderationLevel', 40);
  await page.waitForFunction((n) => document.querySelectorAll('#events li[data-kind="LocalPlanSent"]').length > n, before, WAIT);
  const sent = (await logged(page, 'LocalPlanSent')).slice(before);
  assert.ok(sent.every((t) => /^local plan sent: \d+ cells, \d+ control points$/.test(t)), sent.join(' | '));

  await activateAll(page);
  await shownDriven(page, 0.5);
  await shownStatus(page, /^(Driving forward|Turning on the spot)/, ['driving', 'turning_on_the_spot']);
  const plans = (await page.textContent('#telemetry dd[data-key="plans"]')).match(/^(\d+) global · (\d+) local$/);
  assert.ok(plans && Number(plans[1]) >= 1 && Number(plans[2]) >= 1, `plans ${plans} after a plan was sent and driven`);

  // MotorControl inactive: no torque, the robot coasts (it does not "drive").
  await showTab(page, 'rtc');
  await page.click('#components li[data-component="MotorControl"] .act');
  await shownStatus(page, /^MotorControl0 inactive: the robot (coasts|stands)$/, ['inactive']);
  await page.click('#components li[data-component="MotorControl"] .act');
  await expectState(page, 'MotorControl', 'Active');

  // A gain past the stability bound: the robot spins off its command, and the status says so.
  await setParam(page, 'MotorControl', 'PGainL', 5000);
  await shownStatus(page, /^Not following the command: v -?\d+\.\d\d m\/s, ω -?\d+\.\d\d rad\/s \(commanded/, ['off_command']);
  assert.equal(await mapBox(), box0, 'a long status does not move the map');

  // The log: times with three decimals, no number with a tail of binary digits, in order.
  await showTab(page, 'log');
  const entries = await shownLine(page, 'MotorControl.PGainL = 5000');
  assert.ok(entries.length > 10);
  for (const [time, text] of entries) {
    assert.match(time, /^\d+\.\d{3} s$/);
    assert.doesNotMatch(text, /\d\.\d{7,}/, text);
  }
  // Each change logged once (the core's line; the page adds none of its own).
  const set = entries.filter(([, text]) => /^MotorControl\.PGainL = 5000$/.test(text));
  assert.equal(set.length, 1, 'one line for one parameter change');
  const times = entries.map(([t]) => parseFloat(t));
  for (let i = 1; i < times.length; i++) assert.ok(times[i] <= times[i - 1], `newest first: ${times[i - 1]} then ${times[i]}`);

  // No route: the robot stands and the status says why, before and after Activate all.
  await pick(page, 'unreachable');
  await shownStatus(page, /^No route \(/, ['no_route']);
  await activateAll(page);
  // A second of simulated time later, the robot has not moved and the status still says why.
  await clockRuns(page, 1);
  await shownStatus(page, /^No route \(.*\); the robot stands$/, ['no_route']);
  assert.equal(await page.textContent('#telemetry dd[data-key="driven"]'), '0.00 m');
  assert.equal((await telemetry(page)).path_length, 0);
  assert.deepEqual(problems, []);
  await page.close();
});

// ------------------------------------------------------------------------------------ (4)

/** The world point under the page point `(x, y)`. */
const worldAt = (page, [x, y]) => page.evaluate(([x, y]) => {
  const c = document.getElementById('overlay');
  const r = c.getBoundingClientRect();
  return window.rtnav.demo.pixel_to_world(((x - r.left) * c.width) / r.width, ((y - r.top) * c.height) / r.height);
}, [x, y]);
const near = (a, b, tol) => Math.hypot(a[0] - b[0], a[1] - b[1]) < tol;

test('(4) wheel, buttons and Pan zoom and move the map; Fit; the legend folds; brushes in metres; the hint outside the map', { timeout: 90_000 }, async () => {
  const { page, problems } = await open();
  const box = await page.$eval('#overlay', (e) => { const r = e.getBoundingClientRect(); return { x: r.left, y: r.top, w: r.width, h: r.height }; });
  // Whole pixels: a mouse event's position is one.
  const p = [Math.round(box.x + box.w * 0.3), Math.round(box.y + box.h * 0.6)];
  const ppm = () => page.evaluate(() => window.rtnav.demo.pixels_per_metre());
  const ppm0 = await ppm();
  const w0 = await worldAt(page, p);
  // The wheel: zoom about the mouse; the point under it stays.
  await page.mouse.move(p[0], p[1]);
  await page.mouse.wheel(0, -400);
  await page.waitForFunction(() => window.rtnav.demo.zoom() > 1.5, null, WAIT);
  const zoom = await page.evaluate(() => window.rtnav.demo.zoom());
  assert.ok(Math.abs(await ppm() / ppm0 - zoom) < 1e-9, 'pixels per metre follow the zoom');
  assert.ok(near(await worldAt(page, p), w0, 0.02), 'the point under the wheel stays');
  // The buttons zoom about the middle; Fit shows the whole map.
  await page.click('#zoom-in');
  assert.ok(Math.abs(await page.evaluate(() => window.rtnav.demo.zoom()) - zoom * 1.5) < 1e-9);
  await page.click('#zoom-out');
  assert.ok(Math.abs(await page.evaluate(() => window.rtnav.demo.zoom()) - zoom) < 1e-9);
  await shownText(page, '#zoom-fit', /^Fit · \d/);
  // Pan: the world point dragged goes with the mouse.
  await page.click('#tool-pan');
  const q = [p[0] + 80, p[1] - 40];
  const wq = await worldAt(page, p);
  await page.mouse.move(p[0], p[1]);
  await page.mouse.down();
  await page.mouse.move(q[0], q[1], { steps: 5 });
  await page.mouse.up();
  assert.ok(near(await worldAt(page, q), wq, 0.02), 'the dragged point follows the mouse');
  // The middle button pans with any tool.
  await page.click('#tool-goal');
  const wm = await worldAt(page, q);
  await page.mouse.move(q[0], q[1]);
  await page.mouse.down({ button: 'middle' });
  await page.mouse.move(p[0], p[1], { steps: 4 });
  await page.mouse.up({ button: 'middle' });
  assert.ok(near(await worldAt(page, p), wm, 0.02), 'the middle button pans');
  assert.equal((await plan(page)).goal.x, 23, 'and sets no goal');
  await page.click('#zoom-fit');
  assert.equal(await page.evaluate(() => window.rtnav.demo.zoom()), 1);
  assert.equal(await ppm(), ppm0);
  assert.equal(await page.isDisabled('#zoom-fit'), true);

  // The legend folds and unfolds.
  const legendOpen = () => page.$eval('#legend', (d) => d.open);
  const wasOpen = await legendOpen();
  await page.click('#legend summary');
  assert.equal(await legendOpen(), !wasOpen);
  await page.click('#legend summary');
  assert.equal(await legendOpen(), wasOpen);
  assert.match(await page.textContent('#legend-scale'), /\d m$/);
  // The open legend keeps off the robot: with the robot under it, it takes the other corner.
  await page.evaluate(() => { document.getElementById('legend').open = true; });
  await frames(page, 2);
  await page.evaluate(() => {
    const { demo, app } = window.rtnav;
    const t = JSON.parse(demo.telemetry_json());
    const c = document.getElementById('overlay');
    const cr = c.getBoundingClientRect();
    const l = document.getElementById('legend').getBoundingClientRect();
    const s = c.width / cr.width;
    const target = [((l.left + l.right) / 2 - cr.left) * s, ((l.top + l.bottom) / 2 - cr.top) * s];
    const [px, py] = demo.world_to_pixel(t.pose.x, t.pose.y);
    demo.zoom_at(px, py, 2);
    const [qx, qy] = demo.world_to_pixel(t.pose.x, t.pose.y);
    demo.pan_by(target[0] - qx, target[1] - qy);
    app.emit('view');
  });
  await until(page, 'the open legend in the right corner, off the robot', () => {
    const l = document.getElementById('legend');
    const a = l.getBoundingClientRect();
    const r = window.rtnav.app.stage.robotBox();
    const clear = !(a.left < r.right && r.left < a.right && a.top < r.bottom && r.top < a.bottom);
    return { ok: l.dataset.corner === 'right' && clear, shown: `the legend in the ${l.dataset.corner} corner, ${clear ? 'off' : 'over'} the robot` };
  });
  await page.click('#zoom-fit');

  // The hint is outside the map.
  await page.click('#tool-paint');
  await shownText(page, '#tool-hint', /one MapUpdate/);
  const apart = await page.evaluate(() => {
    const h = document.getElementById('tool-hint').getBoundingClientRect();
    const m = document.getElementById('canvas-wrap').getBoundingClientRect();
    return h.bottom <= m.top || h.top >= m.bottom;
  });
  assert.equal(apart, true, 'the hint does not cover the map');

  // A brush of 1 m: a square of 1 m of cells, whatever the cell size.
  const m = await mapInfo(page);
  await page.selectOption('#brush-unit', 'm');
  await page.selectOption('#brush', '1');
  const free = await page.evaluate((m) => {
    // A free spot of 2 m × 2 m away from the path.
    const { demo } = window.rtnav;
    const n = Math.ceil(2 / m.grid_size);
    for (let y = m.height - n - 2; y > 2; y--) {
      for (let x = 2; x < m.width - n - 2; x++) {
        let ok = true;
        for (let dy = 0; dy < n && ok; dy++) for (let dx = 0; dx < n && ok; dx++) ok = demo.cell(x + dx, y + dy) === 0;
        if (ok) return [x + n / 2, y + n / 2];
      }
    }
    return null;
  }, m);
  const before = (await mapInfo(page)).obstacles;
  const [fx, fy] = await cellToPage(page, free);
  await page.mouse.click(fx, fy);
  await page.waitForFunction((b) => JSON.parse(window.rtnav.demo.map_json()).obstacles > b, before, WAIT);
  const painted = (await mapInfo(page)).obstacles - before;
  const side = 1 / m.grid_size;
  assert.ok(painted >= (side - 1) ** 2 && painted <= (side + 1) ** 2, `a 1 m brush painted ${painted} cells of ${m.grid_size} m`);
  assert.deepEqual(problems, []);
  await page.close();
});

// ------------------------------------------------------------------------------------ (5)

test('(5) notices end with their state — Reset, a new scenario, a new goal — and never cover the robot', { timeout: 300_000 }, async () => {
  const { page, problems } = await open();
  await activateAll(page);
  const mc = '#components li[data-component="MotorControl"]';
  await page.click(`${mc} .fault`);
  await page.waitForSelector('#notice[data-level="error"]:not([hidden])', WAIT);
  assert.match(await page.textContent('#notice-text'), /^MotorControl0: on_execute failed/);
  // Reset ends the Error and its notice at once.
  await page.click(`${mc} .act`);
  await expectState(page, 'MotorControl', 'Inactive');
  await frames(page, 2);
  assert.equal(await page.isVisible('#notice'), false, 'the notice goes with the Error');
  // A bump's notice goes with a new scenario.
  await page.click(`${mc} .act`);
  await page.click(`${mc} .fault`);
  await page.waitForSelector('#notice[data-level="error"]:not([hidden])', WAIT);
  await pick(page, 'backward_dock');
  assert.equal(await page.isVisible('#notice'), false, 'a new scenario starts without the old notices');

  // Arrival: the notice stays while the robot is there, off the robot.
  await activateAll(page);
  await page.selectOption('#speed', '16');
  await page.waitForSelector('#telemetry[data-arrived="true"]', DRIVE);
  await page.waitForSelector('#notice[data-level="success"]:not([hidden])', WAIT);
  assert.match(await page.textContent('#notice-text'), /^arrived at/);
  const clear = () => page.evaluate(() => {
    const n = document.getElementById('notice').getBoundingClientRect();
    const r = window.rtnav.app.stage.robotBox();
    return !(n.left < r.right && r.left < n.right && n.top < r.bottom && r.top < n.bottom);
  });
  assert.equal(await clear(), true, 'the arrival notice is off the robot');
  // Put the robot right under the notice's place at the top: the notice moves to the bottom.
  await page.evaluate(() => {
    const { demo, app } = window.rtnav;
    const t = JSON.parse(demo.telemetry_json());
    const c = document.getElementById('overlay');
    const n = document.getElementById('notice');
    const wrap = document.getElementById('canvas-wrap').getBoundingClientRect();
    const noticeY = (n.dataset.place === 'bottom' ? 50 : n.getBoundingClientRect().top - wrap.top + n.offsetHeight / 2);
    const s = c.width / c.getBoundingClientRect().width;
    const [px, py] = demo.world_to_pixel(t.pose.x, t.pose.y);
    demo.zoom_at(px, py, 3);
    const [qx, qy] = demo.world_to_pixel(t.pose.x, t.pose.y);
    demo.pan_by(c.width / 2 - qx, noticeY * s - qy);
    app.emit('view');
  });
  await until(page, 'the notice at the bottom', () => {
    const n = document.getElementById('notice');
    return { ok: n.dataset.place === 'bottom', shown: `the notice at the ${n.dataset.place}` };
  });
  assert.equal(await clear(), true, 'the notice moved off the robot');
  await page.click('#zoom-fit');
  // A new goal ends "arrived" and its notice (at 1×, so the robot takes its time to the
  // new goal and arrives there well after the page has shown the old arrival gone).
  await page.selectOption('#speed', '1');
  const goal = (await plan(page)).goal;
  await page.evaluate((g) => window.rtnav.demo.set_goal(g.x - 1, g.y, g.theta_deg, false), goal);
  await until(page, 'the arrival and its notice gone with the new goal', () => {
    const n = document.getElementById('notice');
    const arrived = document.getElementById('telemetry').dataset.arrived;
    return { ok: arrived === 'false' && !(n.dataset.level === 'success' && !n.hidden), shown: `arrived ${arrived}, the notice ${n.hidden ? 'hidden' : `"${n.textContent.trim()}" (${n.dataset.level})`}` };
  });
  assert.deepEqual(problems, []);
  await page.close();
});

// ------------------------------------------------------------------------------------ (6)

test('(6) one paint stroke is one MapUpdate and one plan; a stroke that changes nothing sends nothing', { timeout: 180_000 }, async () => {
  const { page, problems } = await open();
  const count = async () => Object.fromEntries(await Promise.all(['MapUpdated', 'LocalPlanSent', 'GlobalPlan']
    .map(async (k) => [k, (await logged(page, k)).length])));
  const { local_path: path } = await plan(page);
  const at = path[Math.floor(path.length * 0.5)];
  await page.click('#tool-paint');
  await page.selectOption('#brush', '3');
  const stroke = async () => {
    const [x0, y0] = await cellToPage(page, [at[0] - 6, at[1] + 6]);
    const [x1, y1] = await cellToPage(page, [at[0] + 6, at[1] - 6]);
    await page.mouse.move(x0, y0);
    await page.mouse.down();
    await page.mouse.move(x1, y1, { steps: 24 });
    await page.mouse.up();
  };
  // What a stroke makes is shown within a second of simulated time (the planners run many
  // times a second): the log is counted after that.
  const settled = () => clockRuns(page, 1.5);
  await settled();
  const c0 = await count();
  await stroke();
  await shownLogged(page, 'MapUpdated', c0.MapUpdated + 1);
  await settled();
  const c1 = await count();
  const lines = (await logged(page, 'MapUpdated')).slice(c0.MapUpdated);
  assert.equal(lines.length, 1, `one log line for the stroke: ${lines}`);
  const [, listed, changed] = lines[0].match(/^map updated: (\d+) cells listed, (\d+) changed$/);
  assert.equal(listed, changed, 'only cells that change are sent');
  assert.ok(c1.LocalPlanSent - c0.LocalPlanSent <= 2, `${c1.LocalPlanSent - c0.LocalPlanSent} local plans for one stroke`);
  assert.ok(c1.GlobalPlan - c0.GlobalPlan <= 1, `${c1.GlobalPlan - c0.GlobalPlan} global plans for one stroke`);
  // The same stroke again changes nothing: nothing is sent, nothing planned.
  await stroke();
  await settled();
  assert.deepEqual(await count(), c1);
  // While the robot drives: still one update per stroke.
  await activateAll(page);
  await shownDriven(page, 0.3);
  await page.click('#tool-erase');
  await stroke();
  await shownLogged(page, 'MapUpdated', c1.MapUpdated + 1);
  await settled();
  assert.equal((await count()).MapUpdated, c1.MapUpdated + 1);
  assert.deepEqual(problems, []);
  await page.close();
});

// ------------------------------------------------------------------------------------ (7)

test('(7) parameters in English with the seed\'s Japanese; the gains explained and warned; applied torque and MaxTorque; one dmin', { timeout: 120_000 }, async () => {
  const { page, problems } = await open();
  await showTab(page, 'params');
  const rows = await page.$$eval('#params-panel .param', (ps) => ps.map((p) => ({
    component: p.dataset.component,
    name: p.dataset.name,
    en: p.querySelector('.param-en')?.textContent ?? '',
    ja: p.querySelector('.param-ja')?.textContent ?? null,
  })));
  assert.ok(rows.length >= 30, `${rows.length} parameters`);
  for (const r of rows) {
    assert.ok(/[A-Za-z]{3}.*[A-Za-z]{3}/.test(r.en) && !/[\u3040-\u30ff\u4e00-\u9fff]/u.test(r.en), `${r.component}.${r.name}: English, "${r.en}"`);
    if (r.component === 'LocalPathPlanning' || r.component === 'MotorControl') {
      assert.match(r.ja ?? '', /[\u3040-\u30ff\u4e00-\u9fff]/u, `${r.component}.${r.name}: the seed's Japanese`);
    } else {
      assert.equal(r.ja, null, `${r.component}.${r.name} is not in the seeds`);
    }
  }
  // One dmin control.
  assert.equal(rows.filter((r) => r.name === 'dmin').length, 1);
  // What P and D act on, and the bound.
  const explain = await page.textContent('#pd-explain');
  assert.match(explain, /P·\(ω\* \+ ω\)·Δt\/2/);
  assert.match(explain, /P < 2·D\/Δt/);
  assert.match(explain, /Δt = 1 ms: P must stay below 4000 \(left\) and 4000 \(right\)/);

  // PGainL past the bound: warned beside the gain; the torque plot shows the command cut
  // at the frame and the applied torque within ±MaxTorque.
  await setParam(page, 'MotorControl', 'PGainL', 5000);
  await page.waitForSelector(`${row('MotorControl', 'PGainL')} .param-warning:not([hidden])`, WAIT);
  assert.match(await page.textContent(`${row('MotorControl', 'PGainL')} .param-warning`), /P 5000 is above 2·D\/Δt = 4000/);
  await activateAll(page);
  await showTab(page, 'plots');
  // The plot shows the command off its scale; the core's samples say what it drew.
  await page.waitForSelector('#plot-torques[data-off-scale="true"]', { state: 'attached', ...WAIT });
  const data = await page.evaluate(() => JSON.parse(window.rtnav.demo.plot_json(10)));
  const most = (k) => Math.max(...data[k].map(Math.abs));
  assert.equal(data.max_torque, 5);
  assert.ok(most('torque_l') > 5, `commanded up to ${most('torque_l')} N·m`);
  assert.ok(most('applied_l') <= 5 && most('applied_l') > 4.9, `applied up to ${most('applied_l')} N·m`);
  await page.click('#deactivate-all');
  // D = 0: a limp wheel.
  await setParam(page, 'MotorControl', 'PGainL', 5);
  await setParam(page, 'MotorControl', 'DGainL', 0);
  assert.match(await page.textContent(`${row('MotorControl', 'DGainL')} .param-warning`), /limp/);
  await setParam(page, 'MotorControl', 'DGainL', 2);
  assert.equal(await page.isVisible(`${row('MotorControl', 'PGainL')} .param-warning`), false);

  // dmin: one value for both planners; the warning when the body can touch.
  await setParam(page, 'LocalPathPlanning', 'dmin', 0.5);
  assert.equal(await page.isVisible(`${row('LocalPathPlanning', 'dmin')} .param-warning`), false, '0.5 − 0.05 ≥ 0.45');
  await setParam(page, 'LocalPathPlanning', 'dmin', 0.45);
  await page.waitForSelector(`${row('LocalPathPlanning', 'dmin')} .param-warning:not([hidden])`, WAIT);
  assert.match(await page.textContent(`${row('LocalPathPlanning', 'dmin')} .param-warning`), /body can touch obstacles: dmin 0\.45 m − half a cell \(0\.05 m\) is less than radiusOfBodyArea 0\.45 m/);
  const conf = await page.evaluate(() => window.rtnav.demo.conf_export());
  const dmins = [...conf.matchAll(/^conf\.default\.dmin: (.+)$/gm)].map((m) => m[1]);
  assert.deepEqual(dmins, ['0.45', '0.45'], 'GlobalPathPlanning\'s dmin follows');
  // The warning is logged once (the log shows the core's events from the next frame on).
  await shownLogged(page, 'ClearanceWarning');
  await frames(page, 2);
  assert.equal((await logged(page, 'ClearanceWarning')).length, 1);
  await setParam(page, 'LocalPathPlanning', 'dmin', 0.6);
  assert.equal(await page.isVisible(`${row('LocalPathPlanning', 'dmin')} .param-warning`), false);
  assert.deepEqual(problems, []);
  await page.close();
});

// ------------------------------------------------------------------------------------ (8)

test('(8) the inspector gives metres beside the cell, and G = G(parent) + R + A + P with the parent', { timeout: 60_000 }, async () => {
  const { page, problems } = await open();
  await showTab(page, 'inspector');
  const { local_path: path } = await plan(page);
  const cell = path[Math.floor(path.length * 0.4)];
  const [x, y] = await cellToPage(page, cell);
  await page.mouse.move(x - 3, y);
  await page.mouse.move(x, y);
  await page.waitForSelector(`#inspector-panel[data-cell="${cell[0]},${cell[1]}"]`, { state: 'attached', ...WAIT });
  const j = JSON.parse(await page.getAttribute('#inspector-panel', 'data-json'));
  const m = await mapInfo(page);
  const centre = [m.origin[0] + (cell[0] + 0.5) * m.grid_size, m.origin[1] + (cell[1] + 0.5) * m.grid_size];
  assert.ok(near(j.centre, centre, 1e-9));
  assert.equal(await page.textContent('#inspector dd[data-key="centre"]'), `x ${centre[0].toFixed(2)} m, y ${centre[1].toFixed(2)} m`);
  assert.match(await page.textContent('#inspector-where'), new RegExp(`\\(${cell[0]}, ${cell[1]}\\) at x ${centre[0].toFixed(2)} m, y ${centre[1].toFixed(2)} m`));
  const f = j.field;
  assert.ok(f.parent, 'a reached cell has a parent');
  assert.equal(Math.max(Math.abs(f.parent.x - cell[0]), Math.abs(f.parent.y - cell[1])), 1, 'the parent is a neighbour');
  const sum = f.parent.potential + f.repulsion + f.attraction + f.posture;
  assert.ok(Math.abs(sum - f.potential) <= 1e-9 * f.potential, `G ${f.potential} = ${sum}`);
  assert.match(await page.textContent('#inspector dd[data-key="parent"]'), new RegExp(` at \\(${f.parent.x}, ${f.parent.y}\\)$`));
  assert.match(await page.textContent('#inspector-sum'), /G = G\(parent\) \+ R \+ A \+ P/);
  assert.deepEqual(problems, []);
  await page.close();
});

// ------------------------------------------------------------------------------------ (9)

test('(9) the unreachable lesson in the page: find the wall near y = 9 m, erase a door, set the goal again, arrive', { timeout: 300_000 }, async () => {
  const { page, problems } = await open();
  await pick(page, 'unreachable');
  const lesson = await page.textContent('#about-lesson');
  assert.match(lesson, /y ≈ 8 m to 10 m/);
  await shownStatus(page, /^No route \(/, ['no_route']);
  // The inspector finds the west wall of the storeroom at y = 9 m: walk east along y = 9 m.
  await showTab(page, 'inspector');
  const m = await mapInfo(page);
  const row9 = Math.floor((9 - m.origin[1]) / m.grid_size);
  let wall = null;
  for (let x = Math.floor(m.width / 2); x < m.width && !wall; x++) {
    const j = JSON.parse(await page.evaluate(([x, y]) => window.rtnav.demo.inspect_cell(x, y), [x, row9]));
    if (j.occupancy === 1) wall = j;
  }
  assert.ok(wall && Math.abs(wall.centre[1] - 9.05) < 1e-9, JSON.stringify(wall));
  // Erase it from y = 8 m to 10 m with a 1 m brush, in one stroke.
  await page.click('#tool-erase');
  await page.selectOption('#brush-unit', 'm');
  await page.selectOption('#brush', '1');
  const wx = wall.centre[0] + 0.3;
  const toPage = (wx, wy) => page.evaluate(([wx, wy]) => {
    const [px, py] = window.rtnav.demo.world_to_pixel(wx, wy);
    const c = document.getElementById('overlay');
    const r = c.getBoundingClientRect();
    return [r.left + (px * r.width) / c.width, r.top + (py * r.height) / c.height];
  }, [wx, wy]);
  const [ax, ay] = await toPage(wx, 8.2);
  const [bx, by] = await toPage(wx, 9.8);
  await page.mouse.move(ax, ay);
  await page.mouse.down();
  await page.mouse.move(bx, by, { steps: 10 });
  await page.mouse.up();
  await page.waitForFunction(([x, y]) => window.rtnav.demo.cell(x, y) === 0, [wall.x, wall.y], WAIT);
  // The goal again, from where the robot stands, then drive.
  const goal = (await plan(page)).goal;
  await page.evaluate((g) => window.rtnav.demo.set_goal(g.x, g.y, g.theta_deg, false), goal);
  await shownStatus(page, /^Plan ready/, ['ready']);
  await activateAll(page);
  await page.selectOption('#speed', '16');
  await page.waitForSelector('#telemetry[data-arrived="true"]', DRIVE);
  assert.equal((await telemetry(page)).bumps, 0);
  assert.deepEqual(problems, []);
  await page.close();
});

// ------------------------------------------------------------------------------------ (10)

test('(10) the trail is drawn over the paths', { timeout: 60_000 }, async () => {
  const { page, problems } = await open();
  await activateAll(page);
  await page.selectOption('#speed', '4');
  await shownDriven(page, 6);
  await page.click('#pause');
  await frames(page, 3);
  const seen = await page.evaluate(() => {
    const { demo } = window.rtnav;
    const c = document.getElementById('view');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    const t = JSON.parse(demo.telemetry_json());
    const robot = demo.world_to_pixel(t.pose.x, t.pose.y);
    const start = demo.world_to_pixel(t.start.x, t.start.y);
    const radius = (t.body_radius + 0.3) * demo.pixels_per_metre();
    const trail = JSON.parse(demo.trail_json());
    const p = JSON.parse(demo.plan_json());
    const onPath = new Set(p.local_path.map(([x, y]) => `${x},${y}`));
    const markers = p.control_points.map(([x, y]) => demo.world_to_pixel(x, y));
    const m = JSON.parse(demo.map_json());
    let teal = 0;
    let checked = 0;
    let underLocal = 0;
    for (const [x, y] of trail) {
      const [px, py] = demo.world_to_pixel(x, y);
      if (Math.hypot(px - robot[0], py - robot[1]) < radius || Math.hypot(px - start[0], py - start[1]) < radius) continue;
      // The control points' markers are drawn over everything, the trail too.
      if (markers.some(([mx, my]) => Math.hypot(px - mx, py - my) < 7)) continue;
      const i = 4 * (Math.round(py - 0.5) * c.width + Math.round(px - 0.5));
      const [r, g, b] = [d[i], d[i + 1], d[i + 2]];
      checked++;
      const isTeal = g > r + 60 && b > r + 50;
      if (isTeal) teal++;
      const cell = `${Math.floor((x - m.origin[0]) / m.grid_size)},${Math.floor((y - m.origin[1]) / m.grid_size)}`;
      if (onPath.has(cell)) underLocal += isTeal ? 1 : 0;
    }
    return { teal, checked, underLocal };
  });
  console.log(`trail: ${seen.teal} of ${seen.checked} points drawn in its colour, ${seen.underLocal} of them on the local path`);
  assert.ok(seen.checked > 50 && seen.teal / seen.checked > 0.85, JSON.stringify(seen));
  assert.ok(seen.underLocal > 10, `the trail shows where it runs on the local path: ${JSON.stringify(seen)}`);
  assert.deepEqual(problems, []);
  await page.close();
});

// ------------------------------------------------------------------------------------ (11)

test('(11) the title shows the version of rtnav the page runs: the workspace\'s, from Cargo.toml', { timeout: 60_000 }, async () => {
  const cargo = readFileSync(new URL('../../Cargo.toml', import.meta.url), 'utf8');
  const expected = /^\[workspace\.package\]\n(?:.*\n)*?version = "([^"]+)"/m.exec(cargo)?.[1];
  assert.ok(expected, 'Cargo.toml names the workspace version');
  const { page, problems } = await open();
  await page.waitForFunction((v) => document.getElementById('version')?.textContent === v, expected, WAIT);
  assert.deepEqual(problems, []);
  await page.close();
});
