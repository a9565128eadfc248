// End-to-end: the page in Japanese with everything it says — not only its labels
// but the event log's lines of every kind that happens, the refusals (a goal inside an
// obstacle, an illegal lifecycle request, a bad parameter value), the parameter warnings,
// the System tab, the inspector, the plots, the timeline, the compare view and the exercise
// panel — at 1280×800 and 390×844. After each step every visible text node and every
// `title`, `aria-label` and `placeholder` of every tab is read, and any Latin word that is
// not a name fails the test: the names are the page's own (components, instances, ports,
// interfaces, operations and parameters, read from the core's description), states, units
// and a few terms. Nothing may overlap. Screenshots of the System tab and of the event log in
// Japanese go to docs/ (UPDATE_SCREENSHOTS=1).
import { test, after } from 'node:test';
import assert from 'node:assert/strict';
import { WAIT, DRIVE, launch, openPage, screenshot, showTab, frames, layoutProblems, telemetry, mapInfo, cellToPage, solidObstacleCell, shownDriven } from './helpers.mjs';

const browsers = [];
after(async () => {
  for (const b of browsers) await b.close();
});

const TABS = ['rtc', 'system', 'params', 'inspector', 'plots', 'log'];
/** Names and terms kept as they are in Japanese, besides the page's own names. */
const TERMS = [
  // lifecycle and context states (RT System Editor's words), the seeds' requests and modes
  'Created', 'Inactive', 'Active', 'Error', 'Finalized', 'Running', 'Stopped', 'Clear', 'SafeMode',
  'SetPosition', 'SetPDGain', 'MapUpdate', 'GlobalPathCourse', 'GridSize', 'MapLengthX', 'MapLengthY', 'MapData', 'SetMap', 'PlanningFailure', 'Odometry', 'SimulatedPose',
  'InventGUI', 'GUI', 'OpenRTM', 'OpenINVENT', 'rtnav', 'rtshell', 'rtinject', 'dmin', 'Motor', 'Direction',
  'TargetArea', 'Deviatinglen', 'onExecute', 'SLAM', 'ROS', 'MovingAI', 'Willow', 'Garage', 'Dragon', 'Age',
  'JSON', 'PNG', 'CSV', 'YAML', 'EDT', 'RT', 'RTC', 'PD', 'ID', 'IIS', 'RH0', 'rh0', 'NaN', 'inf', 'English', 'Enter',
  // units
  'm', 's', 'ms', 'ns', 'rad', 'Hz', 'kg', 'N', 'KB', 'deg',
  // what this test types into a parameter
  'abc',
];

/** Names of several words (tools, places, games). */
const PHRASES = ['RT System Editor', 'Willow Garage', 'Dragon Age', 'pure pursuit'];

/** In the page: the text a person sees (visible text nodes, titles, labels, placeholders). */
function visibleText() {
  const parts = [];
  const walk = (node) => {
    for (const c of node.childNodes) {
      if (c.nodeType === Node.TEXT_NODE) {
        const p = c.parentElement;
        if (p && p.checkVisibility() && !p.closest('option, script, style')) parts.push(c.textContent);
      } else if (c.nodeType === Node.ELEMENT_NODE && c.querySelector(':scope > wbr')) {
        // A name with its line breaks marked (`Posture<wbr>Consideration<wbr>Level`) is one word.
        if (c.checkVisibility()) parts.push(c.textContent);
      } else if (c.nodeType === Node.ELEMENT_NODE) walk(c);
    }
  };
  walk(document.body);
  // SVG text (the System tab's boxes and ports) is text nodes too; titles of SVG paths are
  // what a hover shows.
  for (const e of document.querySelectorAll('[title], [aria-label], [placeholder], svg title')) {
    const host = e.tagName.toLowerCase() === 'title' ? e.parentElement : e;
    if (!host?.checkVisibility?.()) continue;
    if (e.tagName.toLowerCase() === 'title') parts.push(e.textContent);
    else parts.push(e.getAttribute('title') ?? '', e.getAttribute('aria-label') ?? '', e.getAttribute('placeholder') ?? '');
  }
  return parts.join('\n');
}

/** The page's own names: components, instances, ports, interfaces, operations, parameters, scenarios. */
async function pageNames(page) {
  return page.evaluate(() => {
    const { demo } = window.rtnav;
    const names = new Set();
    const words = (s) => String(s ?? '').split(/[^A-Za-z0-9_]+/).filter(Boolean).forEach((w) => names.add(w));
    const g = JSON.parse(demo.system_json());
    for (const c of g.components) {
      words(c.name); words(c.instance_name);
      for (const p of c.ports) { words(p.name); words(p.interface); for (const o of p.operations ?? []) words(o); }
    }
    for (const c of JSON.parse(demo.params_json())) {
      words(c.component); words(c.instance_name);
      for (const p of c.params) words(p.name);
    }
    // Scenario names, as written and as the page shows them (`ex fault recovery`).
    for (const o of document.querySelectorAll('#scenario option')) { words(o.value); o.value.split('_').forEach((w) => names.add(w)); }
    return [...names];
  });
}

/** Latin words (two letters or more) of `text` that are neither names nor terms. */
function english(text, names) {
  const allowed = new Set([...TERMS, ...names]);
  const cleaned = PHRASES.reduce((s, p) => s.replaceAll(p, ' '), text)
    .replace(/[\w.-]*\.(json|png|map|yaml|yml|conf|csv|pgm)\b/g, ' ') // file names and kinds
    .replace(/\b[0-9a-f]{8,}\b/g, ' ') // trace hashes
    .replace(/\b\d+(\.\d+)?(e[+-]?\d+)?\b/g, ' '); // numbers, 1e-7
  return [...new Set((cleaned.match(/[A-Za-z][A-Za-z0-9_]*/g) ?? [])
    .filter((w) => w.length >= 2 && !allowed.has(w) && !allowed.has(w.replace(/\d+$/, '')) && !/^on_[a-z_]+$/.test(w)))];
}

/** Opens every tab in turn and fails on English left in any; also checks the layout. */
async function checkAllTabs(page, names, where) {
  for (const tab of TABS) {
    await showTab(page, tab);
    if (tab === 'system') await page.waitForSelector('#system-diagram .sys-box[data-component="DriveControl"]', WAIT);
    await frames(page, 3);
    if (tab === 'inspector') {
      // A cell under the mouse, so the inspector shows its rows.
      const m = await mapInfo(page);
      await page.$eval('#overlay', (c) => c.scrollIntoView({ block: 'center' }));
      const [x, y] = await cellToPage(page, [Math.floor(m.width / 2), Math.floor(m.height / 2)]);
      await page.mouse.move(x, y);
      await page.waitForSelector('#inspector-panel[data-cell]', WAIT);
      await frames(page, 2);
    }
    const text = await page.evaluate(visibleText);
    const left = english(text, names);
    const context = text.split('\n').filter((l) => left.some((w) => new RegExp(`\\b${w}\\b`).test(l))).slice(0, 8);
    assert.deepEqual(left, [], `${where}, tab ${tab}: English left on the Japanese page: ${left.join(', ')}\n${context.join('\n')}`);
  }
  await page.evaluate(() => window.rtnav.app.notice.hide());
  const problems = await page.evaluate(layoutProblems);
  assert.deepEqual(problems, [], `${where}: layout`);
}

/** Waits for a log entry of `kind`; returns its text. */
async function waitLogged(page, kind, timeout = 90_000) {
  await page.waitForSelector(`#events li[data-kind="${kind}"]`, { state: 'attached', timeout });
  return page.$eval(`#events li[data-kind="${kind}"] .text`, (e) => e.textContent);
}

/** The log's entries: [kind, text]. */
const logLines = (page) => page.$$eval('#events li', (items) => items.map((i) => [i.dataset.kind, i.querySelector('.text').textContent]));

/**
 * The core's events in the log said through the English catalogue, from their kinds and
 * fields: [kind, what it said] for those it cannot say (no key, or a placeholder left
 * unfilled). The core hands events over as data; the catalogues are their only words.
 */
const unsaidEvents = (page) => page.evaluate(async () => {
  const { sayer } = await import('./js/say.js');
  const { fill, englishWords } = await import('./js/i18n.js');
  const words = englishWords();
  const english = sayer((key, vars) => fill(words[key] ?? key, vars), (key) => key in words);
  const out = [];
  let said = 0;
  for (const li of document.querySelectorAll('#events li')) {
    const e = li.rtnavEvent;
    if (!e || e.kind === 'Page') continue;
    said++;
    const text = english.eventText(e);
    if (!text || text.startsWith('event.') || /\{[\w.]+(?::[\w.]+)?\}/.test(text)) out.push([e.kind, text]);
  }
  // Nothing said is a broken check, not a pass.
  if (said < 3) out.push(['none', `only ${said} events said`]);
  return out;
});

/** A goal dropped inside an obstacle, through the goal tool: refused. */
async function refusedGoal(page) {
  const cell = await solidObstacleCell(page, 1);
  assert.ok(cell, 'the map has a solid obstacle');
  await page.click('#tool-goal');
  await page.$eval('#overlay', (c) => c.scrollIntoView({ block: 'center' }));
  const [x, y] = await cellToPage(page, cell);
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x + 20, y - 20, { steps: 3 });
  await page.mouse.up();
  await page.waitForSelector('#notice[data-level="error"]:not([hidden])', WAIT);
  const notice = await page.textContent('#notice-text');
  assert.match(notice, /目標/, notice);
  await page.click('#tool-pan');
  return notice;
}

/** A lifecycle request the state does not allow (Reset while Inactive), from the System tab. */
async function illegalLifecycle(page, component) {
  await showTab(page, 'system');
  await page.click(`#system-diagram .sys-box[data-component="${component}"] .sys-title`);
  await page.waitForSelector(`#system-actions[data-component="${component}"]`, WAIT);
  // The button is disabled in this state: a request the core refuses all the same.
  await page.$eval('#system-actions button[data-act="reset"]', (b) => { b.disabled = false; b.click(); });
  await page.waitForSelector('#notice[data-level="error"]:not([hidden])', WAIT);
  const notice = await page.textContent('#notice-text');
  assert.match(notice, /できません/, notice);
  return notice;
}

/** Parameter values refused: not a number, and out of range. */
async function badParameters(page) {
  await showTab(page, 'params');
  const row = '#params-panel .param[data-component="DriveControl"][data-name="MaxVelocity"]';
  await page.waitForSelector(`${row} input`, WAIT);
  const texts = [];
  for (const value of ['abc', '-5']) {
    await page.fill(`${row} input`, value);
    await page.press(`${row} input`, 'Enter');
    await page.waitForSelector(`${row} .param-error:not([hidden])`, WAIT);
    texts.push(await page.textContent(`${row} .param-error`));
  }
  assert.match(texts[0], /MaxVelocity/, texts[0]);
  assert.notEqual(texts[0], texts[1]);
  // A warning beside a parameter: dmin so small the body can touch obstacles.
  const dmin = '#params-panel .param[data-component="LocalPathPlanning"][data-name="dmin"]';
  const kept = await page.$eval(dmin, (e) => e.dataset.value);
  await page.fill(`${dmin} input`, '0.2');
  await page.press(`${dmin} input`, 'Enter');
  await page.waitForSelector(`${dmin} .param-warning:not([hidden])`, WAIT);
  const warning = await page.textContent(`${dmin} .param-warning`);
  assert.match(warning, /radiusOfBodyArea/, warning);
  await page.fill(`${dmin} input`, kept);
  await page.press(`${dmin} input`, 'Enter');
  await page.waitForSelector(`${dmin}[data-value="${kept}"]`, { state: 'attached', ...WAIT });
  return [...texts, warning];
}

async function pick(page, name) {
  await page.selectOption('#scenario', name);
  await page.waitForFunction((n) => window.rtnav.scenarios.current === n, name, WAIT);
  await frames(page, 2);
}

for (const [width, height] of [[1280, 800], [390, 844]]) {
  test(`the page in Japanese at ${width}×${height}: every tab, every event and refusal said in Japanese, nothing overlapping`, { timeout: 600_000 }, async () => {
    const b = await launch({ locale: 'ja-JP', viewport: { width, height } });
    browsers.push(b);
    const { page, problems } = await openPage(b.context, '?lang=ja');
    assert.equal(await page.evaluate(() => document.documentElement.lang), 'ja');
    const names = await pageNames(page);
    const seen = {};

    // A planning failure: the storeroom's goal cannot be reached.
    await pick(page, 'unreachable');
    await page.click('#activate-all');
    seen.planning = await waitLogged(page, 'PlanningFailed');
    assert.match(seen.planning, /経路計画に失敗/, seen.planning);
    await checkAllTabs(page, names, `${width}×${height}, unreachable`);
    const planningLines = await logLines(page);
    assert.deepEqual(await unsaidEvents(page), [], 'the English catalogue says every event');

    // The exercise with a fault injected mid-drive, and everything else on the way.
    await pick(page, 'ex_fault_recovery');
    await page.waitForSelector('#exercise:not([hidden])', WAIT);
    seen.goal = await refusedGoal(page);
    seen.lifecycle = await illegalLifecycle(page, 'DriveControl');
    seen.params = await badParameters(page);
    await showTab(page, 'rtc');
    await page.selectOption('#speed', '16');
    await page.click('#activate-all');
    // The scenario's timeline injects a fault into DriveControl after 8 s: Error.
    seen.fault = await waitLogged(page, 'FaultInjected');
    await page.waitForSelector('#components li[data-component="DriveControl"][data-state="Error"]', { timeout: 90_000 });
    seen.componentError = await waitLogged(page, 'ComponentError');
    await checkAllTabs(page, names, `${width}×${height}, a fault`);
    // Reset and Activate, then the robot arrives.
    await showTab(page, 'rtc');
    await page.click('#components li[data-component="DriveControl"] button.act');
    await page.waitForSelector('#components li[data-component="DriveControl"][data-state="Inactive"]', WAIT);
    await page.click('#components li[data-component="DriveControl"] button.act');
    seen.arrived = await waitLogged(page, 'Arrived', DRIVE.timeout);
    await page.waitForSelector('#exercise .exercise-verdict:is([data-verdict="passed"], [data-verdict="failed"])', DRIVE);
    await checkAllTabs(page, names, `${width}×${height}, arrived`);
    const lines = [...planningLines, ...await logLines(page)];
    assert.deepEqual(await unsaidEvents(page), [], 'the English catalogue says every event');

    // The compare view (at the width that shows it beside the page).
    if (width >= 1000) {
      await showTab(page, 'params');
      await page.click('#compare-form summary');
      await page.selectOption('#compare-param', 'LocalPathPlanning/PostureConsiderationLevel');
      await page.fill('#compare-value', '0');
      await page.click('#compare-run');
      await page.waitForSelector('#compare-view:not([hidden]) #compare-table tr', { timeout: 120_000 });
      const left = english(await page.evaluate(visibleText), names);
      assert.deepEqual(left, [], `compare view: English left: ${left.join(', ')}`);
      await page.click('#compare-close');
    }

    // A fault injected from the page into a component that is Active, and an obstacle
    // painted where the driving robot is: refused, in Japanese (spec §5 Decision 0.4).
    await pick(page, 'open_field');
    await page.selectOption('#speed', '1');
    await page.click('#activate-all');
    await page.waitForSelector('#system-state[data-state="Active"]', WAIT);
    await shownDriven(page, 0.3);
    // Paused while the obstacle is painted on the robot (a slow machine must not let it drive
    // off first).
    await page.click('#pause');
    await page.waitForFunction(() => window.rtnav.demo.paused(), null, WAIT);
    const t = await telemetry(page);
    const m = await mapInfo(page);
    const at = [Math.floor((t.pose.x - m.origin[0]) / m.grid_size), Math.floor((t.pose.y - m.origin[1]) / m.grid_size)];
    await page.click('#tool-paint');
    await page.selectOption('#brush', '5');
    await page.$eval('#overlay', (c) => c.scrollIntoView({ block: 'center' }));
    const [px, py] = await cellToPage(page, at);
    await page.mouse.click(px, py);
    await page.waitForSelector('#notice[data-level="error"]:not([hidden])', WAIT);
    seen.underRobot = await page.textContent('#notice-text');
    assert.match(seen.underRobot, /車体の下/, seen.underRobot);
    assert.deepEqual(english(seen.underRobot, names), [], seen.underRobot);
    await page.click('#tool-pan');
    await page.click('#pause');
    await showTab(page, 'rtc');
    await page.click('#components li[data-component="LocalPathPlanning"] button.fault');
    await page.waitForSelector('#components li[data-component="LocalPathPlanning"][data-state="Error"]', WAIT);
    await checkAllTabs(page, names, `${width}×${height}, painted on the robot`);
    lines.push(...await logLines(page));
    assert.deepEqual(await unsaidEvents(page), [], 'the English catalogue says every event');

    // Every kind that happened is said in Japanese in the log (no line as the core wrote it).
    await showTab(page, 'log');
    const kinds = new Set(lines.map(([k]) => k));
    for (const k of ['PlanningFailed', 'FaultInjected', 'ComponentError', 'StateChanged', 'Arrived', 'GlobalPlan', 'LocalPlanSent', 'GoalSet', 'ParameterSet', 'Page']) {
      assert.ok(kinds.has(k), `the log has a ${k} line: ${[...kinds].join(', ')}`);
    }
    // Lines made of names and numbers only (a parameter set, SetPDGain) have no Japanese to say.
    const NAMES_ONLY = new Set(['ParameterSet', 'GainsSet', 'StateChanged']);
    for (const [kind, text] of lines) {
      assert.deepEqual(english(text, names), [], `a ${kind} line in Japanese: ${text}`);
      if (!NAMES_ONLY.has(kind)) assert.match(text, /[ぁ-んァ-ヶ一-龠]/, `a ${kind} line in Japanese: ${text}`);
    }
    await page.evaluate(() => window.rtnav.app.notice.hide());
    await screenshot(page, `page-ja-log-${width}x${height}.png`, { fullPage: width < 1000 });
    await showTab(page, 'system');
    await page.click('#system-diagram .sys-box[data-component="DriveControl"] .sys-title');
    // The tab from its top: its title, legend and hint, the selected box's actions.
    await page.evaluate(() => {
      for (let e = document.getElementById('system-panel'); e; e = e.parentElement) e.scrollTop = 0;
      if (window.innerWidth >= 1000) window.scrollTo(0, 0);
    });
    await frames(page, 3);
    await screenshot(page, `page-ja-system-${width}x${height}.png`, { fullPage: width < 1000 });
    console.log(JSON.stringify(seen, null, 1));
    assert.deepEqual(problems, []);
  });
}
