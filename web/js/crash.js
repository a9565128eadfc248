// @ts-check
// Shows a Rust panic instead of a frozen tab (egui's WebHandle style).
//
// After a panic the wasm instance must not be used: the object that panicked stays borrowed
// and further calls throw. `has_panicked()` / `panic_message()` are free functions exported
// by rtnav-wasm that read what the panic hook recorded.
import { has_panicked, panic_message } from '../pkg/rtnav_wasm.js';
import { t } from './i18n.js';

/**
 * @param {HTMLElement} box
 * @param {HTMLElement} messageEl
 * @returns {App['guard']}
 */
export function createCrashGuard(box, messageEl) {
  /** @type {Array<() => void>} */
  const listeners = [];
  const guard = {
    crashed: false,

    // Runs `fn`; if Rust panicked, shows the crash and returns undefined. Other errors
    // (an illegal request, a refused value) are thrown on to the caller.
    /**
     * @template T
     * @param {() => T} fn
     * @returns {T | undefined}
     */
    call(fn) {
      if (guard.crashed) return undefined;
      try {
        return fn();
      } catch (e) {
        if (guard.check()) return undefined;
        throw e;
      }
    },

    // Shows the crash if Rust has panicked; returns whether it has.
    check() {
      if (guard.crashed) return true;
      if (!has_panicked()) return false;
      guard.crashed = true;
      messageEl.textContent = panic_message() ?? t('crash.unknown');
      box.hidden = false;
      document.body.dataset.crashed = 'true';
      for (const l of listeners) l();
      return true;
    },

    /** @param {() => void} listener */
    onCrash(listener) {
      listeners.push(listener);
    },
  };
  window.addEventListener('error', () => guard.check());
  window.addEventListener('unhandledrejection', () => guard.check());
  return guard;
}
