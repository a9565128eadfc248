// rtnav page entry: loads the wasm module, creates the host, mounts the panels, runs the
// clock. No simulation logic lives here: the page owns the clock (requestAnimationFrame)
// and the DOM; Rust owns every state (SPEC §1, §6).
import init, { ComponentHost } from './pkg/rtnav_wasm.js';
import { createCrashGuard } from './js/crash.js';
import { startLoop } from './js/loop.js';
import { createDiagram } from './js/panels/diagram.js';
import { createLifecyclePanel } from './js/panels/lifecycle.js';
import { createConfigPanel } from './js/panels/config.js';
import { createEventLog } from './js/panels/event-log.js';

const $ = (id) => document.getElementById(id);

async function boot() {
  await init();
  const guard = createCrashGuard($('crash'), $('crash-message'));
  const host = guard.call(() => new ComponentHost());
  if (!host) return;

  const panels = [
    createDiagram($('diagram'), host),
    createLifecyclePanel($('lifecycle-panel'), host, guard),
    createConfigPanel($('config-panel'), host, guard),
    createEventLog($('log-panel'), host, guard),
  ];
  const simTime = $('sim-time');

  const loop = startLoop((elapsedMs) => {
    guard.call(() => host.step(elapsedMs));
    if (guard.crashed) return false;
    simTime.textContent = `${(host.time_ms() / 1000).toFixed(3)} s`;
    for (const p of panels) p.update();
    return !guard.crashed;
  });
  guard.onCrash(() => loop.stop());

  // For the console and the end-to-end test: the host, and a way to prove that a panic
  // is shown instead of freezing the page.
  window.rtnav = {
    host,
    debugPanic: () => guard.call(() => host.debug_panic()),
  };
  document.body.dataset.ready = 'true';
}

boot().catch((e) => {
  const box = $('crash');
  box.querySelector('h2').textContent = 'The demo could not start';
  box.querySelector('p').textContent =
    'Could not load the WebAssembly module. Build it with `cargo xtask demo`.';
  $('crash-message').textContent = String(e && e.stack ? e.stack : e);
  box.hidden = false;
});
