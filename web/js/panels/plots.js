// @ts-check
// The plots: the last 10 s of telemetry (`Demo.plot(10)`) on four small canvases
// drawn here with the 2D context (no chart library):
//   (a) MotorControl's target wheel rates against the physics' actual ones, left and right;
//   (b) the wheel torques MotorControl commands, those the physics applies (saturated) and
//       the saturation limit ±MaxTorque;
//   (c) DriveControl's commanded v and ω against the actual ones;
//   (d) the deviation from the path, with a line at LocalPathPlanning's Deviatinglen (above
//       it, a local replan is requested, 000 §5.2.4.6).
// Vertical marks show when a global or local plan was made. The y-ranges follow the data.
//
// Drawn at most ten times a second, only while the tab is shown and simulated time moved
// (or the size changed): the main frame (step + render + blit) does not pay for it.
import { el } from '../dom.js';
import { t } from '../i18n.js';

const WINDOW_S = 10;
const REDRAW_MS = 100;
const HEIGHT_CSS = 140;
const FONT = '11px system-ui, -apple-system, "Segoe UI", "Liberation Sans", sans-serif';
const INK = '#1d2330';
const MUTED = '#5d6677';
const GRID = '#e6e9ef';
const REPLAN = '#f08c00';
const LEFT = '#1c7ed6';
const RIGHT = '#e8590c';
const V = '#2b8a3e';
const W = '#7048e8';
const DEV = '#c92a2a';
const DASH = [5, 3];

/**
 * A field of the plot window that is a series over time.
 * @typedef {{ [K in keyof PlotWindow]: PlotWindow[K] extends ReadonlyArray<number | null> ? K : never }[keyof PlotWindow]} SeriesKey
 */
/**
 * A field of the plot window that is one number (a limit drawn as a line).
 * @typedef {{ [K in keyof PlotWindow]: PlotWindow[K] extends number ? K : never }[keyof PlotWindow]} LimitKey
 */
/** A series drawn: its field, label, colour and dash (solid without). @typedef {[key: SeriesKey, label: string, colour: string, dash?: number[]]} Series */
/**
 * One plot.
 * @typedef {object} PlotSpec
 * @property {string} id the canvas's id
 * @property {string} title
 * @property {string} unit
 * @property {Series[]} series
 * @property {SeriesKey[]} [range] the series the y-range follows (else all)
 * @property {[key: LimitKey, label: string]} [limit] a limit drawn as a dotted line
 * @property {boolean} [symmetric] the limit is drawn at ± its value
 */

/** @type {PlotSpec[]} */
const PLOTS = [
  {
    id: 'plot-rates', title: t('plots.rates'), unit: 'rad/s',
    series: [
      ['target_rate_l', t('plots.target_l'), LEFT, DASH], ['rate_l', t('plots.l'), LEFT],
      ['target_rate_r', t('plots.target_r'), RIGHT, DASH], ['rate_r', t('plots.r'), RIGHT],
    ],
  },
  {
    // Commanded (MotorControl) dashed, applied (the physics, saturated) solid, and the
    // saturation limit ±MaxTorque. The y-range follows the applied torques and the limit: a
    // command far beyond it is cut at the frame and said so.
    id: 'plot-torques', title: t('plots.torques'), unit: 'N·m',
    series: [
      ['torque_l', t('plots.cmd_l'), LEFT, DASH], ['applied_l', t('plots.l'), LEFT],
      ['torque_r', t('plots.cmd_r'), RIGHT, DASH], ['applied_r', t('plots.r'), RIGHT],
    ],
    range: ['applied_l', 'applied_r'],
    limit: ['max_torque', '±MaxTorque'], symmetric: true,
  },
  {
    id: 'plot-velocity', title: t('plots.velocity'), unit: 'm/s · rad/s',
    series: [['v_cmd', t('plots.v_cmd'), V, DASH], ['v', 'v', V], ['w_cmd', t('plots.w_cmd'), W, DASH], ['w', 'ω', W]],
  },
  {
    id: 'plot-deviation', title: t('plots.deviation'), unit: 'm',
    series: [['deviation', 'deviation', DEV]], limit: ['deviatinglen', 'Deviatinglen'],
  },
];

/** A step of 1, 2 or 5 × 10^n giving about `n` intervals over `range`. @param {number} range @param {number} n */
function niceStep(range, n) {
  const raw = range / n;
  const p = 10 ** Math.floor(Math.log10(raw));
  const f = raw / p;
  return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * p;
}

/** A tick's label, with the decimals the step needs. @param {number} v @param {number} step */
function tickLabel(v, step) {
  const digits = Math.max(0, -Math.floor(Math.log10(step) + 1e-9));
  const t = v.toFixed(Math.min(digits, 6));
  return t === '-0' || /^-0\.0*$/.test(t) ? t.slice(1) : t;
}

/**
 * The y-range of every finite value in `arrays` (and `extra`), padded.
 * @param {Array<ReadonlyArray<number | null> | undefined>} arrays
 * @param {number[]} extra
 * @returns {[number, number]}
 */
function yRange(arrays, extra) {
  let lo = Infinity;
  let hi = -Infinity;
  for (const a of arrays) {
    for (const v of a ?? []) {
      if (v === null || !Number.isFinite(v)) continue;
      if (v < lo) lo = v;
      if (v > hi) hi = v;
    }
  }
  for (const v of extra) {
    if (Number.isFinite(v)) {
      lo = Math.min(lo, v);
      hi = Math.max(hi, v);
    }
  }
  if (!Number.isFinite(lo)) return [-1, 1];
  if (hi - lo < 1e-9) {
    const pad = Math.max(Math.abs(hi) * 0.1, 0.05);
    return [lo - pad, hi + pad];
  }
  const pad = (hi - lo) * 0.08;
  return [lo - pad, hi + pad];
}

/**
 * @param {HTMLElement} root the Plots tab's section
 * @param {App} app
 */
export function createPlots(root, app) {
  const { demo } = app;
  let lastDraw = -Infinity;
  /** @type {number | null} */
  let lastT = null;
  let dirty = true;
  let draws = 0;

  const canvases = PLOTS.map((p) => el('canvas', { id: p.id, class: 'plot', role: 'img', 'aria-label': `${p.title} [${p.unit}]` }));
  root.append(
    el('div', { class: 'panel-head' }, el('h2', {}, t('plots.title')), el('span', { class: 'legend' }, t('plots.window', { s: WINDOW_S }))),
    el('p', { class: 'panel-hint small' },
      t('plots.hint'),
      el('span', { class: 'replan-key' }, '┆'), t('plots.replan')),
    ...canvases.map((c) => el('div', { class: 'plot-box' }, c)),
  );

  /**
   * Sizes `canvas` for the device's pixels; its context in CSS pixels, and its size.
   * @param {HTMLCanvasElement} canvas
   * @returns {[CanvasRenderingContext2D, number, number]}
   */
  function prepare(canvas) {
    const dpr = Math.min(window.devicePixelRatio || 1, 2);
    const w = Math.max(120, Math.round(canvas.clientWidth * dpr));
    const h = Math.round(HEIGHT_CSS * dpr);
    if (canvas.width !== w || canvas.height !== h) {
      canvas.width = w;
      canvas.height = h;
    }
    const ctx = /** @type {CanvasRenderingContext2D} */ (canvas.getContext('2d'));
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    return [ctx, w / dpr, h / dpr];
  }

  /**
   * Draws the plot `spec` of `data` over the times `t0`…`t1` [s].
   * @param {HTMLCanvasElement} canvas
   * @param {PlotSpec} spec
   * @param {PlotWindow} data
   * @param {number} t0
   * @param {number} t1
   */
  function drawPlot(canvas, spec, data, t0, t1) {
    const [ctx, W_, H] = prepare(canvas);
    ctx.clearRect(0, 0, W_, H);
    ctx.textBaseline = 'middle';
    // Title with the unit, top left; the legend beside it, or under it when it does not fit.
    const title = `${spec.title} [${spec.unit}]`;
    /** @type {Array<[label: string, colour: string, dash: number[] | undefined]>} */
    const legend = spec.series.map(([, label, colour, dash]) => [label, colour, dash]);
    if (spec.limit) legend.push([spec.limit[1], INK, [2, 2]]);
    ctx.font = FONT;
    const legendWidth = legend.reduce((w, [label]) => w + ctx.measureText(label).width + 26, 0);
    ctx.font = `600 ${FONT}`;
    const titleWidth = ctx.measureText(title).width;
    const twoLines = titleWidth + 12 + legendWidth > W_ - 8;
    const m = { l: 46, r: 8, t: twoLines ? 32 : 20, b: 18 };
    const pw = W_ - m.l - m.r;
    const ph = H - m.t - m.b;
    ctx.fillStyle = INK;
    ctx.fillText(title, 4, 9);
    ctx.font = FONT;
    let lx = W_ - m.r;
    const ly = twoLines ? 22 : 9;
    for (const [label, colour, dash] of [...legend].reverse()) {
      const w = ctx.measureText(label).width;
      lx -= w;
      ctx.fillStyle = MUTED;
      ctx.fillText(label, lx, ly);
      lx -= 18;
      ctx.strokeStyle = colour;
      ctx.lineWidth = 1.6;
      ctx.setLineDash(dash ?? []);
      ctx.beginPath();
      ctx.moveTo(lx, ly + 0.5);
      ctx.lineTo(lx + 14, ly + 0.5);
      ctx.stroke();
      ctx.setLineDash([]);
      lx -= 8;
    }

    const limit = spec.limit ? data[spec.limit[0]] : undefined;
    const limits = limit === undefined ? [] : spec.symmetric ? [limit, -limit] : [limit];
    const ranged = spec.range ?? spec.series.map(([k]) => k);
    const [lo, hi] = yRange(ranged.map((k) => data[k]), [...limits, 0]);
    // Values of the other series beyond the range are cut at the frame: say so.
    const beyond = spec.series.some(([k]) => (data[k] ?? []).some((v) => v !== null && Number.isFinite(v) && (v > hi || v < lo)));
    const x = (/** @type {number} */ t) => m.l + ((t - t0) / (t1 - t0)) * pw;
    const y = (/** @type {number} */ v) => m.t + (1 - (v - lo) / (hi - lo)) * ph;

    // Grid, ticks and labels.
    ctx.strokeStyle = GRID;
    ctx.fillStyle = MUTED;
    ctx.lineWidth = 1;
    const ys = niceStep(hi - lo, 3);
    ctx.textAlign = 'right';
    for (let v = Math.ceil(lo / ys) * ys; v <= hi; v += ys) {
      const py = Math.round(y(v)) + 0.5;
      ctx.beginPath();
      ctx.moveTo(m.l, py);
      ctx.lineTo(m.l + pw, py);
      ctx.stroke();
      ctx.fillText(tickLabel(v, ys), m.l - 4, py);
    }
    ctx.textAlign = 'center';
    for (let t = Math.ceil(t0 / 2) * 2; t <= t1 + 1e-9; t += 2) {
      const px = Math.round(x(t)) + 0.5;
      ctx.beginPath();
      ctx.moveTo(px, m.t);
      ctx.lineTo(px, m.t + ph);
      ctx.stroke();
      ctx.fillText(String(Math.round(t)), px, m.t + ph + 9);
    }
    ctx.strokeStyle = '#aab2c0';
    ctx.strokeRect(m.l + 0.5, m.t + 0.5, pw - 1, ph - 1);
    ctx.textAlign = 'left';
    ctx.fillText('t [s]', 4, m.t + ph + 9);

    // Inside the frame only.
    ctx.save();
    ctx.beginPath();
    ctx.rect(m.l, m.t, pw, ph);
    ctx.clip();
    // Replans.
    ctx.strokeStyle = REPLAN;
    ctx.lineWidth = 1;
    ctx.setLineDash([3, 3]);
    for (const t of data.replans ?? []) {
      if (t < t0 || t > t1) continue;
      const px = Math.round(x(t)) + 0.5;
      ctx.beginPath();
      ctx.moveTo(px, m.t);
      ctx.lineTo(px, m.t + ph);
      ctx.stroke();
    }
    // The limit line(s).
    for (const v of limits) {
      if (!Number.isFinite(v)) continue;
      ctx.strokeStyle = INK;
      ctx.setLineDash([2, 2]);
      const py = Math.round(y(v)) + 0.5;
      ctx.beginPath();
      ctx.moveTo(m.l, py);
      ctx.lineTo(m.l + pw, py);
      ctx.stroke();
    }
    // The series (a gap where a value is missing).
    const ts = data.t ?? [];
    ctx.lineWidth = 1.5;
    ctx.lineJoin = 'round';
    for (const [key, , colour, dash] of spec.series) {
      const vs = data[key] ?? [];
      ctx.strokeStyle = colour;
      ctx.setLineDash(dash ?? []);
      ctx.beginPath();
      let pen = false;
      for (let i = 0; i < ts.length; i++) {
        const v = vs[i];
        if (v === null || v === undefined || !Number.isFinite(v)) {
          pen = false;
          continue;
        }
        if (pen) ctx.lineTo(x(ts[i]), y(v));
        else ctx.moveTo(x(ts[i]), y(v));
        pen = true;
      }
      ctx.stroke();
    }
    ctx.restore();
    ctx.setLineDash([]);
    canvas.dataset.offScale = String(beyond);
    if (beyond) {
      // Inside the frame's bottom left, on a white box, clear of the legend.
      const note = t('plots.beyond');
      const w = ctx.measureText(note).width + 8;
      ctx.fillStyle = 'rgba(255, 255, 255, 0.85)';
      ctx.fillRect(m.l + 2, m.t + ph - 16, w, 14);
      ctx.fillStyle = '#c92a2a';
      ctx.textAlign = 'left';
      ctx.fillText(note, m.l + 6, m.t + ph - 9);
    }
    if (ts.length === 0) {
      ctx.fillStyle = MUTED;
      ctx.textAlign = 'center';
      ctx.fillText(t('plots.empty'), m.l + pw / 2, m.t + ph / 2);
    }
  }

  function redraw() {
    const r = app.attempt(() => demo.plot(WINDOW_S));
    if (!r.ok || r.value === undefined) return false;
    const data = r.value;
    const ts = data.t ?? [];
    const end = ts.length ? ts[ts.length - 1] : demo.time_s();
    const t1 = Math.max(end, WINDOW_S);
    const t0 = t1 - WINDOW_S;
    PLOTS.forEach((spec, i) => drawPlot(canvases[i], spec, data, t0, t1));
    draws++;
    root.dataset.draws = String(draws);
    root.dataset.t = String(end);
    return true;
  }

  app.on('loaded', () => { dirty = true; });
  app.on('changed', () => { dirty = true; });
  app.on('tab', (name) => { if (name === 'plots') dirty = true; });
  window.addEventListener('resize', () => { dirty = true; });

  return {
    /**
     * Called every frame: redraws at most every 100 ms, and only when time moved.
     * @param {number} now the frame's time [ms]
     * @param {boolean} visible whether the Plots tab is shown
     */
    update(now, visible) {
      if (!visible || now - lastDraw < REDRAW_MS) return;
      const t = demo.time_s();
      if (!dirty && t === lastT) return;
      lastDraw = now;
      lastT = t;
      dirty = false;
      redraw();
    },
  };
}
