// @ts-check
// rtnav page entry: loads the wasm module, creates the Demo handle (the whole system and
// its renderer, in Rust memory), mounts the stage and the panels, loads the default
// scenario, runs the clock. No simulation logic lives here: the page owns the clock
// (requestAnimationFrame), the DOM and the mouse; Rust owns every state (spec §1, §6).
import init, { Demo, version } from './pkg/rtnav_wasm.js';
import { createCrashGuard } from './js/crash.js';
import { startLoop } from './js/loop.js';
import { createNotice } from './js/notice.js';
import { createStage } from './js/stage.js';
import { createScene } from './js/scene.js';
import { createKeyGuide } from './js/keys.js';
import { createScenarios } from './js/scenarios.js';
import { createToolbar } from './js/panels/toolbar.js';
import { createRtcPanel } from './js/panels/rtc.js';
import { createSystemPanel } from './js/panels/system.js';
import { createSystemBar } from './js/panels/systembar.js';
import { createLegend } from './js/legend.js';
import { createEventLog } from './js/panels/event-log.js';
import { createTelemetry } from './js/panels/telemetry.js';
import { createTabs } from './js/tabs.js';
import { createParamsPanel } from './js/panels/params.js';
import { createInspector } from './js/panels/inspector.js';
import { createPlots } from './js/panels/plots.js';
import { createShare } from './js/panels/share.js';
import { createTimeline } from './js/panels/timeline.js';
import { createCompare } from './js/compare.js';
import { createExercisePanel } from './js/panels/exercise.js';
import { language, switchLanguage, translateStatic, t } from './js/i18n.js';
import { errorText } from './js/say.js';
import { keepRun, takeRun, restoreRun } from './js/carry.js';
import { takeOverWaitingBuild, keepOffline } from './js/offline.js';

/** The element with `id` (the page's HTML has every one these modules ask for). @param {string} id */
const $ = (id) => /** @type {HTMLElement} */ (document.getElementById(id));

/** How many frame times the page keeps (for the end-to-end test's median). */
const FRAME_TIMES = 600;
/** Wall time a frame may spend simulating [ms]; the ticks left over run in the next frames
 * (the same ticks: the trace does not change), so a plan on a large map doesn't freeze the
 * page for the rest of its frame's simulated time. */
const STEP_BUDGET_MS = 10;
/** Owed simulated time [s] from which the clock shows that it is behind. */
const BEHIND_S = 0.05;

async function boot() {
  // A new build waiting for this load: the page loads again from it (js/offline.js).
  if (await takeOverWaitingBuild()) return;
  translateStatic();
  // The module index.html began to download and compile as the page opened (else: fetched now).
  const wasm = await init({ module_or_path: (await window.rtnavWasm) ?? undefined });
  // The core's package version, beside the title (replays record the same one).
  $('version').textContent = version();
  const guard = createCrashGuard($('crash'), $('crash-message'));
  const demo = guard.call(() => new Demo(640, 400));
  if (!demo) return;

  // What every module shares: the handle, the crash guard, the page's own settings, and
  // `attempt` — a request whose refusal (an error value from Rust) is shown, not thrown.
  /** Each event's listeners (`AppEvents` says what each is handed). @type {Map<string, Array<(...args: unknown[]) => void>>} */
  const listeners = new Map();
  const app = /** @type {App} */ ({
    demo,
    guard,
    memory: wasm.memory,
    ui: { tool: 'goal', backward: false, brush: { size: 1, unit: 'cells' }, pendingStart: null },
    /**
     * @template {keyof AppEvents} K
     * @param {K} name
     * @param {(...args: AppEvents[K]) => void} fn
     */
    on(name, fn) {
      const fns = listeners.get(name) ?? [];
      fns.push(/** @type {(...args: unknown[]) => void} */ (fn));
      listeners.set(name, fns);
    },
    /**
     * @template {keyof AppEvents} K
     * @param {K} name
     * @param {AppEvents[K]} args
     */
    emit(name, ...args) {
      for (const fn of listeners.get(name) ?? []) fn(...args);
    },
    /** Wall time [ms] the requests took since the last frame (see the loop below). */
    requestMs: 0,
    /**
     * @template T
     * @param {() => T} fn
     * @returns {Attempt<T>}
     */
    attempt(fn) {
      const t0 = performance.now();
      try {
        return { ok: true, value: guard.call(fn) };
      } catch (e) {
        // The refusal in the page's language, from the error's detail (`say.js`).
        return { ok: false, error: errorText(e), message: e instanceof Error ? e.message : String(e) };
      } finally {
        app.requestMs += performance.now() - t0;
      }
    },
    /**
     * A lifecycle request of a button (`what` names it): a refusal goes to the notice and the
     * log; Reset and Activate (`endsNotices`) end the notices of the states they leave.
     */
    /**
     * @template T
     * @param {string} what
     * @param {() => T} fn
     * @returns {Attempt<T>}
     */
    request(what, fn, endsNotices = false) {
      if (endsNotices) app.notice.endState();
      const r = app.attempt(fn);
      if (!r.ok) {
        app.notice.show(t('refused', { what, error: r.error }), 'error');
        app.log.page(t('refused', { what, error: r.error }), 'warn');
      }
      app.emit('changed');
      return r;
    },
  });
  app.notice = createNotice($('notice'), $('notice-text'), $('notice-close'), $('notice-said'));
  app.log = createEventLog($('log-panel'), app);
  app.stage = createStage($('canvas-wrap'), /** @type {HTMLCanvasElement} */ ($('view')),
    /** @type {HTMLCanvasElement} */ ($('overlay')), $('tool-hint'), $('map-cursor'), app);
  const scene = createScene($('scene-description'), $('scene-status'), app);
  const toolbar = createToolbar($('toolbar'), $('clock-controls'), $('map-controls'), app);
  createKeyGuide(/** @type {HTMLButtonElement} */ ($('keys-open')));
  const systemBar = createSystemBar($('system-group'), app);
  const rtc = createRtcPanel($('rtc-panel'), app);
  const system = createSystemPanel($('system-panel'), app);
  const legend = createLegend(/** @type {HTMLDetailsElement} */ ($('legend')), $('legend-body'),
    /** @type {HTMLCanvasElement} */ ($('view')), app);
  const telemetry = createTelemetry($('telemetry'), app);
  const params = createParamsPanel($('params-panel'), app);
  const inspector = createInspector($('inspector-panel'), app);
  const plots = createPlots($('plots-panel'), app);
  createShare($('share'), /** @type {HTMLCanvasElement} */ ($('view')), app);
  const exercise = createExercisePanel($('exercise'), app);
  // English / 日本語: the page reloads in the other language with this run (js/carry.js);
  // for a map loaded from a file, which cannot be carried, only if the person agrees.
  const languageSelect = /** @type {HTMLSelectElement} */ ($('language'));
  languageSelect.value = language();
  languageSelect.addEventListener('change', () => {
    const kept = keepRun(app, languageSelect.value);
    if (!kept.go) {
      languageSelect.value = language();
      return;
    }
    switchLanguage(languageSelect.value, kept.share ?? null);
  });
  const tabPanels = /** @type {NodeListOf<HTMLElement>} */ (document.querySelectorAll('#panels .tab-panel'));
  const tabs = createTabs($('panel-tabs'), [...tabPanels], app, 'rtc');
  app.tabs = tabs;
  const scenarios = createScenarios(
    { select: /** @type {HTMLSelectElement} */ ($('scenario')),
      file: /** @type {HTMLInputElement} */ ($('map-file')), about: $('about'), title: $('about-title'),
      description: $('about-description'), lesson: $('about-lesson') },
    app,
  );
  app.scenarios = scenarios;
  const timeline = createTimeline($('timeline'), app);
  // The timeline's time changes every frame: shown, not spoken (an <output> is a live region).
  $('tl-time').setAttribute('aria-live', 'off');
  const compare = createCompare($('params-panel'), $('compare-view'), app);
  const simTime = $('sim-time');

  /** @type {number[]} */
  const frameTimes = [];
  // The frame budget counts what the requests between two frames took (a stroke's MapUpdate
  // or a goal on a large map): after one that took the budget, the frame steps no further,
  // and its ticks stay owed to the next frames (the same ticks: the trace does not change).
  // A frame that spent more than its budget and would redraw the map or the paths (a new
  // plan, an edit: `draws_from_cache` false) leaves its drawing to the next frame, which
  // then only draws: an expensive tick or request and the expensive redraw it causes fall
  // into two frames instead of adding up in one.
  let drawOwed = false;
  const loop = startLoop((elapsedMs) => {
    const t0 = performance.now();
    const budget = drawOwed ? 0 : STEP_BUDGET_MS - app.requestMs;
    guard.call(() => demo.step_within(elapsedMs, budget));
    const spent = app.requestMs + performance.now() - t0;
    drawOwed = !drawOwed && spent > STEP_BUDGET_MS && !guard.call(() => demo.draws_from_cache());
    if (!drawOwed) app.stage.draw();
    const t1 = performance.now();
    if (guard.crashed) return false;
    // What reads the page's layout (where the robot and goal are on screen) goes before the panels
    // write to the page: the layout of the last frame is still valid then, and is not made
    // again in the middle of this one.
    // One read of the session per frame (`Session::frame`): the clock, the telemetry and
    // status, the components, the events since the last frame, the exercise — handed to
    // every panel, which reads nothing of it again.
    const frame = guard.call(() => demo.frame());
    if (!frame) return false;
    app.frame = frame;
    legend.update(app.stage.robotBox);
    app.notice.update(app.stage.keepClear);
    frameTimes.push(t1 - t0);
    if (frameTimes.length > FRAME_TIMES) frameTimes.shift();
    const { clock } = frame;
    simTime.textContent = `${clock.time_s.toFixed(3)} s`;
    simTime.classList.toggle('behind', clock.behind_s > BEHIND_S);
    simTime.title = clock.behind_s > BEHIND_S ? t('clock.behind', { s: clock.behind_s.toFixed(2) }) : '';
    systemBar.update(frame.telemetry.state, frame.components, frame.telemetry.start !== null);
    rtc.update(frame.components);
    app.log.update(frame.events);
    telemetry.update(frame.telemetry);
    scene.update(frame);
    timeline.update();
    toolbar.update(clock);
    exercise.update(frame.exercise);
    // The teaching panels work only while shown, and at their own pace (not every frame).
    const now = performance.now();
    params.update(now, tabs.visible('params'));
    inspector.update(now, tabs.visible('inspector'));
    plots.update(now, tabs.visible('plots'));
    system.update(now, tabs.visible('system'), frame.components);
    // This frame's own requests (drawing, the panels) are not the next frame's.
    app.requestMs = 0;
    return !guard.crashed;
  });
  guard.onCrash(() => loop.stop());

  // For the console and the end-to-end test.
  window.rtnav = {
    demo,
    app,
    scenarios,
    tabs,
    exercise,
    inspector,
    timeline,
    compare,
    system,
    /** Frame times (step + render + blit) of the last frames, ms. */
    frameTimes: () => frameTimes.slice(),
    clearFrameTimes: () => { frameTimes.length = 0; },
    /** Fixes the frame size (pixels) instead of fitting the canvas to the page. */
    /** @param {number} w @param {number} h */
    setFrameSize: (w, h) => app.stage.setFixedSize(w, h),
    debugPanic: () => guard.call(() => demo.debug_panic()),
  };

  // A run carried from the other language goes on where it was; else a share link
  // (`?share=TOKEN`) opens its set-up; anything else the default scenario.
  const carried = takeRun(language());
  await scenarios.loadDefault(new URLSearchParams(location.search).get('share'),
    carried && (() => restoreRun(app, carried)));
  document.body.dataset.ready = 'true';
  keepOffline(app);
}

boot().catch((e) => {
  const box = $('crash');
  /** @type {HTMLElement} */ (box.querySelector('h2')).textContent = t('crash.boot.title');
  /** @type {HTMLElement} */ (box.querySelector('p')).textContent = t('crash.boot.text');
  $('crash-message').textContent = String(e && e.stack ? e.stack : e);
  box.hidden = false;
});
