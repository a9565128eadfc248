// End-to-end, on a phone (390×844, touch): every control a finger can reach is at least
// 44 × 44 CSS pixels (WCAG 2.5.5), on every tab and in the menus; and a notice over the map
// covers neither the robot nor the goal nor more than a quarter of the map (js/notice.js).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { WAIT, launch, openPage, screenshot, showTab, activateAll, frames } from './helpers.mjs';

const PHONE = { viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true, deviceScaleFactor: 2 };
/** The smallest target, CSS pixels (less half a pixel for rounding). */
const MIN_PX = 44 - 0.5;

let phone;
before(async () => {
  phone = await launch(PHONE);
});
after(async () => {
  await phone?.close();
});

/**
 * In the page: every visible control that is smaller than 44 × 44 — its name and size. A check
 * box or radio button is measured by its label (a tap on the label is a tap on it); a file
 * input by the label that shows it.
 */
function smallTargets(min) {
  const CONTROLS = 'button, select, input, textarea, a[href], summary, [role="tab"], [role="button"], label.file-button';
  const shown = (e) => e.checkVisibility({ checkOpacity: false, checkVisibilityCSS: true })
    && e.getBoundingClientRect().width > 0 && e.getBoundingClientRect().height > 0;
  const name = (e) => (e.id ? `#${e.id}` : `${e.tagName.toLowerCase()}.${[...e.classList].join('.')} "${(e.textContent || e.getAttribute('aria-label') || '').trim().slice(0, 30)}"`);
  const small = [];
  const seen = new Set();
  for (const control of document.querySelectorAll(CONTROLS)) {
    const target = control.matches('input[type="checkbox"], input[type="radio"], input[type="file"]')
      ? control.closest('label') ?? (control.id && document.querySelector(`label[for="${control.id}"]`))
      : control;
    if (!target || seen.has(target) || !shown(target)) continue;
    seen.add(target);
    const r = target.getBoundingClientRect();
    if (r.width < min || r.height < min) small.push(`${name(target)}: ${r.width.toFixed(1)} × ${r.height.toFixed(1)}`);
  }
  return small;
}

test('at 390×844 every control on every tab, in the menus and in a notice is at least 44 × 44 px', { timeout: 120_000 }, async () => {
  const { page, problems } = await openPage(phone.context, '?lang=en');
  const found = {};
  const check = async (where) => {
    const small = await page.evaluate(smallTargets, MIN_PX);
    if (small.length) found[where] = small;
  };
  for (const tab of ['rtc', 'system', 'params', 'inspector', 'plots', 'log']) {
    await showTab(page, tab);
    await check(`tab ${tab}`);
  }
  // The folds and menus open, a notice up (the share link's), the legend open.
  await page.tap('#legend > summary');
  await page.waitForSelector('#legend[open]', WAIT);
  for (const menu of await page.$$('.toolbar details.menu > summary')) await menu.tap();
  await page.tap('#share-copy');
  await page.waitForSelector('#notice:not([hidden])', WAIT);
  await check('menus, legend, notice, share link');
  await screenshot(page, 'touch-390x844.png', { docs: false, fullPage: true });
  assert.deepEqual(found, {}, 'controls smaller than 44 × 44 px');
  assert.deepEqual(problems, []);
  await page.close();
});

/** What the notice covers: the robot, the goal (their boxes as the page keeps them clear), and its share of the map's area. */
const covered = (page) => page.evaluate(() => {
  const n = document.getElementById('notice').getBoundingClientRect();
  const map = document.getElementById('canvas-wrap').getBoundingClientRect();
  const { stage } = window.rtnav.app;
  const over = (b) => Boolean(b) && n.left < b.right && b.left < n.right && n.top < b.bottom && b.top < n.bottom;
  const robot = stage.robotBox();
  const [, goal] = stage.keepClear().length === 2 ? stage.keepClear() : [null, null];
  const w = Math.max(0, Math.min(n.right, map.right) - Math.max(n.left, map.left));
  const h = Math.max(0, Math.min(n.bottom, map.bottom) - Math.max(n.top, map.top));
  return { robot: over(robot), goal: over(goal), share: (w * h) / (map.width * map.height), text: document.getElementById('notice-text').textContent };
});

const assertClear = (c, what) => {
  assert.equal(c.robot, false, `${what}: the notice covers the robot ("${c.text}")`);
  assert.equal(c.goal, false, `${what}: the notice covers the goal ("${c.text}")`);
  assert.ok(c.share <= 0.25, `${what}: the notice covers ${(100 * c.share).toFixed(0)} % of the map ("${c.text}")`);
};

test('at 390×844 a notice covers neither the robot nor the goal nor more than a quarter of the map', { timeout: 120_000 }, async () => {
  const { page, problems } = await openPage(phone.context, '?lang=en');
  // A long notice (a refused goal, in an obstacle) while the robot stands at its start.
  const cell = await page.evaluate(() => {
    const { demo } = window.rtnav;
    const m = JSON.parse(demo.map_json());
    for (let y = 2; y < m.height - 2; y++) {
      for (let x = 2; x < m.width - 2; x++) {
        let solid = true;
        for (let d = -2; d <= 2 && solid; d++) solid = demo.cell(x + d, y) === 1 && demo.cell(x, y + d) === 1;
        if (solid) {
          const [px, py] = demo.world_to_pixel(m.origin[0] + (x + 0.5) * m.grid_size, m.origin[1] + (y + 0.5) * m.grid_size);
          const c = document.getElementById('overlay');
          const r = c.getBoundingClientRect();
          return [r.left + (px * r.width) / c.width, r.top + (py * r.height) / c.height];
        }
      }
    }
    return null;
  });
  assert.ok(cell, 'an obstacle to tap');
  await page.tap('#tool-goal');
  await page.touchscreen.tap(cell[0], cell[1]);
  await page.waitForSelector('#notice[data-level="error"]:not([hidden])', WAIT);
  await frames(page, 3);
  assertClear(await covered(page), 'a refused goal');
  await screenshot(page, 'notice-refused-390x844.png', { docs: false });

  // Arrival: the notice stays while the robot is at the goal, off both.
  await page.evaluate(() => window.rtnav.app.notice.hide());
  await activateAll(page);
  await page.selectOption('#speed', '16');
  await page.waitForSelector('#telemetry[data-arrived="true"]', { timeout: 90_000 });
  await page.waitForSelector('#notice[data-level="success"]:not([hidden])', WAIT);
  await frames(page, 3);
  assertClear(await covered(page), 'arrival');
  await screenshot(page, 'notice-arrival-390x844.png', { docs: false });

  // The robot (at the goal) zoomed and panned under each of the notice's places in turn: the
  // notice moves, and still covers neither.
  for (const at of [0.12, 0.5, 0.88]) {
    await page.evaluate((at) => {
      const { demo, app } = window.rtnav;
      const t = JSON.parse(demo.telemetry_json());
      const c = document.getElementById('overlay');
      const [px, py] = demo.world_to_pixel(t.pose.x, t.pose.y);
      demo.zoom_at(px, py, 2);
      const [qx, qy] = demo.world_to_pixel(t.pose.x, t.pose.y);
      demo.pan_by(c.width / 2 - qx, c.height * at - qy);
      app.emit('view');
    }, at);
    await frames(page, 3);
    assertClear(await covered(page), `the robot at ${at} of the map's height`);
    await page.click('#zoom-fit');
  }
  assert.deepEqual(problems, []);
  await page.close();
});
