// End-to-end: switching the language keeps the run (js/carry.js). English ↔ 日本語 reloads
// the page; the robot's run — its goal, a painted obstacle, a parameter, the lifecycle
// requests, the time it had reached and every tick on the way — comes back in the other
// language, replayed by the core to the same tick (the same pose and trace hash), with the
// page's own settings (paused, speed, tool, direction, tab). A map loaded from a file cannot
// be carried: the page asks first, and staying keeps it.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { REPO, WAIT, launch, openPage, cellToPage, activateAll, showTab, within, shownDriven } from './helpers.mjs';

let browser;
before(async () => {
  browser = await launch();
});
after(async () => {
  await browser?.close();
});

/** Switches the language with the picker and waits for the page in it. */
async function switchTo(page, lang) {
  await Promise.all([page.waitForNavigation(), page.selectOption('#language', lang)]);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 60_000 });
  assert.equal(await page.evaluate(() => document.documentElement.lang), lang);
}

/** Pauses or runs the clock with its button (in either language) and waits until it shows so. */
async function setPaused(page, paused) {
  await page.click('#pause');
  await page.waitForSelector(`#pause[data-paused="${paused}"]`, { state: 'attached', ...WAIT });
}

/** What the run is: time, pose, goal, plan, the map's key, the trace hash of the timeline. */
const state = (page) => page.evaluate(() => {
  const { demo } = window.rtnav;
  const tm = JSON.parse(demo.telemetry_json());
  return {
    time: demo.time_s(),
    pose: tm.pose,
    goal: tm.goal,
    bumps: tm.bumps,
    local_plans: tm.local_plans,
    state: tm.state,
    map_obstacles: JSON.parse(demo.map_json()).obstacles,
    params: demo.params_json(),
    trace: JSON.parse(demo.replay_json()).trace_hash,
  };
});

test('switching the language carries the run: goal, edits, parameters, time, pause and tools', { timeout: 180_000 }, async () => {
  const { page, problems } = await openPage(browser.context, '?lang=en');
  // A goal of the person's own, an obstacle painted away from the path, a parameter changed.
  await page.click('#tool-goal');
  const [gx, gy] = await cellToPage(page, [200, 40]);
  await page.mouse.click(gx, gy);
  await page.waitForFunction(() => JSON.parse(window.rtnav.demo.plan_json()).goal?.x === 20.05, null, WAIT);
  assert.ok(await page.evaluate(() => window.rtnav.demo.set_cells(Int32Array.of(5, 6), Int32Array.of(170, 170), 1) === undefined));
  await showTab(page, 'params');
  await page.fill('#param-DriveControl-MaxVelocity', '0.4');
  await page.press('#param-DriveControl-MaxVelocity', 'Enter');
  await activateAll(page);
  // The clock has run since the page opened: what counts is that the robot has driven.
  await shownDriven(page, 1, { timeout: 60_000 });
  await setPaused(page, true);
  await page.click('#tool-pan');
  await page.click('#dir-backward');
  await page.selectOption('#speed', '2');
  const before = await state(page);
  assert.equal(before.goal.x, 20.05);
  assert.ok(before.pose.x > 2.6, `the robot drove (${before.pose.x})`);

  await switchTo(page, 'ja');
  await page.waitForFunction((t) => window.rtnav.demo.time_s() === t, before.time, WAIT);
  assert.deepEqual(await state(page), before, 'the same run, to the tick, in Japanese');
  assert.equal(await page.evaluate(() => window.rtnav.demo.paused()), true);
  assert.equal(await page.inputValue('#speed'), '2');
  assert.equal(await page.getAttribute('#tool-pan', 'aria-pressed'), 'true');
  assert.equal(await page.getAttribute('#dir-backward', 'aria-pressed'), 'true');
  assert.equal(await page.getAttribute('#tab-params', 'aria-selected'), 'true');
  assert.equal(await page.inputValue('#param-DriveControl-MaxVelocity'), '0.4');
  assert.equal(await page.textContent('#activate-all'), 'すべてアクティブ化');
  assert.doesNotMatch(page.url(), /share=/, 'the run is carried, not a share link');

  // It goes on from there; and back to English, still the same run.
  await setPaused(page, false);
  await page.waitForFunction((t) => window.rtnav.demo.time_s() > t + 1, before.time, { timeout: 60_000 });
  await setPaused(page, true);
  const later = await state(page);
  await switchTo(page, 'en');
  await page.waitForFunction((t) => window.rtnav.demo.time_s() === t, later.time, WAIT);
  assert.deepEqual(await state(page), later, 'the same run, to the tick, back in English');

  // A plain reload afterwards starts afresh: the carry is taken once.
  await page.reload();
  await page.waitForSelector('body[data-ready="true"]', { timeout: 60_000 });
  assert.ok(await page.evaluate(() => window.rtnav.demo.time_s()) < later.time);
  assert.deepEqual(problems, []);
});

test('a map loaded from a file cannot be carried: the page asks, and staying keeps it', { timeout: 120_000 }, async () => {
  const { page, problems } = await openPage(browser.context, '?lang=en');
  await page.setInputFiles('#map-file', join(REPO, 'fixtures/maps/yard.map'));
  await page.waitForFunction(() => window.rtnav.scenarios.current === null, null, WAIT);
  const map = await page.evaluate(() => JSON.parse(window.rtnav.demo.map_json()).name);
  // Asked, and the person stays: same page, same map, the picker back on English.
  const asked = [];
  const dismissed = new Promise((done) => page.once('dialog', async (d) => {
    asked.push(d.message());
    await d.dismiss();
    done();
  }));
  await page.selectOption('#language', 'ja');
  await within(dismissed, 'the question whether to leave the map behind');
  // The picker goes back to English once the question is answered.
  await page.waitForFunction(() => document.getElementById('language').value === 'en', null, WAIT);
  assert.equal(asked.length, 1);
  assert.match(asked[0], /cannot be carried/);
  assert.equal(await page.inputValue('#language'), 'en');
  assert.equal(await page.evaluate(() => document.documentElement.lang), 'en');
  assert.equal(await page.evaluate(() => JSON.parse(window.rtnav.demo.map_json()).name), map);
  // Asked again, and the person goes: Japanese, the default scenario.
  page.once('dialog', (d) => d.accept());
  await switchTo(page, 'ja');
  assert.equal(await page.evaluate(() => window.rtnav.scenarios.current), 'open_field');
  assert.deepEqual(problems, []);
});
