// A browser report for `cargo xtask bench`, not a check of speed (the machines are noisy), and
// not one of `cargo xtask test`'s e2e tests (not a `.test.mjs`): painting on
// a map the size of Nav2's warehouse (1006 × 1674 cells of 0.03 m, 1.68 M cells) at 16×
// while the robot drives, through the page's own file input, canvas and mouse.
//
// The map is generated here as a ROS map (YAML + PGM), the same layout as the benches'
// `core/benches/support/warehouse.rs`. The test loads it, sets a goal across the warehouse,
// activates everything, runs at 16× and paints a stroke of the 5 × 5 brush across the
// route, then prints one line — `RTNAV-FRAME {...}` — with the worst and median frame
// during the stroke: the whole frame (requestAnimationFrame to requestAnimationFrame:
// MapUpdate, simulation, drawing, panels) and the page's own step + render time. It runs
// twice: the page as it is, and as a baseline the page's steps without their frame budget.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { launch, openPage, plan, mapInfo, cellToPage, activateAll, WAIT } from './helpers.mjs';

const W = 1006;
const H = 1674;
const GRID = 0.03;

/** The warehouse's cells, x fastest, y up, 1 = obstacle (as `warehouse.rs`). */
function warehouse() {
  const c = new Uint8Array(W * H);
  const set = (x0, y0, x1, y1, v = 1) => {
    for (let y = y0; y < Math.min(y1, H); y++) c.fill(v, y * W + Math.min(x0, W), y * W + Math.min(x1, W));
  };
  set(0, 0, W, 5);
  set(0, H - 5, W, H);
  set(0, 0, 5, H);
  set(W - 5, 0, W, H);
  for (let k = 0; k < 6; k++) {
    const x0 = 150 + k * 125;
    for (const [y0, y1] of [[200, 500], [580, 880], [960, 1260], [1340, 1480]]) {
      set(x0, y0, x0 + 35, y1);
      if (k % 2 === 1 && y0 === 580) set(x0, 710, x0 + 35, 750, 0);
    }
  }
  set(5, 1540, 130, 1545);
  set(180, 1540, 305, 1545);
  set(300, 1540, 305, H - 5);
  for (let y = 100; y < H - 100; y += 200) set(900, y, 913, y + 13);
  for (let x = 200; x < W - 100; x += 200) set(x, 120, x + 13, 133);
  // The pallets: the same LCG as the Rust generator (64-bit, BigInt).
  let seed = 0x9e3779b97f4a7c15n;
  const next = (m) => {
    seed = (seed * 6364136223846793005n + 1442695040888963407n) & 0xffffffffffffffffn;
    return Number((seed >> 33n) % BigInt(m));
  };
  for (let i = 0; i < 14; i++) {
    const w = 30 + next(11);
    const h = 30 + next(11);
    const x = 330 + next(W - 330 - 60);
    const y = next(2) === 0 ? 20 + next(40) : 1500 + next(120);
    set(x, y, x + w, y + h);
  }
  return c;
}

/** The ROS map: `warehouse.pgm` (row 0 at the top; 0 occupied, 254 free) and its YAML. */
function rosFiles() {
  const cells = warehouse();
  const header = Buffer.from(`P5\n${W} ${H}\n255\n`);
  const pixels = Buffer.alloc(W * H);
  for (let row = 0; row < H; row++) {
    const y = H - 1 - row;
    for (let x = 0; x < W; x++) pixels[row * W + x] = cells[y * W + x] ? 0 : 254;
  }
  const yaml = 'image: warehouse.pgm\nmode: trinary\nresolution: 0.03\norigin: [0.0, 0.0, 0.0]\n' +
    'negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.25\n';
  return [
    { name: 'warehouse.yaml', mimeType: 'text/yaml', buffer: Buffer.from(yaml) },
    { name: 'warehouse.pgm', mimeType: 'image/x-portable-graymap', buffer: Buffer.concat([header, pixels]) },
  ];
}

let browser;
before(async () => {
  browser = await launch();
});
after(async () => {
  await browser?.close();
});

/** Paints the stroke and reports; `budget` false runs the page's steps without the frame
 * budget (every tick a frame owes in that frame: the page before it had one). */
async function paint(budget) {
  const { page, problems } = await openPage(browser.context, '', {
    // Every frame's start, from the page's own requestAnimationFrame.
    init: () => {
      window.__frames = [];
      const raf = window.requestAnimationFrame.bind(window);
      window.requestAnimationFrame = (cb) => raf((t) => {
        window.__frames.push(t);
        cb(t);
      });
    },
  });
  await page.evaluate((b) => {
    window.rtnav.setFrameSize(1280, 800);
    const demo = window.rtnav.demo;
    if (!b) demo.step_within = (elapsedMs) => demo.step(elapsedMs);
  }, budget);
  const t0 = Date.now();
  await page.setInputFiles('#map-file', rosFiles());
  await page.waitForFunction(() => JSON.parse(window.rtnav.demo.map_json()).name === 'warehouse.yaml', null, { timeout: 120_000 });
  const loadMs = Date.now() - t0;
  assert.deepEqual(await mapInfo(page).then((m) => [m.width, m.height, m.grid_size]), [W, H, GRID]);
  // Start in the loading zone, goal beyond the racks (the benches' long route, reversed).
  const c = (x) => (x + 0.5) * GRID;
  const t1 = Date.now();
  await page.evaluate(([sx, sy, gx, gy]) => window.rtnav.demo.set_position(sx, sy, 90, gx, gy, 90, false),
    [c(975), c(25), c(250), c(1650)]);
  const goalMs = Date.now() - t1;
  await page.waitForFunction(() => JSON.parse(window.rtnav.demo.plan_json()).global_path.length > 0, null, { timeout: 120_000 });
  await activateAll(page);
  await page.selectOption('#speed', '16');
  await page.waitForFunction(() => JSON.parse(window.rtnav.demo.telemetry_json()).path_length > 0.3, null, { timeout: 120_000 });
  // A stroke of the 5 × 5 brush across the route, 3 m ahead of the robot.
  const { global_path: route } = await plan(page);
  assert.ok(route.length > 100, `a route of ${route.length} cells`);
  const at = route[Math.min(route.length - 1, 100)];
  await page.click('#tool-paint');
  await page.selectOption('#brush', '5');
  const [x0, y0] = await cellToPage(page, [at[0] - 25, at[1] - 25]);
  const [x1, y1] = await cellToPage(page, [at[0] + 25, at[1] + 25]);
  await page.evaluate(() => {
    window.__frames.length = 0;
    window.rtnav.clearFrameTimes();
  });
  await page.mouse.move(x0, y0);
  await page.mouse.down();
  await page.mouse.move(x1, y1, { steps: 30 });
  await page.mouse.up();
  // The frames while the edits are planned around, and a moment after.
  await page.waitForTimeout(1500);
  // One more frame start, so a long last frame counts too.
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));
  const { frames, own, updates } = await page.evaluate(() => ({
    frames: window.__frames.slice(),
    own: window.rtnav.frameTimes(),
    updates: [...document.querySelectorAll('#events li[data-kind="MapUpdated"]')].length,
  }));
  const gaps = frames.slice(1).map((t, i) => t - frames[i]).sort((a, b) => a - b);
  const sorted = own.slice().sort((a, b) => a - b);
  const q = (a, f) => (a.length ? a[Math.min(a.length - 1, Math.floor(a.length * f))] : NaN);
  const report = {
    budget,
    cells: W * H,
    map_load_ms: loadMs,
    set_position_ms: goalMs,
    frames: gaps.length,
    map_updates: updates,
    worst_frame_ms: Number(q(gaps, 1).toFixed(1)),
    median_frame_ms: Number(q(gaps, 0.5).toFixed(1)),
    worst_step_render_ms: Number(q(sorted, 1).toFixed(1)),
    median_step_render_ms: Number(q(sorted, 0.5).toFixed(1)),
  };
  console.log(`RTNAV-FRAME ${JSON.stringify(report)}`);
  assert.ok(gaps.length > 3, 'the page kept drawing');
  assert.ok(updates >= 1, 'the stroke reached the map');
  assert.deepEqual(problems, []);
  await page.close();
}

test('painting on a 1.7 M-cell warehouse at 16×: the worst frame (reported)', { timeout: 600_000 }, () => paint(true));
test('the same without the frame budget: the baseline of this run (reported)', { timeout: 600_000 }, () => paint(false));
