// SPDX-License-Identifier: MIT
// impulse2d for JavaScript: the WebAssembly build of the library behind World, Body,
// Shape and Joint classes. Load once, then make worlds:
//   const i2d = await loadImpulse2d();
//   const world = i2d.createWorld({ gravity: [0, -10] });
import { Replay } from './recording.js';
import { Runtime } from './runtime.js';
import { stepWorlds } from './batch.js';
import { clipVector, defaultCharacterDef, solvePlanes } from './mover.js';
import { readWorldDef, World } from './world.js';
import { vx, vy } from './vectors.js';

export { Impulse2dError } from './errors.js';
export { Replay } from './recording.js';
export { SIMD_PATH_NAMES, World } from './world.js';
export { BodyMoves } from './body_moves.js';
export { Body } from './body.js';
export { Shape } from './shape.js';
export { DRAW_COLORS, GRAPH_COLORS, colorToCss } from './colors.js';
export {
  Joint, RevoluteJoint, PrismaticJoint, DistanceJoint, WeldJoint, WheelJoint, MotorJoint, MouseJoint, FilterJoint,
} from './joint.js';

// The smallest module that uses a SIMD instruction (i8x16.splat, i8x16.popcnt): engines
// that validate it run the SIMD build.
const SIMD_PROBE = new Uint8Array([0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0, 10, 10, 1, 8,
                                   0, 65, 0, 253, 15, 253, 98, 11]);

/** Whether this JavaScript engine runs WebAssembly SIMD (128-bit) modules. */
export function wasmSimdSupported() {
  return typeof WebAssembly === 'object' && WebAssembly.validate(SIMD_PROBE);
}

/** Whether this engine can run the threads build: shared memory, and in a page cross-origin
 *  isolation (the page's server sends Cross-Origin-Opener-Policy: same-origin and
 *  Cross-Origin-Embedder-Policy: require-corp). */
export function wasmThreadsSupported() {
  const isolated = typeof crossOriginIsolated === 'undefined' || crossOriginIsolated;
  return typeof SharedArrayBuffer === 'function' && isolated && wasmSimdSupported();
}

/** The threads build's workers started with the module (build.sh's THREAD_POOL_SIZE). */
const THREAD_POOL_SIZE = 3;

const isNode = typeof process === 'object' && process.versions?.node !== undefined;

/** The build to load for the `simd` and `threads` options: its file names and what it has. */
function chooseBuild(simd, threads) {
  for (const [name, value] of [['simd', simd], ['threads', threads]]) {
    if (value !== 'auto' && typeof value !== 'boolean') {
      throw new TypeError(`impulse2d: ${name} is ${String(value)}; it must be 'auto', true or false`);
    }
  }
  if (threads === true && !wasmThreadsSupported()) {
    throw new Error('impulse2d: threads: true, but this engine has no shared WebAssembly memory with SIMD ' +
                    '(a page must be cross-origin isolated)');
  }
  if (simd === true && !wasmSimdSupported()) {
    throw new Error('impulse2d: simd: true, but this JavaScript engine has no WebAssembly SIMD');
  }
  // The threads build has the SIMD kernels: it is only chosen with them.
  if (threads === true || (threads === 'auto' && simd !== false && wasmThreadsSupported())) {
    return { loader: 'threads/impulse2d_wasm_threads.js', wasm: 'threads/impulse2d_wasm_threads.wasm', simd: true,
             threads: THREAD_POOL_SIZE };
  }
  const useSimd = simd === 'auto' ? wasmSimdSupported() : simd;
  const name = useSimd ? 'impulse2d_wasm_simd' : 'impulse2d_wasm';
  return { loader: `${name}.mjs`, wasm: `${name}.wasm`, simd: useSimd, threads: 0 };
}

/** The factory of a classic-script loader (the threads build): require in node, a script
 *  element in a page (its workers load the same script by its URL). */
async function loadClassicFactory(url) {
  if (isNode) {
    const { createRequire } = await import('node:module');
    const { fileURLToPath } = await import('node:url');
    return createRequire(import.meta.url)(fileURLToPath(url));
  }
  await new Promise((resolve, reject) => {
    const script = document.createElement('script');
    script.src = String(url);
    script.onload = resolve;
    script.onerror = () => reject(new Error(`impulse2d: could not load ${url}`));
    document.head.appendChild(script);
  });
  return globalThis.createImpulse2dModule;
}

/**
 * Instantiates the module. Three builds, all giving the same bits:
 * - SIMD (4-lane contact kernels), the default where the engine has WebAssembly SIMD;
 * - scalar elsewhere (or with `simd: false`);
 * - threads, with `threads: true` (or 'auto': where the engine has shared memory, that
 *   is node and pages that are cross-origin isolated): the SIMD kernels, and worlds made
 *   with createWorld({ workerCount: 2 }) step on Web Workers over shared memory. It
 *   starts its 3 workers with the module; a world with more than one worker cannot have
 *   JavaScript contact hooks (they would run on those workers).
 * In node the .wasm is read from the package (or `wasmBinary`, which must be the chosen
 * build's); in a page it is fetched next to the loader (or from `wasmUrl`).
 */
export async function loadImpulse2d(options = {}) {
  let { wasmBinary } = options;
  const { wasmUrl, simd = 'auto', threads = false } = options;
  const build = chooseBuild(simd, threads);
  const loaderUrl = new URL(`../dist/${build.loader}`, import.meta.url);
  const createImpulse2dModule = build.threads > 0 ? await loadClassicFactory(loaderUrl)
                                                   : (await import(loaderUrl)).default;
  const url = wasmUrl ?? new URL(`../dist/${build.wasm}`, import.meta.url);
  if (wasmBinary === undefined && isNode) {
    const { readFile } = await import('node:fs/promises');
    wasmBinary = await readFile(url);
  }
  // locateFile also finds the threads build's worker script, beside its loader.
  const locateFile = (file) => (file.endsWith('.wasm') ? String(url) : new URL(file, loaderUrl).href);
  const module = await createImpulse2dModule(wasmBinary !== undefined ? { wasmBinary } : { locateFile });
  if (build.threads > 0 && isNode) {
    // The pool's workers idle between steps; they must not keep node's process alive.
    for (const worker of module.PThread.unusedWorkers) worker.unref();
  }
  return new Impulse2d(new Runtime(module, undefined, build.threads), build.simd);
}

export class Impulse2d {
  /** @internal */
  constructor(rt, simd) {
    this.rt = rt;
    /** Whether this is a WebAssembly SIMD build (worlds solve on I2D_SIMD_WASM128). */
    this.simd = simd;
    /** Worker threads this build lends worlds (0 but in the threads build): a world may
     *  have up to threads + 1 workers, and all worlds alive share them. */
    this.threads = rt.threadPoolSize;
  }

  /** The library's version packed as (major << 16) | (minor << 8) | patch. */
  get version() { return this.rt.m._i2d_version(); }

  createWorld(options) { return World.create(this.rt, options); }

  /**
   * Steps the worlds in one call (i2d_worlds_step), each as world.step(timeStep, substeps)
   * would. A world that is not a World, is destroyed or is listed twice, or a bad timeStep
   * or substeps, throws naming it, and no world moves. Here in WebAssembly the worlds
   * are stepped in turn on this thread. Throws, once all are stepped, the first error a
   * contact hook threw.
   */
  stepWorlds(worlds, timeStep = 1 / 60, substeps = 4) { stepWorlds(this.rt, worlds, timeStep, substeps); }

  /** A new world from a snapshot's bytes: World.fromSnapshot(this, bytes). */
  worldFromSnapshot(bytes) { return World.fromSnapshot(this, bytes); }

  /** Opens a recording (World.startRecording's bytes) to replay it in a world of its own,
   *  checking every step's hash (i2d_replay_open): see Replay. */
  openReplay(bytes) { return new Replay(this.rt, bytes, World); }

  /** The default world settings for a world in lengthUnitsPerMeter units per metre
   *  (i2d_default_world_def_in_units; [1e-3, 1e4]), as World.settings gives them. */
  defaultWorldSettings(lengthUnitsPerMeter = 1) {
    const rt = this.rt;
    rt.m._i2d_default_world_def_in_units(rt.result(), lengthUnitsPerMeter);
    rt.checkLast();
    return readWorldDef(rt, rt.result());
  }

  /** The character def's defaults, as World.moveCharacter's settings: {maxSlopeAngle,
   *  stepHeight, snapDistance, skin, maxIterations, pushMass, filter}. */
  defaultCharacterDef() { return defaultCharacterDef(this.rt); }

  /**
   * The move nearest targetDelta that runs into none of the rigid planes (soft ones push
   * at most their pushLimit): {translation, iterationCount, pushes (how far each plane
   * pushed)} (i2d_solve_planes). Planes are as World.collideMover gives them; pushLimit
   * defaults to rigid (Infinity is rigid too), clipVelocity to true. Needs no world.
   */
  solvePlanes(targetDelta, planes) { return solvePlanes(this.rt, targetDelta, planes); }

  /** The vector less its part that runs into the planes with clipVelocity (i2d_clip_vector). */
  clipVector(vector, planes) { return clipVector(this.rt, vector, planes); }

  /**
   * The closest points of two convex shapes, each {points (1 to 8, their own frame),
   * radius = 0, position = [0, 0], angle = 0} (i2d_make_proxy, i2d_shape_distance):
   * {pointA, pointB, normal, distance}. Works in metres, whatever a world's unit.
   */
  shapeDistance(a, b) {
    const rt = this.rt;
    const proxySize = rt.size('i2d_shape_proxy');
    const proxies = rt.m._malloc(2 * proxySize);
    try {
      [a, b].forEach((shape, k) => {
        const points = Array.isArray(shape?.points) ? shape.points : [];
        const at = rt.arg(0);  // up to 8 points fill one 64-byte argument slot
        if (points.length <= 8) points.forEach((p, i) => rt.writeVec2(at + 8 * i, vx(p), vy(p)));
        rt.m._i2d_make_proxy(proxies + k * proxySize, at, points.length, shape?.radius ?? 0);
        rt.checkLast();
      });
      const at = rt.result();
      rt.m._i2d_shape_distance(at, proxies, rt.transform(0, a.position ?? [0, 0], a.angle ?? 0),
                               proxies + proxySize, rt.transform(1, b.position ?? [0, 0], b.angle ?? 0));
      rt.checkLast();
      const field = (name) => at + rt.field(`i2d_distance_result.${name}`);
      return { pointA: rt.readVec2(field('point_a')), pointB: rt.readVec2(field('point_b')),
               normal: rt.readVec2(field('normal')), distance: rt.f32[field('distance') >> 2] };
    } finally {
      rt.m._free(proxies);
    }
  }
}
