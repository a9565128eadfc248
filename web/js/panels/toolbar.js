// @ts-check
// The toolbar above the canvas: what the mouse does (goal, start, obstacle, erase, pan) and
// the brush's size (in cells or metres), the driving direction, Clear and SafeMode
// (000 §5.2.4.7) and the layers the renderer draws; over the map: zoom in, out, Fit; in the
// system bar beside the clock: pause, one tick, speed.
import { el } from '../dom.js';
import { t } from '../i18n.js';

const TOOLS = [
  ['goal', t('tool.goal'), 'g', t('tool.goal.title')],
  ['start', t('tool.start'), 's', t('tool.start.title')],
  ['paint', t('tool.paint'), 'o', t('tool.paint.title')],
  ['erase', t('tool.erase'), 'e', t('tool.erase.title')],
  ['pan', t('tool.pan'), 'p', t('tool.pan.title')],
];
const SPEEDS = [0.25, 0.5, 1, 2, 4, 8, 16];
/** Brush sizes: a square of n×n cells, or of a side in metres. */
const BRUSHES = { cells: [1, 3, 5, 9], m: [0.25, 0.5, 1, 2] };
const LAYER_NAMES = {
  occupancy: t('layer.occupancy'),
  dmin_zone: t('layer.dmin_zone'),
  heat_map: t('layer.heat_map'),
  global_path: t('layer.global_path'),
  local_path: t('layer.local_path'),
  control_points: t('layer.control_points'),
  local_target: t('layer.local_target'),
  robot: t('layer.robot'),
  trail: t('layer.trail'),
  start_goal: t('layer.start_goal'),
};

/**
 * @param {HTMLElement} root
 * @param {HTMLElement} clockRoot
 * @param {HTMLElement} mapRoot
 * @param {App} app
 */
export function createToolbar(root, clockRoot, mapRoot, app) {
  const { demo } = app;

  // ---- tools
  const toolButtons = new Map();
  for (const [tool, label, key, title] of TOOLS) {
    const b = el('button', {
      type: 'button', id: `tool-${tool}`, class: 'seg', title: `${title} (${key.toUpperCase()})`,
      onclick: () => app.emit('tool', tool),
    }, label);
    toolButtons.set(tool, b);
  }
  // ---- the brush: its size in cells or in metres, as the teacher chooses
  const brush = el('select', { id: 'brush', 'aria-label': t('brush.size') });
  const brushUnit = el('select', { id: 'brush-unit', 'aria-label': t('brush.unit'), title: t('brush.unit.title') },
    el('option', { value: 'cells' }, t('brush.cells')), el('option', { value: 'm' }, 'm'));
  const fillBrush = () => {
    const unit = brushUnit.value;
    const sizes = unit === 'm' ? BRUSHES.m : BRUSHES.cells;
    const keep = sizes.includes(app.ui.brush.size) && app.ui.brush.unit === unit ? app.ui.brush.size : sizes[unit === 'm' ? 2 : 0];
    brush.replaceChildren(...sizes.map((/** @type {number} */ n) => el('option', { value: n, selected: n === keep },
      unit === 'm' ? `${n} m` : `${n}×${n}`)));
    app.ui.brush = { size: keep, unit };
  };
  brushUnit.addEventListener('change', fillBrush);
  brush.addEventListener('change', () => { app.ui.brush = { size: Number(brush.value), unit: brushUnit.value }; });
  fillBrush();
  const brushBox = el('span', { class: 'brush', title: t('brush.title') }, t('brush.label'), brush, brushUnit);
  /** @param {string} tool */
  const showTool = (tool) => {
    for (const [t, b] of toolButtons) b.setAttribute('aria-pressed', String(t === tool));
    brushBox.hidden = !(tool === 'paint' || tool === 'erase');
  };
  app.on('tool', showTool);
  showTool(app.ui.tool);

  // ---- direction
  const dirButtons = {
    forward: el('button', { type: 'button', id: 'dir-forward', class: 'seg', title: t('dir.forward.title') }, t('dir.forward')),
    backward: el('button', { type: 'button', id: 'dir-backward', class: 'seg', title: t('dir.backward.title') }, t('dir.backward')),
  };
  const showDirection = () => {
    dirButtons.forward.setAttribute('aria-pressed', String(!app.ui.backward));
    dirButtons.backward.setAttribute('aria-pressed', String(app.ui.backward));
  };
  for (const [name, b] of Object.entries(dirButtons)) {
    b.addEventListener('click', () => {
      const backward = name === 'backward';
      if (app.ui.backward === backward) return;
      app.ui.backward = backward;
      showDirection();
      app.stage.resubmitDirection();
    });
  }
  app.on('loaded', () => {
    app.ui.backward = demo.plan().direction === 'backward';
    showDirection();
  });
  showDirection();

  // ---- Clear, SafeMode
  const clear = el('button', {
    type: 'button', id: 'clear', class: 'plain', title: t('clear.title'),
    onclick: () => { app.attempt(() => demo.clear()); app.notice.show(t('clear.notice'), 'info'); },
  }, t('clear.label'));
  const safe = el('button', {
    type: 'button', id: 'safe-mode', class: 'plain', title: t('safe.title'),
    onclick: () => { app.attempt(() => demo.safe_mode()); app.notice.show(t('safe.notice'), 'info'); },
  }, t('safe.label'));

  // ---- the clock
  const pause = el('button', { type: 'button', id: 'pause', class: 'plain', title: t('pause.title') }, t('pause.label'));
  const togglePause = () => {
    demo.set_paused(!demo.paused());
  };
  pause.addEventListener('click', togglePause);
  const step = el('button', {
    type: 'button', id: 'step', class: 'plain', title: t('step.title'),
    onclick: () => app.attempt(() => demo.step_ticks(1)),
  }, t('step.label'));
  const speed = el('select', { id: 'speed', title: t('speed.title') },
    ...SPEEDS.map((s) => el('option', { value: s, selected: s === 1 }, `${s}×`)));
  speed.addEventListener('change', () => {
    const r = app.attempt(() => demo.set_speed(Number(speed.value)));
    if (!r.ok) app.notice.show(r.error, 'error');
  });

  // ---- layers
  const layers = demo.layers();
  const layerBoxes = Object.keys(LAYER_NAMES).filter((k) => k in layers).map((name) => {
    const box = el('input', { type: 'checkbox', id: `layer-${name}`, checked: layers[/** @type {keyof Layers} */ (name)] });
    box.addEventListener('change', () => {
      const r = app.attempt(() => demo.set_layer(name, box.checked));
      if (!r.ok) app.notice.show(r.error, 'error');
      app.emit('layers');
    });
    return el('label', { class: 'layer' }, box, LAYER_NAMES[/** @type {keyof typeof LAYER_NAMES} */ (name)]);
  });
  const layerMenu = el('details', { class: 'menu', id: 'layers' },
    el('summary', { class: 'plain' }, t('layers.label')),
    el('div', { class: 'menu-body' }, ...layerBoxes));
  // The menu opens toward whichever side of the page has room.
  layerMenu.addEventListener('toggle', () => {
    const body = /** @type {HTMLElement} */ (layerMenu.querySelector('.menu-body'));
    body.classList.remove('to-right');
    if (layerMenu.open && body.getBoundingClientRect().left < 0) body.classList.add('to-right');
  });

  // A run carried across a change of language (js/carry.js): the controls show its settings.
  app.on('carried', () => {
    showDirection();
    speed.value = String(demo.speed());
    brushUnit.value = app.ui.brush.unit;
    fillBrush();
    const now = demo.layers();
    for (const label of layerBoxes) {
      const box = /** @type {HTMLInputElement} */ (label.querySelector('input'));
      box.checked = Boolean(now[/** @type {keyof Layers} */ (box.id.replace(/^layer-/, ''))]);
    }
  });

  // ---- zoom (over the map, top right)
  const zoomIn = el('button', { type: 'button', id: 'zoom-in', class: 'plain', title: t('zoom.in.title'), 'aria-label': t('zoom.in'), onclick: () => app.stage.zoomAt(1.5) }, '+');
  const zoomOut = el('button', { type: 'button', id: 'zoom-out', class: 'plain', title: t('zoom.out.title'), 'aria-label': t('zoom.out'), onclick: () => app.stage.zoomAt(1 / 1.5) }, '−');
  const zoomFit = el('button', { type: 'button', id: 'zoom-fit', class: 'plain', title: t('zoom.fit.title'), onclick: () => app.stage.fitView() }, t('zoom.fit'));
  mapRoot.append(zoomOut, zoomIn, zoomFit);
  const showZoom = () => {
    const z = demo.zoom();
    mapRoot.dataset.zoom = String(z);
    zoomFit.textContent = z > 1.0001 ? `${t('zoom.fit')} · ${z < 10 ? z.toFixed(1) : Math.round(z)}×` : t('zoom.fit');
    zoomFit.disabled = z <= 1.0001;
    zoomOut.disabled = z <= 1.0001;
  };
  app.on('view', showZoom);
  app.on('loaded', showZoom);

  root.append(
    el('div', { class: 'group', role: 'group', 'aria-label': t('tool.group') }, ...toolButtons.values()),
    brushBox,
    el('div', { class: 'group', role: 'group', 'aria-label': t('dir.group') }, dirButtons.forward, dirButtons.backward),
    el('div', { class: 'group plain-group' }, clear, safe),
    el('span', { class: 'spacer' }),
    layerMenu,
    // The keyboard guide (js/keys.js opens it; `?` too).
    el('button', { type: 'button', id: 'keys-open', class: 'plain', title: t('keys.open.title'), 'aria-keyshortcuts': '?' }, t('keys.open')),
  );
  clockRoot.append(pause, step, speed);

  // Keyboard: tools by letter, Space pauses, "." steps (not while typing in a field).
  window.addEventListener('keydown', (e) => {
    const t = e.target;
    if (t instanceof HTMLInputElement || t instanceof HTMLSelectElement || e.ctrlKey || e.metaKey || e.altKey) return;
    // Not under the keyboard guide (a modal dialog).
    if (document.querySelector('dialog[open]')) return;
    if (t instanceof HTMLButtonElement && (e.key === ' ' || e.key === 'Enter')) return;
    const tool = TOOLS.find((t) => t[2] === e.key.toLowerCase());
    if (tool) app.emit('tool', tool[0]);
    else if (e.key === ' ') { togglePause(); e.preventDefault(); }
    else if (e.key === '.') app.attempt(() => demo.step_ticks(1));
    else if (e.key === '+' || e.key === '=') app.stage.zoomAt(1.5);
    else if (e.key === '-') app.stage.zoomAt(1 / 1.5);
    else if (e.key === '0') app.stage.fitView();
  });

  return {
    /** Every frame: the clock's pause shown. @param {ClockView} clock */
    update(clock) {
      const { paused } = clock;
      if (pause.dataset.paused !== String(paused)) {
        pause.dataset.paused = String(paused);
        pause.textContent = paused ? t('run.label') : t('pause.label');
        pause.classList.toggle('active', paused);
        step.disabled = !paused;
      }
    },
  };
}
