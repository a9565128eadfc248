// @ts-check
// The parameter panel: every configuration parameter of LocalPathPlanning,
// MotorControl, DriveControl and PhysicsSim (`Demo.params()`), grouped by component, with its
// unit, range and reflection timing (OpenRTM's 常時 "always" or 初期化時 "on activation").
//
// A value is edited in place (Enter or leaving the field sends it: `set_param`). Rust decides
// whether it is good; a refused value is explained next to the field and the field goes back
// to the value held. An `on_activation` parameter whose new value waits for the component's
// next activation is marked "pending (next activation)" until it is in use. MotorControl's
// service `Motor::SetPDGain` has its own small form, and the whole configuration can be
// saved and loaded as one OpenRTM `.conf` file.
//
// The panel reads `params()` when the system changes (app events `loaded`, `changed`)
// and every half second while it is shown — never every frame. Rows carry the raw values
// (`data-value`, `data-effective`, `data-pending`) for the end-to-end tests.
import { el, setText } from '../dom.js';
import { downloadText } from '../download.js';
import { t, has, language } from '../i18n.js';
import { warningText } from '../say.js';

const POLL_MS = 500;
/** A reflection timing's label and hint (another: its name as the core gives it). @type {Record<string, [string, string] | undefined>} */
const REFLECTION = {
  always: [t('params.always'), t('params.always.title')],
  on_activation: [t('params.on_activation'), t('params.on_activation.title')],
};
/** SetPDGain's arguments: the parameter each sets, and its label. @type {Array<[string, string]>} */
const PD_GAINS = [['PGainL', t('params.pd.p_left')], ['PGainR', t('params.pd.p_right')], ['DGainL', t('params.pd.d_left')], ['DGainR', t('params.pd.d_right')]];
/** Notes beside a parameter, about the system as a whole. @type {Record<string, string | undefined>} */
const NOTES = {
  'LocalPathPlanning/dmin': t('params.dmin_note'),
};

/** A parameter's value as text that reads back as the same number. @param {number | null | undefined} v */
const show = (v) => (v === null || v === undefined ? '' : String(v));
/** A unit as shown (– for none). @param {string} u */
const unitText = (u) => (!u || u === '-' ? '–' : u);

/**
 * A parameter's name with a break allowed between its words (`Posture<wbr>Consideration<wbr>Level`).
 * @param {string} name
 * @returns {Array<Node | string>}
 */
function wordsOf(name) {
  return name.split(/(?<=[a-z0-9])(?=[A-Z])/).flatMap((w, i) => (i ? [el('wbr'), w] : [w]));
}

/**
 * One parameter's row.
 * @typedef {object} Row
 * @property {HTMLDivElement} node
 * @property {HTMLInputElement} input the value, edited in place
 * @property {HTMLSpanElement} pendingTag "pending (next activation)"
 * @property {HTMLDivElement} error why a value was refused
 * @property {HTMLDivElement} warning the core's warning about the value held
 * @property {string} component
 * @property {string} name
 */
/**
 * MotorControl's SetPDGain form: its inputs by the parameter each sets, and the stability bounds.
 * @typedef {{ inputs: Map<string, HTMLInputElement>, bounds: HTMLSpanElement }} PdForm
 */
/**
 * One component's group of rows.
 * @typedef {{ details: HTMLDetailsElement, list: HTMLDivElement, count: HTMLSpanElement, pd?: PdForm }} Group
 */

/**
 * @param {HTMLElement} root the Parameters tab's section
 * @param {App} app
 */
export function createParamsPanel(root, app) {
  const { demo } = app;
  let last = '';
  let dirty = true;
  let lastPoll = -Infinity;
  /** @type {Map<string, Row>} */
  const rows = new Map();
  /** @type {Map<string, Group>} */
  const groups = new Map();
  /** The latest `params()`, by `component/name`. @type {Map<string, ParameterView>} */
  const held = new Map();

  // ---------------------------------------------------------------- head: .conf files
  const message = el('p', { class: 'panel-message', id: 'conf-message', role: 'status', hidden: true });
  /** @param {string} text @param {string} level */
  const say = (text, level) => {
    message.textContent = text;
    message.dataset.level = level;
    message.hidden = !text;
  };
  const exportButton = el('button', {
    type: 'button', class: 'secondary', id: 'conf-export',
    title: t('params.export.title'),
    onclick: () => {
      const r = app.attempt(() => demo.conf_export());
      if (!r.ok) return say(t('params.export.failed', { error: r.error }), 'error');
      if (r.value === undefined) return undefined; // the page crashed
      downloadText(r.value, 'rtnav.conf');
      say(t('params.export.saved'), 'success');
    },
  }, t('params.export'));
  const importInput = el('input', { type: 'file', id: 'conf-import', accept: '.conf,text/plain' });
  importInput.addEventListener('change', async () => {
    const file = importInput.files?.[0];
    importInput.value = '';
    if (!file) return;
    const text = await file.text();
    const r = app.attempt(() => demo.conf_import(text));
    if (!r.ok) {
      say(t('params.import.refused', { file: file.name, error: r.error }), 'error');
      app.log.page(t('refused', { what: t('params.import.what'), error: r.error }), 'warn');
      return;
    }
    say(t('params.import.done', { file: file.name }), 'success');
    app.log.page(t('params.imported', { file: file.name }), 'info');
    app.emit('changed');
  });
  const importButton = el('label', {
    class: 'file-button light', title: t('params.import.title'),
  }, t('params.import'), importInput);

  const body = el('div', { class: 'param-groups', id: 'param-groups' });
  root.append(
    el('div', { class: 'panel-head' }, el('h2', {}, t('params.title')),
      el('span', { class: 'head-actions' }, exportButton, importButton)),
    el('p', { class: 'panel-hint' }, t('params.hint')),
    message,
    body,
  );

  // ---------------------------------------------------------------- rows

  /** Sends a value typed in `row`'s field. @param {Row} row @param {string} text */
  function send(row, text) {
    const { component, name } = row;
    const r = app.attempt(() => demo.set_param(component, name, text));
    if (!r.ok) {
      row.error.textContent = r.error;
      row.error.hidden = false;
      row.node.classList.add('refused');
      const p = held.get(`${component}/${name}`);
      row.input.value = show(p?.value);
      app.log.page(t('refused', { what: `${component}.${name} = ${text}`, error: r.error }), 'warn');
    } else {
      // The core logs the change itself (ParameterSet).
      row.error.hidden = true;
      row.node.classList.remove('refused');
    }
    dirty = true;
    refresh();
    if (r.ok) row.input.value = show(held.get(`${component}/${name}`)?.value);
    app.emit('changed');
  }

  /** @param {Group} group @param {ComponentParameters} c @param {ParameterView} p @returns {Row} */
  function makeRow(group, c, p) {
    const id = `param-${c.component}-${p.name}`;
    const input = el('input', {
      type: 'text', id, class: 'param-input', inputmode: 'decimal', spellcheck: 'false', autocomplete: 'off',
      'aria-describedby': `${id}-desc ${id}-meta`,
    });
    const [reflectText, reflectTitle] = REFLECTION[p.reflection] ?? [p.reflection, ''];
    const pendingTag = el('span', { class: 'pending-tag', hidden: true });
    const error = el('div', { class: 'param-error', role: 'alert', hidden: true });
    const warning = el('div', { class: 'param-warning', role: 'status', hidden: true });
    const about = NOTES[`${c.component}/${p.name}`];
    // The description in the page's language: the seed's own Japanese, else the catalogue's.
    const described = language() === 'ja' ? (p.seed_text ?? t(`param.${c.component}.${p.name}`)) : p.description;
    const node = el('div', { class: 'param', dataset: { component: c.component, name: p.name, reflection: p.reflection } },
      el('label', { class: 'param-name', for: id, title: described }, ...wordsOf(p.name)),
      input,
      el('span', { class: 'param-unit' }, unitText(p.unit)),
      el('div', { class: 'param-desc', id: `${id}-desc` },
        language() === 'ja'
          ? el('span', { class: 'param-ja', lang: 'ja' }, described)
          : el('span', { class: 'param-en' }, p.description),
        p.seed_text && language() !== 'ja' ? el('span', { class: 'param-ja', lang: 'ja', title: t('params.seed_words') }, p.seed_text) : null,
        about ? el('span', { class: 'param-note' }, about) : null),
      el('div', { class: 'param-meta', id: `${id}-meta` },
        el('span', { class: 'param-range', title: p.type === 'int' ? t('params.int') : t('params.real') }, `${has(`params.type.${p.type}`) ? t(`params.type.${p.type}`) : p.type} ${p.range}`),
        el('span', { class: 'param-reflection', title: reflectTitle }, reflectText),
        pendingTag),
      warning,
      error);
    const row = { node, input, pendingTag, error, warning, component: c.component, name: p.name };
    input.addEventListener('change', () => send(row, input.value.trim()));
    input.addEventListener('keydown', (e) => {
      if (e.key === 'Escape') {
        input.value = show(held.get(`${c.component}/${p.name}`)?.value);
        input.blur();
      }
    });
    group.list.append(node);
    rows.set(`${c.component}/${p.name}`, row);
    return row;
  }

  /** @param {ComponentParameters} c @returns {Group} */
  function makeGroup(c) {
    const count = el('span', { class: 'group-count' });
    const list = el('div', { class: 'param-list' });
    const details = el('details', { class: 'param-group', open: true, dataset: { component: c.component } },
      el('summary', {}, el('span', { class: 'group-name' }, c.component), count),
      list);
    body.append(details);
    /** @type {Group} */
    const group = { details, list, count };
    groups.set(c.component, group);
    if (c.component === 'MotorControl') group.pd = makePdForm(details);
    return group;
  }

  // ---------------------------------------------------------------- SetPDGain
  /** @param {HTMLDetailsElement} details MotorControl's group @returns {PdForm} */
  function makePdForm(details) {
    /** @type {Map<string, HTMLInputElement>} */
    const inputs = new Map();
    const error = el('div', { class: 'param-error', role: 'alert', hidden: true });
    const fields = PD_GAINS.map(([name, label]) => {
      const input = el('input', { type: 'text', inputmode: 'decimal', id: `pd-${name}`, class: 'param-input', autocomplete: 'off', spellcheck: 'false' });
      inputs.set(name, input);
      return el('label', { class: 'pd-field' }, el('span', {}, label), input);
    });
    const number = (/** @type {string} */ t) => (t.trim() === '' ? Number.NaN : Number(t));
    const bounds = el('span', { class: 'pd-bounds', id: 'pd-bounds' });
    const explain = el('div', { class: 'pd-explain', id: 'pd-explain' },
      el('p', {}, t('params.pd.explain')),
      el('p', {}, t('params.pd.stability'), ' ', bounds));
    const form = el('form', { class: 'pd-form', id: 'pd-form', title: t('params.pd.title') },
      explain,
      el('div', { class: 'pd-title' }, t('params.pd.service')),
      el('div', { class: 'pd-fields' }, ...fields,
        el('button', { type: 'submit', id: 'pd-send' }, 'SetPDGain')),
      error);
    form.addEventListener('submit', (e) => {
      e.preventDefault();
      const [pl, pr, dl, dr] = PD_GAINS.map(([n]) => number(/** @type {HTMLInputElement} */ (inputs.get(n)).value));
      const r = app.attempt(() => demo.set_pd_gain(pl, pr, dl, dr));
      if (!r.ok) {
        error.textContent = r.error;
        error.hidden = false;
        app.log.page(t('refused', { what: 'SetPDGain', error: r.error }), 'warn');
        for (const [n, input] of inputs) input.value = show(held.get(`MotorControl/${n}`)?.value);
      } else {
        // The core logs the call itself (GainsSet).
        error.hidden = true;
      }
      dirty = true;
      refresh();
      app.emit('changed');
    });
    /** @type {HTMLElement} */ (details.querySelector('summary')).after(form);
    return { inputs, bounds };
  }

  // ---------------------------------------------------------------- refresh

  function refresh() {
    const r = app.attempt(() => demo.params());
    if (!r.ok || r.value === undefined) return;
    const text = JSON.stringify(r.value);
    dirty = false;
    if (text === last) return;
    last = text;
    const components = r.value;
    held.clear();
    for (const c of components) {
      const group = groups.get(c.component) ?? makeGroup(c);
      let pending = 0;
      for (const p of c.params) {
        const key = `${c.component}/${p.name}`;
        held.set(key, p);
        const row = rows.get(key) ?? makeRow(group, c, p);
        if (document.activeElement !== row.input) row.input.value = show(p.value);
        const d = row.node.dataset;
        d.value = show(p.value);
        d.effective = show(p.effective);
        d.pending = String(Boolean(p.pending));
        row.node.classList.toggle('pending', Boolean(p.pending));
        row.pendingTag.hidden = !p.pending;
        setText(row.pendingTag, p.pending ? t('params.pending', { value: show(p.effective) }) : '');
        row.node.classList.toggle('changed', p.value !== p.default);
        row.node.classList.toggle('warned', Boolean(p.warning));
        row.node.dataset.warning = p.warning?.kind ?? '';
        setText(row.warning, p.warning ? `⚠ ${warningText(p.warning)}` : '');
        row.warning.hidden = !p.warning;
        row.node.title = p.value !== p.default ? t('params.default', { value: show(p.default) }) : '';
        if (p.pending) pending++;
      }
      setText(group.count, t(pending ? 'params.count.pending' : 'params.count', { n: c.params.length, pending }));
      if (group.pd) {
        for (const [n, input] of group.pd.inputs) {
          if (document.activeElement !== input) input.value = show(held.get(`MotorControl/${n}`)?.value);
        }
        // The bounds now: 2·D/Δt for each wheel.
        const dt = c.period_s;
        const bound = (/** @type {string} */ d) => Number((2 * (held.get(`MotorControl/${d}`)?.value ?? Number.NaN) / dt).toPrecision(6));
        setText(group.pd.bounds, t('params.pd.bounds', { dt: Number((dt * 1000).toPrecision(6)), left: bound('DGainL'), right: bound('DGainR') }));
      }
    }
  }

  app.on('loaded', () => {
    dirty = true;
    say('', 'info');
    for (const row of rows.values()) {
      row.error.hidden = true;
      row.node.classList.remove('refused');
    }
  });
  app.on('changed', () => { dirty = true; });
  app.on('tab', (name) => { if (name === 'params') dirty = true; });

  return {
    /**
     * Called every frame: reads the parameters when something changed, else twice a second.
     * @param {number} now the frame's time [ms]
     * @param {boolean} visible whether the Parameters tab is shown
     */
    update(now, visible) {
      if (!visible) return;
      if (dirty || now - lastPoll >= POLL_MS) {
        lastPoll = now;
        refresh();
      }
    },
    refresh,
  };
}
