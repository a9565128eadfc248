// The page's two catalogues: `web/i18n/en.json` and `web/i18n/ja.json` have the
// same keys, with the same placeholders; every key the page asks for exists; the Japanese
// catalogue translates every scenario's description, lesson and exercise task and every
// parameter the seeds give no Japanese words for. No browser: the files are read.
import test from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { REPO } from './helpers.mjs';

const read = (...p) => readFileSync(join(REPO, ...p), 'utf8');
const en = JSON.parse(read('web', 'i18n', 'en.json'));
const ja = JSON.parse(read('web', 'i18n', 'ja.json'));
/** Translations of texts whose English is elsewhere (the scenario files, the core). */
const JA_ONLY = ['scenario.', 'param.'];
const jaOnly = (k) => JA_ONLY.some((p) => k.startsWith(p));
/** `{name}`, `{pose.x}`, `{speed:.3}`: the placeholders with their formats. */
const placeholders = (s) => [...s.matchAll(/\{([\w.]+(?::[\w.]+)?)\}/g)].map((m) => m[1]).sort();
const snake = (s) => s.replace(/([a-z])([A-Z])/g, '$1_$2').toLowerCase();

/** Every key missing from `b` that `a` has (the page's keys only). */
export function missing(a, b) {
  return Object.keys(a).filter((k) => !jaOnly(k) && !(k in b));
}

test('the missing-key check finds a key removed from either catalogue', () => {
  const some = Object.keys(en)[0];
  const { [some]: _gone, ...less } = ja;
  assert.deepEqual(missing(en, less), [some]);
  assert.deepEqual(missing(less, en), []);
  assert.deepEqual(missing({ ...en, 'made.up': 'x' }, ja), ['made.up']);
});

test('both catalogues have the same keys and placeholders', () => {
  assert.deepEqual(missing(en, ja), [], 'keys missing in ja.json');
  assert.deepEqual(missing(ja, en), [], 'keys missing in en.json');
  assert.deepEqual(Object.keys(en).filter(jaOnly), [], 'en.json holds no translations of other files');
  for (const k of Object.keys(en)) {
    assert.deepEqual(placeholders(ja[k]), placeholders(en[k]), `placeholders of ${k}`);
    assert.ok(ja[k].trim() && en[k].trim(), `${k} is empty`);
  }
});

test('every key the page asks for is in the catalogue', () => {
  const files = ['main.js', ...readdirSync(join(REPO, 'web', 'js')).filter((f) => f.endsWith('.js')).map((f) => `js/${f}`),
    ...readdirSync(join(REPO, 'web', 'js', 'panels')).map((f) => `js/panels/${f}`)];
  const asked = new Set();
  for (const f of files) {
    for (const m of read('web', f).matchAll(/\bt\('([\w.]+)'/g)) asked.add(m[1]);
  }
  for (const m of read('web', 'index.html').matchAll(/data-i18n(?:-[a-z-]+)?="([\w.]+)"/g)) asked.add(m[1]);
  assert.ok(asked.size > 150, `only ${asked.size} keys found: the scan is broken`);
  // Keys made from the core's names: the checks, the exercise states and verdicts.
  const exercise = read('core', 'src', 'system', 'runs', 'exercise.rs');
  const enumBody = (name) => exercise.split(`pub enum ${name} {`)[1].split('\n}')[0];
  const variants = (name) => [...enumBody(name).matchAll(/^ {4}([A-Z]\w*)/gm)].map((m) => snake(m[1]));
  const checks = variants('Check');
  assert.ok(checks.includes('reach_speed') && checks.includes('only_allowed'), checks.join());
  for (const c of checks) asked.add(`check.${c}`).add(`measured.${c}`);
  for (const s of variants('CheckState')) asked.add(`exercise.state.${s}`);
  for (const v of variants('Verdict')) asked.add(`exercise.verdict.${v}`).add(`exercise.verdict.${v}_after`);
  const lost = [...asked].filter((k) => !(k in en));
  assert.deepEqual(lost, [], 'keys the page uses that en.json lacks');
});

test('the Japanese catalogue translates every scenario and exercise', () => {
  const dir = join(REPO, 'fixtures', 'scenarios');
  const wanted = new Set();
  for (const f of readdirSync(dir).filter((n) => n.endsWith('.json'))) {
    const s = JSON.parse(readFileSync(join(dir, f), 'utf8'));
    wanted.add(`scenario.${s.name}.description`).add(`scenario.${s.name}.lesson`);
    if (s.exercise) wanted.add(`scenario.${s.name}.task`);
  }
  const have = new Set(Object.keys(ja).filter((k) => k.startsWith('scenario.')));
  assert.deepEqual([...wanted].filter((k) => !have.has(k)), [], 'scenario texts without Japanese');
  assert.deepEqual([...have].filter((k) => !wanted.has(k)), [], 'Japanese for scenarios that do not exist');
});

test('every parameter shown has Japanese words: the seed\'s, else the catalogue\'s', () => {
  const wanted = [];
  for (const [component, file] of [['DriveControl', 'drive_control.rs'], ['PhysicsSim', 'physics_sim.rs'],
    ['MotorControl', 'motor_control.rs'], ['LocalPathPlanning', 'local_path_planning/params.rs']]) {
    const src = read('core', 'src', 'components', file);
    for (const m of src.matchAll(/= \("(\w+)",([\s\S]*?)\),\n/g)) {
      if (!m[2].includes('seed:')) wanted.push(`param.${component}.${m[1]}`);
    }
  }
  assert.ok(wanted.length >= 15, wanted.join());
  assert.deepEqual(wanted.filter((k) => !(k in ja)), [], 'parameters without Japanese words');
  const have = Object.keys(ja).filter((k) => k.startsWith('param.'));
  assert.deepEqual(have.filter((k) => !wanted.includes(k)), [], 'Japanese for parameters that have the seed\'s words or do not exist');
});

test('every number a scenario\'s English says is in its Japanese (a changed limit is changed in both)', () => {
  const dir = join(REPO, 'fixtures', 'scenarios');
  const numbers = (s) => new Set(s.match(/\d+(?:\.\d+)?/g) ?? []);
  const wrong = [];
  for (const f of readdirSync(dir).filter((n) => n.endsWith('.json'))) {
    const s = JSON.parse(readFileSync(join(dir, f), 'utf8'));
    const english = { description: s.description, lesson: s.lesson, task: s.exercise?.task };
    for (const [what, text] of Object.entries(english)) {
      if (!text) continue;
      const key = `scenario.${s.name}.${what}`;
      const said = numbers(ja[key] ?? '');
      const lost = [...numbers(text)].filter((n) => !said.has(n));
      if (lost.length) wrong.push(`${key} lacks ${lost.join(', ')}`);
    }
  }
  assert.deepEqual(wrong, []);
});
