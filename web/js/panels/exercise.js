// @ts-check
// The exercise of a scenario: its task, the parameters it lets change, the
// checks as a live checklist and the verdict at the end. Every check is evaluated by the
// core (`Session::exercise_view`, in each frame's read; `rtnav::system::ExerciseWatch`) from the facts and samples
// of the run, so `rtnav check` gives the same verdict; this panel only shows them, with the
// clock's pause as the same read says it (never "running" while the clock stands still).
// Restart (Shift+R) starts the scenario again as loaded, with the parameters as they are,
// the clock running and the checklist cleared (`Session::restart`).
import { el, setText } from '../dom.js';
import { t, num, has } from '../i18n.js';

/** A check's line in the language: `check.KIND` with the check's numbers. */
/** @param {Check} check */
export function checkText(check) {
  const { check: kind, ...numbers } = check;
  /** @type {Record<string, unknown>} */
  const vars = {};
  for (const [k, v] of Object.entries(numbers)) vars[k] = typeof v === 'number' ? num(v, 4) : v;
  return t(`check.${kind}`, vars);
}

/** What was measured, in the check's unit. */
/** @param {CheckStatus} c */
function measuredText(c) {
  if (c.changed?.length) return t('exercise.changed', { names: c.changed.join(', ') });
  if (c.warned?.length) return t('exercise.warned', { names: c.warned.join(', ') });
  if (c.measured === null || c.measured === undefined) return '';
  return t(`measured.${c.check.check}`, { value: num(c.measured, 3) });
}

/**
 * @param {HTMLElement} root
 * @param {App} app
 */
export function createExercisePanel(root, app) {
  const { demo } = app;
  const task = el('p', { class: 'exercise-task' });
  const allowed = el('p', { class: 'exercise-allowed' });
  const list = el('ul', { class: 'exercise-checks', 'aria-live': 'polite' });
  const verdict = el('p', { class: 'exercise-verdict', role: 'status' });
  const title = el('strong', {}, t('exercise.title'));
  const restartButton = el('button', {
    type: 'button', id: 'exercise-restart', class: 'secondary', title: t('exercise.restart.title'),
    'aria-keyshortcuts': 'Shift+R', onclick: () => restart(),
  }, t('exercise.restart'));
  root.replaceChildren(el('div', { class: 'exercise-head' }, title, ' ', task), allowed, list,
    el('div', { class: 'exercise-foot' }, verdict, restartButton));
  let last = '';

  /**
   * Starts the scenario again as loaded, with the parameters as they are now, the clock
   * running, the checklist cleared: a new system, which every panel reads afresh.
   */
  function restart() {
    const r = app.request(t('exercise.restart'), () => demo.restart(), true);
    if (!r.ok) return;
    // Whatever the notices and the log said was about the run before.
    app.notice.hide();
    app.emit('loaded');
    app.log.clear();
    app.log.update();
    app.log.page(t('exercise.restarted'), 'info');
    app.stage.draw();
  }

  // Shift+R restarts while an exercise is shown (not while typing in a field).
  window.addEventListener('keydown', (e) => {
    const target = e.target;
    if (root.hidden || e.key.toLowerCase() !== 'r' || !e.shiftKey || e.ctrlKey || e.metaKey || e.altKey) return;
    if (target instanceof HTMLInputElement || target instanceof HTMLSelectElement || target instanceof HTMLTextAreaElement) return;
    e.preventDefault();
    restart();
  });

  /** @param {ExerciseView} status */
  function scenarioTask(status) {
    const s = demo.scenario();
    const key = `scenario.${s?.name}.task`;
    const text = t(key);
    return text === key ? status.task : text;
  }

  /** @param {ExerciseView | null} status */
  function show(status) {
    root.hidden = !status;
    if (!status) return;
    setText(task, scenarioTask(status));
    const may = status.may_change.length
      ? t('exercise.may_change', { names: status.may_change.join(', ') })
      : '';
    const acts = status.actions.length
      ? t('exercise.actions', { names: status.actions.map((a) => (has(`action.${a}`) ? t(`action.${a}`) : a)).join(t('exercise.then')) })
      : '';
    setText(allowed, [may, acts].filter(Boolean).join(' '));
    list.replaceChildren(...status.checks.map((c) => el('li', {
      class: 'exercise-check', dataset: { state: c.state, check: c.check.check },
    },
    el('span', { class: 'exercise-mark', 'aria-hidden': 'true' }, c.state === 'passed' ? '✓' : c.state === 'failed' ? '✗' : '○'),
    el('span', { class: 'exercise-text' }, checkText(c.check)),
    el('span', { class: 'exercise-measured' }, measuredText(c)),
    el('span', { class: 'visually-hidden' }, t(`exercise.state.${c.state}`)))));
    verdict.dataset.verdict = status.verdict;
    // Waiting or running with the clock paused: the drive goes on only when it runs.
    const stands = status.paused && (status.verdict === 'waiting' || status.verdict === 'running');
    verdict.dataset.paused = String(stands);
    setText(verdict, stands
      ? t(`exercise.verdict.${status.verdict}_paused`)
      : status.ended_after === null
        ? decidedText(status) ?? t(`exercise.verdict.${status.verdict}`)
        : t(`exercise.verdict.${status.verdict}_after`, { s: num(status.ended_after, 1) }));
  }

  /**
   * A verdict decided while the run goes on (the core's `decided_by`): the check that can no
   * longer pass, and, for a run that cannot move on by itself, why.
   * @param {ExerciseView} status
   * @returns {string | null}
   */
  function decidedText(status) {
    const by = status.decided_by;
    const decided = by ? status.checks[by.check] : undefined;
    if (status.verdict !== 'failed' || !by || !decided) return null;
    const check = checkText(decided.check);
    if (!by.stuck) return t('exercise.verdict.failed_by', { check });
    const why = t(`exercise.stuck.${by.stuck.kind}`, 'component' in by.stuck ? { component: by.stuck.component } : {});
    return t('exercise.verdict.failed_stuck', { check, why });
  }

  /**
   * Shows the exercise as the frame read it, when it changed.
   * @param {ExerciseView | null} status
   */
  function update(status) {
    const key = JSON.stringify(status);
    if (key === last) return;
    last = key;
    show(status);
  }

  app.on('loaded', () => update(demo.exercise()));
  return { update, restart };
}
