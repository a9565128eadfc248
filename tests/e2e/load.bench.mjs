// A browser report for `cargo xtask bench`, not a check of speed (the machines are noisy), and
// not one of `cargo xtask test`'s e2e tests (not a `.test.mjs`): the first load of the page
// on a slow network. Each run is a fresh browser profile (a cold cache, no service worker)
// whose network Chromium throttles to 10 Mbit/s down and up with 40 ms of latency
// (DevTools' `Network.emulateNetworkConditions`); the time is from the navigation's start
// to the first animation frame after the default scenario's map is drawn
// (`body[data-ready]`). It runs the page served compressed (the browser's own
// `Accept-Encoding`: `cargo xtask serve` sends the dist folder's brotli copies) and plain
// (`Accept-Encoding: identity`: the files as a server without the copies sends them), each
// `RUNS` times, and prints one line per way — `RTNAV-LOAD {...}` — with the median, the
// fastest and the slowest time, the requests and the bytes transferred.
import { test, after } from 'node:test';
import assert from 'node:assert/strict';
import { URL, launch } from './helpers.mjs';

const RUNS = Number(process.env.RTNAV_LOAD_RUNS ?? 5);
/** 10 Mbit/s in bytes per second, and the round trip's latency [ms]. */
const NETWORK = { offline: false, latency: 40, downloadThroughput: 10e6 / 8, uploadThroughput: 10e6 / 8 };

/** The browser of the run under way (closed after each; here too if a run fails). */
let browser = null;
after(async () => {
  await browser?.close();
});

/** One cold load: the time to the map drawn [ms], the requests and bytes, the encodings seen. */
async function coldLoad(compressed) {
  browser = await launch();
  try {
    const page = await browser.context.newPage();
    // The first frame after the page says it is ready: its time since the navigation began.
    await page.addInitScript(() => {
      const look = () => {
        if (document.body?.dataset.ready === 'true') window.__drawnAt = performance.now();
        else requestAnimationFrame(look);
      };
      requestAnimationFrame(look);
    });
    const cdp = await browser.context.newCDPSession(page);
    await cdp.send('Network.enable');
    await cdp.send('Network.emulateNetworkConditions', NETWORK);
    if (!compressed) await cdp.send('Network.setExtraHTTPHeaders', { headers: { 'Accept-Encoding': 'identity' } });
    const encodings = new Set();
    cdp.on('Network.responseReceived', (e) => {
      const h = Object.fromEntries(Object.entries(e.response.headers).map(([k, v]) => [k.toLowerCase(), v]));
      encodings.add(h['content-encoding'] ?? 'identity');
    });
    const problems = [];
    page.on('pageerror', (e) => problems.push(e.message));
    page.on('console', (m) => { if (m.type() === 'error') problems.push(m.text()); });
    await page.goto(URL, { waitUntil: 'commit', timeout: 120_000 });
    await page.waitForSelector('body[data-ready="true"], #crash:not([hidden])', { timeout: 120_000 });
    assert.equal(await page.isVisible('#crash'), false, `the page did not start: ${problems.join('\n')}`);
    await page.waitForFunction(() => window.__drawnAt !== undefined, null, { timeout: 10_000, polling: 50 });
    const result = await page.evaluate(() => {
      const entries = [...performance.getEntriesByType('navigation'), ...performance.getEntriesByType('resource')];
      return {
        drawn_ms: window.__drawnAt,
        requests: entries.length,
        transferred: entries.reduce((sum, e) => sum + (e.transferSize ?? 0), 0),
      };
    });
    return { ...result, encodings: [...encodings].sort() };
  } finally {
    await browser.close();
    browser = null;
  }
}

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};

for (const compressed of [true, false]) {
  const way = compressed ? 'compressed' : 'plain';
  test(`first load at 10 Mbit/s and 40 ms, cold cache, ${way} (reported)`, { timeout: 600_000 }, async () => {
    const runs = [];
    for (let i = 0; i < RUNS; i++) runs.push(await coldLoad(compressed));
    const times = runs.map((r) => r.drawn_ms);
    const report = {
      way,
      runs: RUNS,
      median_ms: Math.round(median(times)),
      fastest_ms: Math.round(Math.min(...times)),
      slowest_ms: Math.round(Math.max(...times)),
      requests: runs[0].requests,
      transferred_kb: Math.round(median(runs.map((r) => r.transferred)) / 1000),
      encodings: runs[0].encodings,
    };
    console.log(`RTNAV-LOAD ${JSON.stringify(report)}`);
    // What was measured is what was meant: the copies, or none of them.
    if (compressed) assert.ok(report.encodings.includes('br'), `no brotli: ${report.encodings}`);
    else assert.deepEqual(report.encodings, ['identity']);
  });
}
