// End-to-end: an exercise retried as a student would, without reloading the page — a wrong
// dmin typed into the Parameters tab fails ex_door_dmin; Restart (the exercise panel's
// button, and once Shift+R in the middle of a drive) starts the scenario again as loaded,
// the typed value kept, the clock running, the checklist cleared; the right value then
// passes. And the timeline taken back to 0 with Activate all pressed there: the exercise
// panel says the clock is paused, as the status does, until Run.
import { test, after } from 'node:test';
import assert from 'node:assert/strict';
import { WAIT, DRIVE, launch, openPage, showTab, until, frames, setParam } from './helpers.mjs';

const browsers = [];
after(async () => {
  for (const b of browsers) await b.close();
});



/** Waits until the exercise's verdict reads `verdict` (`data-verdict`); returns its text. */
function verdictShown(page, verdict, options = WAIT) {
  return until(page, `the exercise's verdict to be ${verdict}`, (v) => {
    const e = document.querySelector('#exercise .exercise-verdict');
    return { ok: e?.dataset.verdict === v, value: e?.textContent, shown: `${e?.dataset.verdict}: ${e?.textContent}` };
  }, verdict, options);
}

/**
 * Waits until the page shows a restarted run: the verdict waiting, every check but the rules
 * on parameters (only_allowed, no_warning) open with nothing measured, the clock running from near 0; then, once the
 * Parameters tab has read the restarted system, that it shows `dmin` as typed.
 */
async function restartedShown(page, dmin) {
  await until(page, 'a restarted run', () => {
    const verdict = document.querySelector('#exercise .exercise-verdict');
    const checks = [...document.querySelectorAll('#exercise .exercise-check')];
    const open = checks.filter((c) => c.dataset.check !== 'only_allowed' && c.dataset.check !== 'no_warning');
    const cleared = open.length > 0 && open.every((c) => c.dataset.state === 'open'
      && c.querySelector('.exercise-measured').textContent === '');
    const time = parseFloat(document.getElementById('sim-time').textContent);
    const running = document.getElementById('pause').dataset.paused === 'false';
    const ok = verdict.dataset.verdict === 'waiting' && verdict.dataset.paused === 'false'
      && cleared && time < 20 && running;
    return {
      ok,
      value: time,
      shown: `verdict ${verdict.dataset.verdict} (paused ${verdict.dataset.paused}), checks ${checks.map((c) => `${c.dataset.check}=${c.dataset.state}`).join(' ')}, clock ${time} s${running ? '' : ' paused'}`,
    };
  });
  // The panels read the new system in the frames after the restart.
  await frames(page, 3);
  await until(page, `the Parameters tab to show dmin ${dmin}`, (want) => {
    const value = document.querySelector('#params-panel .param[data-component="LocalPathPlanning"][data-name="dmin"]')?.dataset.value;
    return { ok: value === want, shown: `dmin ${value}` };
  }, String(dmin));
}

test('an exercise failed, restarted by the button and by Shift+R, then passed with the right value, without reloading', { timeout: 600_000 }, async () => {
  const b = await launch();
  browsers.push(b);
  const { page, problems } = await openPage(b.context, '?lang=en');
  let navigations = 0;
  page.on('framenavigated', (f) => { if (f === page.mainFrame()) navigations += 1; });
  await page.selectOption('#scenario', 'ex_door_dmin');
  await verdictShown(page, 'waiting');
  await page.selectOption('#speed', '16');

  // Wrong: dmin 0.7 m, more than half the 1.2 m door.
  await setParam(page, 'LocalPathPlanning', 'dmin', 0.7);
  await page.click('#activate-all');
  await verdictShown(page, 'failed', DRIVE);
  await page.waitForSelector('#exercise .exercise-check[data-check="arrived"][data-state="failed"]', WAIT);

  // Restart by the button: the same value, the run from the start, nothing decided.
  const button = await page.$('#exercise-restart');
  assert.match(await button.getAttribute('title'), /Shift\+R/);
  await page.click('#exercise-restart');
  await restartedShown(page, '0.7');
  assert.match(await page.textContent('#exercise .exercise-verdict'), /^Waiting/);

  // A drive started again, and restarted in its middle by Shift+R. With no route through the
  // door the verdict is decided at once (spec §7 Decision 0.4), and says why.
  await page.click('#activate-all');
  const decided = await verdictShown(page, 'failed');
  assert.match(decided, /^Failed unless something changes: .+ cannot pass while there is no route to the goal\.$/);
  await page.keyboard.press('Shift+R');
  await restartedShown(page, '0.7');

  // Right: 0.55 m, below half the door, above the body's reach.
  await setParam(page, 'LocalPathPlanning', 'dmin', 0.55);
  await page.click('#activate-all');
  const text = await verdictShown(page, 'passed', DRIVE);
  assert.match(text, /^Passed: every check met/);
  const states = await page.$$eval('#exercise .exercise-check', (items) => items.map((i) => i.dataset.state));
  assert.deepEqual(states, ['passed', 'passed', 'passed', 'passed', 'passed']);
  assert.equal(navigations, 0, 'the page was not reloaded');
  assert.deepEqual(problems, []);
});

test('back at 0 on the timeline, Activate all: the exercise panel says the clock is paused, as the status does', { timeout: 180_000 }, async () => {
  const b = await launch();
  browsers.push(b);
  const { page, problems } = await openPage(b.context, '?lang=en');
  await page.selectOption('#scenario', 'ex_door_dmin');
  await verdictShown(page, 'waiting');
  await setParam(page, 'LocalPathPlanning', 'dmin', 0.55);
  await page.click('#activate-all');
  await until(page, 'the drive a second on', () => {
    const t = parseFloat(document.getElementById('sim-time').textContent);
    return { ok: t > 1, shown: `the clock at ${t}` };
  });
  // The slider to its start (Home), as a person would with the keyboard: the clock pauses.
  await page.focus('#tl-slider');
  await page.keyboard.press('Home');
  await verdictShown(page, 'waiting');
  await page.click('#activate-all');
  const paused = await until(page, 'the exercise and the status both saying paused', () => {
    const v = document.querySelector('#exercise .exercise-verdict');
    const status = document.querySelector('#telemetry dd[data-key="status"]').textContent;
    const ok = v.dataset.verdict === 'running' && v.dataset.paused === 'true' && /paused/.test(status);
    return { ok, value: v.textContent, shown: `exercise ${v.dataset.verdict} (paused ${v.dataset.paused}) "${v.textContent}", status "${status}"` };
  });
  assert.match(paused, /^Paused/);
  assert.doesNotMatch(paused, /Running/);
  // Run: both say the drive goes on.
  await page.click('#pause');
  await until(page, 'the exercise running and the status not paused', () => {
    const v = document.querySelector('#exercise .exercise-verdict');
    const status = document.querySelector('#telemetry dd[data-key="status"]').textContent;
    const ok = v.dataset.verdict !== 'waiting' && v.dataset.paused === 'false' && !/paused/.test(status)
      && /^(Running|Passed)/.test(v.textContent);
    return { ok, shown: `exercise ${v.dataset.verdict} (paused ${v.dataset.paused}) "${v.textContent}", status "${status}"` };
  });
  assert.deepEqual(problems, []);
});
