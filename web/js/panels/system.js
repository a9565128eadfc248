// @ts-check
// The System tab: the system as RT System Editor draws it — every RT-component a
// box in its state's colour, its data ports and service ports as markers on the box, the
// connections as lines — laid out from the core's own description (`demo.system_graph()`,
// rtnav::system::SystemGraph), never drawn by hand: a component, port or connection the core
// adds appears here.
//
// Live: a port whose count grew pulses (at most every UPDATE_MS, whatever the speed); hovering
// or tapping a port shows its IDL type (or interface) and its newest sample with its
// timestamp, or a service port's last call. Acting on the picture: a tapped box gets
// Activate, Deactivate, Reset and Inject fault (RT System Editor's context menu); a tapped
// port lists its connections, and a data connection between two components can be cut and
// restored — a request the core logs (`Input::CutConnection`).
import { el, setText, textOn } from '../dom.js';
import { t, has } from '../i18n.js';
import { activityText } from '../say.js';

const SVG = 'http://www.w3.org/2000/svg';
/** How often the view reads the description while shown [ms]. */
const UPDATE_MS = 250;
/** The diagram's units: box width, header, status line and port row heights, gaps. */
const BOX_W = 210;
const HEAD_H = 22;
const STATUS_H = 14;
const ROW_H = 13;
const GAP_X = 64;
const GAP_Y = 26;
const PAD = 12;
/** Which side of the box a port sits on. */
const LEFT = new Set(['in', 'provided']);
/** A port's kind in words (`system.kind.in`, …). @param {PortKind} kind */
const kindWords = (kind) => (has(`system.kind.${kind}`) ? t(`system.kind.${kind}`) : kind);
const GUI_NOTE = t('system.gui_note');

/**
 * An SVG element: `svg('rect', { x, y, class }, child…)`.
 * @template {keyof SVGElementTagNameMap} K
 * @param {K} tag
 * @param {Record<string, string | number | boolean | null | undefined>} [attrs]
 * @param {...(Node | string | null | undefined)} children
 * @returns {SVGElementTagNameMap[K]}
 */
function svg(tag, attrs = {}, ...children) {
  const node = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (v === undefined || v === null || v === false) continue;
    node.setAttribute(k, String(v));
  }
  node.append(...children.filter((c) => c !== null && c !== undefined));
  return node;
}

/** A port's key: `component.port`. @param {string} component @param {string} port */
const portKey = (component, port) => `${component}.${port}`;

/**
 * A component's box before it is placed: its ports on the left (in, provided) and on the
 * right (out, required), its height and column.
 * @typedef {{ c: GraphComponent, left: GraphPort[], right: GraphPort[], h: number, col: number }} Box
 */
/** A box placed (its top left corner). @typedef {Box & { x: number, y: number }} PlacedBox */
/** A port placed: where its marker is, on which side, and whose it is. @typedef {{ x: number, y: number, left: boolean, port: GraphPort, box: string }} PlacedPort */
/**
 * The diagram's layout: the boxes by component, the ports by `portKey`, the size.
 * @typedef {{ boxes: Map<string, PlacedBox>, ports: Map<string, PlacedPort>, width: number, height: number }} Geometry
 */

/**
 * Boxes in the description's order (data-flow order), `cols` to a row; ports in rows.
 * @param {SystemGraph} graph
 * @param {number} cols
 * @returns {Geometry}
 */
function layout(graph, cols) {
  /** @type {Map<string, PlacedBox>} */
  const boxes = new Map();
  /** @type {Box[][]} */
  const rows = [];
  graph.components.forEach((c, i) => {
    const left = c.ports.filter((p) => LEFT.has(p.kind));
    const right = c.ports.filter((p) => !LEFT.has(p.kind));
    const h = HEAD_H + STATUS_H + (left.length + right.length) * ROW_H + 6;
    const row = Math.floor(i / cols);
    (rows[row] ??= []).push({ c, left, right, h, col: i % cols });
  });
  /** @type {Map<string, PlacedPort>} */
  const ports = new Map();
  let y = PAD;
  for (const row of rows) {
    const rowH = Math.max(...row.map((b) => b.h));
    for (const b of row) {
      const x = PAD + b.col * (BOX_W + GAP_X);
      boxes.set(b.c.name, { ...b, x, y });
      let py = y + HEAD_H + STATUS_H + ROW_H / 2 + 2;
      for (const p of b.left) {
        ports.set(portKey(b.c.name, p.name), { x, y: py, left: true, port: p, box: b.c.name });
        py += ROW_H;
      }
      for (const p of b.right) {
        ports.set(portKey(b.c.name, p.name), { x: x + BOX_W, y: py, left: false, port: p, box: b.c.name });
        py += ROW_H;
      }
    }
    y += rowH + GAP_Y;
  }
  const width = PAD * 2 + cols * BOX_W + (cols - 1) * GAP_X;
  return { boxes, ports, width, height: y - GAP_Y + PAD };
}

/**
 * A curve from an out-port (right edge) to an in-port (left edge), around the boxes' sides.
 * @param {PlacedPort} a
 * @param {PlacedPort} b
 */
function curve(a, b) {
  const d = Math.max(36, Math.abs(b.x - a.x) / 2);
  const ax = a.left ? a.x - d : a.x + d;
  const bx = b.left ? b.x - d : b.x + d;
  return `M${a.x},${a.y} C${ax},${a.y} ${bx},${b.y} ${b.x},${b.y}`;
}

/**
 * A port in lines: what it is, its operations (a service port's), its newest sample or last
 * call, how many it carried.
 * @param {string} component
 * @param {GraphPort} p
 * @returns {string[]}
 */
function describePort(component, p) {
  const head = `${component}.${p.name} · ${kindWords(p.kind)} · ${p.interface}`;
  const ops = p.operations?.length ? t('system.operations', { names: p.operations.join(', ') }) : null;
  const service = p.kind === 'provided' || p.kind === 'required';
  const last = p.last ? p.last.text : t(service ? 'system.no_call' : 'system.no_sample');
  return /** @type {string[]} */ ([head, ops, last, t(service ? 'system.calls' : 'system.samples', { n: p.count })].filter(Boolean));
}

/**
 * The element matching `selector` at or around the event's target (the diagram's are SVG).
 * @param {Event} e
 * @param {string} selector
 * @returns {SVGElement | null}
 */
const around = (e, selector) => (e.target instanceof Element ? e.target.closest(selector) : null);

/**
 * @param {HTMLElement} root the System tab's section
 * @param {App} app
 */
export function createSystemPanel(root, app) {
  const { demo } = app;
  /** The description last read. @type {SystemGraph | null} */
  let graph = null;
  /** @type {Geometry | null} */
  let geometry = null;
  let cols = 0;
  let shape = '';
  let last = -Infinity;
  /** @type {string | null} */
  let selectedBox = null;
  /** @type {string | null} */
  let selectedPort = null;
  /** @type {string | null} */
  let hoverPort = null;
  /** Each port's count when last painted (a grown one pulses). @type {Map<string, number>} */
  const counts = new Map();
  /** @type {Map<string, { g: SVGGElement, marker: SVGCircleElement | SVGRectElement }>} */
  const portNodes = new Map();
  /** @type {Map<string, { g: SVGGElement, head: SVGRectElement, title: SVGTextElement, state: SVGTextElement, status: SVGTextElement }>} */
  const boxNodes = new Map();
  /** @type {Map<string, SVGPathElement>} */
  const lineNodes = new Map();
  /** The frame's components (their colours, states and activities). @type {ComponentView[]} */
  let components = [];

  /** @param {string} what @param {() => unknown} fn */
  const request = (what, fn, ends = false) => {
    const r = app.request(what, fn, ends);
    last = -Infinity;
    return r;
  };

  // ------------------------------------------------------------------ the frame

  const picture = svg('svg', { class: 'system-svg', role: 'group', 'aria-label': t('system.picture.aria') });
  const wrap = el('div', { class: 'system-wrap', id: 'system-diagram' }, picture);
  const tooltip = el('div', { class: 'system-tip', id: 'system-tip', role: 'tooltip', hidden: true });
  wrap.append(tooltip);

  const actTitle = el('span', { class: 'system-act-title' });
  const buttons = {
    activate: el('button', { type: 'button', 'data-act': 'activate' }, t('rtc.activate')),
    deactivate: el('button', { type: 'button', class: 'secondary', 'data-act': 'deactivate' }, t('rtc.deactivate')),
    reset: el('button', { type: 'button', class: 'secondary', 'data-act': 'reset' }, t('rtc.reset')),
    fault: el('button', { type: 'button', class: 'danger', 'data-act': 'fault' }, t('rtc.fault')),
  };
  for (const [key, b] of Object.entries(buttons)) {
    const act = /** @type {keyof typeof buttons} */ (key);
    b.addEventListener('click', () => {
      if (!selectedBox) return;
      const name = selectedBox;
      if (act === 'fault') request(t('rtc.fault.request', { name }), () => demo.inject_fault(name));
      else request(t(`system.act.${act}`, { name }), () => demo[act](name), act === 'activate' || act === 'reset');
    });
  }
  const actions = el('div', { class: 'system-actions', id: 'system-actions', role: 'group', 'aria-label': t('system.actions.aria') },
    actTitle, el('span', { class: 'system-act-buttons' }, ...Object.values(buttons)));

  const details = el('div', { class: 'system-details', id: 'system-details', 'aria-live': 'polite' });

  root.append(
    el('div', { class: 'panel-head' },
      el('h2', {}, t('system.title')),
      el('span', { class: 'legend' },
        ...[['#0000ff', 'Inactive'], ['#00ff00', 'Active'], ['#ff0000', 'Error']].map(([c, state]) =>
          el('span', { class: 'legend-item' }, el('span', { class: 'swatch', style: `--c:${c}` }), t(`state.${state}`))))),
    el('p', { class: 'panel-hint' },
      t('system.hint')),
    actions,
    wrap,
    details,
  );

  // ------------------------------------------------------------------ drawing

  /** Draws the diagram of `graph` anew. @param {SystemGraph} graph */
  function build(graph) {
    picture.replaceChildren();
    portNodes.clear();
    boxNodes.clear();
    lineNodes.clear();
    const geo = layout(graph, cols);
    geometry = geo;
    picture.setAttribute('viewBox', `0 0 ${geo.width} ${geo.height}`);
    picture.style.aspectRatio = `${geo.width} / ${geo.height}`;
    const lines = svg('g', { class: 'sys-lines' });
    for (const e of graph.connections) {
      const a = geo.ports.get(portKey(e.from.component, e.from.port));
      const b = geo.ports.get(portKey(e.to.component, e.to.port));
      if (!a || !b) continue;
      const path = svg('path', { d: curve(a, b), class: `sys-line ${e.kind}`, 'data-id': e.id });
      path.append(svg('title', {}, `${e.id.replace('->', ' → ')} (${e.interface})`));
      lines.append(path);
      lineNodes.set(e.id, path);
    }
    const boxes = svg('g', { class: 'sys-boxes' });
    for (const [name, b] of geo.boxes) {
      const g = svg('g', { class: `sys-box${b.c.rtc ? '' : ' gui'}`, 'data-component': name, tabindex: 0, role: 'button',
        'aria-label': b.c.rtc ? t('system.box.aria', { name: b.c.instance_name }) : 'InventGUI' });
      const body = svg('rect', { x: b.x, y: b.y, width: BOX_W, height: b.h, rx: 5, class: 'sys-body' });
      const head = svg('rect', { x: b.x, y: b.y, width: BOX_W, height: HEAD_H, rx: 5, class: 'sys-head' });
      const title = svg('text', { x: b.x + 7, y: b.y + 15, class: 'sys-title' }, b.c.instance_name);
      const state = svg('text', { x: b.x + BOX_W - 7, y: b.y + 15, class: 'sys-state', 'text-anchor': 'end' }, b.c.state ?? '');
      const status = svg('text', { x: b.x + 7, y: b.y + HEAD_H + 11, class: 'sys-status' }, b.c.rtc ? '' : t('system.gui_status'));
      g.append(body, head, title, state, status);
      for (const p of [...b.left, ...b.right]) {
        const at = /** @type {PlacedPort} */ (geo.ports.get(portKey(name, p.name)));
        const service = p.kind === 'provided' || p.kind === 'required';
        const marker = service
          ? svg('circle', { cx: at.x, cy: at.y, r: 4, class: `sys-port ${p.kind}` })
          : svg('rect', { x: at.x - 4, y: at.y - 4, width: 8, height: 8, class: `sys-port ${p.kind}` });
        const label = svg('text', {
          x: at.left ? at.x + 8 : at.x - 8, y: at.y + 3.2, class: `sys-label ${p.kind}`,
          'text-anchor': at.left ? 'start' : 'end',
        }, p.name);
        // A wide, invisible target: the whole row, so a finger can hit it.
        const hit = svg('rect', {
          x: b.x, y: at.y - ROW_H / 2, width: BOX_W, height: ROW_H, class: 'sys-hit',
          'data-port': p.name, 'data-component': name, 'data-kind': p.kind,
        });
        const pg = svg('g', { class: 'sys-port-row', 'data-port': p.name, 'data-component': name, 'data-kind': p.kind }, label, marker, hit);
        g.append(pg);
        portNodes.set(portKey(name, p.name), { g: pg, marker });
      }
      boxNodes.set(name, { g, head, title, state, status });
      boxes.append(g);
    }
    picture.append(lines, boxes);
  }

  /** The port `name` of `component` in the description last read. @param {string} component @param {string} name */
  function port(component, name) {
    return graph?.components.find((c) => c.name === component)?.ports.find((p) => p.name === name);
  }

  /**
   * Shows the port `key`'s lines beside it (under the pointer of `event`, if given).
   * @param {string} key
   * @param {PointerEvent | MouseEvent} [event]
   */
  function showTip(key, event) {
    const at = geometry?.ports.get(key);
    const node = portNodes.get(key);
    if (!at || !node) return;
    hoverPort = key;
    const p = port(at.box, at.port.name);
    if (!p) return; // the layout is of the description read: never
    tooltip.replaceChildren(...describePort(at.box, p).map((line, i) => el('div', { class: i === 0 ? 'tip-head' : null }, line)));
    tooltip.hidden = false;
    const r = node.marker.getBoundingClientRect();
    const w = wrap.getBoundingClientRect();
    const x = (event?.clientX ?? r.left + r.width / 2) - w.left + wrap.scrollLeft;
    const y = r.bottom - w.top + wrap.scrollTop + 6;
    tooltip.style.left = `${Math.max(0, Math.min(x - 40, wrap.clientWidth - tooltip.offsetWidth - 4))}px`;
    tooltip.style.top = `${y}px`;
  }

  function hideTip() {
    hoverPort = null;
    tooltip.hidden = true;
  }

  /** @param {string} key */
  function selectPort(key) {
    selectedPort = key;
    const at = geometry?.ports.get(key);
    if (at && graph?.components.find((c) => c.name === at.box)?.rtc) selectedBox = at.box;
    paint();
  }

  /** The port row's key (its `data-component` and `data-port`). @param {SVGElement} row */
  const rowKey = (row) => portKey(row.dataset.component ?? '', row.dataset.port ?? '');
  picture.addEventListener('pointerover', (e) => {
    const row = around(e, '.sys-port-row');
    if (row) showTip(rowKey(row), e);
  });
  picture.addEventListener('pointerout', (e) => {
    const row = around(e, '.sys-port-row');
    if (row && !row.contains(/** @type {Node | null} */ (e.relatedTarget))) hideTip();
  });
  picture.addEventListener('click', (e) => {
    const row = around(e, '.sys-port-row');
    if (row) {
      const key = rowKey(row);
      selectPort(key);
      showTip(key, e);
      return;
    }
    const box = around(e, '.sys-box');
    if (box) {
      const c = graph?.components.find((x) => x.name === box.dataset.component);
      selectedBox = c?.rtc ? c.name : null;
      selectedPort = null;
      if (!c?.rtc) details.replaceChildren(el('p', { class: 'panel-hint' }, GUI_NOTE));
      paint();
    }
  });
  picture.addEventListener('keydown', (e) => {
    if (e.key !== 'Enter' && e.key !== ' ') return;
    const box = around(e, '.sys-box');
    if (!box) return;
    const c = graph?.components.find((x) => x.name === box.dataset.component);
    selectedBox = c?.rtc ? c.name : null;
    selectedPort = null;
    paint();
    e.preventDefault();
  });

  // ------------------------------------------------------------------ live state

  function paintDetails() {
    if (!selectedPort) {
      if (details.dataset.port) details.replaceChildren();
      delete details.dataset.port;
      return;
    }
    if (!graph || !geometry) return;
    const at = geometry.ports.get(selectedPort);
    const p = at && port(at.box, at.port.name);
    if (!p) return;
    const lines = describePort(at.box, p);
    const conns = graph.connections.filter((e) => portKey(e.from.component, e.from.port) === selectedPort
      || portKey(e.to.component, e.to.port) === selectedPort);
    const sig = `${selectedPort}|${conns.map((e) => `${e.id}:${e.cut}`).join(',')}`;
    if (details.dataset.port !== sig) {
      details.dataset.port = sig;
      const list = el('ul', { class: 'system-conns' });
      for (const e of conns) {
        const li = el('li', { 'data-id': e.id, 'data-cut': String(e.cut) },
          el('span', { class: 'conn-name' }, e.id.replace('->', ' → ')),
          el('span', { class: 'conn-count' }));
        if (e.cuttable) {
          const b = el('button', { type: 'button', class: e.cut ? 'restore' : 'cut danger' }, t(e.cut ? 'system.restore' : 'system.cut'));
          b.addEventListener('click', () => {
            const what = t(e.cut ? 'system.restore.what' : 'system.cut.what', { id: e.id.replace('->', ' → ') });
            request(what, () => (e.cut ? demo.restore_connection(e.id) : demo.cut_connection(e.id)));
          });
          li.append(b);
        }
        list.append(li);
      }
      details.replaceChildren(
        el('div', { class: 'system-port-head' }, lines[0]),
        el('div', { class: 'system-port-sample', id: 'system-sample' }),
        el('div', { class: 'system-port-count' }),
        conns.length ? list : el('p', { class: 'panel-hint small' }, t('system.not_connected')),
      );
    }
    setText(details.querySelector('.system-port-sample'), lines.slice(1, -1).join(' · '));
    setText(details.querySelector('.system-port-count'), lines[lines.length - 1]);
    for (const li of /** @type {NodeListOf<HTMLLIElement>} */ (details.querySelectorAll('.system-conns li'))) {
      const e = graph.connections.find((x) => x.id === li.dataset.id);
      if (e) setText(li.querySelector('.conn-count'), e.cut ? t('system.cut_state') : t(e.kind === 'service' ? 'system.calls' : 'system.samples', { n: e.carried }));
    }
  }

  function paint() {
    if (!graph) return;
    const info = new Map(components.map((c) => [c.name, c]));
    for (const c of graph.components) {
      const node = boxNodes.get(c.name);
      if (!node) continue;
      const ci = info.get(c.name);
      const colour = ci?.colour ?? '#c9ced8';
      node.g.dataset.state = c.state ?? 'none';
      node.g.classList.toggle('selected', c.name === selectedBox);
      node.head.style.fill = colour;
      node.g.style.setProperty('--state', colour);
      const ink = textOn(colour);
      node.title.style.fill = ink;
      node.state.style.fill = ink;
      if (c.state) setText(node.state, `${c.state} · ${c.rate_hz} Hz`);
      if (ci) {
        const status = activityText(ci.status);
        const short = status.length > 38 ? `${status.slice(0, 37)}…` : status;
        setText(node.status, short);
        node.status.dataset.full = status;
      }
      for (const p of c.ports) {
        const key = portKey(c.name, p.name);
        const pn = portNodes.get(key);
        if (!pn) continue;
        const before = counts.get(key);
        counts.set(key, p.count);
        pn.g.classList.toggle('selected', key === selectedPort);
        if (before !== undefined && p.count !== before) {
          // A short pulse; restarted so that a port fed at every update pulses each time.
          pn.marker.classList.remove('pulse');
          void pn.marker.getBoundingClientRect();
          pn.marker.classList.add('pulse');
        }
      }
    }
    for (const e of graph.connections) {
      const line = lineNodes.get(e.id);
      if (!line) continue;
      line.classList.toggle('cut', e.cut);
      const touches = selectedPort && (portKey(e.from.component, e.from.port) === selectedPort
        || portKey(e.to.component, e.to.port) === selectedPort);
      line.classList.toggle('hot', Boolean(touches));
    }
    // The selected box's actions, as RT System Editor's context menu.
    const ci = selectedBox ? info.get(selectedBox) : null;
    actions.dataset.component = selectedBox ?? '';
    setText(actTitle, ci ? `${ci.instance_name} · ${ci.state}` : t('system.act.none'));
    buttons.activate.disabled = !ci || ci.state !== 'Inactive';
    buttons.deactivate.disabled = !ci || ci.state !== 'Active';
    buttons.reset.disabled = !ci || ci.state !== 'Error';
    buttons.fault.disabled = !ci || !(ci.state === 'Inactive' || ci.state === 'Active') || ci.fault_pending;
    setText(buttons.fault, t(ci?.fault_pending ? 'rtc.fault.pending' : 'rtc.fault'));
    paintDetails();
    if (hoverPort) {
      const at = geometry?.ports.get(hoverPort);
      const p = at && port(at.box, at.port.name);
      if (p) {
        const lines = describePort(at.box, p);
        [...tooltip.children].forEach((d, i) => setText(d, lines[i] ?? ''));
      }
    }
  }

  function columns() {
    const w = wrap.clientWidth || root.clientWidth || 360;
    return Math.max(1, Math.min(3, Math.floor((w + 40) / 300)));
  }

  /** Reads the description; lays the diagram out again if its shape changed (or `force`). @param {boolean} force */
  function refresh(force) {
    const r = app.attempt(() => demo.system_graph());
    if (!r.ok || r.value === undefined) return;
    const g = r.value;
    graph = g;
    const c = columns();
    const s = `${c}|${g.components.map((x) => `${x.name}:${x.ports.map((p) => p.name).join(',')}`).join(';')}|${g.connections.length}`;
    if (force || s !== shape) {
      cols = c;
      shape = s;
      build(g);
    }
    paint();
  }

  new ResizeObserver(() => {
    if (graph && columns() !== cols) refresh(true);
  }).observe(wrap);
  app.on('changed', () => { last = -Infinity; });

  return {
    /**
     * Reads the description at most every UPDATE_MS, and only while the tab is shown.
     * @param {number} now the frame's time [ms]
     * @param {boolean} visible whether the System tab is shown
     * @param {ComponentView[]} [comps] the frame's components
     */
    update(now, visible, comps) {
      components = comps ?? components;
      if (!visible || now - last < UPDATE_MS) return;
      last = now;
      refresh(false);
    },
    /** The description last read (for the end-to-end test). */
    graph: () => graph,
  };
}
