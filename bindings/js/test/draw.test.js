// SPDX-License-Identifier: MIT
// World.draw through a recording drawer, as tests/api/test_api_debug_draw.c checks
// i2d_world_draw in C: each shape once through its method in its body state's colour,
// joints, bounds, mass, contacts and islands only when asked, culling, drawers lacking
// methods, errors thrown by a method, nested draws, the table slots kept per module, and
// refusals; and the colour constants against the C header.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { i2d, groundedWorld, refused, assertNear, stepSeconds } from './fixture.js';
import { colorToCss, DRAW_COLORS, GRAPH_COLORS } from '../src/index.js';
import { drawTablePointers } from '../src/debug_draw.js';

const METHODS = ['drawPolygon', 'drawSolidPolygon', 'drawCircle', 'drawSolidCircle', 'drawSolidCapsule',
  'drawSegment', 'drawTransform', 'drawPoint', 'drawString'];

/** A drawer with every method (or those named), recording {method, args} per call. Vertex
 *  views are copied: they are only valid during the call. */
function recorder(methods = METHODS) {
  const calls = [];
  const drawer = { calls };
  for (const method of methods) {
    drawer[method] = (...args) => calls.push({ method, args: args.map((a) => (a instanceof Float32Array ? [...a] : a)) });
  }
  drawer.count = (method, color) => calls.filter((c) => c.method === method &&
                                                   (color === undefined || c.args.at(-1) === color)).length;
  return drawer;
}

/** Where a call is placed: a transform's or a point's x, y (the first argument). */
const at = (call) => call.args[0];
const near = (p, x, y) => Math.abs(p.x - x) < 1e-4 && Math.abs(p.y - y) < 1e-4;

test('the colour constants are the header\'s, and colorToCss writes them for a canvas', () => {
  const header = readFileSync(new URL('../../../include/impulse2d/toolkit.h', import.meta.url), 'utf8');
  const defined = new Map([...header.matchAll(/#define I2D_COLOR_(\w+) 0x([0-9A-F]{6})u/g)]
    .map(([, name, hex]) => [name.toLowerCase().replace(/_(\w)/g, (_, c) => c.toUpperCase()), parseInt(hex, 16)]));
  assert.ok(defined.size >= 20);
  assert.deepEqual(Object.fromEntries(defined), { ...DRAW_COLORS });
  const palette = /#define I2D_GRAPH_COLORS[\s\\]*\{([^}]*)\}/.exec(header)[1];
  assert.deepEqual([...palette.matchAll(/0x([0-9A-F]{6})u/g)].map(([, hex]) => parseInt(hex, 16)), [...GRAPH_COLORS]);
  assert.equal(colorToCss(DRAW_COLORS.static), '#80e680');
  assert.equal(colorToCss(0x0000ff), '#0000ff');
  assert.equal(colorToCss(0x3366ff, 0.5), 'rgba(51, 102, 255, 0.5)');
});

/** One shape per body state at its own x, a segment and a rounded triangle. */
function shapesByState() {
  const world = i2d.createWorld({ gravity: [0, 0] });
  const ground = world.createBody();
  ground.createBox(1, 1);
  ground.createSegment([-2, 2], [2, 2]);
  world.createBody({ type: 'kinematic', position: [10, 0] }).createCapsule([-0.5, 0], [0.5, 0], 0.25);
  world.createBody({ type: 'dynamic', position: [20, 0] }).createCircle(0.5);
  const asleep = world.createBody({ type: 'dynamic', position: [30, 0] });
  asleep.createBox(0.5, 0.5);
  asleep.awake = false;
  const bullet = world.createBody({ type: 'dynamic', position: [40, 0] });
  bullet.createCircle(0.1);
  bullet.bullet = true;
  world.createBody({ type: 'dynamic', position: [50, 0] }).createCircle(0.5, { isSensor: true });
  const disabled = world.createBody({ type: 'dynamic', position: [60, 0] });
  disabled.createBox(0.5, 0.5);
  disabled.disable();
  const rounded = world.createBody({ position: [70, 0] }).createPolygon([[0, 0], [1, 0], [0, 1]]);
  rounded.setPolygon([[0, 0], [1, 0], [0, 1]], 0.1);
  return world;
}

test('each shape is drawn once, through its method, in its body state\'s colour', () => {
  const world = shapesByState();
  const d = recorder();
  world.draw(d);
  assert.equal(d.calls.length, 9);
  assert.equal(d.count('drawSolidPolygon'), 4);
  assert.equal(d.count('drawSolidCircle'), 3);
  assert.equal(d.count('drawSolidCapsule'), 1);
  assert.equal(d.count('drawSegment'), 1);
  const one = (method, x, color) => d.calls.filter((c) => c.method === method && near(at(c), x, c.method === 'drawSegment' ? 2 : 0)
                                                     && c.args.at(-1) === color).length;
  assert.equal(one('drawSolidPolygon', 0, 0x80E680), 1, 'static');
  assert.equal(d.count('drawSegment', 0x80E680), 1, 'static segment');
  assert.ok(near(d.calls.find((c) => c.method === 'drawSegment').args[1], 2, 2));
  assert.equal(one('drawSolidCircle', 20, 0xE6B380), 1, 'awake');
  assert.equal(one('drawSolidPolygon', 30, 0x999999), 1, 'asleep');
  assert.equal(one('drawSolidCircle', 40, 0xE6E64D), 1, 'bullet');
  assert.equal(one('drawSolidCircle', 50, 0x33CCFF), 1, 'sensor');
  assert.equal(one('drawSolidPolygon', 60, 0x666666), 1, 'disabled');
  const capsule = d.calls.find((c) => c.method === 'drawSolidCapsule');
  assert.deepEqual(capsule.args, [{ x: 9.5, y: 0 }, { x: 10.5, y: 0 }, 0.25, 0x8080E6]);
  // Polygons: a transform {x, y, c, s}, local vertices as x, y pairs, the radius.
  const box = d.calls.find((c) => c.method === 'drawSolidPolygon' && near(at(c), 0, 0));
  assert.deepEqual(box.args[0], { x: 0, y: 0, c: 1, s: 0 });
  assert.deepEqual(box.args[1], [-1, -1, 1, -1, 1, 1, -1, 1]);
  assert.equal(box.args[2], 0);
  const triangle = d.calls.find((c) => c.method === 'drawSolidPolygon' && near(at(c), 70, 0));
  assert.equal(triangle.args[1].length, 6);
  assertNear(triangle.args[2], 0.1, 1e-7, 'rounded polygon radius');
  const circle = d.calls.find((c) => c.method === 'drawSolidCircle' && near(at(c), 20, 0));
  assert.equal(circle.args[1], 0.5);
  // Shapes off: nothing.
  const none = recorder();
  world.draw(none, { drawShapes: false });
  assert.equal(none.calls.length, 0);
  world.destroy();
});

/** A ground box, an arm on a revolute joint (limit and motor) to it, and a ball. */
function jointScene() {
  const world = i2d.createWorld({ gravity: [0, 0] });
  const ground = world.createBody();
  ground.createBox(0.5, 0.5);
  const arm = world.createBody({ type: 'dynamic', position: [2, 0] });
  arm.createBox(0.5, 0.5);
  const ball = world.createBody({ type: 'dynamic', position: [10, 0] });
  ball.createCircle(0.5);
  world.createRevoluteJoint(ground, arm, {
    localAnchorA: [1, 0], localAnchorB: [-1, 0], enableLimit: true, lowerAngle: -0.5, upperAngle: 0.5,
    enableMotor: true,
  });
  return { world, arm, ball };
}

test('joints, joint extras, bounds, mass and islands are drawn when asked', () => {
  const { world, arm, ball } = jointScene();
  let d = recorder();
  world.draw(d);  // defaults: shapes and the joint's links
  assert.equal(d.count('drawSegment', DRAW_COLORS.joint), 3);
  assert.equal(d.count('drawPoint', DRAW_COLORS.jointAnchor), 2);
  assert.equal(d.count('drawPolygon') + d.count('drawTransform') + d.count('drawCircle'), 0);

  d = recorder();
  world.draw(d, { drawJointExtras: true });
  assert.equal(d.count('drawSegment', DRAW_COLORS.jointLimit), 2);
  assert.equal(d.count('drawCircle', DRAW_COLORS.jointMotor), 1);

  d = recorder();
  world.draw(d, { drawJoints: false });
  assert.equal(d.count('drawSegment') + d.count('drawPoint'), 0);

  d = recorder();
  world.draw(d, { drawJoints: false, drawBounds: true });
  assert.equal(d.count('drawPolygon', DRAW_COLORS.bounds), 3);
  for (const call of d.calls.filter((c) => c.method === 'drawPolygon')) assert.equal(call.args[0].length, 8);

  d = recorder();
  world.draw(d, { drawJoints: false, drawMass: true });
  assert.equal(d.count('drawTransform'), 2);
  const masses = d.calls.filter((c) => c.method === 'drawString');
  assert.equal(masses.length, 2);
  assert.ok(masses.every((c) => c.args[2] === DRAW_COLORS.mass && typeof c.args[1] === 'string' && /\d/.test(c.args[1])));
  assert.ok(masses.some((c) => near(c.args[0], ball.worldCenterOfMass.x, ball.worldCenterOfMass.y)));
  assert.ok(d.calls.some((c) => c.method === 'drawTransform' && near(at(c), arm.position.x, arm.position.y)));

  d = recorder();
  world.draw(d, { drawJoints: false, drawIslands: true });
  assert.equal(d.count('drawPolygon', DRAW_COLORS.island), 2);  // the arm and the ball, each awake
  world.destroy();
});

test('contacts, normals, impulses and graph colours are drawn when asked', () => {
  const { world } = groundedWorld();
  world.createBody({ type: 'dynamic', position: [0, 0.5] }).createBox(0.5, 0.5);
  for (let i = 0; i < 10; i++) world.step();
  let d = recorder();
  world.draw(d);
  assert.equal(d.count('drawPoint'), 0);
  d = recorder();
  world.draw(d, { drawContacts: true });
  assert.equal(d.count('drawPoint', DRAW_COLORS.contact), 2);
  d = recorder();
  world.draw(d, { drawContactNormals: true, drawContactImpulses: true, drawFrictionImpulses: true });
  const normals = d.calls.filter((c) => c.method === 'drawSegment' && c.args[2] === DRAW_COLORS.contactNormal);
  assert.equal(normals.length, 2);
  for (const { args: [p, q] } of normals) assertNear(q.y - p.y, 0.3, 1e-4, 'a normal is 0.3 m up');
  const impulses = d.calls.filter((c) => c.method === 'drawSegment' && c.args[2] === DRAW_COLORS.contactImpulse);
  assert.equal(impulses.length, 2);
  assert.ok(impulses.every(({ args: [p, q] }) => q.y > p.y), 'the ground pushes up');
  d = recorder();
  world.draw(d, { drawGraphColors: true });
  const points = d.calls.filter((c) => c.method === 'drawPoint');
  assert.ok(points.length >= 2 && points.every((c) => GRAPH_COLORS.includes(c.args[2])));
  world.destroy();
});

test('drawingBounds culls to the shapes whose bounds overlap it', () => {
  const world = i2d.createWorld({ gravity: [0, 0] });
  const bodies = [];
  for (let i = -5; i <= 5; i++) {
    const body = world.createBody({ position: [4 * i, 0] });
    body.createCircle(0.75);
    bodies.push(body);
  }
  const d = recorder();
  world.draw(d, { drawingBounds: { minX: -5, minY: -1, maxX: 9, maxY: 1 } });
  // Circles at -4, 0, 4, 8 reach into [-5, 9]; -8 (to -7.25) and 12 (from 11.25) do not.
  assert.deepEqual(d.calls.map((c) => at(c).x).sort((a, b) => a - b), [-4, 0, 4, 8]);
  const far = recorder();
  world.draw(far, { drawingBounds: { minX: 1000, minY: 1000, maxX: 1001, maxY: 1001 } });
  assert.equal(far.calls.length, 0);
  const all = recorder();
  world.draw(all, { drawingBounds: null });
  assert.equal(all.calls.length, 11);
  world.destroy();
});

test('a drawer without some methods gets only the others, and an empty one nothing', () => {
  const { world } = jointScene();
  const circles = recorder(['drawSolidCircle']);
  world.draw(circles, { drawJointExtras: true, drawBounds: true, drawMass: true, drawIslands: true });
  assert.equal(circles.calls.length, 1);
  assert.equal(circles.calls[0].method, 'drawSolidCircle');
  const points = recorder(['drawPoint']);
  world.draw(points);
  assert.equal(points.calls.length, 2);
  world.draw({});
  world.draw({ drawPolygon: undefined, drawSegment: null });
  world.destroy();
});

test('an error thrown in a drawer method is thrown after the call, which ends the drawing', () => {
  const { world } = jointScene();
  const boom = new Error('from the drawer');
  let calls = 0;
  const drawer = { drawSolidPolygon() { calls++; throw boom; }, drawSolidCircle() { calls++; } };
  assert.throws(() => world.draw(drawer), (error) => error === boom);
  assert.equal(calls, 1, 'nothing more was handed to the drawer');
  // The world was not left locked, and the next draw runs whole.
  world.step();
  const d = recorder();
  world.draw(d);
  assert.equal(d.count('drawSolidPolygon'), 2);
  // A method changing the world is refused (locked); uncaught, the refusal comes out.
  refused(() => world.draw({ drawSolidCircle: () => world.step() }), 'I2D_ERR_WORLD_LOCKED', 'i2d_world_step');
  world.destroy();
});

test('a drawer may query its world and draw another from inside a method', () => {
  const { world } = jointScene();
  const other = i2d.createWorld();
  other.createBody().createCapsule([0, 0], [1, 0], 0.5);
  const outer = recorder(['drawSolidPolygon']);
  const inner = recorder();
  let counted = 0;
  outer.drawSolidCircle = () => {
    counted = world.counters().bodyCount;
    other.draw(inner);
  };
  world.draw(outer);
  assert.equal(counted, 3);
  assert.equal(outer.count('drawSolidPolygon'), 2, 'the outer draw went on after the inner one');
  assert.deepEqual(inner.calls.map((c) => c.method), ['drawSolidCapsule']);
  other.destroy();
  world.destroy();
});

test('the nine trampolines take table slots once per module, whatever the draws', () => {
  const table = Object.values(i2d.rt.m.asm).find((e) => e instanceof WebAssembly.Table);
  const { world } = jointScene();
  world.draw(recorder());
  const pointers = drawTablePointers(i2d.rt);
  assert.equal(pointers.length, 9);
  assert.equal(new Set(pointers).size, 9);
  const size = table.length;
  for (let i = 0; i < 200; i++) world.draw(recorder(i % 2 ? ['drawSegment'] : METHODS), { drawBounds: i % 3 === 0 });
  assert.equal(table.length, size);
  assert.deepEqual(drawTablePointers(i2d.rt), pointers);
  world.destroy();
});

test('draw refuses what is not a drawer, unknown options, bad bounds and a destroyed world', () => {
  const { world } = jointScene();
  stepSeconds(world, 0.1);
  const hash = world.stateHash();
  assert.throws(() => world.draw(), TypeError);
  assert.throws(() => world.draw(null), TypeError);
  assert.throws(() => world.draw({ drawSegment: 'red' }), TypeError);
  assert.throws(() => world.draw({}, { drawShape: true }), TypeError);
  assert.throws(() => world.draw({}, 5), TypeError);
  const d = recorder();
  refused(() => world.draw(d, { drawingBounds: { minX: NaN, minY: 0, maxX: 1, maxY: 1 } }),
          'I2D_ERR_INVALID_ARGUMENT', 'drawing_bounds');
  refused(() => world.draw(d, { drawingBounds: { minX: 2, minY: 0, maxX: 1, maxY: 1 } }),
          'I2D_ERR_INVALID_ARGUMENT', 'drawing_bounds');
  refused(() => world.draw(d, { drawingBounds: {} }), 'I2D_ERR_INVALID_ARGUMENT', 'drawing_bounds');
  assert.equal(d.calls.length, 0);
  assert.equal(world.stateHash(), hash);
  world.destroy();
  refused(() => world.draw(d), 'I2D_ERR_INVALID_HANDLE', 'world');
});
