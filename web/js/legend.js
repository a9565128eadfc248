// @ts-check
// The legend over the map's corner: what the colours and lines mean, the heat
// map's colour scale (the potential's range, log scale, from the renderer) and a scale bar.
// It folds away (a <details>, folded at first) and is kept small: never more than about 15 %
// of the map (on a narrow screen it sits under the map). The colours are the renderer's (`render::style`).
import { el, setText } from './dom.js';
import { t } from './i18n.js';

/**
 * [layer, label, how the swatch looks (a CSS class)].
 * @type {Array<[keyof Layers, string, string]>}
 */
const ENTRIES = [
  ['occupancy', t('legend.obstacle'), 'sw-obstacle'],
  ['dmin_zone', t('legend.dmin_zone'), 'sw-dmin'],
  ['global_path', t('legend.global_path'), 'sw-global'],
  ['local_path', t('legend.local_path'), 'sw-local'],
  ['trail', t('legend.trail'), 'sw-trail'],
  ['control_points', t('legend.control_point'), 'sw-control'],
  ['local_target', t('legend.local_target'), 'sw-target'],
  ['robot', t('legend.robot'), 'sw-robot'],
  ['start_goal', t('legend.start'), 'sw-start'],
  ['start_goal', t('legend.goal'), 'sw-goal'],
];
/** The scale bar's longest length, CSS pixels. */
const SCALE_MAX_PX = 70;

/** A short number: three significant digits at most (1.23e5 beyond). @param {number} v */
function short(v) {
  const a = Math.abs(v);
  if (a !== 0 && (a >= 1e4 || a < 0.01)) return v.toExponential(1).replace('e+', 'e');
  return String(Number(v.toPrecision(3)));
}

/**
 * @param {HTMLDetailsElement} details the legend (folds away)
 * @param {HTMLElement} body what the legend holds
 * @param {HTMLCanvasElement} canvas the map's canvas (the scale bar's pixels per metre)
 * @param {App} app
 */
export function createLegend(details, body, canvas, app) {
  const { demo } = app;
  // Folded at first: the map is what the page is for; the legend is one click away.
  details.open = false;
  const rows = ENTRIES.map(([layer, label, cls]) => {
    const row = el('li', { class: 'legend-row', dataset: { layer } }, el('span', { class: `sw ${cls}`, 'aria-hidden': 'true' }), label);
    return row;
  });
  const lo = el('span', { class: 'heat-lo' });
  const hi = el('span', { class: 'heat-hi' });
  const heat = el('div', { class: 'heat', id: 'legend-heat', title: t('legend.potential.title') },
    el('span', { class: 'heat-title' }, t('legend.potential')),
    el('span', { class: 'heat-bar', 'aria-hidden': 'true' }),
    el('span', { class: 'heat-labels' }, lo, hi));
  const bar = el('span', { class: 'scale-bar', 'aria-hidden': 'true' });
  const barLabel = el('span', { class: 'scale-label' });
  const scale = el('div', { class: 'scale', id: 'legend-scale' }, bar, barLabel);
  body.append(el('ul', { class: 'legend-list' }, ...rows), heat, scale);

  let lastRange = '';
  let lastScale = '';

  function showLayers() {
    const layers = demo.layers();
    ENTRIES.forEach(([layer], i) => { rows[i].hidden = !layers[layer]; });
    heat.hidden = !layers.heat_map;
  }
  app.on('layers', showLayers);
  showLayers();

  /** @param {ClientBox} a @param {ClientBox} b */
  const overlaps = (a, b) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;

  /**
   * Over the map (a wide screen), the open legend keeps off the robot: it moves to the other
   * bottom corner when the robot is under it and not under the other one.
   * @param {() => ClientBox | null} robot
   */
  function keepOffRobot(robot) {
    if (getComputedStyle(details).position !== 'absolute') return;
    const box = robot();
    if (!box) return;
    const r = details.getBoundingClientRect();
    if (!overlaps(r, box)) return;
    const p = details.offsetParent?.getBoundingClientRect();
    if (!p) return;
    const mirrored = { left: p.left + p.right - r.right, right: p.left + p.right - r.left, top: r.top, bottom: r.bottom };
    if (!overlaps(mirrored, box)) details.dataset.corner = details.dataset.corner === 'right' ? 'left' : 'right';
  }

  return {
    /**
     * Every frame (cheap): the colour scale and the scale bar when they change, and the
     * corner (`robot()` gives the robot's client box; asked only while the legend is open).
     * @param {() => ClientBox | null} robot
     */
    update(robot) {
      if (!details.open) return;
      keepOffRobot(robot);
      const range = demo.heat_range();
      const key = range ? range.join(',') : '';
      if (key !== lastRange) {
        lastRange = key;
        heat.classList.toggle('empty', !range);
        setText(lo, range ? short(range[0]) : '—');
        setText(hi, range ? `${range[2] ? '>' : ''}${short(range[1])}` : t('legend.no_field'));
      }
      // The scale bar: the longest 1-2-5 length in metres within SCALE_MAX_PX.
      const rect = canvas.getBoundingClientRect();
      const cssPerMetre = demo.pixels_per_metre() * (rect.width / Math.max(1, canvas.width));
      const s = `${cssPerMetre}`;
      if (s === lastScale || !(cssPerMetre > 0)) return;
      lastScale = s;
      let length = 0.001;
      for (let e = -3; e <= 6; e++) {
        for (const m of [1, 2, 5]) {
          const l = m * 10 ** e;
          if (l * cssPerMetre <= SCALE_MAX_PX) length = l;
        }
      }
      bar.style.width = `${(length * cssPerMetre).toFixed(1)}px`;
      setText(barLabel, `${short(length)} m`);
    },
  };
}
