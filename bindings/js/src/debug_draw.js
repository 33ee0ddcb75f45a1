// SPDX-License-Identifier: MIT
// World.draw: the world handed to a drawer object's methods through i2d_world_draw.
//
// Cost is what matters here (a page draws every frame), so the nine trampolines are put in
// the module's function table once per module, not per call: each finds the drawer of
// the draw in progress from the context pointer, which is its depth in a stack of draws
// (a drawer may draw another world, or the same one, from inside a method). Only the
// trampolines for methods the drawer has are given to the library, which then skips the
// other kinds of picture altogether. Vertex arrays are views of the module's memory.
import { DRAW_CALLBACKS, DRAW_FLAGS } from './draw_fields.js';

const DRAW_OPTIONS = [...Object.keys(DRAW_FLAGS), 'drawingBounds'];

/** The table slots and the stack of draws of one loaded module. */
class DrawTable {
  constructor(rt) {
    this.rt = rt;
    /** The draws in progress, outermost first: {drawer, failed, error}. */
    this.draws = [];
    /** The table slot of each callback, by C field. */
    this.pointers = new Map();
    const trampolines = makeTrampolines(rt, (depth, call) => this.forward(depth, call));
    for (const [field, method, signature] of DRAW_CALLBACKS) {
      this.pointers.set(field, rt.m.addFunction(trampolines[method], signature));
    }
    /** One i2d_debug_draw, rewritten for each draw (the library copies it at the call). */
    this.block = rt.m._malloc(rt.size('i2d_debug_draw'));
  }

  // A JS exception must not unwind through the library's frames (the world would stay
  // locked): the first is kept for draw() to throw, and the rest of that draw is skipped.
  forward(depth, call) {
    const draw = this.draws[depth];
    if (draw === undefined || draw.failed) return;
    try {
      call(draw.drawer);
    } catch (error) {
      draw.failed = true;
      draw.error = error;
    }
  }

  draw(world, drawer, options) {
    checkDrawer(drawer);
    const rt = this.rt;
    writeDebugDraw(rt, this.block, options);
    for (const [field, method] of DRAW_CALLBACKS) {
      const wanted = typeof drawer[method] === 'function';
      rt.u32[(this.block + rt.field(`i2d_debug_draw.${field}`)) >> 2] = wanted ? this.pointers.get(field) : 0;
    }
    const depth = this.draws.length;
    rt.u32[(this.block + rt.field('i2d_debug_draw.context')) >> 2] = depth;
    const draw = { drawer, failed: false, error: undefined };
    this.draws.push(draw);
    let status;
    try {
      status = rt.m._i2d_world_draw(world.id, this.block);
    } finally {
      this.draws.pop();
    }
    rt.check(status);
    if (draw.failed) throw draw.error;
  }
}

const tables = new WeakMap();

/** World.draw: the table of world's module, made at the first draw. */
export function drawWorld(world, drawer, options = {}) {
  let table = tables.get(world.rt);
  if (table === undefined) {
    table = new DrawTable(world.rt);
    tables.set(world.rt, table);
  }
  table.draw(world, drawer, options);
}

/** @internal For tests: the table slots a module's draws use (none before its first draw). */
export function drawTablePointers(rt) {
  return [...(tables.get(rt)?.pointers.values() ?? [])];
}

function checkDrawer(drawer) {
  if (drawer === null || typeof drawer !== 'object') {
    throw new TypeError(`World.draw takes a drawer object with draw methods, not ${String(drawer)}`);
  }
  for (const [, method] of DRAW_CALLBACKS) {
    const value = drawer[method];
    if (value !== undefined && value !== null && typeof value !== 'function') {
      throw new TypeError(`the drawer's ${method} is ${typeof value}, not a function`);
    }
  }
}

// The default def, the flags the options give, and the culling box when given (a missing
// or non-finite corner reads as NaN, which the library refuses with its message).
function writeDebugDraw(rt, at, options) {
  if (options === null || typeof options !== 'object') throw new TypeError('World.draw\'s options must be an object');
  for (const name of Object.keys(options)) {
    if (!DRAW_OPTIONS.includes(name)) {
      throw new TypeError(`World.draw has no option '${name}'; known: ${DRAW_OPTIONS.join(', ')}`);
    }
  }
  rt.u8.set(rt.defaults.debugDraw, at);
  const field = (name) => at + rt.field(`i2d_debug_draw.${name}`);
  for (const [option, name] of Object.entries(DRAW_FLAGS)) {
    if (options[option] !== undefined) rt.u8[field(name)] = options[option] ? 1 : 0;
  }
  const bounds = options.drawingBounds;
  if (bounds !== undefined && bounds !== null) {
    const box = field('drawing_bounds');
    rt.writeVec2(box + rt.field('i2d_aabb.min'), Number(bounds.minX), Number(bounds.minY));
    rt.writeVec2(box + rt.field('i2d_aabb.max'), Number(bounds.maxX), Number(bounds.maxY));
    rt.u8[field('use_drawing_bounds')] = 1;
  }
}

/**
 * The function the library calls for each drawer method: the raw wasm arguments turned
 * into what the method takes (points {x, y}, transforms {x, y, c, s} as Body.transform
 * gives them, vertices a Float32Array of x, y pairs viewing the module's memory, colours
 * 0xRRGGBB numbers) and handed to forward(depth, call) with the context, the draw's depth.
 */
function makeTrampolines(rt, forward) {
  const point = (at) => rt.readVec2(at);
  const transform = (at) => {
    const f = rt.f32;
    const i = at >> 2;
    return { x: f[i], y: f[i + 1], c: f[i + 2], s: f[i + 3] };
  };
  const vertices = (at, count) => rt.f32.subarray(at >> 2, (at >> 2) + 2 * count);
  const color = (c) => c >>> 0;  // i2d_color is unsigned; an i32 arrives signed
  return {
    drawPolygon: (v, count, c, depth) => forward(depth, (d) => d.drawPolygon(vertices(v, count), color(c))),
    drawSolidPolygon: (xf, v, count, radius, c, depth) => forward(depth, (d) => d.drawSolidPolygon(
      transform(xf), vertices(v, count), radius, color(c))),
    drawCircle: (center, radius, c, depth) => forward(depth, (d) => d.drawCircle(point(center), radius, color(c))),
    drawSolidCircle: (xf, radius, c, depth) => forward(depth, (d) => d.drawSolidCircle(transform(xf), radius,
                                                                                        color(c))),
    drawSolidCapsule: (p1, p2, radius, c, depth) => forward(depth, (d) => d.drawSolidCapsule(
      point(p1), point(p2), radius, color(c))),
    drawSegment: (p1, p2, c, depth) => forward(depth, (d) => d.drawSegment(point(p1), point(p2), color(c))),
    drawTransform: (xf, depth) => forward(depth, (d) => d.drawTransform(transform(xf))),
    drawPoint: (p, size, c, depth) => forward(depth, (d) => d.drawPoint(point(p), size, color(c))),
    drawString: (p, text, c, depth) => forward(depth, (d) => d.drawString(point(p), rt.m.UTF8ToString(text), color(c))),
  };
}
