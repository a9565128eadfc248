// End-to-end: an exercise done in the page — its checklist live, its verdict at
// the end, the same as `rtnav check` gives for the same configuration — and the page in
// Japanese: chosen from the browser's language, kept in local storage, carried by share
// links; at 1280×800, 768×1024 and 390×844 no English left (apart from names: RT-components, ports,
// parameters, services, states, units) and nothing overlapping. Screenshots of the verdict
// and of the Japanese page go to docs/ (UPDATE_SCREENSHOTS=1).
import { test, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFile } from 'node:child_process';
import { promisify } from 'node:util';
import { WAIT, DRIVE, REPO, launch, openPage, screenshot, showTab, frames, layoutProblems, setParam } from './helpers.mjs';

const run = promisify(execFile);
const browsers = [];
after(async () => {
  for (const b of browsers) await b.close();
});
async function browser(options = {}) {
  const b = await launch(options);
  browsers.push(b);
  return b;
}

/** Sets the parameter in the Parameters tab, then goes back to the RT-components tab. */
async function setParamThenBack(page, component, name, value) {
  await setParam(page, component, name, value);
  await showTab(page, 'rtc');
}
async function pick(page, name) {
  await page.selectOption('#scenario', name);
  await page.waitForFunction((n) => window.rtnav.scenarios.current === n, name, WAIT);
  await page.waitForSelector('#exercise:not([hidden]) .exercise-verdict[data-verdict="waiting"]', WAIT);
}
const checklist = (page) => page.$$eval('#exercise .exercise-check', (items) => items.map((i) => ({
  check: i.dataset.check, state: i.dataset.state, text: i.querySelector('.exercise-text').textContent,
})));
async function drive(page) {
  await page.selectOption('#speed', '16');
  await page.click('#activate-all');
  await page.waitForSelector('#exercise .exercise-verdict:not([data-verdict="waiting"])', WAIT);
  await page.waitForSelector('#exercise .exercise-verdict:is([data-verdict="passed"], [data-verdict="failed"])', DRIVE);
  await frames(page, 2);
  return page.$eval('#exercise .exercise-verdict', (v) => v.dataset.verdict);
}

test('an exercise done in the page: the live checklist, then the verdict; the same as rtnav check', { timeout: 480_000 }, async () => {
  const { context } = await browser();
  const { page, problems } = await openPage(context, '?lang=en');
  await pick(page, 'ex_backward_dock');
  const before = await checklist(page);
  assert.deepEqual(before.map((c) => c.check), ['arrived', 'no_bump', 'backward_distance', 'only_allowed', 'no_warning']);
  assert.deepEqual(before.map((c) => c.state), ['open', 'open', 'open', 'passed', 'passed']);
  assert.match(before[2].text, /at least 1 m backward/);
  assert.match(await page.textContent('#exercise .exercise-task'), /Dock backward/);

  // Done wrong first: TargetArea as the scenario has it.
  assert.equal(await drive(page), 'failed');
  const wrong = await checklist(page);
  assert.equal(wrong.find((c) => c.check === 'backward_distance').state, 'failed', JSON.stringify(wrong));

  // Then right: TargetArea 2 m, the dock within it.
  await pick(page, 'ex_backward_dock');
  await setParamThenBack(page, 'LocalPathPlanning', 'TargetArea', 2);
  // A parameter the exercise does not name shows at once, and can be put back.
  await setParamThenBack(page, 'DriveControl', 'MaxVelocity', 0.4);
  await page.waitForSelector('#exercise .exercise-check[data-check="only_allowed"][data-state="failed"]', WAIT);
  assert.match(await page.textContent('#exercise .exercise-check[data-check="only_allowed"]'), /DriveControl\.MaxVelocity/);
  await setParamThenBack(page, 'DriveControl', 'MaxVelocity', 0.5);
  await page.waitForSelector('#exercise .exercise-check[data-check="only_allowed"][data-state="passed"]', WAIT);
  assert.equal(await drive(page), 'passed');
  const right = await checklist(page);
  assert.deepEqual(right.map((c) => c.state), ['passed', 'passed', 'passed', 'passed', 'passed']);
  assert.match(await page.textContent('#exercise .exercise-verdict'), /^Passed: every check met/);
  await screenshot(page, 'exercise-verdict.png');

  // `rtnav check` with the same configuration gives the same verdict.
  if (process.env.RTNAV_CLI) {
    const conf = await page.evaluate(() => window.rtnav.demo.conf_export());
    const { writeFile, mkdtemp } = await import('node:fs/promises');
    const { tmpdir } = await import('node:os');
    const { join } = await import('node:path');
    const dir = await mkdtemp(join(tmpdir(), 'rtnav-check-'));
    await writeFile(join(dir, 'page.conf'), conf);
    const { stdout } = await run(process.env.RTNAV_CLI,
      ['check', 'fixtures/scenarios/ex_backward_dock.json', '--conf', join(dir, 'page.conf'), '--json'], { cwd: REPO });
    const cli = JSON.parse(stdout);
    assert.equal(cli.verdict, 'passed');
    assert.deepEqual(cli.checks.map((c) => c.state), right.map((c) => c.state));
  } else {
    console.log('rtnav check not compared: RTNAV_CLI is not set');
  }
  assert.deepEqual(problems, []);
});

/** Names that stay as they are in Japanese: components, ports, services, parameters, states, units. */
const NAMES = /\b([A-Z]{2,}\w*|\w+[a-z][A-Z]\w*|Deviatinglen|Localization\d*|rtnav|OpenINVENT|RT|RTC|MapBuilder|MapMaintenance|PhysicsSim|MotorControl|Localization|GlobalPathPlanning|LocalPathPlanning|DriveControl|[A-Z][a-z]+[A-Z]\w*|Active|Inactive|Error|Partial|dmin|A\*|PNG|CSV|conf|SLAM|ROS|MovingAI|Willow|Garage|Dragon|Age|JSON|map_server|pure|pursuit|v|ω|m|s|rad|N|kg|cells?|Inject|G|R|A|P|L|x|y|Δt|Hz|ms|D|EDT|OpenRTM|rtshell|rtinject|RH0|NaN|SetPosition|SetPDGain|MapUpdate|Clear|SafeMode|Direction|TargetArea|English)\b/g;
/** Words of three or more Latin letters left once the names are taken out. */
const english = (text) => (text.replace(/\.[a-z]{2,4}\b/g, ' ').replace(NAMES, ' ').match(/[A-Za-z]{3,}/g) ?? []);

for (const [width, height, scenario] of [[1280, 800, 'ex_fault_recovery'], [768, 1024, 'ex_door_dmin'], [390, 844, 'ex_pd_gains']]) {
  test(`the page in Japanese at ${width}×${height}: no English left, nothing overlapping`, { timeout: 180_000 }, async () => {
    // The browser's language chooses Japanese (nothing in the address, nothing kept).
    const { context } = await browser({ locale: 'ja-JP', viewport: { width, height } });
    const { page, problems } = await openPage(context);
    assert.equal(await page.evaluate(() => document.documentElement.lang), 'ja');
    await page.selectOption('#scenario', scenario);
    await page.waitForFunction((n) => window.rtnav.scenarios.current === n, scenario, WAIT);
    // The exercise panel shows the scenario's task and checklist.
    await page.waitForSelector('#exercise:not([hidden]) .exercise-verdict[data-verdict="waiting"]', WAIT);
    await frames(page, 3);
    const visible = await page.evaluate(() => {
      // What a person sees: the text of every visible element (the panels not shown are
      // hidden; the scenario picker's options are names), plus titles and labels.
      const parts = [];
      const walk = (node) => {
        for (const c of node.childNodes) {
          if (c.nodeType === Node.TEXT_NODE) {
            const p = c.parentElement;
            if (p && p.checkVisibility() && !p.closest('#scenario, option, .visually-hidden')) parts.push(c.textContent);
          } else if (c.nodeType === Node.ELEMENT_NODE) walk(c);
        }
      };
      walk(document.body);
      for (const e of document.querySelectorAll('[title], [aria-label]')) {
        if (!e.checkVisibility() || e.closest('#scenario')) continue;
        parts.push(e.getAttribute('title') ?? '', e.getAttribute('aria-label') ?? '');
      }
      return parts.join('\n');
    });
    const left = english(visible.replaceAll(scenario, ' ').replaceAll(scenario.replaceAll('_', ' '), ' '));
    assert.deepEqual(left, [], `English left on the Japanese page: ${left.join(', ')}`);
    assert.match(visible, /演習/);
    assert.match(visible, /やってみよう/);
    await page.evaluate(() => window.rtnav.app.notice.hide());
    assert.deepEqual(await page.evaluate(layoutProblems), [], `${width}×${height}`);
    await screenshot(page, `page-ja-${width}x${height}.png`, { fullPage: width < 1000 });
    assert.deepEqual(problems, []);
  });
}

test('the choice is kept in local storage and goes into the share link', { timeout: 120_000 }, async () => {
  const { context } = await browser({ locale: 'ja-JP' });
  const { page } = await openPage(context);
  assert.equal(await page.evaluate(() => document.documentElement.lang), 'ja');
  // English chosen: the page reloads in English and keeps the choice.
  await Promise.all([page.waitForNavigation(), page.selectOption('#language', 'en')]);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 60_000 });
  assert.equal(await page.evaluate(() => document.documentElement.lang), 'en');
  assert.equal(await page.evaluate(() => localStorage.getItem('rtnav.lang')), 'en');
  await page.goto(page.url().split('?')[0]);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 60_000 });
  assert.equal(await page.evaluate(() => document.documentElement.lang), 'en', 'kept over the browser\'s language');
  assert.equal(await page.textContent('#activate-all'), 'Activate all');
  // Back to Japanese; a share link carries it.
  await Promise.all([page.waitForNavigation(), page.selectOption('#language', 'ja')]);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 60_000 });
  assert.equal(await page.textContent('#activate-all'), 'すべてアクティブ化');
  await page.click('#share-copy');
  await page.waitForSelector('#share-link:not([hidden])', WAIT);
  const link = await page.inputValue('#share-link');
  assert.match(link, /[?&]lang=ja&share=/);
  await page.close();
  // Opened in a browser that chose English, the link shows Japanese.
  const en = await browser({ locale: 'en-GB' });
  const { page: other } = await openPage(en.context, `?${link.split('?')[1]}`);
  assert.equal(await other.evaluate(() => document.documentElement.lang), 'ja');
  assert.equal(await other.textContent('#activate-all'), 'すべてアクティブ化');
});
