// @ts-check
// Offline after the first visit: the page's service worker (`sw.js`), which a dist folder's
// build fills (`cargo xtask dist`) and which keeps that build's files in one cache.
//
// The worker is registered once the page is ready, so its downloads never slow the first
// load. A new build is installed by the browser beside the running one while the page is
// open; it takes over only at the next load of the page (`takeOverWaitingBuild`, before
// anything else is loaded), never under a running page, so a page is always one build. While
// the page is open, a notice says that the new build is ready. `document.body.dataset.offline`
// says which build the worker keeps (its version), once it keeps one.
import { t } from './i18n.js';

const WORKER = './sw.js';
/** How long the start waits for the browser to say whether a new build is waiting [ms]. */
const LOOK_MS = 500;

const supported = () => 'serviceWorker' in navigator && window.isSecureContext;

/**
 * At the start of a load: if a new build is installed and waiting, it takes over and the
 * page loads again from it (resolves true: the caller stops); else resolves false.
 * @returns {Promise<boolean>}
 */
export async function takeOverWaitingBuild() {
  if (!supported()) return false;
  const registration = await Promise.race([
    navigator.serviceWorker.getRegistration().catch(() => undefined),
    /** @type {Promise<undefined>} */ (new Promise((done) => setTimeout(done, LOOK_MS))),
  ]);
  const waiting = registration?.waiting;
  if (!waiting || !navigator.serviceWorker.controller) return false;
  navigator.serviceWorker.addEventListener('controllerchange', () => location.reload(), { once: true });
  waiting.postMessage({ type: 'take-over' });
  return true;
}

/**
 * The version of the build `worker` keeps (null: none, as in `web/`).
 * @param {ServiceWorker} worker
 * @returns {Promise<string | null>}
 */
function versionOf(worker) {
  return new Promise((done) => {
    const channel = new MessageChannel();
    channel.port1.onmessage = (event) => done(event.data?.version ?? null);
    worker.postMessage({ type: 'version' }, [channel.port2]);
  });
}

/**
 * Registers the worker (the page is ready) and tells of a new build when one is installed.
 * @param {App} app
 */
export function keepOffline(app) {
  if (!supported()) return;
  const container = navigator.serviceWorker;
  // A build installed while this page runs on an older one: it is used from the next load
  // (a worker without a build, as in `web/`, is no new version of the page).
  /** @param {ServiceWorker} worker */
  const tell = async (worker) => {
    if (!container.controller || document.body.dataset.offlineUpdate) return;
    if (!(await versionOf(worker))) return;
    document.body.dataset.offlineUpdate = 'ready';
    // It stays until closed: a class may not look up within a fading notice's seconds.
    app.notice.show(t('offline.update_ready'), 'info', { stays: true });
  };
  container.register(WORKER).then(async (registration) => {
    if (registration.waiting) tell(registration.waiting);
    registration.addEventListener('updatefound', () => {
      const installing = registration.installing;
      installing?.addEventListener('statechange', () => {
        if (installing.state === 'installed') tell(installing);
      });
    });
    // Whether the server has a new build (offline, it cannot say: nothing to tell).
    registration.update().catch(() => {});
    const ready = await container.ready;
    const version = ready.active ? await versionOf(ready.active) : null;
    if (version) document.body.dataset.offline = version;
  }).catch((e) => {
    // No worker (a private window, storage refused): the page works online as before.
    console.warn(`rtnav: the page is not kept for offline use: ${e}`);
  });
}
