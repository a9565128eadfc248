// End-to-end: what a QA pass of the page found, each checked where a person meets it.
// - In Japanese the robot's status says which component and why (the core's `Status` fields
//   through `status.<kind>`), and with the English catalogue the same words are the core's
//   own English text; the legend's potential scale, the scenario titles and the compare
//   heading (not uppercased) are the page's language too.
// - A component in Error is "in Error: not executing" in the RTC panel (and in Japanese).
// - A notice lets clicks through to the map (only its button takes them) and keeps off the
//   goal as well as the robot.
// - One column below 1080 px, two above; the cards keep their style; at 390 px no parameter
//   name is cut off.
// - One wording for the clock's button in the system bar and the timeline; no "-0"; no
//   inspector row that repeats another; with the Pan tool a tap inspects the cell.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { WAIT, launch, openPage, cellToPage, activateAll, showTab, frames, until, shownStatus } from './helpers.mjs';

let browser;
before(async () => {
  browser = await launch();
});
after(async () => {
  await browser?.close();
});

/** Words of three or more Latin letters that are not the page's names. */
const latin = (text) => text.replace(/\b(DriveControl0|MotorControl0|PhysicsSim0|Error|TargetVelocity|SafeMode|Clear)\b/g, ' ').match(/[A-Za-z]{3,}/g) ?? [];

/** Injects a fault into `name` from its RTC row and waits for its Error. */
async function fault(page, name) {
  await page.click(`#components li[data-component="${name}"] .fault`);
  await page.waitForSelector(`#components li[data-component="${name}"][data-state="Error"]`, WAIT);
  await frames(page, 2);
}

test('in Japanese the status names the component in Error and why; the RTC panel says it does not execute', { timeout: 120_000 }, async () => {
  const { page, problems } = await openPage(browser.context, '?lang=ja');
  await activateAll(page);
  await fault(page, 'DriveControl');
  const { text: status } = await shownStatus(page, /^DriveControl0 がエラー状態：注入された故障：.+（リセットで復帰）；ロボットは.+$/, ['component_error']);
  assert.deepEqual(latin(status), [], status);
  assert.equal(await page.textContent('#components li[data-component="DriveControl"] .rtc-status'), 'エラー状態：実行していない');
  assert.deepEqual(problems, []);
  await page.close();
});

test('in English every status of a run is said in full from the catalogue: its fields filled, no key shown', { timeout: 120_000 }, async () => {
  const { page, problems } = await openPage(browser.context, '?lang=en');
  // Every status the page shows during a run, with what the catalogue makes of its fields.
  await page.evaluate(async () => {
    const { sayer } = await import('./js/say.js');
    const { fill, englishWords } = await import('./js/i18n.js');
    const english = sayer((key, vars) => fill(englishWords()[key] ?? key, vars), (key) => key in englishWords());
    window.__statuses = new Map();
    const look = () => {
      const v = JSON.parse(window.rtnav.demo.telemetry_json());
      window.__statuses.set(english.statusText(v.status_kind, v.status_fields), v.status_kind);
      requestAnimationFrame(look);
    };
    look();
  });
  await activateAll(page);
  await page.waitForSelector('#telemetry[data-driving="true"]', WAIT);
  await page.click('#safe-mode');
  const seenStatus = (what, re) => until(page, `a status ${what} seen`, (re) => {
    const seen = [...window.__statuses.keys()];
    return { ok: seen.some((s) => new RegExp(re).test(s)), shown: JSON.stringify(seen) };
  }, re.source);
  await seenStatus('halted by SafeMode', /^halted by SafeMode/);
  const goal = await cellToPage(page, [60, 150]);
  await page.mouse.click(goal[0], goal[1]);
  await frames(page, 10);
  await fault(page, 'MotorControl');
  await seenStatus('of MotorControl0 in Error', /^MotorControl0 in Error: /);
  await page.click('#reset-all');
  await frames(page, 3);
  const seen = await page.evaluate(() => [...window.__statuses.entries()]);
  assert.ok(seen.length >= 5, JSON.stringify(seen));
  assert.ok(seen.some(([s]) => /^MotorControl0 in Error: /.test(s)), JSON.stringify(seen));
  assert.ok(seen.some(([s]) => /^halted by SafeMode/.test(s)), JSON.stringify(seen));
  for (const [said, kind] of seen) {
    assert.ok(!said.includes('{') && !said.startsWith('status.') && !said.includes('undefined'), `${kind}: "${said}"`);
  }
  assert.deepEqual(problems, []);
  await page.close();
});

test('the RTC panel shows a component in Error as not executing', { timeout: 60_000 }, async () => {
  const { page, problems } = await openPage(browser.context, '?lang=en');
  await activateAll(page);
  await fault(page, 'DriveControl');
  assert.equal(await page.textContent('#components li[data-component="DriveControl"] .rtc-status'), 'in Error, not executing');
  // Reset: Inactive, and its own status again.
  await page.click('#components li[data-component="DriveControl"] .act');
  await page.waitForSelector('#components li[data-component="DriveControl"][data-state="Inactive"]', WAIT);
  assert.notEqual(await page.textContent('#components li[data-component="DriveControl"] .rtc-status'), 'in Error, not executing');
  assert.deepEqual(problems, []);
  await page.close();
});

test('in Japanese the legend, the scenario titles and the compare heading are Japanese', { timeout: 60_000 }, async () => {
  const { page, problems } = await openPage(browser.context, '?lang=ja');
  await page.click('#legend summary');
  await frames(page, 2);
  const heat = await page.$eval('#legend-heat', (e) => [e.querySelector('.heat-title').textContent, e.title]);
  assert.equal(heat[0], 'ポテンシャル（対数）');
  assert.deepEqual(latin(heat.join(' ').replace('LocalPathPlanning', '')), [], heat.join(' '));
  const options = await page.$$eval('#scenario option', (os) => os.filter((o) => o.value).map((o) => [o.value, o.textContent]));
  assert.ok(options.length >= 10);
  for (const [name, title] of options) {
    assert.notEqual(title, name.replaceAll('_', ' '), `${name} has a Japanese title`);
  }
  assert.equal(options.find(([n]) => n === 'open_field')[1], '校庭');
  assert.equal(await page.textContent('#about-title'), 'このシナリオについて：校庭');
  assert.equal(await page.$eval('#compare-title', (e) => getComputedStyle(e).textTransform), 'none');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a notice lets clicks through to the map, keeps its button, and keeps off the goal', { timeout: 60_000 }, async () => {
  const { page, problems } = await openPage(browser.context, '?lang=en');
  await page.evaluate(() => window.rtnav.app.notice.show('A notice over the map', 'warn'));
  await frames(page, 2);
  const box = await page.$eval('#notice-text', (e) => { const r = e.getBoundingClientRect(); return [r.left + r.width / 2, r.top + r.height / 2]; });
  assert.equal(await page.evaluate(([x, y]) => document.elementFromPoint(x, y)?.id, box), 'overlay', 'the map is under the notice\'s text');
  // A click on it is a click on the map: a goal there (set, or refused with the reason).
  await page.mouse.click(box[0], box[1]);
  await page.waitForFunction(() => /goal/i.test(document.getElementById('notice-text').textContent), null, WAIT);
  // Its button still takes a click.
  await page.evaluate(() => window.rtnav.app.notice.show('Another notice', 'error'));
  await frames(page, 2);
  await page.click('#notice-close');
  assert.equal(await page.isVisible('#notice'), false);
  // The robot placed halfway up the map's left edge (under neither place of the notice), and
  // a goal where the notice would be (a free cell well clear of obstacles under its place at
  // the top): the notice goes to the bottom, off the goal.
  const top = await page.evaluate(() => {
    const { demo } = window.rtnav;
    const n = document.getElementById('notice');
    n.hidden = false;
    delete n.dataset.place;
    const r = n.getBoundingClientRect();
    n.hidden = true;
    const c = document.getElementById('overlay');
    const o = c.getBoundingClientRect();
    const m = JSON.parse(demo.map_json());
    const free = (x, y) => JSON.parse(demo.inspect_cell(x, y)).obstacle_distance > 1.2;
    const centre = (x, y) => [m.origin[0] + (x + 0.5) * m.grid_size, m.origin[1] + (y + 0.5) * m.grid_size];
    const client = ([wx, wy]) => {
      const [px, py] = demo.world_to_pixel(wx, wy);
      return [o.left + (px * o.width) / c.width, o.top + (py * o.height) / c.height];
    };
    const mid = Math.floor(m.height / 2);
    const sx = [...Array(m.width).keys()].find((x) => free(x, mid));
    const goal = JSON.parse(demo.plan_json()).goal;
    const [wx, wy] = centre(sx, mid);
    demo.set_position(wx, wy, 0, goal.x, goal.y, goal.theta_deg, false);
    for (let y = m.height - 1; y >= 0; y--) {
      for (let x = 0; x < m.width; x++) {
        const [cx, cy] = client(centre(x, y));
        if (cx < r.left + 30 || cx > r.right - 30 || cy < r.top + 5 || cy > r.bottom - 5) continue;
        if (free(x, y)) return [cx, cy];
      }
    }
    return null;
  });
  assert.ok(top, 'a free cell under the notice');
  await page.click('#tool-goal');
  await page.mouse.click(top[0], top[1]);
  // The goal's notice, at the bottom, off the new goal.
  await until(page, 'the goal\'s notice at the bottom, off the goal', () => {
    const n = document.getElementById('notice');
    const box = n.getBoundingClientRect();
    const goal = window.rtnav.app.stage.keepClear().at(-1);
    const off = Boolean(goal) && (box.bottom <= goal.top || box.top >= goal.bottom || box.right <= goal.left || box.left >= goal.right);
    return { ok: !n.hidden && n.dataset.place === 'bottom' && off, shown: `the notice "${n.textContent.trim()}" ${n.hidden ? 'hidden' : `at the ${n.dataset.place}`}, ${JSON.stringify(box)}, the goal at ${JSON.stringify(goal)}` };
  });
  assert.deepEqual(problems, []);
  await page.close();
});

test('a notice that would cover the goal at the top and the robot at the bottom keeps to a side', { timeout: 60_000 }, async () => {
  const { page, problems } = await openPage(browser.context, '?lang=ja');
  // The doorway exercise: its goal is in the far room under the notice's place at the top,
  // the robot under its place at the bottom; planning fails, and the notice says so.
  await page.selectOption('#scenario', 'ex_door_dmin');
  await page.waitForFunction(() => window.rtnav.scenarios.current === 'ex_door_dmin', null, WAIT);
  await page.waitForSelector('#notice:not([hidden])', WAIT);
  await until(page, 'the notice off the robot and the goal', () => {
    const n = document.getElementById('notice');
    const box = n.getBoundingClientRect();
    const clear = window.rtnav.app.stage.keepClear();
    const covered = clear.filter((c) => !(box.bottom <= c.top || box.top >= c.bottom || box.right <= c.left || box.left >= c.right));
    return { ok: !n.hidden && clear.length === 2 && covered.length === 0, shown: `the notice ${n.hidden ? 'hidden' : `at ${n.dataset.place} ${n.dataset.align}`} ${JSON.stringify(box)}, ${clear.length} boxes to keep clear, covering ${JSON.stringify(covered)}` };
  });
  assert.deepEqual(problems, []);
  await page.close();
});

test('one column below 1080 px and two above; the cards keep their style', { timeout: 60_000 }, async () => {
  for (const [width, columns] of [[1280, 2], [1100, 2], [1040, 1], [900, 1], [768, 1]]) {
    const { page, problems } = await openPage(browser.context, '?lang=ja');
    await page.setViewportSize({ width, height: 800 });
    await frames(page, 3);
    const [stage, panels, bg] = await page.evaluate(() => [
      document.querySelector('.stage').getBoundingClientRect().toJSON(),
      document.getElementById('panels').getBoundingClientRect().toJSON(),
      getComputedStyle(document.querySelector('.stage')).backgroundColor,
    ]);
    assert.equal(panels.top >= stage.bottom ? 1 : 2, columns, `${width} px`);
    assert.equal(bg, 'rgb(255, 255, 255)', `the stage is a card at ${width} px`);
    if (columns === 2) {
      // The toolbar keeps to one line beside the panels.
      const rows = await page.$$eval('#toolbar > *:not(.spacer)', (es) => new Set(es.filter((e) => e.offsetParent).map((e) => Math.round(e.getBoundingClientRect().top))).size);
      assert.equal(rows, 1, `the toolbar at ${width} px`);
    }
    assert.deepEqual(problems, []);
    await page.close();
  }
});

test('at 390 px no parameter name is cut off', { timeout: 60_000 }, async () => {
  const phone = await launch({ viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true, deviceScaleFactor: 2 });
  try {
    for (const lang of ['en', 'ja']) {
      const { page, problems } = await openPage(phone.context, `?lang=${lang}`);
      await showTab(page, 'params');
      const cut = await page.evaluate(() => {
        for (const d of document.querySelectorAll('#params-panel details')) d.open = true;
        return [...document.querySelectorAll('.param-name')]
          .filter((e) => e.scrollWidth > e.clientWidth + 1 || getComputedStyle(e).textOverflow === 'ellipsis' && getComputedStyle(e).overflow === 'hidden')
          .map((e) => e.textContent);
      });
      assert.deepEqual(cut, [], lang);
      assert.deepEqual(problems, []);
      await page.close();
    }
  } finally {
    await phone.close();
  }
});

test('one wording for the clock button; no "-0"; no repeated inspector row; a tap with the Pan tool inspects', { timeout: 90_000 }, async () => {
  const phone = await launch({ viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true, deviceScaleFactor: 2 });
  try {
    const { page, problems } = await openPage(phone.context, '?lang=en');
    const bothSay = (word) => until(page, `the system bar's and the timeline's clock buttons to say "${word}"`, (w) => {
      const said = [document.getElementById('pause').textContent, document.getElementById('tl-play').textContent];
      return { ok: said[0] === w && said[1] === w, shown: JSON.stringify(said) };
    }, word);
    await page.click('#pause');
    await bothSay('Run');
    await page.click('#pause');
    await bothSay('Pause');

    // Numbers that round to zero are 0.
    const zeros = await page.evaluate(async () => {
      const { fixed, num } = await import('./js/i18n.js');
      return [fixed(-0.001, 2), fixed(-0, 0), fixed(-0.4, 0), num(-0.0001, 2), num(-0, 3), fixed(-0.5, 2)];
    });
    assert.deepEqual(zeros, ['0.00', '0', '0', '0', '0', '-0.50']);
    const shown = await page.$$eval('#telemetry dd', (dds) => dds.map((d) => d.textContent).join(' | '));
    assert.doesNotMatch(shown, /(^|[^\d.])-0(\.0+)?(?!\.?\d*[1-9])/, shown);

    // The inspector: each row says something no other row says.
    await showTab(page, 'inspector');
    const rows = await page.$$eval('#inspector .inspect-row', (rs) => rs.map((r) => r.dataset.key));
    assert.ok(!rows.includes('unreached'), `the field state already says whether a cell was reached: ${rows}`);
    assert.equal(new Set(rows).size, rows.length);

    // With the Pan tool, a tap (a finger: no hover) inspects the cell under it.
    await page.click('#tool-pan');
    const cell = [130, 90];
    await page.evaluate(() => window.scrollTo(0, 0));
    const [x, y] = await cellToPage(page, cell);
    await page.touchscreen.tap(x, y);
    await page.waitForSelector(`#inspector-panel[data-cell="${cell[0]},${cell[1]}"]`, { state: 'attached', ...WAIT });
    assert.deepEqual(problems, []);
    await page.close();
  } finally {
    await phone.close();
  }
});
