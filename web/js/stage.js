// The stage: the canvas that shows the core's frame, and the mouse on it.
//
// The frame is drawn by the core's tiny-skia renderer into Rust memory; it reaches the canvas
// without a copy: a Uint8ClampedArray view over wasm memory at `frame_ptr()` → ImageData →
// putImageData. The view is made again when wasm memory grows (the old buffer is detached)
// or the frame moves (a resize). An overlay canvas above it shows what the mouse is doing:
// the arrow of a start or goal being dragged, the brush, a start waiting for its goal.

const TOOL_HINTS = {
  goal: 'Goal: press where the robot should go and drag toward the heading it should end with.',
  start: 'Start: press where the robot should stand and drag toward its heading (while it is not driving).',
  paint: 'Obstacle: paint cells with the mouse, even while the robot drives (each stroke is a MapUpdate).',
  erase: 'Erase: free cells with the mouse (a MapUpdate with value 0).',
};
const COLOURS = { goal: '#e8590c', start: '#1c7ed6', paint: '#212529', erase: '#f8f9fa' };
/** A drag shorter than this (canvas pixels) keeps the current heading. */
const MIN_DRAG_PX = 8;

const deg = (rad) => (rad * 180) / Math.PI;
const round2 = (v) => Math.round(v * 100) / 100;

export function createStage(wrap, view, overlay, hint, app) {
  const { demo } = app;
  const ctx = view.getContext('2d', { alpha: false });
  const octx = overlay.getContext('2d');
  let image = null;
  let buffer = null;
  let ptr = 0;
  let len = 0;
  let drawn = false;
  let blitAgain = true;
  let fixed = null;
  let map = null;
  let hover = null;
  let drag = null;
  const pending = new Map();

  // ------------------------------------------------------------------ size and blit

  function fit() {
    const rect = wrap.getBoundingClientRect();
    const dpr = Math.min(window.devicePixelRatio || 1, 2);
    const [w, h] = fixed ?? [
      Math.max(64, Math.round(rect.width * dpr)),
      Math.max(64, Math.round(rect.height * dpr)),
    ];
    if (view.width === w && view.height === h) return;
    const r = app.attempt(() => demo.resize(w, h));
    if (!r.ok) {
      app.notice.show(`Cannot draw at ${w}×${h}: ${r.error}`, 'error');
      return;
    }
    view.width = overlay.width = w;
    view.height = overlay.height = h;
    image = null;
    blitAgain = true;
    drawOverlay();
  }
  new ResizeObserver(fit).observe(wrap);

  /** Renders if anything changed and puts the frame on the canvas. */
  function draw() {
    const r = app.attempt(() => demo.render());
    if (!r.ok) {
      app.notice.show(`Drawing failed: ${r.error}`, 'error');
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

  const telemetry = () => JSON.parse(demo.telemetry_json());
  const plan = () => JSON.parse(demo.plan_json());
  const fmt = (p) => `(${p.x.toFixed(2)} m, ${p.y.toFixed(2)} m, ${Math.round(p.theta_deg)}°)`;

  function refused(what, error, kept) {
    app.notice.show(`${what} refused: ${error}. ${kept}`, 'error');
    app.log.page(`${what} refused: ${error}`, 'warn');
  }

  /** A new goal: from the robot while it drives, else from its start (or a waiting start). */
  function setGoal(goal) {
    const ps = app.ui.pendingStart;
    const driving = telemetry().driving;
    const r = ps && !driving
      ? app.attempt(() => demo.set_position(ps.x, ps.y, ps.theta_deg, goal.x, goal.y, goal.theta_deg, app.ui.backward))
      : app.attempt(() => demo.set_goal(goal.x, goal.y, goal.theta_deg, app.ui.backward));
    if (!r.ok) {
      refused('Goal', r.error, 'The previous goal and its path are kept.');
      return false;
    }
    app.ui.pendingStart = null;
    app.notice.show(`Goal set at ${fmt(goal)}, driving ${app.ui.backward ? 'backward' : 'forward'}.`, 'success');
    drawOverlay();
    return true;
  }

  /** Places the robot (SetPosition with the current goal); without a goal, waits for one. */
  function setStart(start) {
    if (telemetry().driving) {
      app.notice.show('The robot is driving: deactivate it (Deactivate all) before placing it again.', 'warn');
      return false;
    }
    const goal = plan().goal;
    if (!goal) {
      app.ui.pendingStart = start;
      app.emit('tool', 'goal');
      app.notice.show(`Start placed at ${fmt(start)}. Now drag the goal.`, 'info');
      drawOverlay();
      return true;
    }
    const r = app.attempt(() =>
      demo.set_position(start.x, start.y, start.theta_deg, goal.x, goal.y, goal.theta_deg, app.ui.backward));
    if (!r.ok) {
      refused('Start', r.error, 'The robot stays where it was.');
      return false;
    }
    app.notice.show(`Robot placed at ${fmt(start)}.`, 'success');
    return true;
  }

  /** The current goal again with the direction now chosen. */
  function resubmitDirection() {
    const p = plan();
    if (!p.goal) return;
    const g = p.goal;
    const r = telemetry().driving || !p.start
      ? app.attempt(() => demo.set_goal(g.x, g.y, g.theta_deg, app.ui.backward))
      : app.attempt(() => demo.set_position(p.start.x, p.start.y, p.start.theta_deg, g.x, g.y, g.theta_deg, app.ui.backward));
    if (r.ok) {
      app.notice.show(`Driving ${app.ui.backward ? 'backward' : 'forward'} to the goal.`, 'success');
    } else {
      refused('Direction', r.error, 'The previous goal and its path are kept.');
    }
  }

  // ------------------------------------------------------------------ the brush

  function addCells([cx, cy]) {
    const r = (app.ui.brush - 1) / 2;
    for (let dy = -r; dy <= r; dy++) {
      for (let dx = -r; dx <= r; dx++) {
        const x = cx + dx;
        const y = cy + dy;
        if (map && x >= 0 && y >= 0 && x < map.width && y < map.height) pending.set(`${x},${y}`, [x, y]);
      }
    }
  }

  /** The cells under the brush from `a` to `b` (canvas pixels), every half cell. */
  function paintSegment(a, b) {
    if (!map) return;
    const cellPx = Math.max(1, demo.pixels_per_metre() * map.grid_size);
    const steps = Math.max(1, Math.ceil(Math.hypot(b[0] - a[0], b[1] - a[1]) / (cellPx / 2)));
    for (let i = 0; i <= steps; i++) {
      const t = i / steps;
      const c = demo.pixel_to_cell(a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t);
      if (c) addCells([c[0], c[1]]);
    }
  }

  /** Sends the cells painted since the last frame as one MapUpdate. */
  function flushPaint() {
    if (pending.size === 0 || !drag) return;
    const cells = [...pending.values()];
    pending.clear();
    const xs = Int32Array.from(cells, (c) => c[0]);
    const ys = Int32Array.from(cells, (c) => c[1]);
    const value = drag.tool === 'paint' ? 1 : 0;
    const r = app.attempt(() => demo.set_cells(xs, ys, value));
    if (!r.ok) app.notice.show(`MapUpdate refused: ${r.error}`, 'error');
  }

  // ------------------------------------------------------------------ the mouse

  function toCanvas(e) {
    const r = overlay.getBoundingClientRect();
    return [((e.clientX - r.left) * overlay.width) / r.width, ((e.clientY - r.top) * overlay.height) / r.height];
  }

  overlay.addEventListener('pointerdown', (e) => {
    if (e.button !== 0 || !map) return;
    const p = toCanvas(e);
    const w = demo.pixel_to_world(p[0], p[1]);
    if (!w) return;
    overlay.setPointerCapture(e.pointerId);
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
    hover = p;
    // The cell under the mouse, for whoever listens (an inspector).
    app.emit('hover', map ? demo.pixel_to_cell(p[0], p[1]) ?? null : null);
    if (drag && (drag.tool === 'paint' || drag.tool === 'erase')) paintSegment(drag.p, p);
    if (drag) drag.p = p;
    drawOverlay();
  });

  overlay.addEventListener('pointerleave', () => {
    hover = null;
    app.emit('hover', null);
    drawOverlay();
  });

  function finish(e) {
    if (!drag) return;
    const d = drag;
    if (d.tool === 'paint' || d.tool === 'erase') {
      flushPaint();
    } else {
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
    drag = null;
    if (e) overlay.releasePointerCapture?.(e.pointerId);
    drawOverlay();
  }
  overlay.addEventListener('pointerup', finish);
  overlay.addEventListener('pointercancel', () => {
    drag = null;
    pending.clear();
    drawOverlay();
  });

  // ------------------------------------------------------------------ the overlay

  function arrow(from, to, colour) {
    const [x0, y0] = from;
    const [x1, y1] = to;
    const a = Math.atan2(y1 - y0, x1 - x0);
    const s = Math.max(8, overlay.width / 120);
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
    if (hover && map && (tool === 'paint' || tool === 'erase')) {
      const side = demo.pixels_per_metre() * map.grid_size * app.ui.brush;
      octx.lineWidth = 2;
      octx.strokeStyle = tool === 'paint' ? '#c92a2a' : '#495057';
      octx.setLineDash(tool === 'erase' ? [4, 3] : []);
      octx.strokeRect(hover[0] - side / 2, hover[1] - side / 2, side, side);
      octx.setLineDash([]);
    }
  }

  function setTool(tool) {
    app.ui.tool = tool;
    overlay.dataset.tool = tool;
    hint.textContent = TOOL_HINTS[tool] ?? '';
    drawOverlay();
  }
  app.on('tool', setTool);
  setTool(app.ui.tool);

  app.on('loaded', () => {
    map = JSON.parse(demo.map_json());
    app.ui.pendingStart = null;
    drag = null;
    blitAgain = true;
    drawOverlay();
  });

  return {
    draw,
    flushPaint,
    setGoal,
    setStart,
    resubmitDirection,
    setFixedSize(w, h) {
      fixed = w && h ? [w, h] : null;
      fit();
    },
  };
}
