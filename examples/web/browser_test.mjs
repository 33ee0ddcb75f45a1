#!/usr/bin/env node
// SPDX-License-Identifier: MIT
// Opens the scene page in headless Chromium and checks it: every scene runs a few
// seconds live, its state read back from the page (bodies moved, the pyramid standing,
// nothing escaping), the buttons and pointer dragging work, holding R or the rewind
// button takes the world back to an earlier frame's state hash, no error reaches the
// console, and a screenshot per scene is saved (its canvas checked not blank).
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

// A page or browser that hangs fails the test rather than waiting for CTest's timeout.
const WATCHDOG_SECONDS = 120;
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
  const deadline = Date.now() + 30000;
  while (!(await evaluate("document.body?.dataset.ready === 'true'"))) {
    if (Date.now() > deadline || consoleErrors.length) throw new Error(`page not ready: ${consoleErrors.join('; ')}`);
    await wait(100);
  }
  const scenes = await evaluate('impulse2dPage.scenes');
  expect(scenes.length === 3, `the picker offers ${scenes.join(', ')}`);
  mkdirSync(OUT, { recursive: true });

  for (const scene of scenes) {
    await evaluate(`impulse2dPage.loadScene(${JSON.stringify(scene)})`);
    await wait(LIVE_SECONDS * 1000);
    const liveSteps = (await evaluate('impulse2dPage.state()')).steps;
    expect(liveSteps > 10, `${scene}: ran live on animation frames (${liveSteps} steps in ${LIVE_SECONDS} s)`);
    if (liveSteps < MIN_STEPS) await evaluate(`impulse2dPage.runSteps(${MIN_STEPS - liveSteps})`);
    const state = await evaluate('impulse2dPage.state()');
    console.log(`     ${JSON.stringify(state)}`);
    expect(state.bodyCount > 100 && state.moved > 0, `${scene}: ${state.moved} of ${state.bodyCount} bodies moved`);
    expect(state.msPerStep > 0, `${scene}: ${state.msPerStep.toFixed(2)} ms per step`);
    if (scene === 'pyramid') expect(state.topDrop < 0.2, `pyramid still standing: top dropped ${state.topDrop.toFixed(3)} m`);
    if (scene === 'mixed') expect(state.below === 0, `mixed: no shape fell through the floor (${state.below})`);
    if (scene === 'tumbler') {
      expect(state.escaped === 0, `tumbler: no box escaped the drum (${state.escaped})`);
      expect(Math.abs(state.drumAngle) > 0.5, `tumbler: the drum turned (${state.drumAngle.toFixed(2)} rad)`);
      // The real drum: dynamic, on one revolute joint whose motor keeps 25 deg/s under the
      // boxes (the native bench allows half a degree) and whose pivot holds its centre.
      expect(state.drumType === 'dynamic' && state.jointCount === 1,
             `tumbler: a ${state.drumType} drum on ${state.jointCount} joint`);
      expect(Math.abs(state.drumAngleError) < 0.5 * Math.PI / 180,
             `tumbler: the motor kept time (${(state.drumAngleError * 180 / Math.PI).toFixed(4)} deg off)`);
      expect(state.drumDrift < 0.01, `tumbler: the drum's centre stayed on its pivot (${state.drumDrift.toExponential(2)} m)`);
    }
    const painted = await evaluate('impulse2dPage.paintedPixels()');
    expect(painted > 10000, `${scene}: canvas drawn (${painted} painted pixels)`);
    const { data } = await page('Page.captureScreenshot', { format: 'png' });
    const file = path.join(OUT, `${scene}.png`);
    writeFileSync(file, Buffer.from(data, 'base64'));
    console.log(`     screenshot ${file}`);
  }

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
  const mouse = (type, x, y) => page('Input.dispatchMouseEvent', { type, x, y, button: 'left', buttons: type === 'mouseReleased' ? 0 : 1, clickCount: 1 });
  await mouse('mousePressed', target.x, target.y);
  expect(await evaluate('impulse2dPage.isHolding()'), 'pressing on a body takes hold of it');
  expect((await evaluate('impulse2dPage.state()')).jointCount === 1, 'holding is a joint (the mouse joint)');
  for (let i = 1; i <= 10; i++) await mouse('mouseMoved', target.x, target.y - 15 * i);
  await evaluate('impulse2dPage.runSteps(60)');
  const after = await evaluate(`impulse2dPage.bodyPosition(${target.index})`);
  await mouse('mouseReleased', target.x, target.y - 150);
  expect(after.y - before.y > 2, `the dragged body rose ${(after.y - before.y).toFixed(2)} m toward the pointer`);
  expect(!(await evaluate('impulse2dPage.isHolding()')), 'releasing lets go');
  expect((await evaluate('impulse2dPage.state()')).jointCount === 0, 'releasing destroys the mouse joint');
  // Letting go changed the world's structure: the rewind keeps only what came after, and
  // holding R now goes back through that without a refusal (which would reach the console).
  await page('Input.dispatchKeyEvent', { type: 'keyDown', key: 'r', code: 'KeyR', windowsVirtualKeyCode: 82 });
  await wait(200);
  await page('Input.dispatchKeyEvent', { type: 'keyUp', key: 'r', code: 'KeyR', windowsVirtualKeyCode: 82 });

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
  await page('Input.dispatchKeyEvent', { type: 'keyDown', key: 'r', code: 'KeyR', windowsVirtualKeyCode: 82 });
  expect((await evaluate('impulse2dPage.state()')).rewinding, 'holding R rewinds');
  await holdUntilBack(last);
  await page('Input.dispatchKeyEvent', { type: 'keyUp', key: 'r', code: 'KeyR', windowsVirtualKeyCode: 82 });
  rewind = await evaluate('impulse2dPage.state()');
  let hash = await evaluate('impulse2dPage.hash()');
  expect(!rewind.rewinding && rewind.steps < last && rewind.steps >= first && hash === hashAt.get(rewind.steps),
         `holding R went back ${last - rewind.steps} frames to step ${rewind.steps}, its hash ${hash}`);
  const byKey = rewind.steps;
  const button = await evaluate(`(() => { const r = document.getElementById('rewind').getBoundingClientRect();
                                          return { x: r.left + r.width / 2, y: r.top + r.height / 2 }; })()`);
  await mouse('mousePressed', button.x, button.y);
  await holdUntilBack(byKey);
  await mouse('mouseReleased', button.x, button.y);
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
