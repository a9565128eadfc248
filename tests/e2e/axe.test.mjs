// End-to-end: axe-core (Deque's accessibility rules, through @axe-core/playwright) finds no
// violation of the WCAG 2.1 A and AA rules on any tab of the page, nor with the keyboard guide
// open, in English and in Japanese, at a laptop's, a tablet's and a phone's size.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { AxeBuilder } from '@axe-core/playwright';
import { launch, openPage, showTab, frames } from './helpers.mjs';

const TAGS = ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa'];
const TABS = ['rtc', 'system', 'params', 'inspector', 'plots', 'log'];
const SIZES = [
  { viewport: { width: 1280, height: 800 } },
  { viewport: { width: 768, height: 1024 }, hasTouch: true },
  { viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true, deviceScaleFactor: 2 },
];

/** Each violation as one line: the rule, what it says, and the first few elements it names. */
const described = (violations) => violations.map((v) =>
  `${v.id} (${v.impact}): ${v.help} — ${v.nodes.slice(0, 4).map((n) => `${n.target.join(' ')}${n.failureSummary ? ` [${n.failureSummary.split('\n').slice(1).join(' ').trim()}]` : ''}`).join('; ')}${v.nodes.length > 4 ? ` and ${v.nodes.length - 4} more` : ''}`);

for (const size of SIZES) {
  const { width, height } = size.viewport;
  test(`at ${width}×${height} no tab, in English or Japanese, violates a WCAG 2.1 A or AA rule`, { timeout: 300_000 }, async () => {
    const browser = await launch(size);
    try {
      const found = {};
      for (const lang of ['en', 'ja']) {
        const { page, problems } = await openPage(browser.context, `?lang=${lang}`);
        for (const tab of TABS) {
          await showTab(page, tab);
          await frames(page, 2);
          const { violations } = await new AxeBuilder({ page }).withTags(TAGS).analyze();
          if (violations.length) found[`${lang} ${tab}`] = described(violations);
        }
        // The keyboard guide, open over the page.
        await page.click('#keys-open');
        await page.waitForSelector('#keys[open]');
        const { violations } = await new AxeBuilder({ page }).withTags(TAGS).analyze();
        if (violations.length) found[`${lang} keyboard guide`] = described(violations);
        await page.keyboard.press('Escape');
        await page.waitForSelector('#keys:not([open])', { state: 'attached' });
        assert.deepEqual(problems, []);
        await page.close();
      }
      assert.deepEqual(found, {}, 'axe-core violations');
    } finally {
      await browser.close();
    }
  });
}
