#!/usr/bin/env node
// SPDX-License-Identifier: MIT
// Opens the scene page in headless Chromium and checks it: every scene runs a few
// seconds live, its state read back from the page (bodies moved, the pyramid standing,
// nothing escaping, the joints holding, a blast throwing the pile about), the buttons
// and pointer dragging work, the draw-flag toggles change what World.draw hands the
// canvas, the platformer's character walked from key events walks, climbs the 0.2 m
// ledge, jumps up through the one-way platform and stands on it, and rides the moving
// platform, holding R or the rewind button takes the world back to an earlier frame's
// state hash (and the character to where it was), no error reaches the console, and a
// screenshot per scene is saved (its canvas checked not blank).
// Drives Chromium through the DevTools protocol over a pipe: no packages needed.
//   node examples/web/browser_test.mjs [output-dir]     (exit 77: skipped, says why)
import { spawn } from 'node:child_process';
import { existsSync, mkdtempSync, mkdirSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { startServer } from './serve.mjs';

const HERE = path.dirname(fileURLToPath(import.meta.url));
const OUT = path.resolve(process.argv[2] ?? path.join(os.tmpdir(), 'impulse2d_web'));
const CHROMIUM = process.env.CHROMIUM ?? '/usr/bin/chromium';
const LIVE_SECONDS = 3;
const MIN_STEPS = 180;  // every scene is judged after at least 3 simulated seconds
const SCENES = ['pyramid', 'mixed', 'tumbler', 'platformer', 'explosion', 'joints'];
// The platformer's character (examples/web/character.js): 4 m/s, its feet kept the skin
// and 7/8 of the contact slop (0.01 + 0.004375 m) above what it stands on.
const WALK_SPEED = 4;
const REST_GAP = 0.014375;
const STAND_TOLERANCE = 0.005;
/** The joints scene's joints: 17 bridge pins, 10 chain pins, a slider, a spring, two
 *  wheels, a weld. */
const JOINTS_SCENE_JOINTS = 32;
/** DevTools key events: key, code and Windows key code of each key the test presses. */
const KEYS = {
  d: { key: 'd', code: 'KeyD', windowsVirtualKeyCode: 68 },
  right: { key: 'ArrowRight', code: 'ArrowRight', windowsVirtualKeyCode: 39 },
  space: { key: ' ', code: 'Space', windowsVirtualKeyCode: 32 },
  r: { key: 'r', code: 'KeyR', windowsVirtualKeyCode: 82 },
};

function skip(reason) {
  console.log(`SKIPPED: ${reason}`);
  process.exit(77);
}
if (!existsSync(CHROMIUM)) skip(`no Chromium at ${CHROMIUM} (apt-get install chromium, or set CHROMIUM)`);
if (!existsSync(path.join(HERE, '../../bindings/js/dist/impulse2d_wasm.wasm'))) {
  skip('no WebAssembly build; run bindings/js/build.sh (needs emscripten)');
}

/** The DevTools protocol over --remote-debugging-pipe: JSON messages ending in NUL. */
class DevTools {
  constructor(child) {
    this.child = child;
    this.nextId = 1;
    this.pending = new Map();
    this.listeners = [];
    let buffered = '';
    child.stdio[4].on('data', (chunk) => {
      buffered += chunk.toString('utf8');
      let end;
      while ((end = buffered.indexOf('\0')) >= 0) {
        this.receive(JSON.parse(buffered.slice(0, end)));
        buffered = buffered.slice(end + 1);
      }
    });
  }

  receive(message) {
    if (message.id !== undefined) {
      const { resolve, reject, method } = this.pending.get(message.id);
      this.pending.delete(message.id);
      if (message.error) reject(new Error(`${method}: ${message.error.message}`));
      else resolve(message.result);
    } else {
      for (const listener of this.listeners) listener(message);
    }
  }

  send(method, params = {}, sessionId) {
    const id = this.nextId++;
    this.child.stdio[3].write(JSON.stringify({ id, method, params, sessionId }) + '\0');
    return new Promise((resolve, reject) => this.pending.set(id, { resolve, reject, method }));
  }
}

const wait = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
const failures = [];
function expect(condition, what) {
  console.log(`${condition ? 'ok  ' : 'FAIL'} ${what}`);
  if (!condition) failures.push(what);
}

const near = (a, b, tolerance) => Math.abs(a - b) <= tolerance;

/** A key of KEYS pressed ('keyDown') or let go ('keyUp'), as a user's keyboard would. */
function key(ctx, type, name) {
  return ctx.page('Input.dispatchKeyEvent', { type, ...KEYS[name] });
}

function mouse(ctx, type, x, y) {
  return ctx.page('Input.dispatchMouseEvent', { type, x, y, button: 'left', buttons: type === 'mouseReleased' ? 0 : 1,
                                                clickCount: 1 });
}

async function click(ctx, point) {
  await mouse(ctx, 'mousePressed', point.x, point.y);
  await mouse(ctx, 'mouseReleased', point.x, point.y);
}

/** What each scene must show after its live seconds (state: impulse2dPage.state()). */
/** Loads the tumbler, steps it TUMBLER_STEPS times at once (no frame between) and gives its hash. */
const TUMBLER_STEPS = 120;
const TUMBLER_HASH = `(() => { impulse2dPage.loadScene('tumbler'); impulse2dPage.runSteps(${TUMBLER_STEPS}); ` +
                     'return impulse2dPage.hash(); })()';

const SCENE_CHECKS = {
  pyramid: (state) => {
    expect(state.bodyCount > 100 && state.moved > 0, `pyramid: ${state.moved} of ${state.bodyCount} bodies moved`);
    expect(state.topDrop < 0.2, `pyramid still standing: top dropped ${state.topDrop.toFixed(3)} m`);
  },
  mixed: (state) => {
    expect(state.bodyCount > 100 && state.moved > 0, `mixed: ${state.moved} of ${state.bodyCount} bodies moved`);
    expect(state.below === 0, `mixed: no shape fell through the floor (${state.below})`);
  },
  tumbler: (state) => {
    expect(state.bodyCount > 100 && state.moved > 0, `tumbler: ${state.moved} of ${state.bodyCount} bodies moved`);
    expect(state.escaped === 0, `tumbler: no box escaped the drum (${state.escaped})`);
    expect(Math.abs(state.drumAngle) > 0.5, `tumbler: the drum turned (${state.drumAngle.toFixed(2)} rad)`);
    // The real drum: dynamic, on one revolute joint whose motor keeps 25 deg/s under the
    // boxes (the native bench allows half a degree) and whose pivot holds its centre.
    expect(state.drumType === 'dynamic' && state.jointCount === 1,
           `tumbler: a ${state.drumType} drum on ${state.jointCount} joint`);
    expect(Math.abs(state.drumAngleError) < 0.5 * Math.PI / 180,
           `tumbler: the motor kept time (${(state.drumAngleError * 180 / Math.PI).toFixed(4)} deg off)`);
    expect(state.drumDrift < 0.01, `tumbler: the drum's centre stayed on its pivot (${state.drumDrift.toExponential(2)} m)`);
  },
  platformer: (state) => {
    const c = state.character;
    expect(c.onGround && c.ground === 'ground' && near(c.y, REST_GAP, STAND_TOLERANCE),
           `platformer: the character stands on the ground untouched (y ${c.y.toFixed(4)}, on ${c.ground})`);
    const p = state.platform;
    expect(Math.abs(p.vx) === 2 && Math.abs(p.x - state.movingMinX) > 1e-3,
           `platformer: the platform moves back and forth (at x ${p.x.toFixed(2)}, ${p.vx} m/s)`);
  },
  explosion: async (state, ctx) => {
    expect(state.blasts === 0 && state.fast === 0, `explosion: the pile rests before a blast (${state.fast} moving)`);
    await ctx.evaluate("document.getElementById('action').click()");
    await ctx.evaluate('impulse2dPage.runSteps(6)');
    const blown = await ctx.evaluate('impulse2dPage.state()');
    expect(blown.blasts === 1 && blown.fast >= 10, `explosion: Blast threw ${blown.fast} pieces faster than 2 m/s`);
    // A click off every body (high in the empty room) blasts there too.
    await click(ctx, await ctx.evaluate('impulse2dPage.pagePoint({ x: -12, y: 14 })'));
    expect((await ctx.evaluate('impulse2dPage.state()')).blasts === 2, 'explosion: a click off the bodies blasts');
    await ctx.evaluate('impulse2dPage.runSteps(120)');
    const settled = await ctx.evaluate('impulse2dPage.state()');
    expect(settled.escaped === 0 && settled.maxMove > 1,
           `explosion: pieces thrown up to ${settled.maxMove.toFixed(1)} m, none out of the room (${settled.escaped})`);
    await ctx.evaluate("document.getElementById('action').click()");
    await ctx.evaluate('impulse2dPage.runSteps(4)');  // the screenshot shows a blast and its reach
  },
  joints: (state) => {
    expect(state.jointCount === JOINTS_SCENE_JOINTS, `joints: ${state.jointCount} joints`);
    expect(state.bridgeSag > 0 && state.bridgeSag < 1.5, `joints: the bridge sags ${state.bridgeSag.toFixed(2)} m`);
    expect(state.chainEndDrop > 2, `joints: the chain swung down (its end ${state.chainEndDrop.toFixed(2)} m lower)`);
    expect(state.carTravel > 0.5, `joints: the car's motors drove it ${state.carTravel.toFixed(2)} m`);
    expect(state.below === 0, `joints: nothing fell through the floor (${state.below})`);
  },
};

/** The draw flags' checkboxes change what World.draw hands the canvas drawer. */
async function checkDrawToggles(ctx) {
  const { evaluate } = ctx;
  await evaluate("impulse2dPage.loadScene('mixed')");
  await evaluate("document.getElementById('pause').click()");
  await evaluate('impulse2dPage.runSteps(120)');
  const counts = () => evaluate('impulse2dPage.drawCounts()');
  const toggle = async (option) => {
    await evaluate(`document.getElementById('flag-${option}').click()`);
    await evaluate('impulse2dPage.runSteps(1)');
    return counts();
  };
  const shapes = (c) => (c.drawSolidPolygon ?? 0) + (c.drawSolidCircle ?? 0) + (c.drawSolidCapsule ?? 0);
  const base = await counts();
  expect(shapes(base) > 200 && !base.drawPolygon && !base.drawPoint,
         `draw flags: shapes only by default (${JSON.stringify(base)})`);
  const bounds = await toggle('drawBounds');
  expect(bounds.drawPolygon >= shapes(base), `draw flags: bounds draws an outline per shape (${bounds.drawPolygon})`);
  const contacts = await toggle('drawContacts');
  expect(contacts.drawPoint > 100, `draw flags: contacts draws contact points (${contacts.drawPoint})`);
  const mass = await toggle('drawMass');
  expect(mass.drawString > 100 && mass.drawTransform > 100, `draw flags: mass draws ${mass.drawString} masses`);
  const noShapes = await toggle('drawShapes');
  expect(shapes(noShapes) === 0 && noShapes.drawPolygon > 0, 'draw flags: shapes off draws no shape, the rest still');
  const flags = await evaluate('impulse2dPage.drawFlags()');
  expect(!flags.drawShapes && flags.drawBounds && flags.drawContacts && flags.drawMass,
         `draw flags: the page holds them (${JSON.stringify(flags)})`);
  await ctx.screenshot('draw_flags');
  for (const option of ['drawBounds', 'drawContacts', 'drawMass', 'drawShapes']) await toggle(option);
  expect(shapes(await counts()) === shapes(base), 'draw flags: toggled back, the shapes are drawn again');
  await evaluate("document.getElementById('pause').click()");
}

/**
 * The platformer driven by key events, the page paused and stepped a frame at a time so
 * that each check is of the simulation rather than of the machine's speed.
 */
async function drivePlatformer(ctx) {
  const { evaluate } = ctx;
  const character = async () => (await evaluate('impulse2dPage.state()')).character;
  const platformState = () => evaluate('impulse2dPage.state()');
  const steps = (n) => evaluate(`impulse2dPage.runSteps(${n})`);
  /** Holds `name` for n frames. */
  const hold = async (name, n) => {
    await key(ctx, 'keyDown', name);
    await steps(n);
    await key(ctx, 'keyUp', name);
  };
  /** Holds `name`, a frame at a time, until done(character) or `most` frames. */
  const holdUntil = async (name, done, most) => {
    await key(ctx, 'keyDown', name);
    for (let i = 0; i < most && !done(await character()); i++) await steps(1);
    await key(ctx, 'keyUp', name);
  };
  await evaluate("impulse2dPage.loadScene('platformer')");
  await evaluate("document.getElementById('pause').click()");
  await steps(20);
  const start = await character();

  // Walk: D for half a second covers 2 m at 4 m/s (within 1 %).
  await hold('d', 30);
  let c = await character();
  const walked = c.x - start.x;
  expect(near(walked, WALK_SPEED * 0.5, 0.01 * WALK_SPEED * 0.5) && c.onGround,
         `platformer: D walked the character ${walked.toFixed(4)} m in 0.5 s (expected 2)`);
  // Climb: the right arrow for another half second takes it onto the 0.2 m ledge.
  await hold('right', 30);
  c = await character();
  expect(c.ground === 'ledge' && near(c.y, 0.2 + REST_GAP, STAND_TOLERANCE),
         `platformer: climbed the 0.2 m ledge (feet at ${c.y.toFixed(4)}, on ${c.ground})`);

  // Under the one-way platform, Space: up through it from below, then standing on it.
  await holdUntil('right', (ch) => ch.x >= 1, 300);
  await steps(5);
  c = await character();
  const { oneWay } = await platformState();
  expect(c.ground === 'ground' && c.x >= 1 && c.x < 2, `platformer: under the one-way platform (x ${c.x.toFixed(2)})`);
  await key(ctx, 'keyDown', 'space');
  let highest = c.y;
  for (let i = 0; i < 90; i++) {
    await steps(1);
    if (i === 2) await key(ctx, 'keyUp', 'space');
    highest = Math.max(highest, (await character()).y);
  }
  c = await character();
  expect(highest > oneWay + 0.5, `platformer: the jump took the feet up through the platform to ${highest.toFixed(2)} m`);
  expect(c.onGround && c.ground === 'oneWay' && near(c.y, oneWay + REST_GAP, STAND_TOLERANCE),
         `platformer: landed on the one-way platform (feet at ${c.y.toFixed(4)}, on ${c.ground})`);
  await steps(60);
  c = await character();
  expect(c.ground === 'oneWay' && near(c.y, oneWay + REST_GAP, STAND_TOLERANCE),
         `platformer: a second later it still stands on it (feet at ${c.y.toFixed(4)})`);

  // Onto the moving platform: to the one-way platform's end, wait for the moving one to
  // come back to it, walk across, and stand still.
  await holdUntil('right', (ch) => ch.x >= 2.4, 100);
  const arriving = (s) => s.platform.vx < 0 && s.platform.x - s.platform.halfWidth <= 3.3;
  for (let i = 0; i < 600 && !arriving(await platformState()); i++) await steps(1);
  await hold('right', 20);
  await steps(1);
  let s = await platformState();
  expect(s.character.ground === 'moving', `platformer: walked onto the moving platform (on ${s.character.ground})`);
  const offset = s.character.x - s.platform.x;
  const from = s.platform.x;
  const xAt = new Map();
  for (let i = 0; i < 45; i++) {
    await steps(1);
    s = await platformState();
    xAt.set(s.steps, s.character.x);
  }
  const drift = s.character.x - s.platform.x - offset;
  expect(s.character.ground === 'moving' && Math.abs(drift) < 0.02 && Math.abs(s.platform.x - from) > 1,
         `platformer: standing still, it rode ${(s.platform.x - from).toFixed(2)} m with the platform ` +
         `(${drift.toExponential(2)} m off its place on it)`);
  await ctx.screenshot('platformer_riding');

  // Rewind takes the character back with the world: at the step it returns to, it is where it was.
  const last = s.steps;
  await key(ctx, 'keyDown', 'r');
  const until = Date.now() + 10000;
  while ((await platformState()).steps > last - 20 && Date.now() < until) await wait(30);
  await key(ctx, 'keyUp', 'r');
  s = await platformState();
  expect(xAt.has(s.steps) && s.character.x === xAt.get(s.steps),
         `platformer: rewound to step ${s.steps}, the character back at x ${s.character.x.toFixed(3)}`);
  await evaluate("document.getElementById('pause').click()");
}

// A page or browser that hangs fails the test rather than waiting for CTest's timeout.
const WATCHDOG_SECONDS = 240;
setTimeout(() => {
  console.log(`FAIL no result after ${WATCHDOG_SECONDS} s`);
  process.exit(1);
}, WATCHDOG_SECONDS * 1000).unref();

const server = await startServer(0);
const pageUrl = `http://127.0.0.1:${server.address().port}/examples/web/`;
const profile = mkdtempSync(path.join(os.tmpdir(), 'impulse2d_chromium_'));
const chromium = spawn(CHROMIUM, [
  '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
  '--disable-dev-shm-usage', `--user-data-dir=${profile}`, '--remote-debugging-pipe',
  '--window-size=1000,720', 'about:blank',
], { stdio: ['ignore', 'ignore', 'pipe', 'pipe', 'pipe'] });
let chromiumLog = '';
chromium.stderr.on('data', (d) => { chromiumLog += d; });
chromium.on('error', (error) => { console.log(`FAIL cannot start ${CHROMIUM}: ${error.message}`); process.exit(1); });

const consoleErrors = [];
try {
  const devtools = new DevTools(chromium);
  const { targetId } = await devtools.send('Target.createTarget', { url: 'about:blank' });
  const { sessionId } = await devtools.send('Target.attachToTarget', { targetId, flatten: true });
  const page = (method, params) => devtools.send(method, params, sessionId);
  devtools.listeners.push((message) => {
    if (message.sessionId !== sessionId) return;
    if (message.method === 'Runtime.consoleAPICalled' && ['error', 'assert'].includes(message.params.type)) {
      consoleErrors.push(message.params.args.map((a) => a.value ?? a.description).join(' '));
    } else if (message.method === 'Runtime.exceptionThrown') {
      const d = message.params.exceptionDetails;
      consoleErrors.push(d.exception?.description ?? d.text);
    } else if (message.method === 'Log.entryAdded' && message.params.entry.level === 'error') {
      consoleErrors.push(`${message.params.entry.text} ${message.params.entry.url ?? ''}`);
    }
  });
  await page('Runtime.enable');
  await page('Log.enable');
  await page('Page.enable');
  // The window's size minus its frame is not the viewport: set the viewport itself.
  await page('Emulation.setDeviceMetricsOverride', { width: 1000, height: 720, deviceScaleFactor: 1, mobile: false });
  await page('Page.navigate', { url: pageUrl });

  const evaluate = async (expression) => {
    const { result, exceptionDetails } = await page('Runtime.evaluate', { expression, returnByValue: true, awaitPromise: true });
    if (exceptionDetails) throw new Error(`${expression}: ${exceptionDetails.exception?.description ?? exceptionDetails.text}`);
    return result.value;
  };
  const waitReady = async () => {
    const deadline = Date.now() + 30000;
    while (!(await evaluate("document.body?.dataset.ready === 'true'"))) {
      if (Date.now() > deadline || consoleErrors.length) throw new Error(`page not ready: ${consoleErrors.join('; ')}`);
      await wait(100);
    }
  };
  await waitReady();
  const scenes = await evaluate('impulse2dPage.scenes');
  expect(JSON.stringify(scenes) === JSON.stringify(SCENES), `the picker offers ${scenes.join(', ')}`);
  mkdirSync(OUT, { recursive: true });
  const screenshot = async (name) => {
    const { data } = await page('Page.captureScreenshot', { format: 'png' });
    const file = path.join(OUT, `${name}.png`);
    writeFileSync(file, Buffer.from(data, 'base64'));
    console.log(`     screenshot ${file}`);
  };
  const ctx = { page, evaluate, screenshot };

  // Chromium has WebAssembly SIMD and threads, and serve.mjs isolates the page: it must
  // have loaded the threads build (SIMD kernels). On this 2-core machine its scenes step
  // on 1 worker; the end of the test asks for 2.
  const build = await evaluate('impulse2dPage.state()');
  expect(build.isolated && build.threadsBuild && build.simdBuild && build.simdPath === 'wasm128',
         `the page is cross-origin isolated and runs the threads build with SIMD kernels ` +
         `(isolated ${build.isolated}, threads ${build.threadsBuild}, path ${build.simdPath})`);
  const buildReadout = await evaluate('impulse2dPage.readout()');
  expect(buildReadout.includes(`wasm threads, wasm128 kernels, ${build.workerCount} worker`),
         `the readout names the build, its kernels and the worker count (${buildReadout})`);
  const oneWorkerHash = await evaluate(TUMBLER_HASH);

  for (const scene of scenes) {
    await evaluate(`impulse2dPage.loadScene(${JSON.stringify(scene)})`);
    await wait(LIVE_SECONDS * 1000);
    const liveSteps = (await evaluate('impulse2dPage.state()')).steps;
    expect(liveSteps > 10, `${scene}: ran live on animation frames (${liveSteps} steps in ${LIVE_SECONDS} s)`);
    if (liveSteps < MIN_STEPS) await evaluate(`impulse2dPage.runSteps(${MIN_STEPS - liveSteps})`);
    const state = await evaluate('impulse2dPage.state()');
    console.log(`     ${JSON.stringify(state)}`);
    // The timer's grain (0.1 ms here) rounds the small scenes' steps to 0; the big ones take longer.
    const heavy = state.bodyCount > 100;
    expect(heavy ? state.msPerStep > 0 : state.msPerStep >= 0, `${scene}: ${state.msPerStep.toFixed(2)} ms per step`);
    await SCENE_CHECKS[scene](state, ctx);
    const painted = await evaluate('impulse2dPage.paintedPixels()');
    expect(painted > 10000, `${scene}: canvas drawn (${painted} painted pixels)`);
    const counts = await evaluate('impulse2dPage.drawCounts()');
    expect(Object.keys(counts).length > 0, `${scene}: drawn through World.draw's drawer (${JSON.stringify(counts)})`);
    await screenshot(scene);
  }

  await checkDrawToggles(ctx);
  await drivePlatformer(ctx);

  // Buttons: pause stops stepping, step advances one, reset starts over.
  await evaluate("impulse2dPage.loadScene('mixed')");
  await wait(500);
  await evaluate("document.getElementById('pause').click()");
  const paused = (await evaluate('impulse2dPage.state()')).steps;
  await wait(500);
  expect((await evaluate('impulse2dPage.state()')).steps === paused, 'pause stops stepping');
  await evaluate("document.getElementById('step').click()");
  expect((await evaluate('impulse2dPage.state()')).steps === paused + 1, 'step advances one step');
  await evaluate("document.getElementById('reset').click()");
  expect((await evaluate('impulse2dPage.state()')).steps === 0, 'reset starts the scene over');
  await evaluate("document.getElementById('pause').click()");

  // Dragging: press on a body, move the pointer 150 px up, and the body follows on a mouse
  // joint that releasing destroys.
  await evaluate("impulse2dPage.loadScene('pyramid')");
  await wait(300);
  const target = await evaluate('impulse2dPage.pickDynamicBody()');
  const before = await evaluate(`impulse2dPage.bodyPosition(${target.index})`);
  await mouse(ctx, 'mousePressed', target.x, target.y);
  expect(await evaluate('impulse2dPage.isHolding()'), 'pressing on a body takes hold of it');
  expect((await evaluate('impulse2dPage.state()')).jointCount === 1, 'holding is a joint (the mouse joint)');
  for (let i = 1; i <= 10; i++) await mouse(ctx, 'mouseMoved', target.x, target.y - 15 * i);
  await evaluate('impulse2dPage.runSteps(60)');
  const after = await evaluate(`impulse2dPage.bodyPosition(${target.index})`);
  await mouse(ctx, 'mouseReleased', target.x, target.y - 150);
  expect(after.y - before.y > 2, `the dragged body rose ${(after.y - before.y).toFixed(2)} m toward the pointer`);
  expect(!(await evaluate('impulse2dPage.isHolding()')), 'releasing lets go');
  expect((await evaluate('impulse2dPage.state()')).jointCount === 0, 'releasing destroys the mouse joint');
  // Letting go changed the world's structure: the rewind keeps only what came after, and
  // holding R now goes back through that without a refusal (which would reach the console).
  await key(ctx, 'keyDown', 'r');
  await wait(200);
  await key(ctx, 'keyUp', 'r');

  // Rewind: the page keeps a rollback state per frame. Paused, 90 steps are run one at a
  // time, each step's hash noted; holding R, then the rewind button, takes the world back
  // to the very state (the same hash) of an earlier step; playing on from there goes
  // through the same states again; running again resumes stepping.
  await evaluate("impulse2dPage.loadScene('mixed')");
  await evaluate("document.getElementById('pause').click()");
  const hashAt = new Map();
  const note = async () => {
    const { steps } = await evaluate('impulse2dPage.state()');
    hashAt.set(steps, await evaluate('impulse2dPage.hash()'));
    return steps;
  };
  const first = await note();
  for (let i = 0; i < 90; i++) {
    await evaluate('impulse2dPage.runSteps(1)');
    await note();
  }
  const last = first + 90;
  // Holds until the page has gone back at least 10 frames from `from` (animation frames
  // may come slowly on a loaded machine), at most 10 s.
  const holdUntilBack = async (from) => {
    const until = Date.now() + 10000;
    while ((await evaluate('impulse2dPage.state()')).steps > from - 10 && Date.now() < until) await wait(30);
  };
  let rewind = await evaluate('impulse2dPage.state()');
  expect(rewind.steps === last && rewind.rewindFrames >= 90 && rewind.rewindBytes > 0,
         `rewind keeps a state per frame (${rewind.rewindFrames} frames, ${rewind.rewindBytes} bytes)`);
  const readout = await evaluate('impulse2dPage.readout()');
  expect(/rewind \d+\.\d s \(\d+ frames, \d+\.\d MiB\)/.test(readout), `the readout shows the buffer: ${readout}`);
  await key(ctx, 'keyDown', 'r');
  expect((await evaluate('impulse2dPage.state()')).rewinding, 'holding R rewinds');
  await holdUntilBack(last);
  await key(ctx, 'keyUp', 'r');
  rewind = await evaluate('impulse2dPage.state()');
  let hash = await evaluate('impulse2dPage.hash()');
  expect(!rewind.rewinding && rewind.steps < last && rewind.steps >= first && hash === hashAt.get(rewind.steps),
         `holding R went back ${last - rewind.steps} frames to step ${rewind.steps}, its hash ${hash}`);
  const byKey = rewind.steps;
  const button = await evaluate(`(() => { const r = document.getElementById('rewind').getBoundingClientRect();
                                          return { x: r.left + r.width / 2, y: r.top + r.height / 2 }; })()`);
  await mouse(ctx, 'mousePressed', button.x, button.y);
  await holdUntilBack(byKey);
  await mouse(ctx, 'mouseReleased', button.x, button.y);
  rewind = await evaluate('impulse2dPage.state()');
  hash = await evaluate('impulse2dPage.hash()');
  expect(!rewind.rewinding && rewind.steps < byKey && rewind.steps >= first && hash === hashAt.get(rewind.steps),
         `holding the button went back ${byKey - rewind.steps} more frames to step ${rewind.steps}, its hash ${hash}`);
  await evaluate('impulse2dPage.runSteps(5)');
  const replayed = await evaluate('impulse2dPage.state()');
  expect(await evaluate('impulse2dPage.hash()') === hashAt.get(replayed.steps),
         `playing on from there gives step ${replayed.steps}'s hash again`);
  await evaluate("document.getElementById('pause').click()");
  await wait(300);
  expect((await evaluate('impulse2dPage.state()')).steps > replayed.steps, 'running again resumes stepping');

  // ?workers=2: the scenes step on 2 workers (Web Workers sharing the module's memory),
  // to the same bits as on one.
  await page('Page.navigate', { url: `${pageUrl}?workers=2` });
  await waitReady();
  const twoWorkerHash = await evaluate(TUMBLER_HASH);
  const shared = await evaluate('impulse2dPage.state()');
  expect(shared.workerCount === 2 && (await evaluate('impulse2dPage.readout()')).includes('2 workers'),
         `?workers=2: the tumbler steps on ${shared.workerCount} workers and the readout says so`);
  expect(twoWorkerHash === oneWorkerHash,
         `the tumbler after ${TUMBLER_STEPS} steps: hash ${twoWorkerHash} on 2 workers, ${oneWorkerHash} on ${build.workerCount}`);

  expect(consoleErrors.length === 0, `no console errors${consoleErrors.length ? ': ' + consoleErrors.join('; ') : ''}`);
} catch (error) {
  failures.push(String(error));
  console.log(`FAIL ${error.stack ?? error}`);
  if (chromiumLog) console.log(chromiumLog.slice(-2000));
} finally {
  // Chromium writes to its profile until it has exited.
  const exited = new Promise((resolve) => chromium.once('exit', resolve));
  chromium.kill();
  await Promise.race([exited, wait(5000)]);
  server.close();
  // Its helper processes can outlive it for a moment and still write there: a profile
  // left in the temporary directory is reported, not failed.
  try {
    rmSync(profile, { recursive: true, force: true, maxRetries: 10, retryDelay: 300 });
  } catch (error) {
    console.log(`note: could not remove ${profile} (${error.code}); left for the system to clean`);
  }
}
console.log(failures.length ? `${failures.length} check(s) failed` : 'browser test passed');
process.exit(failures.length ? 1 : 0);
