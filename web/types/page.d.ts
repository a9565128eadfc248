// The page's own shapes shared by its modules (written by hand; the core's view types are
// in core.d.ts, written from Rust). Global declarations: the modules name them in JSDoc.

/** The result of `app.attempt`: the value, or the refusal in the page's words. */
type Attempt<T> =
  | { ok: true; value: T | undefined }
  | { ok: false; error: string; message: string };

/** A scenario of the fixtures' index (`fixtures/index.json`, written by `cargo xtask`). */
type ScenarioEntry = ScenarioView & {
  /** The scenario file, relative to the page. */
  url: string;
  /** The files its map names (as the scenario writes their paths) → their URLs. */
  files: Record<string, string>;
};

/** The fixtures' index: the default scenario's name and every scenario the page offers. */
type ScenarioIndex = { default: string | null; scenarios: ScenarioEntry[] };

/** A box on the page in client coordinates. */
type ClientBox = { left: number; right: number; top: number; bottom: number };

/**
 * The page's own events (`app.on`, `app.emit`) and what each hands its listeners.
 */
interface AppEvents {
  /** A scenario or map file is loaded: a new system. */
  loaded: [];
  /** A request changed the system (a button, a parameter, a replay). */
  changed: [];
  /** A run carried from the other language is restored (`carry.js`). */
  carried: [];
  /** The layers shown changed. */
  layers: [];
  /** The map's view (zoom, pan) changed. */
  view: [];
  /** The side panel's tab `name` is shown. */
  tab: [name: string];
  /** The stage's tool is now `tool` (`goal`, `start`, `paint`, …). */
  tool: [tool: string];
  /** The map cell under the pointer (column, row), or null when it left the map. */
  hover: [cell: ArrayLike<number> | null];
}

/** What every module shares (built in main.js). */
interface App {
  demo: import('../pkg/rtnav_wasm.js').Demo;
  guard: {
    crashed: boolean;
    call<T>(fn: () => T): T | undefined;
    check(): boolean;
    onCrash(listener: () => void): void;
  };
  memory: WebAssembly.Memory;
  ui: {
    tool: string;
    backward: boolean;
    brush: { size: number; unit: string };
    pendingStart: PoseView | null;
  };
  on<K extends keyof AppEvents>(name: K, fn: (...args: AppEvents[K]) => void): void;
  emit<K extends keyof AppEvents>(name: K, ...args: AppEvents[K]): void;
  requestMs: number;
  attempt<T>(fn: () => T): Attempt<T>;
  request<T>(what: string, fn: () => T, endsNotices?: boolean): Attempt<T>;
  /** The last frame's read of the session (`Demo.frame`); undefined before the first. */
  frame?: FrameView;
  notice: {
    show(text: string, level: string, options?: { until?: () => boolean, stays?: boolean }): void;
    hide(): void;
    update(keepClear: () => Array<ClientBox | null>): void;
    endState(): void;
    /** Hides whatever the notice says (a new run: it was about the old one). */
    hide(): void;
  };
  log: {
    clear(): void;
    update(events?: EventView[]): void;
    page(text: string, level?: string): void;
  };
  stage: {
    draw(): void;
    robotBox(): ClientBox | null;
    keepClear(): Array<ClientBox | null>;
    [name: string]: any;
  };
  /** The side panel's tabs (set in main.js once they are made, before the first frame). */
  tabs: ReturnType<typeof import('../js/tabs.js').createTabs>;
  /** The scenario picker and loader (set in main.js, before the first frame). */
  scenarios: ReturnType<typeof import('../js/scenarios.js').createScenarios>;
}

interface Window {
  /** The page's test hook (main.js): the handle, the app and the panels. */
  rtnav: Record<string, unknown>;
  /** The wasm module index.html began to download and compile as the page opened. */
  rtnavWasm?: Promise<WebAssembly.Module | null> | null;
}
