// End-to-end: the page works offline after its first visit (sw.js, js/offline.js), and a new
// build replaces the kept one whole.
//
// 1. After one visit, with the network off: a reload opens the page and the scenario last
//    opened; another scenario, a share link, a replay and the other language still work.
// 2. A new build (a copy of the dist folder with three files changed and sealed again by
//    `cargo xtask dist --seal`, served by `cargo xtask serve`): a reload first opens the old
//    build whole, the page then says a new version is ready, and the next reload opens the
//    new build whole — every changed file, one cache — online and offline.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { cp, mkdtemp, readFile, rm, writeFile } from 'node:fs/promises';
import { createServer } from 'node:net';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { WAIT, launch, openPage, activateAll, frames } from './helpers.mjs';

/** The dist folder the tests are served from, and the xtask program that seals and serves. */
const SITE = process.env.RTNAV_SITE;
const XTASK = process.env.RTNAV_XTASK;
const NO_BUILD = !SITE || !XTASK
  ? 'RTNAV_SITE (the dist folder served) and RTNAV_XTASK (the xtask program) are set by `cargo xtask test`'
  : false;

/** Waits until the page's service worker keeps a build; its version. */
async function keptBuild(page) {
  await page.waitForSelector('body[data-offline]', { timeout: 60_000, state: 'attached' });
  return page.getAttribute('body', 'data-offline');
}

/** The build `sw.js` in `dir` names. */
async function buildOf(dir) {
  const text = await readFile(join(dir, 'sw.js'), 'utf8');
  const line = text.split('\n').find((l) => l.startsWith('const BUILD = '));
  return JSON.parse(line.slice('const BUILD = '.length).replace(/;\s*$/, ''));
}

/** Waits for the page to be ready, or fails with what the crash box says. */
async function ready(page) {
  await page.waitForSelector('body[data-ready="true"], #crash:not([hidden])', { timeout: 60_000 });
  if (await page.isVisible('#crash')) assert.fail(`the page did not start: ${await page.innerText('#crash')}`);
}

let browser;
before(async () => {
  browser = await launch();
});
after(async () => {
  await browser?.close();
});

test('offline after one visit: a reload opens the page and the last scenario; scenarios, share links, replays and the other language work', { timeout: 240_000 }, async () => {
  const { page, problems } = await openPage(browser.context, '?lang=en');
  const version = await keptBuild(page);
  assert.match(version, /^[0-9a-f]{16}$/);
  // The person opens another scenario, then the network goes.
  await page.selectOption('#scenario', 'corridor_turn');
  await page.waitForFunction(() => window.rtnav.scenarios.current === 'corridor_turn', null, WAIT);
  await browser.context.setOffline(true);
  try {
    await page.reload({ waitUntil: 'domcontentloaded' });
    await ready(page);
    assert.equal(await page.inputValue('#scenario'), 'corridor_turn', 'the scenario last opened');
    assert.match(await page.textContent('#about-title'), /corridor/i);
    assert.equal(await keptBuild(page), version, 'the same build, from the worker');

    // A scenario not opened before, from the kept build; it drives.
    await page.selectOption('#scenario', 'parking_wall');
    await page.waitForFunction(() => window.rtnav.scenarios.current === 'parking_wall', null, WAIT);
    await activateAll(page);
    await page.waitForFunction(() => window.rtnav.demo.time_s() > 1, null, WAIT);

    // A share link made offline opens offline, in a new tab.
    await page.click('#share-copy');
    await page.waitForSelector('#share-link:not([hidden])', WAIT);
    const link = new URL(await page.inputValue('#share-link'));
    const { page: shared, problems: sharedProblems } = await openPage(browser.context, link.search);
    assert.equal(await shared.inputValue('#scenario'), 'parking_wall');
    await shared.waitForSelector('#notice:not([hidden])', WAIT);
    assert.match(await shared.textContent('#notice-text'), /shared/i);
    assert.deepEqual(sharedProblems, []);
    await shared.close();

    // A replay downloaded offline loads offline, to the same trace.
    await page.evaluate(() => window.rtnav.demo.set_paused(true));
    await frames(page, 2);
    const hash = await page.evaluate(() => JSON.parse(window.rtnav.demo.replay_json()).trace_hash);
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#replay-download')]);
    const file = await download.path();
    await page.setInputFiles('#replay-file', file);
    await page.waitForSelector('#timeline[data-replay-matches="true"]', { timeout: 60_000 });
    assert.equal(await page.getAttribute('#timeline', 'data-replay-hash'), hash);

    // The other language is the same page with another address: also kept.
    await page.selectOption('#language', 'ja');
    await page.waitForFunction(() => document.documentElement.lang === 'ja' && document.body.dataset.ready === 'true', null, { timeout: 60_000 });
    assert.equal(await page.textContent('#activate-all'), 'すべてアクティブ化');
  } finally {
    await browser.context.setOffline(false);
  }
  // Offline, the only failures the page may see are the requests that are not the build's
  // (none here), so none at all.
  assert.deepEqual(problems.filter((p) => !/ERR_INTERNET_DISCONNECTED/.test(p)), []);
  await page.close();
});

/** A free port on the loopback interface. */
function freePort() {
  return new Promise((done, fail) => {
    const s = createServer();
    s.once('error', fail);
    s.listen(0, '127.0.0.1', () => {
      const { port } = s.address();
      s.close(() => done(port));
    });
  });
}

/** Runs `xtask args…`; resolves when it exits 0. */
function xtask(args) {
  return new Promise((done, fail) => {
    const child = spawn(XTASK, args, { stdio: ['ignore', 'ignore', 'pipe'] });
    let err = '';
    child.stderr.on('data', (d) => { err += d; });
    child.on('exit', (code) => (code === 0 ? done() : fail(new Error(`xtask ${args.join(' ')}: exit ${code}\n${err}`))));
  });
}

/** `cargo xtask serve --dir root` on a free port, once it answers; `stop()` ends it. */
async function serve(root) {
  const port = await freePort();
  const child = spawn(XTASK, ['serve', '--port', String(port), '--dir', root], { stdio: 'ignore' });
  const url = `http://127.0.0.1:${port}/`;
  const deadline = Date.now() + 20_000;
  for (;;) {
    try {
      await fetch(url);
      break;
    } catch (e) {
      if (Date.now() > deadline || child.exitCode !== null) throw new Error(`the server did not start: ${e}`);
      await new Promise((r) => setTimeout(r, 100));
    }
  }
  return { url, stop: () => child.kill() };
}

/** What of the three changed files a page shows: [index.html's, main.js's, the catalogue's]. */
const changes = (page) => page.evaluate(() => [
  document.querySelector('meta[name="rtnav-build-test"]')?.content ?? null,
  document.documentElement.dataset.buildTest ?? null,
  document.querySelector('.subtitle').textContent.includes('(second build)'),
]);

test('a new build replaces the kept one whole: the old page until it is ready, then the new one', { timeout: 240_000, skip: NO_BUILD }, async () => {
  const root = await mkdtemp(join(tmpdir(), 'rtnav-build-'));
  const dir = join(root, 'rtnav');
  await cp(SITE, dir, { recursive: true });
  const server = await serve(root);
  const b = await launch();
  try {
    const first = await buildOf(dir);
    const page = await b.context.newPage();
    const problems = [];
    page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
    page.on('console', (m) => { if (m.type() === 'error') problems.push(`console.error: ${m.text()}`); });
    await page.goto(`${server.url}rtnav/?lang=en`, { waitUntil: 'domcontentloaded', timeout: 60_000 });
    await ready(page);
    assert.equal(await keptBuild(page), first.version);
    assert.deepEqual(await changes(page), [null, null, false]);

    // The second build: three files change, the folder is sealed again.
    const edit = async (file, fn) => writeFile(join(dir, file), fn(await readFile(join(dir, file), 'utf8')));
    await edit('index.html', (s) => s.replace('<meta charset="utf-8">', '<meta charset="utf-8">\n  <meta name="rtnav-build-test" content="2">'));
    await edit('main.js', (s) => `${s}\ndocument.documentElement.dataset.buildTest = '2';\n`);
    await edit('i18n/en.json', (s) => s.replace('in your browser"', 'in your browser (second build)"'));
    await xtask(['dist', '--seal', dir]);
    const second = await buildOf(dir);
    assert.notEqual(second.version, first.version);

    // A reload opens the first build whole (the second installs meanwhile), then says so.
    await page.reload({ waitUntil: 'domcontentloaded' });
    await ready(page);
    assert.deepEqual(await changes(page), [null, null, false], 'the first build, none of the second');
    await page.waitForFunction(() => document.body.dataset.offlineUpdate === 'ready', null, { timeout: 60_000 });
    await page.waitForSelector('#notice:not([hidden])', { timeout: 60_000 });
    assert.match(await page.textContent('#notice-text'), /new version/);
    assert.deepEqual(await changes(page), [null, null, false], 'still the first build');

    // The next reload opens the second build whole, and only its files are kept.
    await page.reload({ waitUntil: 'domcontentloaded' });
    await page.waitForFunction(
      (v) => document.body.dataset.ready === 'true' && document.body.dataset.offline === v,
      second.version, { timeout: 60_000 },
    );
    assert.deepEqual(await changes(page), ['2', '2', true], 'the second build, all of it');
    const caches = await page.evaluate(() => caches.keys());
    assert.deepEqual(caches.filter((c) => c.startsWith('rtnav ')).map((c) => c.split(' ').at(-1)), [second.version]);
    // Offline too.
    await b.context.setOffline(true);
    await page.reload({ waitUntil: 'domcontentloaded' });
    await ready(page);
    assert.deepEqual(await changes(page), ['2', '2', true]);
    await b.context.setOffline(false);
    assert.deepEqual(problems, []);
  } finally {
    await b.close();
    server.stop();
    await rm(root, { recursive: true, force: true });
  }
});
