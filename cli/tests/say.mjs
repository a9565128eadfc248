// The page's words for facts, for `words.rs`: reads `[[saying, ...args], …]` (JSON) on
// stdin, says each with the page's own `web/js/say.js` over the English catalogue (as
// `tests/e2e/ja.test.mjs` does in the browser) and prints the texts as one JSON array.
import { readFileSync } from 'node:fs';

const web = new URL('../../web/', import.meta.url);
const english = JSON.parse(readFileSync(new URL('i18n/en.json', web), 'utf8'));
// i18n.js loads the page's catalogues at its top level; outside a page it finds none and
// says so on stderr: the words below are made over the English catalogue read above.
const { fill } = await import(new URL('js/i18n.js', web).href);
const { sayer } = await import(new URL('js/say.js', web).href);
const say = sayer((key, vars) => fill(english[key] ?? key, vars), (key) => key in english);
const facts = JSON.parse(readFileSync(0, 'utf8'));
process.stdout.write(JSON.stringify(facts.map(([saying, ...args]) => say[saying](...args))));
