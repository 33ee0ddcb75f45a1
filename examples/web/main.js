// SPDX-License-Identifier: MIT
// The scene page, a gallery drawn only through World.draw: runs a scene live, one world
// step per animation frame, draws it with the draw-flag toggles through the canvas
// backend, rewinds while the rewind button or R (or Backspace) is held, lets the
// platformer's character be walked from the keys, and exposes window.impulse2dPage for
// the browser test (scene choice, stepping, state read-back).
import { loadImpulse2d, SIMD_PATH_NAMES } from '../../bindings/js/src/index.js';
import { BACKGROUND, CanvasDrawer } from './draw_canvas.js';
import { makeDrawToggles } from './draw_flags.js';
import { Keyboard } from './keyboard.js';
import { Camera, drawFrame } from './renderer.js';
import { Rewind } from './rewind.js';
import { SCENES } from './scenes.js';

const TIME_STEP = 1 / 60;
const SUBSTEPS = 4;
// Dragging is a mouse joint: a spring from the grabbed point to the pointer, solved with
// the contacts, so a held body pushes its neighbours and is stopped by walls instead of
// being driven through them. 5 Hz, nearly critically damped, follows the pointer within
// about a fifth of a second without ringing. The force is capped per kilogram, so every
// body follows alike: 500 m/s^2 lifts a body out from under a stack of 50 of its like,
// yet a body that cannot follow (the tumbler's drum, on its 1e8 N m motor) is not torn.
const DRAG_HERTZ = 5;
const DRAG_DAMPING_RATIO = 0.7;
const DRAG_MAX_ACCELERATION = 500;  // m/s^2: the joint's max force over the body's mass
// Rewind keeps a rollback state per frame: 5 s at 60 Hz, within 96 MiB (a state of the
// 900-box tumbler is about 0.9 MB, so it keeps under 2 s of it; the pyramid's and the
// mixed scene's, about 0.2 MB, keep the 5 s).
const REWIND_FRAMES = 5 * 60;
const REWIND_BYTES = 96 * 1024 * 1024;
/** The drag joint's spring is drawn red, from the grabbed point to the pointer. */
const DRAG_COLOR = 0xDC2626;
/** A dynamic body counts as moved once 1 cm from where the scene put it. */
const MOVED_DISTANCE = 0.01;

// The threads build where the page is cross-origin isolated (serve.mjs makes it so), else
// the SIMD build. Scenes step on WORKERS workers: ?workers=N in the address, else 2 where
// the machine has 4 cores or more and 1 below (on 2 cores a second busy worker takes the
// core the browser draws and composites with: the tumbler took 9 ms a step on 2 workers
// in headless Chromium on this 2-vCPU machine against 2.3 ms on 1).
const i2d = await loadImpulse2d({ threads: 'auto' });
const MIN_CORES_FOR_WORKERS = 4;
const askedWorkers = Number(new URLSearchParams(location.search).get('workers'));
const WORKERS = Math.min(i2d.threads + 1, askedWorkers >= 1 ? askedWorkers
                                                            : (navigator.hardwareConcurrency >= MIN_CORES_FOR_WORKERS ? 2 : 1));
const canvas = document.getElementById('view');
const ctx = canvas.getContext('2d');
const camera = new Camera(canvas);
const drawer = new CanvasDrawer(ctx, camera);
const drawFlags = makeDrawToggles(document.getElementById('flags'));
const keyboard = new Keyboard(window);
const actionButton = document.getElementById('action');
const picker = document.getElementById('scene');
const readout = document.getElementById('readout');
const pauseButton = document.getElementById('pause');
const rewindButton = document.getElementById('rewind');

const state = {
  name: null, world: null, scene: null, starts: [],
  paused: false, steps: 0, stepMs: [], held: null, drag: null, dragAnchor: null,
  rewind: new Rewind(REWIND_FRAMES, REWIND_BYTES), rewinding: false,
};

for (const [name, scene] of Object.entries(SCENES)) picker.add(new Option(scene.title, name));

function loadScene(name) {
  if (state.world) state.world.destroy();
  const definition = SCENES[name];
  const world = i2d.createWorld({ workerCount: WORKERS, ...definition.worldOptions });
  const scene = definition.build(world);
  // The body the drag joint hangs from: static and shapeless, so that the held body still
  // collides with everything (a joint's two bodies do not collide with each other).
  const dragAnchor = world.createBody();
  const starts = world.bodies.filter((b) => b.type === 'dynamic').map((body) => ({ body, ...body.position }));
  Object.assign(state, { name, world, scene, starts, steps: 0, stepMs: [], held: null, drag: null, dragAnchor });
  keyboard.enabled = scene.takesKeys === true;
  keyboard.held.clear();
  actionButton.hidden = scene.action === undefined;
  actionButton.textContent = scene.action?.label ?? '';
  state.rewind.restart(world, scene.saveGame?.());
  picker.value = name;
  camera.setView(scene.view);
}

function step() {
  const start = performance.now();
  state.world.step(TIME_STEP, SUBSTEPS);
  state.stepMs.push(performance.now() - start);
  if (state.stepMs.length > 60) state.stepMs.shift();
  state.steps++;
  // The game's frame after the world's: the platformer moves its character here.
  state.scene.update?.(keyboard.actions(), TIME_STEP);
  state.rewind.save(state.world, state.scene.saveGame?.());
}

/** One frame back, while a body is not held (holding one changes the world's structure). */
function stepBack() {
  if (state.drag) return;
  const back = state.rewind.back(state.world);
  if (back === null) return;
  state.steps--;
  if (back.game !== undefined) state.scene.restoreGame(back.game);
}

/** The world's structure changed: states saved before cannot be restored into it. */
function structureChanged() {
  state.rewind.restart(state.world, state.scene.saveGame?.());
}

function msPerStep() {
  const sorted = [...state.stepMs].sort((a, b) => a - b);
  return sorted.length ? sorted[sorted.length >> 1] : 0;
}

/** Which WebAssembly build the page runs and the contact kernels its world solves with. */
function buildName() {
  const workers = state.world.workerCount;
  return `${i2d.threads > 0 ? 'wasm threads' : i2d.simd ? 'wasm SIMD' : 'wasm scalar'}, ` +
    `${SIMD_PATH_NAMES[state.world.simdPath()]} kernels, ${workers} worker${workers > 1 ? 's' : ''}`;
}

function render() {
  drawFrame(drawer, state.world, drawFlags, (d) => {
    state.scene.drawExtras?.(d);
    if (state.drag) d.drawSegment(state.held.getWorldPoint(state.drag.localAnchorB), state.drag.target, DRAG_COLOR);
  });
  const counters = state.world.counters();
  const rewind = state.rewind;
  readout.textContent = `${msPerStep().toFixed(2)} ms/step (median of 60, ${buildName()}) · ` +
    `${counters.bodyCount} bodies · ` +
    `${counters.contactCount} contacts · step ${state.steps}${state.paused ? ' · paused' : ''} · ` +
    `${state.rewinding ? 'rewinding, ' : ''}rewind ${(rewind.frames * TIME_STEP).toFixed(1)} s ` +
    `(${rewind.frames} frames, ${(rewind.bytes / (1024 * 1024)).toFixed(1)} MiB)`;
}

function frame() {
  if (state.rewinding) stepBack();
  else if (!state.paused) step();
  render();
  requestAnimationFrame(frame);
}

/** A world point in page pixels. */
function pagePoint(p) {
  const screen = camera.toScreen(p.x, p.y);
  const rect = canvas.getBoundingClientRect();
  return { x: rect.left + screen.x * rect.width / canvas.width, y: rect.top + screen.y * rect.height / canvas.height };
}

function pointerWorld(event) {
  const rect = canvas.getBoundingClientRect();
  return camera.toWorld((event.clientX - rect.left) * canvas.width / rect.width,
                        (event.clientY - rect.top) * canvas.height / rect.height);
}

canvas.addEventListener('pointerdown', (event) => {
  const p = pointerWorld(event);
  const r = 0.01;
  const shape = state.world.overlapAABB(p.x - r, p.y - r, p.x + r, p.y + r)
    .find((s) => s && s.body.type === 'dynamic');
  if (!shape) {
    state.scene.click?.(p);  // off every body: the scene's own use of a click (a blast)
    return;
  }
  const body = shape.body;
  // Held at the point pressed, so the body hangs from it and turns as it is pulled.
  state.drag = state.world.createMouseJoint(state.dragAnchor, body, {
    localAnchorB: body.getLocalPoint(p), target: p, hertz: DRAG_HERTZ, dampingRatio: DRAG_DAMPING_RATIO,
    maxForce: DRAG_MAX_ACCELERATION * body.mass,
  });
  state.held = body;
  structureChanged();
  canvas.setPointerCapture(event.pointerId);
});
// Creating the joint woke the held body; setting its target keeps it awake.
canvas.addEventListener('pointermove', (event) => {
  if (!state.drag) return;
  state.drag.target = pointerWorld(event);
  structureChanged();
});
const release = () => {
  if (!state.drag) return;
  state.drag.destroy();
  state.held = null;
  state.drag = null;
  structureChanged();
};
canvas.addEventListener('pointerup', release);
canvas.addEventListener('pointercancel', release);

picker.addEventListener('change', () => loadScene(picker.value));
pauseButton.addEventListener('click', () => {
  state.paused = !state.paused;
  pauseButton.textContent = state.paused ? 'Run' : 'Pause';
});
document.getElementById('step').addEventListener('click', () => { step(); render(); });
document.getElementById('reset').addEventListener('click', () => loadScene(state.name));
actionButton.addEventListener('click', () => state.scene.action?.run());
// Rewind while held: the button, or R or Backspace. Letting go resumes from there.
const rewindKeys = new Set(['r', 'R', 'Backspace']);
const setRewinding = (on) => {
  state.rewinding = on;
  rewindButton.classList.toggle('held', on);
};
rewindButton.addEventListener('pointerdown', (event) => {
  rewindButton.setPointerCapture(event.pointerId);
  setRewinding(true);
});
for (const type of ['pointerup', 'pointercancel', 'lostpointercapture']) {
  rewindButton.addEventListener(type, () => setRewinding(false));
}
window.addEventListener('keydown', (event) => {
  if (!rewindKeys.has(event.key) || event.ctrlKey || event.metaKey || event.altKey) return;
  event.preventDefault();
  setRewinding(true);
});
window.addEventListener('keyup', (event) => { if (rewindKeys.has(event.key)) setRewinding(false); });
window.addEventListener('blur', () => setRewinding(false));

// What the browser test reads back.
window.impulse2dPage = {
  scenes: Object.keys(SCENES),
  loadScene,
  /** Runs n steps now (as frames would), then draws once. */
  runSteps(n) {
    for (let i = 0; i < n; i++) step();
    render();
  },
  state() {
    const counters = state.world.counters();
    const seconds = state.steps * TIME_STEP;
    let moved = 0;
    let maxMove = 0;
    for (const start of state.starts) {
      const p = start.body.position;
      const d = Math.hypot(p.x - start.x, p.y - start.y);
      if (d > MOVED_DISTANCE) moved++;
      maxMove = Math.max(maxMove, d);
    }
    return { scene: state.name, steps: state.steps, msPerStep: msPerStep(), bodyCount: counters.bodyCount,
             simdBuild: i2d.simd, simdPath: SIMD_PATH_NAMES[state.world.simdPath()],
             threadsBuild: i2d.threads > 0, workerCount: state.world.workerCount,
             isolated: globalThis.crossOriginIsolated === true,
             jointCount: state.world.jointCount(), moved, maxMove, paused: state.paused,
             rewindFrames: state.rewind.frames, rewindBytes: state.rewind.bytes, rewinding: state.rewinding,
             ...SCENES[state.name].check(state.world, state.scene, seconds) };
  },
  /** A dynamic body near the middle of the scene: {index, x, y} in canvas pixels. */
  pickDynamicBody() {
    const dynamic = state.world.bodies.filter((b) => b.type === 'dynamic');
    const body = dynamic[dynamic.length >> 1];
    return { index: body.index, ...pagePoint(body.position) };
  },
  /** A world point in page pixels (where a mouse event would hit it). */
  pagePoint,
  bodyPosition(index) { return state.world.bodyByIndex[index].position; },
  /** The world's state hash, 16 hex digits. */
  hash() { return state.world.stateHash().toString(16).padStart(16, '0'); },
  readout() { return readout.textContent; },
  isHolding() { return state.drag !== null && state.drag.isValid(); },
  /** Canvas pixels that differ from the background: a blank canvas has none. */
  paintedPixels() {
    const data = ctx.getImageData(0, 0, canvas.width, canvas.height).data;
    const [r, g, b] = BACKGROUND.rgb;
    let painted = 0;
    for (let i = 0; i < data.length; i += 4) {
      if (data[i] !== r || data[i + 1] !== g || data[i + 2] !== b) painted++;
    }
    return painted;
  },
  /** How many times each drawer method was called for the last frame drawn. */
  drawCounts() { return { ...drawer.counts }; },
  /** The draw flags the toggles hold now. */
  drawFlags() { return { ...drawFlags }; },
};

loadScene('pyramid');
requestAnimationFrame(frame);
document.body.dataset.ready = 'true';
