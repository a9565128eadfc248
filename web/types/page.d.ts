// The page's own shapes shared by its modules (written by hand; the core's view types are
// in core.d.ts, written from Rust). Global declarations: the modules name them in JSDoc.

/** The result of `app.attempt`: the value, or the refusal in the page's words. */
type Attempt<T> =
  | { ok: true; value: T | undefined }
  | { ok: false; error: string; message: string };

/** A box on the page in client coordinates. */
type ClientBox = { left: number; right: number; top: number; bottom: number };

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
  on(name: string, fn: (...args: any[]) => void): void;
  emit(name: string, ...args: unknown[]): void;
  requestMs: number;
  attempt<T>(fn: () => T): Attempt<T>;
  request<T>(what: string, fn: () => T, endsNotices?: boolean): Attempt<T>;
  /** The last frame's read of the session (`Demo.frame`); undefined before the first. */
  frame?: FrameView;
  notice: {
    show(text: string, level: string, options?: { until?: () => boolean }): void;
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
  tabs?: any;
  scenarios?: any;
}

interface Window {
  /** The page's test hook (main.js): the handle, the app and the panels. */
  rtnav: Record<string, unknown>;
  /** The wasm module index.html began to download and compile as the page opened. */
  rtnavWasm?: Promise<WebAssembly.Module | null> | null;
}
