// @ts-check
// The compare view: "compare with…" from the Parameters tab runs the scenario
// loaded twice to its outcome — A with the set-up as it is now (start, goal, map edits,
// changed parameters), B with one parameter changed — and shows both robots on one canvas
// (B as a violet ghost, its trail too), their speeds overlaid, and the summary table: time
// to goal, path length, minimum clearance, arrival heading error, replans and energy
// (Σ|τ·ω|·Δt). The runs are the core's (`CompareView`, `Comparison`); the page draws.
import { CompareView } from '../pkg/rtnav_wasm.js';
import { el } from './dom.js';
import { t, has } from './i18n.js';
import { scenarioTitle } from './scenarios.js';

const WIDTH = 640;
const HEIGHT = 400;

/**
 * The form in the Parameters tab; the view opens under the stage.
 * @param {HTMLElement} formRoot the Parameters tab's section (the form goes at its end)
 * @param {HTMLElement} viewRoot the compare view's section
 * @param {App} app
 */
export function createCompare(formRoot, viewRoot, app) {
  const { demo } = app;
  /** The comparison shown (its runs are held in Rust memory until freed). @type {CompareView | null} */
  let current = null;
  // The table's rows and values as the core names them (`Comparison::rows`), in the page's
  // language; `data-measure` keeps the core's name.
  /** @type {Record<string, string | undefined>} */
  const ROWS = {
    configuration: t('compare.row.configuration'),
    outcome: t('compare.row.outcome'),
    'time to goal': t('compare.row.time_to_goal'),
    'path length': t('compare.row.path_length'),
    'min clearance': t('compare.row.min_clearance'),
    'arrival heading error': t('compare.row.arrival_heading_error'),
    'final heading error': t('compare.row.final_heading_error'),
    replans: t('compare.row.replans'),
    'energy Σ|τ·ω|·Δt': t('compare.row.energy'),
    'trace hash': t('compare.row.trace_hash'),
  };
  /**
   * A row's value for one run: the core's text, or said from the run's summary (`run`).
   * @param {string} measure
   * @param {string} text
   * @param {RunSummary} [run]
   */
  const cell = (measure, text, run) => {
    if (measure === 'outcome' && has(`compare.outcome.${text}`)) return t(`compare.outcome.${text}`);
    if (measure === 'configuration' && text === 'as written') return t('compare.as_written');
    if (measure === 'replans' && run) return t('compare.replans', { local: run.replans, global: run.global_plans });
    return text;
  };

  const select = el('select', { id: 'compare-param', 'aria-label': t('compare.param.aria') });
  const value = el('input', {
    type: 'text', id: 'compare-value', inputmode: 'decimal', size: 8,
    'aria-label': t('compare.value.aria'), placeholder: t('compare.value.placeholder'),
  });
  const run = el('button', { type: 'button', id: 'compare-run', class: 'secondary', onclick: () => start() }, t('compare.run'));
  const note = el('p', { class: 'panel-message', id: 'compare-message', role: 'status', hidden: true });
  formRoot.append(el('details', { class: 'compare-form', id: 'compare-form' },
    el('summary', {}, t('compare.summary')),
    el('p', { class: 'hint' }, t('compare.hint')),
    el('div', { class: 'compare-inputs' }, select, value, run),
    note));

  const canvas = el('canvas', { id: 'compare-canvas', width: WIDTH, height: HEIGHT, 'aria-label': t('compare.canvas.aria') });
  const plot = el('canvas', { id: 'compare-plot', width: WIDTH, height: 160, 'aria-label': t('compare.plot.aria') });
  const table = el('table', { class: 'compare-table', id: 'compare-table' });
  const title = el('h2', { id: 'compare-title' }, t('compare.title'));
  const close = el('button', {
    type: 'button', class: 'link', id: 'compare-close',
    onclick: () => { viewRoot.hidden = true; current?.free(); current = null; },
  }, t('compare.close'));
  viewRoot.append(
    el('div', { class: 'panel-head' }, title, close),
    el('div', { class: 'compare-body' },
      el('div', { class: 'compare-pictures' }, canvas, plot,
        el('p', { class: 'compare-key' },
          el('span', { class: 'key-a' }, t('compare.key.a')), ' · ',
          el('span', { class: 'key-b' }, t('compare.key.b')))),
      table));
  viewRoot.hidden = true;

  function fillParams() {
    const r = app.attempt(() => demo.params());
    if (!r.ok || r.value === undefined) return;
    const keep = select.value;
    select.replaceChildren(...r.value.flatMap((c) => c.params.map((p) => el('option', {
      value: `${c.component}/${p.name}`, dataset: { value: String(p.value) },
    }, `${c.component} · ${p.name}`))));
    if (keep) select.value = keep;
    else select.value = 'LocalPathPlanning/PostureConsiderationLevel';
  }
  select.addEventListener('change', () => {
    value.placeholder = select.selectedOptions[0]?.dataset.value ?? t('compare.value.placeholder');
  });
  /** @type {HTMLDetailsElement} */ (formRoot.querySelector('#compare-form')).addEventListener('toggle', fillParams);
  app.on('loaded', fillParams);

  /** @param {string} text @param {string} level */
  const say = (text, level) => {
    note.textContent = text;
    note.dataset.level = level;
    note.hidden = !text;
  };

  /**
   * Runs the comparison of the parameter `key` (`Component/Name`) set to `text`.
   * @returns {CompareTable | undefined} the table (undefined when refused)
   */
  function start(key = select.value, text = value.value) {
    const [component, name] = key.split('/');
    say(t('compare.running'), 'info');
    const r = app.attempt(() => CompareView.run(demo, component, name, text.trim(), WIDTH, HEIGHT));
    if (!r.ok) {
      say(t('compare.none', { error: r.error }), 'error');
      return undefined;
    }
    if (r.value === undefined) return undefined; // the page crashed
    const view = r.value;
    current?.free();
    current = view;
    say('', 'info');
    show(view, `${name} = ${text.trim()}`);
    return view.table();
  }

  /**
   * Shows the comparison `view` of the change `what`: both runs drawn, the speeds, the table.
   * @param {CompareView} view
   * @param {string} what
   */
  function show(view, what) {
    view.render();
    const bytes = new Uint8ClampedArray(app.memory.buffer, view.frame_ptr(), view.frame_len());
    /** @type {CanvasRenderingContext2D} */ (canvas.getContext('2d')).putImageData(new ImageData(new Uint8ClampedArray(bytes), WIDTH, HEIGHT), 0, 0);
    const data = view.table();
    title.textContent = t('compare.title_on', { scenario: scenarioTitle(data.scenario), what });
    table.replaceChildren(
      el('thead', {}, el('tr', {}, el('th', {}, ''), el('th', {}, 'A'), el('th', {}, t('compare.col.b')))),
      el('tbody', {}, ...data.rows.map(([m, a, b]) => el('tr', { dataset: { measure: m } },
        el('th', { scope: 'row' }, ROWS[m] ?? m), el('td', {}, cell(m, a, data.a)), el('td', {}, cell(m, b, data.b))))),
    );
    drawPlot(view.plots());
    viewRoot.hidden = false;
    viewRoot.scrollIntoView({ block: 'nearest' });
  }

  /** The two runs' speeds over time. @param {ComparePlots} p */
  function drawPlot(p) {
    const ctx = /** @type {CanvasRenderingContext2D} */ (plot.getContext('2d'));
    const { width: w, height: h } = plot;
    ctx.clearRect(0, 0, w, h);
    const tMax = Math.max(...p.t_a.slice(-1), ...p.t_b.slice(-1), 1);
    const vMax = Math.max(0.1, ...p.v_a.map(Math.abs), ...p.v_b.map(Math.abs));
    const x = (/** @type {number} */ t) => 40 + ((w - 50) * t) / tMax;
    const y = (/** @type {number} */ v) => h - 20 - ((h - 30) * v) / vMax;
    ctx.strokeStyle = '#94a3b8';
    ctx.beginPath();
    ctx.moveTo(40, 10); ctx.lineTo(40, h - 20); ctx.lineTo(w - 10, h - 20);
    ctx.stroke();
    ctx.fillStyle = '#334155';
    ctx.font = '11px sans-serif';
    ctx.fillText(`${vMax.toFixed(2)} m/s`, 2, 14);
    ctx.fillText(t('compare.plot.speed'), 2, h / 2);
    ctx.fillText(`${tMax.toFixed(1)} s`, w - 40, h - 6);
    /** @type {Array<[times: number[], speeds: number[], colour: string]>} */
    const runs = [[p.t_a, p.v_a, '#0d9488'], [p.t_b, p.v_b, '#7c3aed']];
    for (const [ts, vs, colour] of runs) {
      ctx.strokeStyle = colour;
      ctx.lineWidth = 1.5;
      ctx.beginPath();
      ts.forEach((t, i) => (i ? ctx.lineTo(x(t), y(vs[i])) : ctx.moveTo(x(t), y(vs[i]))));
      ctx.stroke();
    }
  }

  return { start };
}
