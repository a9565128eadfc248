// @ts-check
// The timeline under the canvas: play and pause, a slider to seek to any time of
// the run, one tick back and forth, the run's events marked on the track (plans, failures,
// bumps, faults, arrival), and the run as a replay file: download it (`*.rtnav.json`: the
// set-up and every request with its simulated time) or load one.
//
// Every state is the core's (`Session`): a seek restores the nearest checkpoint and runs
// from it (`demo.seek`), the recorded requests after the time reached are replayed as the
// clock runs on, and a request made there drops them. The page only reads `timeline()`
// a few times a second and draws it.
import { Demo } from '../../pkg/rtnav_wasm.js';
import { el, setText } from '../dom.js';
import { downloadText } from '../download.js';
import { t, language } from '../i18n.js';
import { errorText, eventText } from '../say.js';
import { scenarioTitle } from '../scenarios.js';

const POLL_MS = 200;

/** @param {number} ns */
const secs = (ns) => ns / 1e9;

/**
 * @param {HTMLElement} root
 * @param {App} app
 */
export function createTimeline(root, app) {
  const { demo } = app;
  /** @type {TimelineView | null} */
  let view = null;
  let lastPoll = -Infinity;
  let dragging = false;
  let marksKey = '';
  /** @type {Record<string, string>} */
  const markTitles = {
    plan: t('timeline.mark.plan'),
    failure: t('timeline.mark.failure'),
    bump: t('timeline.mark.bump'),
    fault: t('timeline.mark.fault'),
    arrival: t('timeline.mark.arrival'),
  };

  const message = el('span', { class: 'timeline-message', id: 'timeline-message', role: 'status' });
  /** @param {string} text @param {string} [level] */
  const say = (text, level = 'info') => {
    message.textContent = text;
    message.dataset.level = level;
  };

  const play = el('button', {
    type: 'button', id: 'tl-play', class: 'plain', title: t('pause.title'),
    onclick: () => {
      demo.set_paused(!demo.paused());
      refresh(true);
    },
  }, t('pause.label'));
  const back = el('button', {
    type: 'button', id: 'tl-back', class: 'plain', 'aria-label': t('timeline.back.aria'),
    title: t('timeline.back.title'),
    onclick: () => stepBy(-1),
  }, '◀ 1');
  const forth = el('button', {
    type: 'button', id: 'tl-forth', class: 'plain', 'aria-label': t('timeline.forth.aria'),
    title: t('timeline.forth.title'), onclick: () => stepBy(1),
  }, '1 ▶');
  const slider = el('input', {
    type: 'range', id: 'tl-slider', min: 0, max: 1, step: 0.001, value: 0,
    'aria-label': t('timeline.slider.aria'), title: t('timeline.slider.title'),
  });
  const marks = el('div', { class: 'timeline-marks', id: 'tl-marks', 'aria-hidden': 'true' });
  const track = el('div', { class: 'timeline-track' }, marks, slider);
  const time = el('output', { class: 'timeline-time', id: 'tl-time' }, '0.0 / 0.0 s');

  const fileInput = el('input', {
    type: 'file', id: 'replay-file', accept: '.json,application/json', hidden: true,
  });
  const download = el('button', {
    type: 'button', id: 'replay-download', class: 'secondary',
    title: t('timeline.download.title'),
    onclick: () => {
      const r = app.attempt(() => demo.replay_json());
      if (!r.ok) return say(t('timeline.download.none', { error: r.error }), 'error');
      if (r.value === undefined) return undefined;
      const name = `${app.scenarios?.current ?? 'run'}-${demo.time_s().toFixed(1)}s.rtnav.json`;
      downloadText(r.value, name, 'application/json');
      say(t('timeline.download.saved', { kb: (r.value.length / 1024).toFixed(1) }), 'success');
    },
  }, t('timeline.download'));
  const load = el('button', {
    type: 'button', id: 'replay-load', class: 'secondary',
    title: t('timeline.load.title'),
    onclick: () => fileInput.click(),
  }, t('timeline.load'));
  fileInput.addEventListener('change', async () => {
    const file = fileInput.files?.[0];
    fileInput.value = '';
    if (file) await loadReplay(await file.text());
  });

  root.append(
    el('div', { class: 'timeline-row' }, play, back, forth, track, time),
    el('div', { class: 'timeline-row timeline-files' }, download, load, fileInput, message),
  );

  /** Everything that reads the system again after a jump in time. */
  function jumped() {
    app.log.clear();
    app.log.update();
    app.emit('changed');
    app.stage.draw();
    refresh(true);
  }

  /** @param {number} s */
  function seek(s) {
    const r = app.attempt(() => demo.seek(s));
    if (!r.ok) say(t('timeline.seek_failed', { error: r.error }), 'error');
    jumped();
  }

  /** @param {number} ticks */
  function stepBy(ticks) {
    demo.set_paused(true);
    if (ticks > 0) {
      app.attempt(() => demo.step_ticks(ticks));
      app.stage.draw();
      refresh(true);
    } else {
      seek(Math.max(0, demo.time_s() + ticks * demo.tick_s()));
    }
  }

  slider.addEventListener('input', () => {
    dragging = true;
    demo.set_paused(true);
    seek(Number(slider.value));
  });
  slider.addEventListener('change', () => {
    dragging = false;
  });

  /**
   * Loads a replay file's text: its scenario first, then the replay, run to its end.
   * @param {string} text
   */
  async function loadReplay(text) {
    let name;
    try {
      name = app.guard.call(() => Demo.replay_scenario(text));
    } catch (e) {
      return say(t('timeline.replay_refused', { error: errorText(e) }), 'error');
    }
    // The replay's scenario, loaded unless it is the one loaded now (then a replay the core
    // refuses — a scenario changed since, another behaviour version — leaves the run as it is).
    if (app.scenarios.current !== name && !(await app.scenarios.load(name))) {
      return say(t('timeline.scenario_failed', { name: scenarioTitle(name) }), 'error');
    }
    demo.set_paused(true);
    const r = app.attempt(() => demo.load_replay(text));
    jumped();
    if (!r.ok) return say(t('timeline.replay_refused', { error: r.error }), 'error');
    const c = r.value;
    if (!c) return undefined;
    root.dataset.replayHash = c.hash;
    root.dataset.replayMatches = String(c.matches);
    const where = t('timeline.where', { s: secs(c.end_ns).toFixed(1), n: c.inputs });
    const hash = c.hash.slice(0, 12);
    if (c.matches) {
      say(t('timeline.loaded', { where }), 'success');
      app.log.page(t('timeline.loaded.log', { name: scenarioTitle(name), where, hash }), 'info');
    } else {
      say(t('timeline.differs', { where }), 'error');
      app.log.page(t('timeline.differs.log', { name: scenarioTitle(name), hash, expected: c.expected_hash.slice(0, 12) }), 'error');
    }
    return c;
  }

  function drawMarks() {
    if (!view) return;
    const v = view;
    const span = Math.max(v.end_ns - v.start_ns, 1);
    const key = `${v.start_ns}/${v.end_ns}/${v.marks.length}`;
    if (key === marksKey) return;
    marksKey = key;
    marks.replaceChildren(...v.marks.map((m) => el('span', {
      class: `timeline-mark mark-${m.kind}`,
      style: `left: ${(100 * (m.t_ns - v.start_ns)) / span}%`,
      // The event marked, said in the page's language as the log says it.
      title: `${secs(m.t_ns).toFixed(2)} s · ${markTitles[m.kind] ?? m.kind}: ${eventText(m.event)}`,
      dataset: { kind: m.kind, t: String(secs(m.t_ns)) },
    })));
  }

  function refresh(force = false) {
    const now = performance.now();
    if (!force && now - lastPoll < POLL_MS) return;
    lastPoll = now;
    const r = app.attempt(() => demo.timeline());
    const paused = demo.paused();
    // The same words as the system bar's button: Run while paused, Pause while running.
    setText(play, paused ? t('run.label') : t('pause.label'));
    play.classList.toggle('active', paused);
    if (!r.ok || !r.value) {
      root.dataset.enabled = 'false';
      return;
    }
    root.dataset.enabled = 'true';
    view = r.value;
    slider.min = String(secs(view.start_ns));
    slider.max = String(secs(view.end_ns));
    if (!dragging) slider.value = String(secs(view.now_ns));
    setText(time, `${secs(view.now_ns).toFixed(1)} / ${secs(view.end_ns).toFixed(1)} s`);
    root.dataset.checkpoints = String(view.checkpoints);
    root.dataset.pending = String(view.pending);
    drawMarks();
  }

  app.on('loaded', () => {
    marksKey = '';
    say('');
    refresh(true);
  });

  return {
    update: () => refresh(false),
    loadReplay,
    seek,
  };
}
