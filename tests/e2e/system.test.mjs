// End-to-end: the System tab — the RT-components, their ports and connections, as
// RT System Editor shows them, live, from the core's own description.
//
// Proves: the view lists every component and every port of seeds 000 and 002 that rtnav
// implements, each box in its state's colour; the tooltip of MotorControl's TargetVelocity
// shows a TimedVelocity whose vx changes while the robot drives; a service port shows its
// last call; the lifecycle buttons act on a selected box; cutting TargetVelocity (a logged
// request) makes MotorControl report its safe stop, and restoring it resumes the drive.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import {
  WAIT, COLOURS, launch, openPage, screenshot, showTab, activateAll, until, shownDriven, shownLogged, driven,
} from './helpers.mjs';

let browser;
before(async () => {
  browser = await launch();
});
after(async () => {
  await browser?.close();
});

/** The seeds' ports (000 §3, 002 §3) that rtnav implements: [component, port]. */
const SEED_PORTS = [
  ...['InCurrentPosition', 'InDeviating', 'InventGUIProv', 'MapBuilderProv', 'MapMaintenanceProv',
    'GlobalPathProv', 'InventGUICons', 'DriveCons', 'BumpCons'].map((p) => ['LocalPathPlanning', p]),
  ...['TargetVelocity', 'InCurrentWheelAngle', 'InSimulatedPosition', 'Torque', 'OutCurrentWheelAngle',
    'OutSimulatedPositionToInventGUI', 'OutSimulatedPositionToLocalization', 'InventGUIProvPort',
    'BumpProvPort'].map((p) => ['MotorControl', p]),
];
const COMPONENTS = ['MapBuilder', 'MapMaintenance', 'PhysicsSim', 'MotorControl', 'Localization',
  'GlobalPathPlanning', 'LocalPathPlanning', 'DriveControl'];
const TARGET_VELOCITY = 'DriveControl.TargetVelocity->MotorControl.TargetVelocity';
const row = (component, port) => `#system-diagram .sys-port-row[data-component="${component}"][data-port="${port}"]`;
const box = (component) => `#system-diagram .sys-box[data-component="${component}"]`;

/** MotorControl's status line as the System view shows it. */
const motorStatus = (page) => page.$eval(`${box('MotorControl')} .sys-status`, (e) => e.dataset.full ?? e.textContent);

test('the System view: components, seed ports, live samples, lifecycle on a box, cut and restore TargetVelocity', { timeout: 180_000 }, async () => {
  const { page, problems } = await openPage(browser.context);
  await showTab(page, 'system');
  await page.waitForSelector(row('MotorControl', 'TargetVelocity'), WAIT);

  // Every component, in the core's description and on the picture.
  const described = await page.evaluate(() => window.rtnav.system.graph().components.map((c) => c.name));
  assert.deepEqual(described, ['InventGUI', ...COMPONENTS]);
  for (const c of COMPONENTS) assert.ok(await page.$(box(c)), `${c} has a box`);
  for (const [c, p] of SEED_PORTS) assert.ok(await page.$(row(c, p)), `${c}.${p} is drawn`);
  // The lines are the description's connections.
  const lines = await page.$$eval('#system-diagram path.sys-line', (ps) => ps.map((p) => p.dataset.id));
  const connections = await page.evaluate(() => window.rtnav.system.graph().connections.map((c) => c.id));
  assert.deepEqual(lines, connections);
  assert.ok(lines.includes(TARGET_VELOCITY));

  // State colours: the planners Active (green), the robot's components Inactive (blue).
  const head = (c) => page.$eval(`${box(c)} .sys-head`, (e) => getComputedStyle(e).fill);
  await page.waitForFunction(() => document.querySelector('#system-diagram .sys-box[data-component="LocalPathPlanning"]')?.dataset.state === 'Active', null, WAIT);
  assert.equal(await head('LocalPathPlanning'), COLOURS.Active);
  assert.equal(await head('MotorControl'), COLOURS.Inactive);

  // Lifecycle on a selected box: Activate MotorControl from the picture, then Deactivate.
  await page.click(`${box('MotorControl')} .sys-title`);
  await page.waitForSelector('#system-actions[data-component="MotorControl"]', WAIT);
  await page.click('#system-actions button[data-act="activate"]');
  await page.waitForSelector(`${box('MotorControl')}[data-state="Active"]`, WAIT);
  assert.equal(await head('MotorControl'), COLOURS.Active);
  await page.click('#system-actions button[data-act="deactivate"]');
  await page.waitForSelector(`${box('MotorControl')}[data-state="Inactive"]`, WAIT);
  // Inject fault → Error (red) → Reset → Inactive.
  await page.click('#system-actions button[data-act="fault"]');
  await page.click('#system-actions button[data-act="activate"]');
  await page.waitForSelector(`${box('MotorControl')}[data-state="Error"]`, WAIT);
  assert.equal(await head('MotorControl'), COLOURS.Error);
  await page.click('#system-actions button[data-act="reset"]');
  await page.waitForSelector(`${box('MotorControl')}[data-state="Inactive"]`, WAIT);

  // A service port shows its last call: SetPosition on LocalPathPlanning's InventGUIProv.
  await page.hover(row('LocalPathPlanning', 'InventGUIProv'));
  await page.waitForSelector('#system-tip:not([hidden])', WAIT);
  const call = await page.textContent('#system-tip');
  assert.match(call, /LocalPathPlanning\.InventGUIProv · service provided · LocalPath/);
  assert.match(call, /SetPosition\(2\.5, 2\.5, 0, 23, 15\.5, 1\.571, 1\)/);

  // Drive: the tooltip of TargetVelocity shows a TimedVelocity whose vx changes.
  await activateAll(page);
  await page.selectOption('#speed', '2');
  await page.mouse.move(0, 0);
  await page.hover(row('MotorControl', 'TargetVelocity'));
  await page.waitForSelector('#system-tip:not([hidden])', WAIT);
  // The tooltip stays up under the mouse and shows each new sample: every line it shows is
  // kept (in the page, at every frame) until the samples' vx has changed.
  const tips = await until(page, 'TargetVelocity\'s tooltip to show samples whose vx changes', () => {
    const tips = window.__velocityTips ?? (window.__velocityTips = []);
    const lines = [...document.querySelectorAll('#system-tip > div')].map((d) => d.textContent);
    const last = tips.at(-1);
    if (!last || last[0] !== lines[0] || last[1] !== lines[1]) tips.push(lines);
    const samples = tips.filter(([, s]) => s && !s.includes('no sample yet'));
    const vx = new Set(samples.map(([, s]) => s.match(/vx: (-?[\d.]+)/)?.[1]));
    return { ok: samples.length >= 3 && vx.size >= 2, value: tips, shown: JSON.stringify(tips.slice(-4)) };
  }, null, { timeout: 60_000 });
  const seen = [];
  const vx = new Set();
  for (const [head, sample] of tips) {
    assert.equal(head, 'MotorControl.TargetVelocity · data in · TimedVelocity');
    // Shown before the first tick after the activation: no sample yet.
    if (seen.length === 0 && sample.includes('no sample yet')) continue;
    const m = sample.match(/^TimedVelocity \{tm: (\d+\.\d{3}) s, vx: (-?[\d.]+), vy: (-?[\d.]+), w: (-?[\d.]+)\}$/);
    assert.ok(m, `a TimedVelocity sample: ${sample}`);
    seen.push(sample);
    vx.add(m[2]);
  }
  console.log(`TargetVelocity samples seen: ${seen.length}, vx values: ${[...vx].join(', ')}`);
  assert.ok(vx.size >= 2, `vx changes while the robot drives: ${seen.join(' | ')}`);
  const times = seen.map((s) => Number(s.match(/tm: ([\d.]+)/)[1]));
  assert.ok(times.every((t, i) => i === 0 || t >= times[i - 1]) && times.at(-1) > times[0], `timestamps advance: ${times}`);

  // The page tour's picture (docs/page-tour.md): the robot under way, TargetVelocity's connections lit.
  await page.click(row('MotorControl', 'TargetVelocity'));
  await page.waitForSelector('#system-details li[data-id="DriveControl.TargetVelocity->MotorControl.TargetVelocity"]', WAIT);
  await page.hover(row('MotorControl', 'TargetVelocity'));
  await page.waitForSelector(`#system-diagram path.sys-line.hot[data-id="${TARGET_VELOCITY}"]`, { state: 'attached', ...WAIT });
  await page.waitForSelector('#system-tip:not([hidden])', WAIT);
  await screenshot(page, 'system-view.png');

  // Cut TargetVelocity: logged; MotorControl reports its safe stop.
  await page.click(`#system-details li[data-id="${TARGET_VELOCITY}"] button.cut`);
  await page.waitForSelector(`#system-diagram path.sys-line.cut[data-id="${TARGET_VELOCITY}"]`, WAIT);
  await page.waitForFunction(() => /safe stop/.test(document.querySelector('#system-diagram .sys-box[data-component="MotorControl"] .sys-status')?.dataset.full ?? ''), null, WAIT);
  const stopped = await motorStatus(page);
  assert.match(stopped, /safe stop, zero torque: .*TargetVelocity/);
  await showTab(page, 'log');
  const cuts = await shownLogged(page, 'ConnectionCut');
  assert.deepEqual(cuts, ['connection DriveControl.TargetVelocity → MotorControl.TargetVelocity cut: no sample passes']);
  await showTab(page, 'system');
  await screenshot(page, 'system-cut.png', { docs: false });

  // Restore: the drive resumes.
  await page.click(row('MotorControl', 'TargetVelocity'));
  await page.click(`#system-details li[data-id="${TARGET_VELOCITY}"] button.restore`);
  await page.waitForSelector(`#system-diagram path.sys-line[data-id="${TARGET_VELOCITY}"]:not(.cut)`, WAIT);
  await page.waitForFunction(() => /running/.test(document.querySelector('#system-diagram .sys-box[data-component="MotorControl"] .sys-status')?.textContent ?? ''), null, WAIT);
  await shownDriven(page, (await driven(page)) + 0.5);
  await showTab(page, 'log');
  assert.equal((await shownLogged(page, 'ConnectionRestored')).length, 1);
  assert.deepEqual(problems, []);
  await page.close();
});

for (const [w, h] of [[1280, 800], [768, 1024], [390, 844]]) {
  test(`the System view at ${w}×${h}: nothing cut off, every box on the picture`, { timeout: 90_000 }, async () => {
    const b = await launch({ viewport: { width: w, height: h }, ...(w < 500 ? { isMobile: true, hasTouch: true, deviceScaleFactor: 2 } : {}) });
    try {
      const { page, problems } = await openPage(b.context);
      await showTab(page, 'system');
      await page.waitForSelector(row('MotorControl', 'TargetVelocity'), WAIT);
      await activateAll(page);
      await shownDriven(page, 0.2);
      // The picture is as wide as its panel (scaled, never cut off).
      const fit = await page.evaluate(() => {
        const svg = document.querySelector('#system-diagram svg').getBoundingClientRect();
        const panel = document.querySelector('#system-panel').getBoundingClientRect();
        return { svg: svg.width, panel: panel.width, left: svg.left - panel.left, right: panel.right - svg.right };
      });
      assert.ok(fit.left >= 0 && fit.right >= 0, `inside its panel: ${JSON.stringify(fit)}`);
      // A tap on a port shows its sample (a phone has no hover).
      await page.click(row('DriveControl', 'TargetVelocity'));
      await page.waitForSelector('#system-details .system-port-sample', WAIT);
      await page.waitForFunction(() => /TimedVelocity \{tm: /.test(document.querySelector('#system-details .system-port-sample')?.textContent ?? ''), null, WAIT);
      await screenshot(page, `system-${w}x${h}.png`, { docs: false, fullPage: w < 1000 });
      assert.deepEqual(problems, []);
      await page.close();
    } finally {
      await b.close();
    }
  });
}
