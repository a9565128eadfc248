// @ts-check
// The run carried across a change of language. Switching English ↔ 日本語 reloads the page
// (every string is drawn anew in the other language); what the robot did must not be lost
// with it. Before the reload the session's replay (`demo.replay_json()`: the set-up and every
// request at its simulated time — the goal, the map edits, the parameters, the lifecycle
// requests) and the page's own state (paused, speed, tool, direction, brush, layers, tab)
// are kept in session storage for the language asked for; the reloaded page takes them once
// and replays the run to the same tick through the core (`demo.load_replay`), so the trace
// is the same bit for bit. A map loaded from a file has no replay: the page asks first.
import { Demo } from '../pkg/rtnav_wasm.js';
import { t } from './i18n.js';
import { errorText } from './say.js';

const KEY = 'rtnav.carry';
/** A carry older than this [ms] is not for this load (a reload long after, another tab). */
const FRESH_MS = 60_000;

/**
 * Keeps the run for a reload in `lang`. Returns false when the person chose to stay (a map
 * loaded from a file cannot be carried, and they were asked), else true — with `share`, a
 * set-up token to put in the address when the run could not be kept (storage blocked).
 */
/**
 * @param {App} app
 * @param {string} lang
 * @param {{confirm?: (text: string) => boolean}} [options]
 */
export function keepRun(app, lang, { confirm = (text) => window.confirm(text) } = {}) {
  const { demo } = app;
  drop();
  if (!app.scenarios.current) {
    // A map file's bytes are not kept: the other language starts from the default scenario.
    return { go: confirm(t('carry.map_file')) };
  }
  const replay = app.attempt(() => demo.replay_json());
  const layers = app.attempt(() => demo.layers());
  const carried = replay.ok && {
    lang,
    at: Date.now(),
    replay: replay.value,
    paused: demo.paused(),
    speed: demo.speed(),
    ui: { tool: app.ui.tool, backward: app.ui.backward, brush: app.ui.brush },
    layers: layers.ok ? layers.value : null,
    tab: app.tabs?.current ?? null,
  };
  try {
    if (!carried) throw new Error('no replay');
    sessionStorage.setItem(KEY, JSON.stringify(carried));
    return { go: true };
  } catch {
    // Not kept: the set-up at least goes with the address, as a share link.
    const share = app.attempt(() => demo.share_token());
    return { go: true, share: share.ok ? share.value : null };
  }
}

function drop() {
  try { sessionStorage.removeItem(KEY); } catch { /* storage blocked: nothing kept */ }
}

/** The run kept for this load in `lang` (taken: a second load does not replay it), or null. */
/** @param {string} lang */
export function takeRun(lang) {
  let carried = null;
  try {
    carried = JSON.parse(sessionStorage.getItem(KEY) ?? 'null');
  } catch {
    carried = null;
  }
  drop();
  if (!carried || carried.lang !== lang || !(Date.now() - carried.at < FRESH_MS)) return null;
  return carried;
}

/**
 * Replays a carried run on its scenario (the index must be read) and puts the page back as it
 * was. Returns whether it did; when it did not, the reason is in the notice and the log.
 */
/**
 * @param {App} app
 * @param {{replay: string, layers?: Record<string, boolean>, [k: string]: any}} carried
 */
export async function restoreRun(app, carried) {
  const { demo } = app;
  let name;
  try {
    name = app.guard.call(() => Demo.replay_scenario(carried.replay));
  } catch (e) {
    return failed(app, errorText(e));
  }
  if (name === undefined || !(await app.scenarios.load(name))) return false;
  const r = app.attempt(() => demo.load_replay(carried.replay));
  if (!r.ok) return failed(app, r.error);
  demo.set_paused(Boolean(carried.paused));
  app.attempt(() => demo.set_speed(carried.speed));
  for (const [layer, on] of Object.entries(carried.layers ?? {})) app.attempt(() => demo.set_layer(layer, on));
  const ui = carried.ui ?? {};
  if (ui.brush) app.ui.brush = ui.brush;
  app.ui.backward = Boolean(ui.backward);
  if (ui.tool) app.emit('tool', ui.tool);
  if (carried.tab) app.tabs?.show(carried.tab);
  app.emit('carried');
  app.emit('layers');
  app.emit('changed');
  app.stage.draw();
  app.log.page(t('carry.restored', { s: demo.time_s().toFixed(1) }), 'info');
  return true;
}

/** @param {App} app @param {string} error */
function failed(app, error) {
  app.notice.show(t('carry.failed', { error }), 'error');
  app.log.page(t('carry.failed', { error }), 'error');
  return false;
}
