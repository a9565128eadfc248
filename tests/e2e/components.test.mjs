// End-to-end: Debian's Chromium (driven by playwright-core, never a downloaded browser)
// against the page served by `cargo xtask test` at $RTNAV_URL.
//
// Proves, through the page's own buttons: the lifecycle of SPEC §1 (Inactive → Active →
// Inactive → Active → Error with its reason → Inactive → Active), the RT System Editor's
// colours, refused requests and values shown as errors, and a Rust panic shown as a crash
// instead of a frozen tab.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtemp, mkdir, rm, copyFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const URL = process.env.RTNAV_URL ?? 'http://127.0.0.1:8080/';
const CHROMIUM = process.env.RTNAV_CHROMIUM ?? '/usr/bin/chromium';
const HERE = dirname(fileURLToPath(import.meta.url));
const REPO = join(HERE, '..', '..');
const ARGS = [
  '--headless',
  '--no-sandbox',
  '--disable-gpu',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
  '--disable-quic',
];
const WAIT = { timeout: 15_000 };
const COLOURS = { Inactive: 'rgb(0, 0, 255)', Active: 'rgb(0, 255, 0)', Error: 'rgb(255, 0, 0)' };

let profile;
let context;

before(async () => {
  profile = await mkdtemp(join(tmpdir(), 'rtnav-e2e-profile-'));
  context = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM,
    headless: true,
    args: ARGS,
    viewport: { width: 1200, height: 720 },
  });
});

after(async () => {
  await context?.close();
  if (profile) await rm(profile, { recursive: true, force: true });
});

/** A fresh page, loaded and ready; `problems` collects page errors and console errors. */
async function open() {
  const page = await context.newPage();
  const problems = [];
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  page.on('console', (m) => {
    if (m.type() === 'error') problems.push(`console.error: ${m.text()}`);
  });
  await page.goto(URL, { waitUntil: 'domcontentloaded', timeout: 60_000 });
  // Ready, or the page's own crash report (then say why).
  await page.waitForSelector('body[data-ready="true"], #crash:not([hidden])', { timeout: 60_000 });
  if (await page.isVisible('#crash')) {
    assert.fail(`the page did not start: ${await page.innerText('#crash')}\n${problems.join('\n')}`);
  }
  return { page, problems };
}

/** Waits until the badge says `state`, then checks its colour. */
async function expectState(page, state) {
  await page.waitForFunction(
    (s) => document.getElementById('state')?.dataset.state === s,
    state,
    WAIT,
  );
  assert.equal(await page.textContent('#state'), state);
  const colour = await page.$eval('#state', (e) => getComputedStyle(e).backgroundColor);
  assert.equal(colour, COLOURS[state], `badge colour in ${state}`);
  const block = await page.$eval('.rtc-block', (e) => e.getAttribute('fill'));
  assert.equal(block, { Inactive: '#0000ff', Active: '#00ff00', Error: '#ff0000' }[state]);
}

const executions = async (page) => Number(await page.textContent('#executions'));

test('lifecycle through the buttons', { timeout: 180_000 }, async () => {
  const { page, problems } = await open();
  await expectState(page, 'Inactive');
  assert.equal(await page.isVisible('#reason'), false);

  await page.click('#activate');
  await expectState(page, 'Active');
  // The requestAnimationFrame loop steps simulated time: the heartbeat executes.
  await page.waitForFunction(() => Number(document.getElementById('executions').textContent) >= 3, null, WAIT);

  await page.click('#deactivate');
  await expectState(page, 'Inactive');
  const frozen = await executions(page);

  // A request the current state does not allow is refused with a clear error, and
  // changes nothing.
  const refused = await page.evaluate(() => {
    try {
      window.rtnav.host.deactivate();
      return null;
    } catch (e) {
      return e.message;
    }
  });
  assert.equal(refused, 'component `Heartbeat0`: cannot deactivate while Inactive');
  await expectState(page, 'Inactive');
  assert.equal(await executions(page), frozen);

  await page.click('#activate');
  await expectState(page, 'Active');
  await page.click('#inject-fault');
  await expectState(page, 'Error');
  assert.equal(await page.textContent('#reason'), 'Reason: injected fault: requested from the page');
  assert.equal(await page.isDisabled('#activate'), true);
  assert.equal(await page.isEnabled('#reset'), true);

  await page.click('#reset');
  await expectState(page, 'Inactive');
  assert.equal(await page.isVisible('#reason'), false);

  await page.click('#activate');
  await expectState(page, 'Active');

  const log = await page.$$eval('#events li .transition', (items) => items.map((i) => i.textContent).reverse());
  assert.deepEqual(log, [
    'Created → Inactive',
    'Inactive → Active',
    'Active → Inactive',
    'Inactive → Active',
    'Active → Error',
    'Error → Inactive',
    'Inactive → Active',
  ]);

  // An out-of-range parameter is refused; the old value stays.
  await page.fill('#param-BeatInterval', '0');
  await page.dispatchEvent('#param-BeatInterval', 'change');
  await page.waitForSelector('#config-refusal:not([hidden])', WAIT);
  assert.match(await page.textContent('#config-refusal'), /BeatInterval.*0 is out of range \[1, 1000\]/);
  assert.equal(await page.inputValue('#param-BeatInterval'), '10');
  await page.fill('#param-BeatInterval', '2');
  await page.dispatchEvent('#param-BeatInterval', 'change');
  await page.waitForSelector('#config-refusal[hidden]', { state: 'attached', ...WAIT });
  const beats = Number(await page.textContent('#beats'));
  await page.waitForFunction((b) => Number(document.getElementById('beats').textContent) >= b + 2, beats, WAIT);

  // The screenshot for the README (tests/e2e/out/; UPDATE_SCREENSHOTS=1 also writes docs/).
  await mkdir(join(HERE, 'out'), { recursive: true });
  const shot = join(HERE, 'out', 'screenshot-components.png');
  await page.evaluate(() => document.activeElement?.blur());
  await page.screenshot({ path: shot, fullPage: true });
  if (process.env.UPDATE_SCREENSHOTS === '1') {
    await mkdir(join(REPO, 'docs'), { recursive: true });
    await copyFile(shot, join(REPO, 'docs', 'screenshot-components.png'));
  }

  assert.deepEqual(problems, []);
  await page.close();
});

test('a Rust panic is shown, not a frozen tab', { timeout: 180_000 }, async () => {
  const { page, problems } = await open();
  assert.equal(await page.isVisible('#crash'), false);
  await page.evaluate(() => window.rtnav.debugPanic());
  await page.waitForSelector('#crash', { state: 'visible', ...WAIT });
  assert.equal(await page.getAttribute('body', 'data-crashed'), 'true');
  const message = await page.textContent('#crash-message');
  assert.match(message, /debug_panic: deliberate panic requested by the page/);
  assert.match(message, /wasm\/src\/lib\.rs/);
  // The panic hook also logs it to the console (console_error_panic_hook); nothing else.
  assert.ok(problems.length >= 1, 'the panic is logged');
  for (const p of problems) assert.match(p, /debug_panic/);
  await page.close();
});
