// Scenarios and maps: the picker over the fixtures (`fixtures/index.json`, staged by
// `cargo xtask`) and loading a map file the user picks. The bytes go to Rust (`Files`);
// which loader a file needs, and whether it is good, is decided there. A bad file is
// refused with the reason and the current map stays.
//
// A share link (`?share=TOKEN`, issue 8) names a scenario (`Demo.share_scenario`): that
// scenario is loaded the usual way, then the token's start, goal, map edits and parameters
// are applied (`apply_share`). A bad link is explained and the default scenario shown.
import { Demo, Files } from '../pkg/rtnav_wasm.js';
import { el } from './dom.js';

const INDEX_URL = 'fixtures/index.json';
/** MovingAI maps have no cell size: they are read at this many metres per cell. */
const MOVINGAI_CELL_M = 1.0;
const CUSTOM = '';

async function fetchOk(url, how) {
  const r = await fetch(url);
  if (!r.ok) throw new Error(`${url}: HTTP ${r.status}`);
  return how === 'text' ? r.text() : new Uint8Array(await r.arrayBuffer());
}

export function createScenarios(dom, app) {
  const { demo } = app;
  let index = { default: null, scenarios: [] };
  const custom = el('option', { value: CUSTOM, disabled: true }, 'Map file');
  let current = null;

  function showAbout() {
    const s = JSON.parse(demo.scenario_json());
    const map = JSON.parse(demo.map_json());
    if (s) {
      dom.title.textContent = `About this scenario: ${s.name.replaceAll('_', ' ')}`;
      dom.description.textContent = s.description;
      showLesson(s.lesson);
    } else {
      dom.title.textContent = `Map file: ${map?.name ?? ''}`;
      dom.description.textContent = map
        ? `${map.width}×${map.height} cells of ${map.grid_size} m. Place the robot with the Start tool, then drag a goal, then Activate all.`
        : '';
      showLesson('');
    }
  }

  /** The scenario's lesson, prominent: "Try this: …". */
  function showLesson(text) {
    dom.lesson.replaceChildren(el('strong', {}, 'Try this'), ' ', text ?? '');
    dom.lesson.hidden = !text;
  }

  function loaded(what) {
    // Whatever the notices said was about the old system.
    app.notice.hide();
    app.emit('loaded');
    showAbout();
    // A new system: a fresh log, starting with what it did while loading.
    app.log.clear();
    app.log.update();
    app.log.page(what, 'info');
  }

  /**
   * Loads the scenario named `name` from the fixtures, then applies the share token `share`
   * if given. Returns whether it loaded; with a token that could not be applied it returns
   * `{ shareError }` (the scenario is then loaded without the token's set-up, announced to
   * nobody: the caller loads the default).
   */
  async function load(name, share = null) {
    const entry = index.scenarios.find((s) => s.name === name);
    if (!entry) {
      app.notice.show(`No scenario named ${name}.`, 'error');
      return false;
    }
    const files = new Files();
    try {
      const [text, ...bytes] = await Promise.all([
        fetchOk(entry.url, 'text'),
        ...Object.values(entry.files).map((url) => fetchOk(url, 'bytes')),
      ]);
      Object.keys(entry.files).forEach((path, i) => files.add(path, bytes[i]));
      const r = app.attempt(() => demo.load_scenario(text, files));
      if (!r.ok) throw new Error(r.error);
      if (share !== null) {
        const s = app.attempt(() => demo.apply_share(share));
        if (!s.ok) return { shareError: s.error };
      }
    } catch (e) {
      app.notice.show(`Could not load scenario ${name}: ${e.message ?? e}. The current one stays.`, 'error');
      app.log.page(`Scenario ${name} not loaded: ${e.message ?? e}`, 'error');
      dom.select.value = current ?? CUSTOM;
      return false;
    } finally {
      files.free();
    }
    current = name;
    dom.select.value = name;
    // The set-up is drawn at once, before the clock runs a tick: the first frame of a load
    // (and of a share link) is the set-up at its own time.
    app.stage.draw();
    loaded(share === null
      ? `Scenario ${name} loaded. Press Activate all to drive.`
      : `Shared set-up of scenario ${name} loaded (its start, goal, map edits and parameters). Press Activate all to drive.`);
    return true;
  }

  /** Loads the set-up a share link carries; false (with a notice) when it cannot. */
  async function loadShared(token) {
    let name;
    try {
      name = app.guard.call(() => Demo.share_scenario(token));
    } catch (e) {
      return refuseShare(e?.message ?? String(e));
    }
    if (name === undefined) return false;
    if (!index.scenarios.some((s) => s.name === name)) {
      return refuseShare(`it is made for the scenario ${name}, which this page does not have`);
    }
    const r = await load(name, token);
    if (r === true) {
      app.notice.show(`Shared set-up of ${name.replaceAll('_', ' ')} loaded.`, 'success');
      return true;
    }
    if (r && r.shareError) return refuseShare(r.shareError);
    return false;
  }

  let shareRefusal = null;
  function refuseShare(reason) {
    shareRefusal = `This share link cannot be used: ${reason}. The default scenario is shown instead.`;
    app.notice.show(shareRefusal, 'error');
    return false;
  }

  async function loadFiles(list) {
    const files = new Files();
    const names = [...list].map((f) => f.name);
    try {
      const bytes = await Promise.all([...list].map(async (f) => new Uint8Array(await f.arrayBuffer())));
      names.forEach((n, i) => files.add(n, bytes[i]));
      const r = app.attempt(() => demo.load_map_files(files, MOVINGAI_CELL_M));
      if (!r.ok) {
        app.notice.show(`Could not load the map: ${r.error}. The current map stays.`, 'error');
        app.log.page(`Map file refused: ${r.error}`, 'error');
        return false;
      }
    } finally {
      files.free();
    }
    current = null;
    dom.select.value = CUSTOM;
    const map = JSON.parse(demo.map_json());
    custom.textContent = `Map file: ${map.name}`;
    app.emit('tool', 'start');
    loaded(`Map ${map.name} loaded: ${map.width}×${map.height} cells of ${map.grid_size} m.`);
    app.notice.show(`Map ${map.name} loaded. Place the robot with the Start tool, then drag a goal.`, 'success');
    return true;
  }

  dom.select.addEventListener('change', () => {
    if (dom.select.value !== CUSTOM) load(dom.select.value);
  });
  dom.file.addEventListener('change', async () => {
    if (dom.file.files.length) await loadFiles(dom.file.files);
    dom.file.value = '';
  });

  return {
    load,
    loadFiles,
    /**
     * Reads the index, fills the picker and loads the set-up of the share link `share` if
     * given and good, else the default scenario.
     */
    async loadDefault(share = null) {
      index = JSON.parse(await fetchOk(INDEX_URL, 'text'));
      dom.select.replaceChildren(
        ...index.scenarios.map((s) => el('option', { value: s.name, title: s.description }, s.name.replaceAll('_', ' '))),
        custom,
      );
      if (share !== null && await loadShared(share)) return;
      const first = index.default ?? index.scenarios[0]?.name;
      if (first) await load(first);
      if (shareRefusal) {
        app.log.page(shareRefusal, 'error');
        app.notice.show(shareRefusal, 'error');
      }
    },
    /** The name of the scenario loaded (null for a map file). */
    get current() {
      return current;
    },
    get index() {
      return index;
    },
  };
}
