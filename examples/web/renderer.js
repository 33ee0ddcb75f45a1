// SPDX-License-Identifier: MIT
// Draws a world's shapes on a 2D canvas from per-body transforms (x, y, cos, sin).

const COLORS = { static: '#6b7280', kinematic: '#2563eb', dynamic: '#f59e0b', asleep: '#a78b5a', held: '#dc2626' };

export class Camera {
  constructor(canvas) { this.canvas = canvas; this.setView({ x: 0, y: 10, height: 30 }); }
  setView(view) { this.cx = view.x; this.cy = view.y; this.height = view.height; }
  get scale() { return this.canvas.height / this.height; }
  toWorld(px, py) {
    return { x: this.cx + (px - this.canvas.width / 2) / this.scale, y: this.cy - (py - this.canvas.height / 2) / this.scale };
  }
}

/** drag, while a body is held: {from, to}, its grabbed point and the pointer (world). */
export function draw(ctx, camera, bodies, transforms, heldBody, drag) {
  const { canvas } = camera;
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.fillStyle = '#f8fafc';
  ctx.fillRect(0, 0, canvas.width, canvas.height);
  const s = camera.scale;
  ctx.lineWidth = 1 / s;
  for (const body of bodies) {
    const t = body.index * 4;
    const view = body.userData;
    // Body frame to screen: y up in the world, down on the canvas.
    const c = transforms[t + 2];
    const sn = transforms[t + 3];
    ctx.setTransform(s * c, -s * sn, -s * sn, -s * c,
                     canvas.width / 2 + s * (transforms[t] - camera.cx),
                     canvas.height / 2 - s * (transforms[t + 1] - camera.cy));
    ctx.fillStyle = body === heldBody ? COLORS.held : view.asleep ? COLORS.asleep : COLORS[view.type];
    ctx.strokeStyle = '#1f2937';
    for (const g of view.geometries) drawGeometry(ctx, g);
  }
  if (drag) {
    // The drag joint's spring, from the grabbed point to the pointer.
    ctx.setTransform(s, 0, 0, -s, canvas.width / 2 - s * camera.cx, canvas.height / 2 + s * camera.cy);
    ctx.strokeStyle = COLORS.held;
    ctx.lineWidth = 2 / s;
    ctx.beginPath();
    ctx.moveTo(drag.from.x, drag.from.y);
    ctx.lineTo(drag.to.x, drag.to.y);
    ctx.stroke();
  }
  ctx.setTransform(1, 0, 0, 1, 0, 0);
}

function drawGeometry(ctx, g) {
  ctx.beginPath();
  if (g.type === 'circle') {
    ctx.arc(g.center.x, g.center.y, g.radius, 0, 2 * Math.PI);
    ctx.moveTo(g.center.x, g.center.y);
    ctx.lineTo(g.center.x + g.radius, g.center.y);
  } else if (g.type === 'polygon') {
    g.vertices.forEach((v, i) => (i === 0 ? ctx.moveTo(v.x, v.y) : ctx.lineTo(v.x, v.y)));
    ctx.closePath();
  } else if (g.type === 'capsule') {
    const angle = Math.atan2(g.center2.y - g.center1.y, g.center2.x - g.center1.x);
    ctx.arc(g.center2.x, g.center2.y, g.radius, angle - Math.PI / 2, angle + Math.PI / 2);
    ctx.arc(g.center1.x, g.center1.y, g.radius, angle + Math.PI / 2, angle + 1.5 * Math.PI);
    ctx.closePath();
  } else {
    ctx.moveTo(g.point1.x, g.point1.y);
    ctx.lineTo(g.point2.x, g.point2.y);
  }
  if (g.type !== 'segment') ctx.fill();
  ctx.stroke();
}
