// SPDX-License-Identifier: MIT
// A canvas backend of World.draw's drawer methods: everything the page shows goes through
// these nine methods, the world's shapes, joints and contacts from the library's debug
// draw and the game's own pictures (the character, a blast) from the page.
//
// World units with y up: begin() sets the canvas transform from the camera, so paths are
// built in metres; line widths and point sizes are divided by the scale to stay in pixels.
import { colorToCss } from '../../bindings/js/src/index.js';

/** The canvas background: dark, since the library's colours are pale (as Box2D's samples). */
export const BACKGROUND = { css: '#1b1e24', rgb: [0x1b, 0x1e, 0x24] };
/** Filled shapes at half strength under a full-strength outline: overlaps stay readable. */
const FILL_ALPHA = 0.5;
const LINE_PIXELS = 1;
/** drawTransform's axes, m: x red, y green. */
const AXIS_LENGTH = 0.4;
const AXIS_COLORS = { x: '#ff4040', y: '#40ff40' };
const FONT = '12px ui-monospace, monospace';

export class CanvasDrawer {
  constructor(ctx, camera) {
    this.ctx = ctx;
    this.camera = camera;
    /** Calls per method in the current frame: what the browser test reads back. */
    this.counts = {};
  }

  /** Clears the canvas and sets world units, y up, for a new frame. */
  begin() {
    const { ctx, camera } = this;
    const { canvas } = camera;
    this.counts = {};
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.fillStyle = BACKGROUND.css;
    ctx.fillRect(0, 0, canvas.width, canvas.height);
    const s = camera.scale;
    this.pixel = 1 / s;
    ctx.setTransform(s, 0, 0, -s, canvas.width / 2 - s * camera.cx, canvas.height / 2 + s * camera.cy);
    ctx.lineJoin = 'round';
    ctx.lineCap = 'round';
  }

  count(method) { this.counts[method] = (this.counts[method] ?? 0) + 1; }

  drawPolygon(vertices, color) {
    this.count('drawPolygon');
    this.tracePoints(vertices, null);
    this.outline(color);
  }

  /** A polygon grown by radius is the polygon stroked with a round pen of twice that width. */
  drawSolidPolygon(transform, vertices, radius, color) {
    this.count('drawSolidPolygon');
    const { ctx } = this;
    this.tracePoints(vertices, transform);
    ctx.fillStyle = colorToCss(color, FILL_ALPHA);
    ctx.fill();
    if (radius > 0) {
      ctx.strokeStyle = ctx.fillStyle;
      ctx.lineWidth = 2 * radius;
      ctx.stroke();
    }
    this.outline(color);
  }

  drawCircle(center, radius, color) {
    this.count('drawCircle');
    this.ctx.beginPath();
    this.ctx.arc(center.x, center.y, radius, 0, 2 * Math.PI);
    this.outline(color);
  }

  /** A disc with a radius along the body's x axis, so that it is seen to turn. */
  drawSolidCircle(transform, radius, color) {
    this.count('drawSolidCircle');
    const { ctx } = this;
    ctx.beginPath();
    ctx.arc(transform.x, transform.y, radius, 0, 2 * Math.PI);
    ctx.fillStyle = colorToCss(color, FILL_ALPHA);
    ctx.fill();
    ctx.moveTo(transform.x, transform.y);
    ctx.lineTo(transform.x + radius * transform.c, transform.y + radius * transform.s);
    this.outline(color);
  }

  drawSolidCapsule(p1, p2, radius, color) {
    this.count('drawSolidCapsule');
    const { ctx } = this;
    const angle = Math.atan2(p2.y - p1.y, p2.x - p1.x);
    ctx.beginPath();
    ctx.arc(p2.x, p2.y, radius, angle - Math.PI / 2, angle + Math.PI / 2);
    ctx.arc(p1.x, p1.y, radius, angle + Math.PI / 2, angle + 1.5 * Math.PI);
    ctx.closePath();
    ctx.fillStyle = colorToCss(color, FILL_ALPHA);
    ctx.fill();
    this.outline(color);
  }

  drawSegment(p1, p2, color) {
    this.count('drawSegment');
    this.ctx.beginPath();
    this.ctx.moveTo(p1.x, p1.y);
    this.ctx.lineTo(p2.x, p2.y);
    this.outline(color);
  }

  drawTransform(transform) {
    this.count('drawTransform');
    const { ctx } = this;
    const { x, y, c, s } = transform;
    for (const [axis, dx, dy] of [['x', c, s], ['y', -s, c]]) {
      ctx.beginPath();
      ctx.moveTo(x, y);
      ctx.lineTo(x + AXIS_LENGTH * dx, y + AXIS_LENGTH * dy);
      ctx.strokeStyle = AXIS_COLORS[axis];
      ctx.lineWidth = LINE_PIXELS * this.pixel;
      ctx.stroke();
    }
  }

  /** size is in pixels, whatever the zoom. */
  drawPoint(p, size, color) {
    this.count('drawPoint');
    const half = 0.5 * size * this.pixel;
    this.ctx.fillStyle = colorToCss(color);
    this.ctx.fillRect(p.x - half, p.y - half, 2 * half, 2 * half);
  }

  /** Text is drawn in screen pixels (upright), at the point's place on the screen. */
  drawString(p, text, color) {
    this.count('drawString');
    const { ctx } = this;
    const screen = this.camera.toScreen(p.x, p.y);
    ctx.save();
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.font = FONT;
    ctx.fillStyle = colorToCss(color);
    ctx.fillText(text, screen.x, screen.y);
    ctx.restore();
  }

  /** A closed path through x, y pairs, placed by transform {x, y, c, s} when given. */
  tracePoints(vertices, transform) {
    const { ctx } = this;
    ctx.beginPath();
    for (let i = 0; i < vertices.length; i += 2) {
      let x = vertices[i], y = vertices[i + 1];
      if (transform) [x, y] = [transform.c * x - transform.s * y + transform.x, transform.s * x + transform.c * y + transform.y];
      if (i === 0) ctx.moveTo(x, y);
      else ctx.lineTo(x, y);
    }
    ctx.closePath();
  }

  outline(color) {
    this.ctx.strokeStyle = colorToCss(color);
    this.ctx.lineWidth = LINE_PIXELS * this.pixel;
    this.ctx.stroke();
  }
}
