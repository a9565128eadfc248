// @ts-check
// The hover inspector: what the core knows about the map cell under the mouse
// (`Demo.inspect`): its indices and its centre in metres, its occupancy, the distance to the
// nearest obstacle and whether that is within dmin, and LocalPathPlanning's potential there
// explained as G = G(parent) + R + A + P (000 §5.2.4.9: the parent's potential, repulsion
// from obstacles, attraction to the goal, the posture term) and the cell's state.
//
// The numbers are shown rounded; each value's exact JSON text is kept in `data-value`, and
// the whole answer from Rust in the panel's `data-json`, for the end-to-end test (which
// compares them with the native `rtnav inspect`). The cell under the mouse comes from the
// stage's `hover` event (`pixel_to_cell`); it is read again while shown, a few times a
// second, because the field changes as the robot drives.
import { el, setText } from '../dom.js';
import { t, has, fixed } from '../i18n.js';

const POLL_MS = 250;

/** A value of the answer, rounded (— for none). @param {number | null | undefined} v */
function num(v, digits = 3) {
  if (v === null || v === undefined) return '—';
  if (!Number.isFinite(v)) return String(v);
  const a = Math.abs(v);
  if (a !== 0 && (a >= 1e5 || a < 1e-3)) return v.toExponential(3);
  return fixed(v, digits);
}

/** A length in metres, two decimals. @param {number} v */
const metres = (v) => `${fixed(v, 2)} m`;

/**
 * A row: key, label, how to read it from the answer, how to show it, a hint.
 * @typedef {[key: string, label: string, read: (j: CellInspection) => unknown, show: (v: unknown) => string, hint: string]} Row
 */
/**
 * A row whose `show` takes what its `read` gives.
 * @template T
 * @param {string} key
 * @param {string} label
 * @param {(j: CellInspection) => T} read
 * @param {(v: T) => string} show
 * @param {string} hint
 * @returns {Row}
 */
const row = (key, label, read, show, hint) => [key, label, read, /** @type {(v: unknown) => string} */ (show), hint];

/** The rows. @type {Row[]} */
const FIELDS = [
  row('cell', t('inspector.cell'), (j) => [j.x, j.y], (v) => `(${v[0]}, ${v[1]})`, t('inspector.cell.title')),
  row('centre', t('inspector.centre'), (j) => j.centre, (v) => `x ${metres(v[0])}, y ${metres(v[1])}`, t('inspector.centre.title')),
  row('occupancy', t('inspector.occupancy'), (j) => j.occupancy, (v) => `${v} · ${t(v === 0 ? 'inspector.free' : 'inspector.obstacle')}`, t('inspector.occupancy.title')),
  row('obstacle_distance', t('inspector.obstacle_distance'), (j) => j.obstacle_distance, (v) => `${num(v)} m`, t('inspector.obstacle_distance.title')),
  row('impassable', t('inspector.impassable'), (j) => j.impassable, (v) => (v ? t('inspector.impassable.yes') : t('inspector.no')), t('inspector.impassable.title')),
  row('potential', t('inspector.potential'), (j) => j.field?.potential ?? null, num, t('inspector.potential.title')),
  row('parent', t('inspector.parent'), (j) => j.field?.parent ?? null, (v) => (v ? t('inspector.parent.value', { g: num(v.potential), x: v.x, y: v.y }) : '—'),
    t('inspector.parent.title')),
  row('repulsion', t('inspector.repulsion'), (j) => j.field?.repulsion ?? null, num, t('inspector.repulsion.title')),
  row('attraction', t('inspector.attraction'), (j) => j.field?.attraction ?? null, num, t('inspector.attraction.title')),
  row('posture', t('inspector.posture'), (j) => j.field?.posture ?? null, num, t('inspector.posture.title')),
  row('state', t('inspector.state'), (j) => j.field?.state ?? null, (v) => (v === null ? '—' : has(`inspector.state.${v}`) ? t(`inspector.state.${v}`) : v), t('inspector.state.title')),
];

/**
 * @param {HTMLElement} root the Inspector tab's section
 * @param {App} app
 */
export function createInspector(root, app) {
  const { demo } = app;
  /** The cell inspected (column, row), or null before the mouse was over the map. @type {[number, number] | null} */
  let cell = null;
  let hovering = false;
  let dirty = false;
  let lastPoll = -Infinity;
  let lastJson = '';

  const where = el('p', { class: 'panel-hint', id: 'inspector-where' }, t('inspector.move'));
  const list = el('dl', { class: 'inspector', id: 'inspector' });
  /** @type {Map<string, HTMLElement>} */
  const values = new Map();
  for (const [key, label, , , hint] of FIELDS) {
    const dd = el('dd', { dataset: { key } }, '—');
    values.set(key, dd);
    list.append(el('div', { class: 'inspect-row', dataset: { key } }, el('dt', { title: hint }, label), dd));
  }
  const error = el('p', { class: 'param-error', hidden: true });
  root.append(
    el('div', { class: 'panel-head' }, el('h2', {}, t('inspector.title'))),
    where, list, error,
    el('p', { class: 'panel-hint small', id: 'inspector-sum' },
      t('inspector.sum')),
  );

  function clearValues() {
    for (const dd of values.values()) {
      setText(dd, '—');
      delete dd.dataset.value;
    }
    delete root.dataset.json;
    delete root.dataset.cell;
    lastJson = '';
  }

  function inspect() {
    if (!cell) return;
    const [x, y] = cell;
    const r = app.attempt(() => demo.inspect(x, y));
    if (!r.ok) {
      error.textContent = r.error;
      error.hidden = false;
      clearValues();
      return;
    }
    error.hidden = true;
    const j = r.value;
    if (!j) return; // the page crashed: nothing to show
    const text = JSON.stringify(j);
    if (text === lastJson) return;
    lastJson = text;
    root.dataset.json = text;
    root.dataset.cell = `${j.x},${j.y}`;
    for (const [key, , read, fmt] of FIELDS) {
      const v = read(j);
      const dd = /** @type {HTMLElement} */ (values.get(key));
      dd.dataset.value = JSON.stringify(v);
      setText(dd, fmt(v));
    }
    const field = j.field ? '' : t('inspector.no_field');
    const at = t('inspector.at', { x: j.x, y: j.y, cx: metres(j.centre[0]), cy: metres(j.centre[1]) });
    setText(where, t(hovering ? 'inspector.under' : 'inspector.last', { at, field }));
  }

  app.on('hover', (c) => {
    hovering = Boolean(c);
    if (!c) {
      if (cell) setText(where, t('inspector.last', { at: `(${cell[0]}, ${cell[1]})`, field: '' }));
      return;
    }
    if (cell && c[0] === cell[0] && c[1] === cell[1]) return;
    cell = [c[0], c[1]];
    dirty = true;
  });
  app.on('loaded', () => {
    cell = null;
    clearValues();
    error.hidden = true;
    setText(where, t('inspector.move'));
  });
  app.on('tab', (name) => { if (name === 'inspector') dirty = true; });

  return {
    /**
     * Called every frame: inspects a new cell at once, the same cell a few times a second.
     * @param {number} now the frame's time [ms]
     * @param {boolean} visible whether the Inspector tab is shown
     */
    update(now, visible) {
      if (!visible || !cell) return;
      if (dirty || now - lastPoll >= POLL_MS) {
        dirty = false;
        lastPoll = now;
        inspect();
      }
    },
    /**
     * The last answer, parsed (or null).
     * @returns {CellInspection | null}
     */
    get last() {
      return lastJson ? JSON.parse(lastJson) : null;
    },
  };
}
