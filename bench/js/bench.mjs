// SPDX-License-Identifier: MIT
// impulse2d.wasm (SIMD, scalar and threads builds) side by side with Rapier2D (plain and SIMD
// builds), planck and matter-js in node: the same scenes built by the same code, engines
// alternating within each round, a new world per run, the first step untimed (as
// scenes.md times), median ms per step over the rounds and each run's sanity figure. With
// --native PATH the native impulse2d_bench runs large_pyramid in the same rounds (its
// widest and scalar kernels), for the native/wasm ratios. --engines keeps the engines
// whose names contain one of its comma-separated words (planck's large_pyramid alone takes
// about 2 minutes a round).
//   node bench.mjs [--rounds 3] [--steps-scale 1] [--native ../../build/bench/impulse2d_bench]
//                  [--engines impulse2d,Rapier]
import { execFileSync } from 'node:child_process';
import { loadEngines } from './engines.mjs';
import { SCENES } from './scenes.mjs';

const STEPS = { large_pyramid: 500, rain_of_circles: 500, small_50: 1000, tumbler: 750 };
// planck takes about a second per step on the 5050-box pyramid here: 500 steps x 3
// rounds would take 25 minutes, so it runs 40 (the table says so). Its first steps are
// its slowest (3 s), so its figure is, if anything, high.
// On the tumbler planck takes about 0.2 s a step (27 s for the first 120): it runs 250 of
// the 750 steps, by when the boxes have landed and tumble with the drum.
const STEP_LIMITS = { 'planck 1.4|large_pyramid': 40, 'planck 1.4|tumbler': 250 };
const stepsFor = (engineName, sceneName) =>
  Math.min(STEP_LIMITS[`${engineName}|${sceneName}`] ?? Infinity, Math.max(2, Math.round(STEPS[sceneName] * stepsScale)));

function option(name, fallback) {
  const at = process.argv.indexOf(name);
  return at > 0 ? process.argv[at + 1] : fallback;
}
const rounds = Number(option('--rounds', 3));
const stepsScale = Number(option('--steps-scale', 1));
const nativeBench = option('--native', null);
const onlyEngines = option('--engines', '').split(',').filter((word) => word !== '');

function runOnce(engine, scene, steps) {
  const world = engine.createWorld({ sleep: scene.sleep });
  const { hook, sanity } = scene.build(world);
  hook?.(0);
  world.step();
  const start = process.hrtime.bigint();
  for (let i = 1; i < steps; i++) {
    hook?.(i);
    world.step();
  }
  const ms = Number(process.hrtime.bigint() - start) / 1e6 / (steps - 1);
  const figure = sanity(steps);
  world.destroy();
  return { ms, figure };
}

function runNative(simd, steps) {
  const out = execFileSync(nativeBench, ['--scene', 'large_pyramid', '--steps', String(steps), '--repeat', '1',
                                         '--simd', simd, '--csv'], { encoding: 'utf8' });
  const lines = out.trim().split('\n').filter((line) => !line.startsWith('#'));
  const header = lines[0].split(',');
  const row = lines[1].split(',');  // median_ms comes before the quoted sanity field
  const column = header.indexOf('median_ms');
  return { ms: Number(row[column]), figure: `native ${simd}` };
}

const median = (values) => {
  const sorted = [...values].sort((a, b) => a - b);
  const mid = sorted.length >> 1;
  return sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
};

const engines = await loadEngines(onlyEngines);
const results = new Map();  // "scene|engine" -> {ms: [], figure}
const record = (scene, engine, run) => {
  const key = `${scene}|${engine}`;
  const entry = results.get(key) ?? { ms: [], figures: [] };
  entry.ms.push(run.ms);
  entry.figures.push(run.figure);
  results.set(key, entry);
};

for (let round = 0; round < rounds; round++) {
  for (const scene of SCENES) {
    const steps = stepsFor('', scene.name);
    // Rotate the order each round so no engine always runs first (or last).
    const order = engines.map((_, i) => engines[(i + round) % engines.length]);
    for (const engine of order) {
      const run = runOnce(engine, scene, stepsFor(engine.name, scene.name));
      record(scene.name, engine.name, run);
      console.error(`round ${round + 1} ${scene.name} ${engine.name}: ${run.ms.toFixed(3)} ms/step, ${run.figure}`);
    }
    if (nativeBench && scene.name === 'large_pyramid') {
      for (const simd of ['automatic', 'scalar']) {
        const run = runNative(simd, steps);
        record(scene.name, `impulse2d native (${simd})`, run);
        console.error(`round ${round + 1} ${scene.name} native ${simd}: ${run.ms.toFixed(3)} ms/step`);
      }
    }
  }
}

console.log(`| scene | steps | engine | ms/step (median of ${rounds}) | min | sanity (last run) |`);
console.log('|---|---|---|---|---|---|');
for (const [key, entry] of results) {
  const [scene, engine] = key.split('|');
  const steps = stepsFor(engine, scene);
  console.log(`| ${scene} | ${steps} | ${engine} | ${median(entry.ms).toFixed(3)} | ${Math.min(...entry.ms).toFixed(3)} | ` +
              `${entry.figures[entry.figures.length - 1]} |`);
}
if (SCENES.some((scene) => scene.name === 'tumbler')) {
  console.log(`\ntumbler's drum: ${engines.map((engine) => `${engine.name} ${engine.drumDrive}`).join('; ')}`);
}
const threaded = ['1 worker', '2 workers'].map((w) => results.get(`large_pyramid|impulse2d.wasm threads ${w}`));
if (threaded[0] && threaded[1]) {
  console.log(`large_pyramid wasm threads, 1 worker / 2 workers: ${(median(threaded[0].ms) / median(threaded[1].ms)).toFixed(2)}x`);
}
for (const build of ['SIMD', 'scalar']) {
  const wasm = results.get(`large_pyramid|impulse2d.wasm ${build}`);
  for (const simd of ['automatic', 'scalar']) {
    const native = results.get(`large_pyramid|impulse2d native (${simd})`);
    if (wasm && native) {
      console.log(`large_pyramid wasm ${build} / native ${simd}: ${(median(wasm.ms) / median(native.ms)).toFixed(2)}x`);
    }
  }
}
