// @ts-check
// Scenarios and maps: the picker over the fixtures (`fixtures/index.json`, staged by
// `cargo xtask`) and loading a map file the user picks. The bytes go to Rust (`Files`);
// which loader a file needs, and whether it is good, is decided there. A bad file is
// refused with the reason and the current map stays.
//
// A share link (`?share=TOKEN`) names a scenario (`Demo.share_scenario`): that
// scenario is loaded the usual way, then the token's start, goal, map edits and parameters
// are applied (`apply_share`). A bad link is explained and the default scenario shown.
import { Demo, Files } from '../pkg/rtnav_wasm.js';
import { el } from './dom.js';
import { t, has } from './i18n.js';
import { errorText } from './say.js';

const INDEX_URL = 'fixtures/index.json';
/** Session storage: the scenario last loaded in this tab, which a reload opens again. */
const LAST_KEY = 'rtnav.scenario';
/** MovingAI maps have no cell size: they are read at this many metres per cell. */
const MOVINGAI_CELL_M = 1.0;
const CUSTOM = '';

/**
 * The file at `url` as text, or as bytes; an error unless the server answered it.
 * @overload
 * @param {string} url
 * @param {'text'} how
 * @returns {Promise<string>}
 */
/**
 * @overload
 * @param {string} url
 * @param {'bytes'} how
 * @returns {Promise<Uint8Array>}
 */
/**
 * @param {string} url
 * @param {'text' | 'bytes'} how
 * @returns {Promise<string | Uint8Array>}
 */
async function fetchOk(url, how) {
  const r = await fetch(url);
  if (!r.ok) throw new Error(`${url}: HTTP ${r.status}`);
  return how === 'text' ? r.text() : new Uint8Array(await r.arrayBuffer());
}

/**
 * A scenario's title in the page's language (`scenario_title.NAME`; else its name, spaced).
 * @param {string | undefined} name
 */
export function scenarioTitle(name) {
  const key = `scenario_title.${name}`;
  return has(key) ? t(key) : String(name).replaceAll('_', ' ');
}

/**
 * A scenario's `description` or `lesson` in the page's language (the file's own is English).
 * @param {ScenarioView} s
 * @param {'description' | 'lesson'} what
 */
function scenarioText(s, what) {
  const key = `scenario.${s.name}.${what}`;
  return has(key) ? t(key) : s[what];
}

/**
 * The top bar's elements this module fills and listens to.
 * @typedef {object} ScenarioElements
 * @property {HTMLSelectElement} select the scenario picker
 * @property {HTMLInputElement} file the map file input
 * @property {HTMLElement} about the "About" box
 * @property {HTMLElement} title its title
 * @property {HTMLElement} description its description
 * @property {HTMLElement} lesson its lesson
 */

/**
 * @param {ScenarioElements} dom
 * @param {App} app
 */
export function createScenarios(dom, app) {
  const { demo } = app;
  /** @type {ScenarioIndex} */
  let index = { default: null, scenarios: [] };
  const custom = el('option', { value: CUSTOM, disabled: true }, t('scenarios.map_file'));
  /** @type {string | null} */
  let current = null;

  function showAbout() {
    const s = demo.scenario();
    const map = demo.map();
    if (s) {
      dom.title.textContent = t('scenarios.about', { name: scenarioTitle(s.name) });
      dom.description.textContent = scenarioText(s, 'description');
      showLesson(scenarioText(s, 'lesson'));
    } else {
      dom.title.textContent = t('scenarios.map_file_named', { name: map?.name ?? '' });
      dom.description.textContent = map
        ? t('scenarios.map_about', { width: map.width, height: map.height, grid: map.grid_size })
        : '';
      showLesson('');
    }
  }

  /** The scenario's lesson, prominent: "Try this: …". @param {string} text */
  function showLesson(text) {
    dom.lesson.replaceChildren(el('strong', {}, t('scenarios.try_this')), ' ', text ?? '');
    dom.lesson.hidden = !text;
  }

  /** A new system is loaded: `what` says which (the log's first entry). @param {string} what */
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
   * nobody: the caller loads the default). No name (what the crash guard gives after a
   * crash) is no scenario of the index.
   * @param {string | undefined} name
   * @param {string | null} [share]
   * @returns {Promise<boolean | { shareError: string }>}
   */
  async function load(name, share = null) {
    const entry = index.scenarios.find((s) => s.name === name);
    if (!entry) {
      app.notice.show(t('scenarios.no_such', { name: scenarioTitle(name) }), 'error');
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
      const error = e instanceof Error ? e.message : e;
      app.notice.show(t('scenarios.load_failed', { name: scenarioTitle(name), error }), 'error');
      app.log.page(t('scenarios.not_loaded', { name: scenarioTitle(name), error }), 'error');
      dom.select.value = current ?? CUSTOM;
      return false;
    } finally {
      files.free();
    }
    current = entry.name;
    dom.select.value = entry.name;
    try { sessionStorage.setItem(LAST_KEY, entry.name); } catch { /* storage blocked: not kept */ }
    // The set-up is drawn at once, before the clock runs a tick: the first frame of a load
    // (and of a share link) is the set-up at its own time.
    app.stage.draw();
    loaded(share === null
      ? t('scenarios.loaded', { name: scenarioTitle(name) })
      : t('scenarios.shared_loaded', { name: scenarioTitle(name) }));
    return true;
  }

  /**
   * Loads the set-up a share link carries; false (with a notice) when it cannot.
   * @param {string} token
   * @returns {Promise<boolean>}
   */
  async function loadShared(token) {
    let name;
    try {
      name = app.guard.call(() => Demo.share_scenario(token));
    } catch (e) {
      return refuseShare(errorText(e));
    }
    if (name === undefined) return false;
    if (!index.scenarios.some((s) => s.name === name)) {
      return refuseShare(t('scenarios.share_unknown', { name: scenarioTitle(name) }));
    }
    const r = await load(name, token);
    if (r === true) {
      app.notice.show(t('scenarios.shared_notice', { name: scenarioTitle(name) }), 'success');
      return true;
    }
    if (r && r.shareError) return refuseShare(r.shareError);
    return false;
  }

  /** @type {string | null} */
  let shareRefusal = null;
  /** A share link refused for `reason` (said once the default is loaded). @param {string} reason */
  function refuseShare(reason) {
    shareRefusal = t('scenarios.share_refused', { reason });
    app.notice.show(shareRefusal, 'error');
    return false;
  }

  /**
   * Loads a map from the files a person picked (a map and the files it names).
   * @param {FileList | File[]} list
   * @returns {Promise<boolean>}
   */
  async function loadFiles(list) {
    const files = new Files();
    const names = [...list].map((f) => f.name);
    try {
      const bytes = await Promise.all([...list].map(async (f) => new Uint8Array(await f.arrayBuffer())));
      names.forEach((n, i) => files.add(n, bytes[i]));
      const r = app.attempt(() => demo.load_map_files(files, MOVINGAI_CELL_M));
      if (!r.ok) {
        app.notice.show(t('scenarios.map_refused', { error: r.error }), 'error');
        app.log.page(t('refused', { what: t('scenarios.map_file'), error: r.error }), 'error');
        return false;
      }
    } finally {
      files.free();
    }
    current = null;
    dom.select.value = CUSTOM;
    const map = /** @type {MapView} */ (demo.map()); // just loaded
    custom.textContent = t('scenarios.map_file_named', { name: map.name });
    app.emit('tool', 'start');
    loaded(t('scenarios.map_loaded', { name: map.name, width: map.width, height: map.height, grid: map.grid_size }));
    app.notice.show(t('scenarios.map_loaded_notice', { name: map.name }), 'success');
    return true;
  }

  dom.select.addEventListener('change', () => {
    if (dom.select.value !== CUSTOM) load(dom.select.value);
  });
  dom.file.addEventListener('change', async () => {
    if (dom.file.files?.length) await loadFiles(dom.file.files);
    dom.file.value = '';
  });

  return {
    load,
    loadFiles,
    /**
     * Reads the index, fills the picker and loads: the run `carried()` restores (a run
     * carried from the other language) if it does, else the set-up of the share link
     * `share` if given and good, else the scenario last loaded in this tab (a reload), else
     * the default scenario.
     * @param {string | null} [share]
     * @param {(() => unknown) | null} [carried]
     */
    async loadDefault(share = null, carried = null) {
      index = /** @type {ScenarioIndex} */ (JSON.parse(await fetchOk(INDEX_URL, 'text')));
      dom.select.replaceChildren(
        ...index.scenarios.map((s) => el('option', { value: s.name, title: scenarioText(s, 'description') }, scenarioTitle(s.name))),
        custom,
      );
      if (carried && await carried()) return;
      if (share !== null && await loadShared(share)) return;
      let last = null;
      try { last = sessionStorage.getItem(LAST_KEY); } catch { /* storage blocked */ }
      const first = (shareRefusal === null && index.scenarios.some((s) => s.name === last) ? last : null)
        ?? index.default ?? index.scenarios[0]?.name;
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
    /** The fixtures' index (`fixtures/index.json`). */
    get index() {
      return index;
    },
  };
}
