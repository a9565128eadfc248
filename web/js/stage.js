// @ts-check
// The stage: the canvas that shows the core's frame, and the mouse, finger or keyboard on it.
//
// The frame is drawn by the core's tiny-skia renderer into Rust memory; it reaches the canvas
// without a copy: a Uint8ClampedArray view over wasm memory at `frame_ptr()` → ImageData →
// putImageData. The view is made again when wasm memory grows (the old buffer is detached)
// or the frame moves (a resize). An overlay canvas above it shows what the mouse is doing:
// the arrow of a start or goal being dragged, the brush and the cells a stroke will change,
// a start waiting for its goal.
//
// The view: the wheel, a pinch or the zoom buttons zoom about a point (the
// renderer's `Camera`: the world point under it stays put); the Pan tool, the middle or
// right mouse button, or two fingers drag the picture; Fit shows the whole map again.
// A paint stroke is one MapUpdate, sent when the stroke ends: the cells under the
// brush are gathered while it moves and previewed on the overlay.
//
// The keyboard: the overlay takes focus (it is the map's one control, `role="application"`,
// described by the scene's words, js/scene.js). With the Goal or Start tool the arrows move a
// cursor (a cell, a metre with Shift), `[` and `]` turn its heading, Enter places it; with
// Obstacle or Erase, Enter or Space paints the brush at the cursor; with Pan the arrows move
// the view. Each goes through the same requests as the mouse (`setGoal`, `setStart`, one
// MapUpdate, `pan_by`); where the cursor is is said in a polite live region, once a key.
import { t, fixed } from './i18n.js';

/** @type {Record<string, string>} */
const TOOL_HINTS = {
  goal: t('hint.goal'),
  start: t('hint.start'),
  paint: t('hint.paint'),
  erase: t('hint.erase'),
  pan: t('hint.pan'),
};
/** @type {Record<string, string>} */
const COLOURS = { goal: '#e8590c', start: '#1c7ed6', paint: '#212529', erase: '#f8f9fa' };
/** Zoom per wheel pixel (a notch of 100 px zooms about 1.16×). */
const WHEEL_ZOOM = 0.0015;
/** The zoom buttons' step. */
const BUTTON_ZOOM = 1.5;
/** A drag shorter than this (canvas pixels) keeps the current heading. */
const MIN_DRAG_PX = 8;

/** The heading's step for `[` and `]` [deg]. */
const TURN_DEG = 15;
/** The view's step for an arrow in the Pan tool, as a share of the canvas (Shift: a larger one). */
const PAN_SHARE = 0.1;
const PAN_SHARE_SHIFT = 0.3;
/** How close to the canvas's edge the cursor may come before the view follows it, canvas pixels. */
const CURSOR_MARGIN_PX = 24;

/** @param {number} rad */
const deg = (rad) => (rad * 180) / Math.PI;
/** @param {number} v */
const round2 = (v) => Math.round(v * 100) / 100;

/** A point on the canvas [px]. @typedef {[number, number]} Px */
/**
 * What a pointer is doing: panning, or a tool's drag from `p0` (world point `w0`) to `p`.
 * @typedef {{ tool: string, p0: Px, p: Px, w0?: Px }} Drag
 */

/**
 * @param {HTMLElement} wrap the canvases' box
 * @param {HTMLCanvasElement} view the core's frame
 * @param {HTMLCanvasElement} overlay what the pointer and the keyboard do, above it (focusable)
 * @param {HTMLElement} hint the tool's hint
 * @param {HTMLElement} said where the keyboard's cursor is said (a polite live region)
 * @param {App} app
 */
export function createStage(wrap, view, overlay, hint, said, app) {
  const { demo } = app;
  const ctx = /** @type {CanvasRenderingContext2D} */ (view.getContext('2d', { alpha: false }));
  const octx = /** @type {CanvasRenderingContext2D} */ (overlay.getContext('2d'));
  /** @type {ImageData | null} */
  let image = null;
  /** @type {ArrayBuffer | null} */
  let buffer = null;
  let ptr = 0;
  let len = 0;
  let drawn = false;
  let blitAgain = true;
  /** @type {[number, number] | null} */
  let fixedSize = null;
  /** @type {MapView | null} */
  let map = null;
  /** @type {Px | null} */
  let hover = null;
  /** @type {Drag | null} */
  let drag = null;
  /** The cells of the stroke being painted, by "x,y". @type {Map<string, [number, number]>} */
  const pending = new Map();
  /** The keyboard's cursor (world metres, degrees); null until the map first takes focus. @type {PoseView | null} */
  let cursor = null;

  // ------------------------------------------------------------------ size and blit

  function fit() {
    const rect = wrap.getBoundingClientRect();
    const dpr = Math.min(window.devicePixelRatio || 1, 2);
    const [w, h] = fixedSize ?? [
      Math.max(64, Math.round(rect.width * dpr)),
      Math.max(64, Math.round(rect.height * dpr)),
    ];
    if (view.width === w && view.height === h) return;
    const r = app.attempt(() => demo.resize(w, h));
    if (!r.ok) {
      app.notice.show(t('stage.cannot_draw', { w, h, error: r.error }), 'error');
      return;
    }
    view.width = overlay.width = w;
    view.height = overlay.height = h;
    image = null;
    blitAgain = true;
    drawOverlay();
  }
  new ResizeObserver(fit).observe(wrap);

  /**
   * In the one-column layout (a narrow window) the map's box takes the map's own aspect —
   * between 260 px and 70 % of the window's height — instead of a fixed share of the window.
   */
  const oneColumn = window.matchMedia('(max-width: 1080px)');
  function fitHeight() {
    if (!map || !oneColumn.matches) {
      wrap.style.removeProperty('--map-h');
      return;
    }
    const w = wrap.getBoundingClientRect().width;
    const h = Math.min(Math.max(w * (map.height / map.width) + 16, 260), window.innerHeight * 0.7);
    wrap.style.setProperty('--map-h', `${Math.round(h)}px`);
  }
  window.addEventListener('resize', fitHeight);

  /** Renders if anything changed and puts the frame on the canvas. */
  function draw() {
    const r = app.attempt(() => demo.render());
    if (!r.ok) {
      app.notice.show(t('stage.draw_failed', { error: r.error }), 'error');
      return;
    }
    if (r.value) drawn = true;
    if (!drawn || !(r.value || blitAgain)) return;
    blitAgain = false;
    const p = demo.frame_ptr();
    const n = demo.frame_len();
    if (!image || buffer !== app.memory.buffer || p !== ptr || n !== len) {
      buffer = app.memory.buffer;
      ptr = p;
      len = n;
      image = new ImageData(new Uint8ClampedArray(buffer, p, n), demo.frame_width(), demo.frame_height());
    }
    ctx.putImageData(image, 0, 0);
  }

  // ------------------------------------------------------------------ requests

  // What a request needs to know now (after the requests since the last frame).
  const driving = () => demo.telemetry().driving;
  const plan = () => demo.plan();
  /** @param {PoseView} p */
  const fmt = (p) => `(${fixed(p.x, 2)} m, ${fixed(p.y, 2)} m, ${fixed(p.theta_deg, 0)}°)`;

  /** @param {string} what @param {string} error @param {string} kept */
  function refused(what, error, kept) {
    app.notice.show(t('refused.kept', { what, error, kept }), 'error');
    app.log.page(t('refused', { what, error }), 'warn');
  }

  /** A new goal: from the robot while it drives, else from its start (or a waiting start). */
  /** @param {PoseView} goal */
  function setGoal(goal) {
    const ps = app.ui.pendingStart;
    const r = ps && !driving()
      ? app.attempt(() => demo.set_position(ps.x, ps.y, ps.theta_deg, goal.x, goal.y, goal.theta_deg, app.ui.backward))
      : app.attempt(() => demo.set_goal(goal.x, goal.y, goal.theta_deg, app.ui.backward));
    if (!r.ok) {
      refused(t('stage.goal'), r.error, t('stage.goal_kept'));
      return false;
    }
    app.ui.pendingStart = null;
    app.notice.show(t('stage.goal_set', { at: fmt(goal), dir: t(app.ui.backward ? 'stage.backward' : 'stage.forward') }), 'success');
    drawOverlay();
    return true;
  }

  /** Places the robot (SetPosition with the current goal); without a goal, waits for one. */
  /** @param {PoseView} start */
  function setStart(start) {
    if (driving()) {
      app.notice.show(t('stage.driving'), 'warn');
      return false;
    }
    const goal = plan().goal;
    if (!goal) {
      app.ui.pendingStart = start;
      app.emit('tool', 'goal');
      app.notice.show(t('stage.start_placed', { at: fmt(start) }), 'info');
      drawOverlay();
      return true;
    }
    const r = app.attempt(() =>
      demo.set_position(start.x, start.y, start.theta_deg, goal.x, goal.y, goal.theta_deg, app.ui.backward));
    if (!r.ok) {
      refused(t('stage.start'), r.error, t('stage.start_kept'));
      return false;
    }
    app.notice.show(t('stage.placed', { at: fmt(start) }), 'success');
    return true;
  }

  /** The current goal again with the direction now chosen. */
  function resubmitDirection() {
    const p = plan();
    if (!p.goal) return;
    const g = p.goal;
    const start = p.start;
    const r = driving() || !start
      ? app.attempt(() => demo.set_goal(g.x, g.y, g.theta_deg, app.ui.backward))
      : app.attempt(() => demo.set_position(start.x, start.y, start.theta_deg, g.x, g.y, g.theta_deg, app.ui.backward));
    if (r.ok) {
      app.notice.show(t('stage.driving_to', { dir: t(app.ui.backward ? 'stage.backward' : 'stage.forward') }), 'success');
    } else {
      refused(t('stage.direction'), r.error, t('stage.goal_kept'));
    }
  }

  // ------------------------------------------------------------------ the brush

  /**
   * The cells the brush covers with its centre at world point `(wx, wy)`: in cells, the
   * n×n cells around the cell under it; in metres, the cells whose centre lies inside the
   * square of that side (at least the cell under it) — the core's (`Session::brush_cells`).
   * @param {number} wx
   * @param {number} wy
   */
  function brushCells(wx, wy) {
    const { size, unit } = app.ui.brush;
    const flat = demo.brush_cells(wx, wy, size, unit === 'm');
    /** @type {Array<[number, number]>} */
    const out = [];
    for (let i = 0; i + 1 < flat.length; i += 2) out.push([flat[i], flat[i + 1]]);
    return out;
  }

  /** The brush's side in canvas pixels. */
  function brushSide() {
    if (!map) return 0;
    const { size, unit } = app.ui.brush;
    return demo.pixels_per_metre() * (unit === 'm' ? size : size * map.grid_size);
  }

  /** The cells under the brush from `a` to `b` (canvas pixels), every half cell or brush. @param {Px} a @param {Px} b */
  function paintSegment(a, b) {
    if (!map) return;
    const step = Math.max(1, Math.min(demo.pixels_per_metre() * map.grid_size, brushSide()) / 2);
    const steps = Math.max(1, Math.ceil(Math.hypot(b[0] - a[0], b[1] - a[1]) / step));
    for (let i = 0; i <= steps; i++) {
      const t = i / steps;
      const w = demo.pixel_to_world(a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t);
      if (!w) continue;
      for (const [x, y] of brushCells(w[0], w[1])) pending.set(`${x},${y}`, [x, y]);
    }
  }

  /** Sends the stroke's cells as one MapUpdate (the core sends only what changes). @param {string} tool */
  function sendStroke(tool) {
    if (pending.size === 0) return;
    const cells = [...pending.values()];
    pending.clear();
    const xs = Int32Array.from(cells, (c) => c[0]);
    const ys = Int32Array.from(cells, (c) => c[1]);
    const value = tool === 'paint' ? 1 : 0;
    const r = app.attempt(() => demo.set_cells(xs, ys, value));
    if (!r.ok) app.notice.show(t('refused', { what: 'MapUpdate', error: r.error }), 'error');
    app.emit('changed');
  }

  // ------------------------------------------------------------------ the view

  /**
   * Zooms by `factor` about canvas pixel `p` (the middle of the canvas without one).
   * @param {number} factor
   * @param {Px} [p]
   */
  function zoomAt(factor, p = [overlay.width / 2, overlay.height / 2]) {
    if (!map) return;
    app.attempt(() => demo.zoom_at(p[0], p[1], factor));
    app.emit('view');
    drawOverlay();
  }

  /** @param {number} dx @param {number} dy canvas pixels */
  function panBy(dx, dy) {
    if (!map) return;
    app.attempt(() => demo.pan_by(dx, dy));
    app.emit('view');
    drawOverlay();
  }

  function fitView() {
    if (!map) return;
    app.attempt(() => demo.fit_view());
    app.emit('view');
    drawOverlay();
  }

  overlay.addEventListener('wheel', (e) => {
    if (!map) return;
    e.preventDefault();
    const lines = e.deltaMode === 1 ? 16 : e.deltaMode === 2 ? 400 : 1;
    zoomAt(Math.exp(-e.deltaY * lines * WHEEL_ZOOM), toCanvas(e));
  }, { passive: false });
  overlay.addEventListener('contextmenu', (e) => e.preventDefault());

  /** Touch pointers down on the map, by id: their last canvas position. @type {Map<number, Px>} */
  const touches = new Map();
  /** @type {{ d0: number, zoom0: number, anchor: Px | null } | null} */
  let pinch = null;

  /** The two fingers' distance and middle (canvas pixels). @returns {{ d: number, mid: Px }} */
  function pinchState() {
    const [a, b] = [...touches.values()];
    return { d: Math.hypot(b[0] - a[0], b[1] - a[1]), mid: [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2] };
  }

  /**
   * A pinch holds on to the world point that was between the fingers when it began, and the
   * zoom and finger distance then: each move scales the zoom by how far the fingers are
   * apart now, and puts that point between them again.
   */
  function startPinch() {
    const s = pinchState();
    const w = demo.pixel_to_world(s.mid[0], s.mid[1]);
    pinch = { d0: s.d, zoom0: demo.zoom(), anchor: w ? [w[0], w[1]] : null };
  }

  function movePinch() {
    const s = pinchState();
    if (!pinch || !pinch.anchor || !(pinch.d0 > 0) || !(s.d > 0)) return;
    const want = (pinch.zoom0 * s.d) / pinch.d0;
    zoomAt(want / demo.zoom(), s.mid);
    const at = demo.world_to_pixel(pinch.anchor[0], pinch.anchor[1]);
    if (at) panBy(s.mid[0] - at[0], s.mid[1] - at[1]);
  }

  // ------------------------------------------------------------------ the mouse

  /** @param {MouseEvent} e @returns {Px} */
  function toCanvas(e) {
    const r = overlay.getBoundingClientRect();
    return [((e.clientX - r.left) * overlay.width) / r.width, ((e.clientY - r.top) * overlay.height) / r.height];
  }

  overlay.addEventListener('pointerdown', (e) => {
    if (!map) return;
    const p = toCanvas(e);
    if (e.pointerType === 'touch') {
      touches.set(e.pointerId, p);
      if (touches.size === 2) {
        // Two fingers: pinch and pan; whatever one finger began is dropped.
        drag = null;
        pending.clear();
        startPinch();
        drawOverlay();
        return;
      }
    }
    const panning = app.ui.tool === 'pan' || e.button === 1 || e.button === 2;
    if (!panning && e.button !== 0) return;
    overlay.setPointerCapture(e.pointerId);
    if (panning) {
      drag = { tool: 'pan', p0: p, p };
      e.preventDefault();
      return;
    }
    const w = demo.pixel_to_world(p[0], p[1]);
    if (!w) return;
    const tool = app.ui.tool;
    drag = { tool, p0: p, p, w0: [w[0], w[1]] };
    if (tool === 'paint' || tool === 'erase') {
      pending.clear();
      paintSegment(p, p);
    }
    drawOverlay();
  });

  overlay.addEventListener('pointermove', (e) => {
    const p = toCanvas(e);
    if (e.pointerType === 'touch' && touches.has(e.pointerId)) {
      touches.set(e.pointerId, p);
      if (pinch && touches.size === 2) {
        movePinch();
        return;
      }
    }
    hover = p;
    // The cell under the mouse, for whoever listens (an inspector).
    app.emit('hover', map ? demo.pixel_to_cell(p[0], p[1]) ?? null : null);
    if (drag && drag.tool === 'pan') {
      panBy(p[0] - drag.p[0], p[1] - drag.p[1]);
    } else if (drag && (drag.tool === 'paint' || drag.tool === 'erase')) {
      paintSegment(drag.p, p);
    }
    if (drag) drag.p = p;
    drawOverlay();
  });

  overlay.addEventListener('pointerleave', () => {
    hover = null;
    app.emit('hover', null);
    drawOverlay();
  });

  /** @param {PointerEvent} [e] */
  function finish(e) {
    if (e && e.pointerType === 'touch') {
      touches.delete(e.pointerId);
      if (pinch) {
        if (touches.size < 2) pinch = null;
        return;
      }
    }
    if (!drag) return;
    const d = drag;
    drag = null;
    if (d.tool === 'pan') {
      // Moved while dragging; a tap without a drag inspects the cell under it (a finger has
      // no hover: this is how a phone reaches the Inspector).
      if (Math.hypot(d.p[0] - d.p0[0], d.p[1] - d.p0[1]) < MIN_DRAG_PX) {
        const cell = demo.pixel_to_cell(d.p0[0], d.p0[1]);
        if (cell) app.emit('hover', cell);
      }
    } else if (d.tool === 'paint' || d.tool === 'erase') {
      sendStroke(d.tool);
    } else if (d.w0) {
      const dx = d.p[0] - d.p0[0];
      const dy = d.p[1] - d.p0[1];
      let heading;
      if (Math.hypot(dx, dy) >= MIN_DRAG_PX) {
        heading = deg(Math.atan2(-dy, dx));
      } else {
        const p = plan();
        const current = d.tool === 'goal' ? p.goal : p.start;
        heading = current ? current.theta_deg : 0;
      }
      const pose = { x: round2(d.w0[0]), y: round2(d.w0[1]), theta_deg: Math.round(heading) };
      if (d.tool === 'goal') setGoal(pose);
      else setStart(pose);
    }
    if (e) overlay.releasePointerCapture?.(e.pointerId);
    drawOverlay();
  }
  overlay.addEventListener('pointerup', finish);
  overlay.addEventListener('pointercancel', (e) => {
    if (e.pointerType === 'touch') touches.delete(e.pointerId);
    if (touches.size < 2) pinch = null;
    drag = null;
    pending.clear();
    drawOverlay();
  });

  // ------------------------------------------------------------------ the keyboard

  /** Whether the keyboard's cursor is shown: the map has the keyboard's focus. */
  const keyboardFocus = () => document.activeElement === overlay && overlay.matches(':focus-visible');

  /** Where the cursor starts: the goal, else the robot, else the map's middle. */
  function firstCursor() {
    const m = /** @type {MapView} */ (map);
    const tel = app.frame?.telemetry;
    const at = tel?.goal ?? (tel && (tel.start || tel.driving) ? tel.pose : null);
    if (at) return { x: round2(at.x), y: round2(at.y), theta_deg: Math.round(at.theta_deg) };
    return {
      x: round2(m.origin[0] + (m.width * m.grid_size) / 2),
      y: round2(m.origin[1] + (m.height * m.grid_size) / 2),
      theta_deg: 0,
    };
  }

  /** Says where the cursor is (the live region beside the map). */
  function sayCursor() {
    if (!cursor) return;
    said.textContent = t('stage.cursor', {
      x: fixed(cursor.x, 2), y: fixed(cursor.y, 2), theta: fixed(cursor.theta_deg, 0),
    });
  }

  /**
   * Moves the cursor by (`dx`, `dy`) metres, kept on the map; the view follows it when it
   * comes near the canvas's edge.
   * @param {number} dx
   * @param {number} dy
   */
  function moveCursor(dx, dy) {
    if (!map || !cursor) return;
    const [ox, oy] = map.origin;
    const half = map.grid_size / 2;
    const clamp = (/** @type {number} */ v, /** @type {number} */ lo, /** @type {number} */ hi) => Math.min(Math.max(v, lo), hi);
    cursor.x = round2(clamp(cursor.x + dx, ox + half, ox + map.width * map.grid_size - half));
    cursor.y = round2(clamp(cursor.y + dy, oy + half, oy + map.height * map.grid_size - half));
    const p = demo.world_to_pixel(cursor.x, cursor.y);
    if (p) {
      const m = CURSOR_MARGIN_PX;
      const px = p[0] < m ? m - p[0] : p[0] > overlay.width - m ? overlay.width - m - p[0] : 0;
      const py = p[1] < m ? m - p[1] : p[1] > overlay.height - m ? overlay.height - m - p[1] : 0;
      if (px || py) panBy(px, py);
    }
  }

  /** Paints (Obstacle) or erases the brush's cells at the cursor: one MapUpdate. @param {string} tool */
  function paintAtCursor(tool) {
    if (!cursor) return;
    pending.clear();
    for (const [x, y] of brushCells(cursor.x, cursor.y)) pending.set(`${x},${y}`, [x, y]);
    sendStroke(tool);
  }

  overlay.addEventListener('focus', () => {
    if (map && !cursor) cursor = firstCursor();
    drawOverlay();
  });
  overlay.addEventListener('blur', drawOverlay);

  overlay.addEventListener('keydown', (e) => {
    if (!map || e.ctrlKey || e.metaKey || e.altKey) return;
    if (!cursor) cursor = firstCursor();
    const tool = app.ui.tool;
    /** @type {Record<string, [number, number]>} */
    const ARROWS = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] };
    const arrow = ARROWS[e.key];
    let done = true;
    if (arrow && tool === 'pan') {
      // The view moves the arrow's way: the picture the other way.
      const share = e.shiftKey ? PAN_SHARE_SHIFT : PAN_SHARE;
      panBy(-arrow[0] * share * overlay.width, arrow[1] * share * overlay.height);
    } else if (arrow) {
      const step = e.shiftKey ? 1 : map.grid_size;
      moveCursor(arrow[0] * step, arrow[1] * step);
      sayCursor();
      // The cell under the cursor, as under the mouse (the Inspector).
      app.emit('hover', demo.world_to_cell(cursor.x, cursor.y) ?? null);
    } else if ((e.key === '[' || e.key === ']') && (tool === 'goal' || tool === 'start')) {
      const turned = cursor.theta_deg + (e.key === '[' ? TURN_DEG : -TURN_DEG);
      cursor.theta_deg = ((((turned + 180) % 360) + 360) % 360) - 180;
      sayCursor();
    } else if (e.key === 'Enter' && tool === 'goal') {
      setGoal({ ...cursor });
    } else if (e.key === 'Enter' && tool === 'start') {
      setStart({ ...cursor });
    } else if ((e.key === 'Enter' || e.key === ' ') && (tool === 'paint' || tool === 'erase')) {
      paintAtCursor(tool);
    } else {
      // Everything else (the tools' letters, Space to pause, zoom) is the page's (toolbar.js).
      done = false;
    }
    if (!done) return;
    e.preventDefault();
    e.stopPropagation();
    drawOverlay();
  });

  // ------------------------------------------------------------------ the overlay

  /**
   * An arrow from `from` to `to`; `size` is its head's (canvas pixels; by default from the canvas's width).
   * @param {Px} from @param {Px} to @param {string} colour @param {number} [size]
   */
  function arrow(from, to, colour, size) {
    const [x0, y0] = from;
    const [x1, y1] = to;
    const a = Math.atan2(y1 - y0, x1 - x0);
    const s = size ?? Math.max(8, overlay.width / 120);
    octx.strokeStyle = colour;
    octx.fillStyle = colour;
    octx.lineWidth = Math.max(2, s / 3);
    octx.beginPath();
    octx.arc(x0, y0, s * 0.7, 0, 2 * Math.PI);
    octx.fill();
    octx.beginPath();
    octx.moveTo(x0, y0);
    octx.lineTo(x1, y1);
    octx.stroke();
    octx.beginPath();
    octx.moveTo(x1, y1);
    octx.lineTo(x1 - s * Math.cos(a - 0.45), y1 - s * Math.sin(a - 0.45));
    octx.lineTo(x1 - s * Math.cos(a + 0.45), y1 - s * Math.sin(a + 0.45));
    octx.closePath();
    octx.fill();
  }

  /** @param {PoseView} pose @param {string} colour */
  function poseArrow(pose, colour) {
    const p = demo.world_to_pixel(pose.x, pose.y);
    if (!p) return;
    const l = Math.max(24, overlay.width / 30);
    const t = (pose.theta_deg * Math.PI) / 180;
    arrow([p[0], p[1]], [p[0] + l * Math.cos(t), p[1] - l * Math.sin(t)], colour);
  }

  function drawOverlay() {
    octx.clearRect(0, 0, overlay.width, overlay.height);
    if (app.ui.pendingStart) poseArrow(app.ui.pendingStart, COLOURS.start);
    if (drag && (drag.tool === 'goal' || drag.tool === 'start')) {
      const long = Math.hypot(drag.p[0] - drag.p0[0], drag.p[1] - drag.p0[1]) >= MIN_DRAG_PX;
      octx.globalAlpha = 0.85;
      arrow(drag.p0, long ? drag.p : [drag.p0[0] + 1, drag.p0[1]], COLOURS[drag.tool]);
      octx.globalAlpha = 1;
    }
    const tool = app.ui.tool;
    if (map && drag && (drag.tool === 'paint' || drag.tool === 'erase') && pending.size) {
      // The stroke so far: the cells it will send when it ends.
      const g = map.grid_size;
      const [ox, oy] = map.origin;
      octx.fillStyle = drag.tool === 'paint' ? 'rgba(33, 37, 41, 0.55)' : 'rgba(248, 249, 250, 0.75)';
      for (const [x, y] of pending.values()) {
        const a = demo.world_to_pixel(ox + x * g, oy + (y + 1) * g);
        const b = demo.world_to_pixel(ox + (x + 1) * g, oy + y * g);
        if (a && b) octx.fillRect(a[0], a[1], b[0] - a[0], b[1] - a[1]);
      }
    }
    if (hover && map && (tool === 'paint' || tool === 'erase')) brushOutline(hover, tool);
    if (map && cursor && keyboardFocus()) drawCursor(cursor, tool);
  }

  /** The brush's square about canvas point `p`. @param {Px} p @param {string} tool */
  function brushOutline(p, tool) {
    const side = brushSide();
    octx.lineWidth = 2;
    octx.strokeStyle = tool === 'paint' ? '#c92a2a' : '#495057';
    octx.setLineDash(tool === 'erase' ? [4, 3] : []);
    octx.strokeRect(p[0] - side / 2, p[1] - side / 2, side, side);
    octx.setLineDash([]);
  }

  /**
   * The keyboard's cursor: cross hairs in a ring (white under dark, to show on any layer),
   * with the heading's arrow for Goal and Start, the brush for Obstacle and Erase.
   * @param {PoseView} at
   * @param {string} tool
   */
  function drawCursor(at, tool) {
    const w = demo.world_to_pixel(at.x, at.y);
    if (!w) return;
    /** @type {Px} */
    const p = [w[0], w[1]];
    if (tool === 'paint' || tool === 'erase') brushOutline(p, tool);
    // Sized in CSS pixels (the canvas may have two pixels to each).
    const k = overlay.width / Math.max(1, overlay.getBoundingClientRect().width);
    const r = 12 * k;
    for (const [colour, width] of [['#ffffff', 5], ['#1d2330', 2]]) {
      octx.strokeStyle = /** @type {string} */ (colour);
      octx.lineWidth = /** @type {number} */ (width) * k;
      octx.beginPath();
      octx.arc(p[0], p[1], r, 0, 2 * Math.PI);
      octx.moveTo(p[0] - 1.8 * r, p[1]);
      octx.lineTo(p[0] - 0.5 * r, p[1]);
      octx.moveTo(p[0] + 0.5 * r, p[1]);
      octx.lineTo(p[0] + 1.8 * r, p[1]);
      octx.moveTo(p[0], p[1] - 1.8 * r);
      octx.lineTo(p[0], p[1] - 0.5 * r);
      octx.moveTo(p[0], p[1] + 0.5 * r);
      octx.lineTo(p[0], p[1] + 1.8 * r);
      octx.stroke();
    }
    if (tool === 'goal' || tool === 'start') {
      // The heading, reaching well past the cross hairs.
      const h = (at.theta_deg * Math.PI) / 180;
      arrow(p, [p[0] + 3.4 * r * Math.cos(h), p[1] - 3.4 * r * Math.sin(h)], COLOURS[tool], 10 * k);
    }
  }

  /** The robot's body on the page (client coordinates), or null when it is not drawn. */
  function robotBox() {
    const t = app.frame?.telemetry;
    if (!map || !t) return null;
    if (!t.start && !t.driving) return null;
    const p = demo.world_to_pixel(t.pose.x, t.pose.y);
    if (!p) return null;
    const r = overlay.getBoundingClientRect();
    const sx = r.width / overlay.width;
    const sy = r.height / overlay.height;
    const radius = Math.max(5, t.body_radius * demo.pixels_per_metre());
    return {
      left: r.left + (p[0] - radius) * sx,
      right: r.left + (p[0] + radius) * sx,
      top: r.top + (p[1] - radius) * sy,
      bottom: r.top + (p[1] + radius) * sy,
    };
  }

  /** Canvas pixels around the goal point its arrow can reach (the renderer's 18 px arrow). */
  const GOAL_REACH_PX = 22;

  /** The goal's marker on the page (client coordinates), or null when there is none. */
  function goalBox() {
    if (!map) return null;
    const goal = app.frame?.telemetry.goal;
    const p = goal && demo.world_to_pixel(goal.x, goal.y);
    if (!p) return null;
    const r = overlay.getBoundingClientRect();
    const sx = r.width / overlay.width;
    const sy = r.height / overlay.height;
    return {
      left: r.left + (p[0] - GOAL_REACH_PX) * sx,
      right: r.left + (p[0] + GOAL_REACH_PX) * sx,
      top: r.top + (p[1] - GOAL_REACH_PX) * sy,
      bottom: r.top + (p[1] + GOAL_REACH_PX) * sy,
    };
  }

  /** What a notice over the map must not cover: the robot and the goal (client boxes). */
  const keepClear = () => /** @type {ClientBox[]} */ ([robotBox(), goalBox()].filter(Boolean));

  /** @param {string} tool */
  function setTool(tool) {
    app.ui.tool = tool;
    overlay.dataset.tool = tool;
    hint.textContent = TOOL_HINTS[tool] ?? '';
    drawOverlay();
  }
  app.on('tool', setTool);
  setTool(app.ui.tool);

  app.on('loaded', () => {
    map = demo.map();
    fitHeight();
    cursor = null;
    app.ui.pendingStart = null;
    drag = null;
    blitAgain = true;
    drawOverlay();
  });

  return {
    draw,
    robotBox,
    keepClear,
    zoomAt,
    panBy,
    fitView,
    setGoal,
    setStart,
    resubmitDirection,
    /** @param {number} w @param {number} h */
    setFixedSize(w, h) {
      fixedSize = w && h ? [w, h] : null;
      fit();
    },
  };
}
