// The page's service worker: the page works offline after its first visit.
//
// `cargo xtask dist` writes the build into the line below: every file of the dist folder with
// its SHA-256, and the build's version (a digest of that list; xtask/src/service_worker.rs).
// On install the worker fetches every file (the page, the wasm, the words, the scenarios and
// their maps) and keeps them in a cache of that version, each only if its digest is the
// listed one: a file of another build fails the install, which the browser tries again later.
// Then it answers the page's requests for those files from that cache alone (cache first,
// and only the files of its build), so a page is always one build, never a mix of two. A new
// build is a new `sw.js`: the browser installs it beside the running one, and it takes over
// when the page asks (`js/offline.js`: at the next load), deleting the old build's cache.
//
// As it is in `web/` (`cargo xtask serve`, `demo`), `BUILD` is null: the worker keeps and
// answers nothing (the page is always fresh from the server), and deletes what an earlier
// build kept on the same origin, reloading the pages it served.
const BUILD = null;

/** The caches of this scope (two folders of one origin have one Cache Storage). */
const PREFIX = `rtnav ${self.registration.scope} `;
const CACHE = BUILD ? PREFIX + BUILD.version : null;

/** Hex SHA-256 of `bytes`. */
async function sha256(bytes) {
  const digest = new Uint8Array(await crypto.subtle.digest('SHA-256', bytes));
  return Array.from(digest, (b) => b.toString(16).padStart(2, '0')).join('');
}

/** Fetches `path` of the build past the HTTP cache; a response of its bytes if they are the build's. */
async function fetchChecked(path, digest) {
  const url = new URL(path, self.registration.scope);
  const response = await fetch(url, { cache: 'no-cache' });
  if (!response.ok) throw new Error(`${path}: HTTP ${response.status}`);
  const bytes = await response.arrayBuffer();
  if ((await sha256(bytes)) !== digest) throw new Error(`${path} is not of build ${BUILD.version}`);
  // Kept as the bytes and their type alone: no Content-Encoding, no Vary.
  const type = response.headers.get('Content-Type');
  return [url, new Response(bytes, { headers: type ? { 'Content-Type': type } : {} })];
}

self.addEventListener('install', (event) => {
  // Without a build there is nothing to wait for: it replaces an earlier build's worker at once.
  if (!BUILD) {
    self.skipWaiting();
    return;
  }
  event.waitUntil((async () => {
    const cache = await caches.open(CACHE);
    const kept = new Set((await cache.keys()).map((r) => r.url));
    // Everything first, then into the cache: a failed install keeps nothing of it.
    const fetched = await Promise.all(Object.entries(BUILD.files)
      .filter(([path]) => !kept.has(new URL(path, self.registration.scope).href))
      .map(([path, digest]) => fetchChecked(path, digest)));
    await Promise.all(fetched.map(([url, response]) => cache.put(url, response)));
  })());
});

self.addEventListener('activate', (event) => {
  event.waitUntil((async () => {
    let replaced = false;
    for (const name of await caches.keys()) {
      if (name.startsWith(PREFIX) && name !== CACHE) {
        await caches.delete(name);
        replaced = true;
      }
    }
    if (!BUILD && replaced) {
      // The pages an earlier build served are reloaded from the server.
      await self.clients.claim();
      for (const client of await self.clients.matchAll({ type: 'window' })) client.navigate(client.url);
    }
  })());
});

self.addEventListener('message', (event) => {
  const message = event.data ?? {};
  // The page asks a waiting worker to take over (js/offline.js).
  if (message.type === 'take-over') self.skipWaiting();
  // The page asks which build this worker keeps (it answers on the port sent with the question).
  if (message.type === 'version') event.ports[0]?.postMessage({ type: 'version', version: BUILD?.version ?? null });
});

/** The build's file a request asks for (a page's address with any query is `index.html`), or null. */
function fileOf(request) {
  if (request.method !== 'GET') return null;
  const url = new URL(request.url);
  const scope = new URL(self.registration.scope);
  if (url.origin !== scope.origin || !url.pathname.startsWith(scope.pathname)) return null;
  let path = decodeURIComponent(url.pathname.slice(scope.pathname.length));
  if (path === '' || path.endsWith('/')) path += 'index.html';
  return Object.hasOwn(BUILD.files, path) ? path : null;
}

// Only a build answers requests: without one the worker has no fetch handler, and the browser
// sends every request to the server as if there were no worker.
if (BUILD) {
  self.addEventListener('fetch', (event) => {
    const path = fileOf(event.request);
    if (path === null) return;
    event.respondWith((async () => {
      const cache = await caches.open(CACHE);
      const kept = await cache.match(new URL(path, self.registration.scope), { ignoreVary: true });
      // Not kept (the cache was cleared under us): the server's, as without a worker.
      return kept ?? fetch(event.request);
    })());
  });
}
