// End-to-end with the keyboard only (no mouse, no touch: `page.keyboard` alone): the map takes
// the focus, the arrows move its cursor, `[`/`]` turn it, Enter sets the goal, the system is
// activated and the robot drives to arrival; Obstacle and Erase paint at the cursor, Pan
// moves the view; `?` opens the keyboard guide and Escape gives the focus back. A screen
// reader's view of it: the accessibility tree (Playwright's ARIA snapshot) holds the scene's
// description and the status; only what changes is spoken, never every frame; the RTC list's
// buttons say which component they act on.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { copyFile, mkdir } from 'node:fs/promises';
import { join } from 'node:path';
import { WAIT, DRIVE, HERE, REPO, launch, openPage, until, shownStatus, frames } from './helpers.mjs';

let browser;
before(async () => {
  browser = await launch();
});
after(async () => {
  await browser?.close();
});

/** The focused element as `#id` (or its tag). */
const focused = (page) => page.evaluate(() => {
  const e = document.activeElement;
  return e ? (e.id ? `#${e.id}` : e.tagName.toLowerCase()) : null;
});

/** Presses Tab (Shift+Tab with `back`) until `selector` has the focus, as a person would. */
async function tabTo(page, selector, { back = false, most = 120 } = {}) {
  for (let i = 0; i < most; i++) {
    if (await page.evaluate((s) => document.activeElement?.matches(s) ?? false, selector)) return;
    await page.keyboard.press(back ? 'Shift+Tab' : 'Tab');
  }
  assert.fail(`${selector} never took the focus in ${most} presses of Tab (the focus is on ${await focused(page)})`);
}

/** Presses `key` `n` times. */
async function press(page, key, n) {
  for (let i = 0; i < n; i++) await page.keyboard.press(key);
}

/** Waits until the map's ARIA snapshot matches every one of `res`; returns the snapshot. */
async function shownInTree(page, res, { timeout = WAIT.timeout } = {}) {
  const box = page.locator('#map-box');
  const end = Date.now() + timeout;
  let last = '';
  while (Date.now() < end) {
    last = await box.ariaSnapshot();
    if (res.every((re) => re.test(last))) return last;
    await frames(page, 4);
  }
  assert.fail(`the accessibility tree never showed ${res.join(', ')}; it showed:\n${last}`);
}

test('from loading to arrival with the keyboard alone: the goal set with the map\'s cursor', { timeout: 240_000 }, async () => {
  const { page, problems } = await openPage(browser.context, '?lang=en');
  // Where the goal will go: a cell of the route the scenario starts with, half-way (a place the
  // robot can reach), in whole cursor steps from where the cursor starts (the goal).
  const aim = await page.evaluate(() => {
    const { demo } = window.rtnav;
    const map = JSON.parse(demo.map_json());
    const plan = JSON.parse(demo.plan_json());
    const [cx, cy] = plan.global_path[Math.floor(plan.global_path.length / 2)];
    const g = map.grid_size;
    const goal = plan.goal;
    const kx = Math.round((map.origin[0] + (cx + 0.5) * g - goal.x) / g);
    const ky = Math.round((map.origin[1] + (cy + 0.5) * g - goal.y) / g);
    return { kx, ky, g, goal };
  });
  assert.ok(Math.abs(aim.kx) + Math.abs(aim.ky) > 0, 'the new goal is not the old one');

  await tabTo(page, '#overlay');
  // The focus ring is drawn (the overlay is :focus-visible) and the map is named as a control.
  assert.equal(await page.$eval('#overlay', (e) => e.matches(':focus-visible') && getComputedStyle(e).outlineStyle), 'solid');
  await page.keyboard.press('g');
  await page.waitForSelector('#tool-goal[aria-pressed="true"]', WAIT);
  await press(page, aim.kx > 0 ? 'ArrowRight' : 'ArrowLeft', Math.abs(aim.kx));
  await press(page, aim.ky > 0 ? 'ArrowUp' : 'ArrowDown', Math.abs(aim.ky));
  await press(page, '[', 2);
  const round2 = (v) => Math.round(v * 100) / 100;
  const want = {
    x: round2(round2(aim.goal.x) + aim.kx * aim.g),
    y: round2(round2(aim.goal.y) + aim.ky * aim.g),
    theta_deg: ((((Math.round(aim.goal.theta_deg) + 30 + 180) % 360) + 360) % 360) - 180,
  };
  // Where the cursor is is said (a polite live region), once a key.
  await until(page, 'the cursor to be said where it is', (w) => {
    const said = document.getElementById('map-cursor').textContent;
    return { ok: said === `Cursor at (${w.x.toFixed(2)} m, ${w.y.toFixed(2)} m), heading ${w.theta_deg}°.`, shown: said };
  }, want);
  await page.keyboard.press('Enter');
  // The goal is the cursor's: the notice says so and the core holds it.
  await until(page, 'the goal set at the cursor', (w) => {
    const text = document.getElementById('notice-text').textContent;
    const goal = JSON.parse(window.rtnav.demo.plan_json()).goal;
    const ok = text.startsWith(`Goal set at (${w.x.toFixed(2)} m, ${w.y.toFixed(2)} m, ${w.theta_deg}°)`)
      && goal && Math.abs(goal.x - w.x) < 1e-9 && Math.abs(goal.y - w.y) < 1e-9 && Math.abs(goal.theta_deg - w.theta_deg) < 1e-9;
    return { ok, shown: `the notice "${text}", the core's goal ${JSON.stringify(goal)}` };
  }, want);

  // The fastest clock, then Activate all, from the keyboard.
  await tabTo(page, '#speed', { back: true });
  await page.keyboard.press('End');
  await until(page, 'the clock at 16×', () => ({ ok: document.getElementById('speed').value === '16', shown: document.getElementById('speed').value }));
  await tabTo(page, '#activate-all');
  await page.keyboard.press('Enter');

  // While it drives, nothing speaks every frame: each live region changes only a few times in
  // a stretch of driving in which the clock shows many frames.
  await shownStatus(page, /^Driving/, ['driving', 'turning_on_the_spot', 'turning_to_goal_heading']);
  const speech = await page.evaluate(() => new Promise((done) => {
    const live = [...document.querySelectorAll('[role="status"], [role="alert"], [role="log"], [aria-live], output')]
      .filter((e) => e.getAttribute('aria-live') !== 'off');
    const changes = new Map(live.map((e) => [e, 0]));
    const observers = live.map((e) => {
      const o = new MutationObserver(() => changes.set(e, changes.get(e) + 1));
      o.observe(e, { childList: true, characterData: true, subtree: true });
      return o;
    });
    let ticks = 0;
    const clock = new MutationObserver(() => { ticks += 1; });
    clock.observe(document.getElementById('sim-time'), { childList: true, characterData: true, subtree: true });
    setTimeout(() => {
      for (const o of observers) o.disconnect();
      clock.disconnect();
      done({ ticks, regions: [...changes].map(([e, n]) => [e.id || e.className || e.tagName, n]) });
    }, 3000);
  }));
  assert.ok(speech.ticks >= 10, `the clock showed ${speech.ticks} frames in 3 s`);
  for (const [region, n] of speech.regions) assert.ok(n <= 3, `${region} spoke ${n} times in ${speech.ticks} frames`);

  // Arrival, and the accessibility tree holds the scene and the status.
  await shownStatus(page, /^Arrived/, ['arrived'], DRIVE);
  const tree = await shownInTree(page, [
    /application "Map, potential field, paths and robot"/,
    /Map \S+, [\d.]+ × [\d.]+ m \(\d+ × \d+ cells of [\d.]+ m\)\./,
    new RegExp(`Goal at \\(${want.x.toFixed(1)} m, ${want.y.toFixed(1)} m\\), heading ${want.theta_deg}°`),
    /Robot at \([\d.-]+ m, [\d.-]+ m\), heading -?\d+°\./,
    /Route [\d.]+ m long\./,
    /Status: Arrived: the robot rests at the goal/,
    /status: "?Arrived: the robot rests at the goal/,
  ]);
  assert.match(tree, /Cursor at/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('Obstacle and Erase paint at the cursor, Pan moves the view, ? opens the guide and Escape gives the focus back', { timeout: 120_000 }, async () => {
  const { page, problems } = await openPage(browser.context, '?lang=en');
  const obstacles = () => page.evaluate(() => JSON.parse(window.rtnav.demo.map_json()).obstacles);
  const before = await obstacles();
  await tabTo(page, '#overlay');
  // Off the goal, two metres toward the robot's side, then a 3×3 brush of obstacles there.
  await page.keyboard.press('o');
  await page.waitForSelector('#tool-paint[aria-pressed="true"]', WAIT);
  await press(page, 'Shift+ArrowDown', 2);
  await page.keyboard.press('Enter');
  const painted = await until(page, 'the cell under the cursor painted', (n) => {
    const now = JSON.parse(window.rtnav.demo.map_json()).obstacles;
    return { ok: now > n, value: now, shown: `${now} obstacle cells (${n} before)` };
  }, before);
  await page.keyboard.press('e');
  await page.waitForSelector('#tool-erase[aria-pressed="true"]', WAIT);
  await page.keyboard.press(' ');
  await until(page, 'the cell under the cursor erased', (n) => {
    const now = JSON.parse(window.rtnav.demo.map_json()).obstacles;
    return { ok: now === n, shown: `${now} obstacle cells (${n} before painting)` };
  }, before);
  assert.ok(painted > before);
  // Space on the map painted: it did not pause the clock.
  assert.equal(await page.$eval('#pause', (b) => b.dataset.paused), 'false');

  // Pan: zoomed in, an arrow moves the view (the map's corner moves on the canvas).
  await page.keyboard.press('p');
  await page.waitForSelector('#tool-pan[aria-pressed="true"]', WAIT);
  await page.keyboard.press('+');
  const corner = () => page.evaluate(() => {
    const m = JSON.parse(window.rtnav.demo.map_json());
    return Array.from(window.rtnav.demo.world_to_pixel(m.origin[0], m.origin[1]));
  });
  const [x0] = await corner();
  await page.keyboard.press('ArrowRight');
  await until(page, 'the view moved right (the picture left)', (x) => {
    const m = JSON.parse(window.rtnav.demo.map_json());
    const [x1] = window.rtnav.demo.world_to_pixel(m.origin[0], m.origin[1]);
    return { ok: x1 < x - 1, shown: `the map's corner at x ${x1} (${x} before)` };
  }, x0);

  // The guide: `?` opens it with the focus in it; Escape closes it and the map has the focus again.
  await page.keyboard.press('?');
  await page.waitForSelector('#keys[open]', WAIT);
  assert.equal(await focused(page), '#keys-close');
  const guide = await page.locator('#keys').ariaSnapshot();
  assert.match(guide, /dialog "Keyboard"/);
  assert.match(guide, /Place the goal or the start at the cursor/);
  await page.keyboard.press('Escape');
  await page.waitForSelector('#keys:not([open])', { ...WAIT, state: 'attached' });
  assert.equal(await focused(page), '#overlay');
  assert.deepEqual(problems, []);
  await page.close();
});

for (const [lang, activate, fault] of [['en', 'Activate MotorControl0', 'Inject fault into PhysicsSim0'], ['ja', 'MotorControl0 をアクティブ化', 'PhysicsSim0 に故障を注入']]) {
  test(`(${lang}) the RTC list's buttons say which component they act on`, { timeout: 60_000 }, async () => {
    const { page, problems } = await openPage(browser.context, `?lang=${lang}`);
    await page.waitForSelector('#components li[data-component="MotorControl"]', WAIT);
    assert.equal(await page.getByRole('button', { name: activate, exact: true }).count(), 1);
    assert.equal(await page.getByRole('button', { name: fault, exact: true }).count(), 1);
    const names = await page.$$eval('#components button', (bs) => bs.map((b) => b.getAttribute('aria-label') ?? b.textContent));
    assert.equal(new Set(names).size, names.length, `repeated names: ${names.join(', ')}`);
    assert.deepEqual(problems, []);
    await page.close();
  });
}

/**
 * The keyboard's cursor and the map's focus ring, at a laptop's, a tablet's and a phone's size:
 * saved in tests/e2e/out/ (and docs/screenshots/ with UPDATE_SCREENSHOTS=1).
 */
for (const size of [
  { viewport: { width: 1280, height: 800 } },
  { viewport: { width: 768, height: 1024 }, hasTouch: true },
  { viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true, deviceScaleFactor: 2 },
]) {
  const { width, height } = size.viewport;
  test(`at ${width}×${height} the map shows the keyboard's focus ring and cursor`, { timeout: 120_000 }, async () => {
    const sized = await launch(size);
    try {
      const { page, problems } = await openPage(sized.context, '?lang=en');
      await tabTo(page, '#overlay');
      await page.keyboard.press('g');
      await press(page, 'Shift+ArrowLeft', 3);
      await press(page, 'Shift+ArrowDown', 2);
      await press(page, '[', 3);
      // The cursor is drawn on the overlay (its pixels are not all clear) inside the focus ring.
      await until(page, 'the cursor drawn on the map', () => {
        const c = document.getElementById('overlay');
        const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
        let n = 0;
        for (let i = 3; i < d.length; i += 4) if (d[i]) n++;
        return { ok: n > 100 && c.matches(':focus-visible'), shown: `${n} pixels drawn, focus-visible ${c.matches(':focus-visible')}` };
      });
      await page.$eval('#canvas-wrap', (e) => e.scrollIntoView({ block: 'center' }));
      await frames(page, 2);
      const name = `keyboard-${width}x${height}.png`;
      await mkdir(join(HERE, 'out'), { recursive: true });
      const shot = join(HERE, 'out', name);
      await page.screenshot({ path: shot });
      if (process.env.UPDATE_SCREENSHOTS === '1') {
        await mkdir(join(REPO, 'docs', 'screenshots'), { recursive: true });
        await copyFile(shot, join(REPO, 'docs', 'screenshots', name));
      }
      assert.deepEqual(problems, []);
    } finally {
      await sized.close();
    }
  });
}
