// SPDX-License-Identifier: MIT
// A frame of the page: the camera's view of a world, drawn only through World.draw into
// the canvas backend (draw_canvas.js), then the game's own pictures through the same
// drawer methods.

export class Camera {
  constructor(canvas) { this.canvas = canvas; this.setView({ x: 0, y: 10, height: 30 }); }
  setView(view) { this.cx = view.x; this.cy = view.y; this.height = view.height; }
  /** Pixels per metre. */
  get scale() { return this.canvas.height / this.height; }
  toWorld(px, py) {
    return { x: this.cx + (px - this.canvas.width / 2) / this.scale, y: this.cy - (py - this.canvas.height / 2) / this.scale };
  }
  toScreen(x, y) {
    return { x: this.canvas.width / 2 + this.scale * (x - this.cx), y: this.canvas.height / 2 - this.scale * (y - this.cy) };
  }
  /** The part of the world on the canvas, as World.draw's drawingBounds. */
  visibleBounds() {
    const halfWidth = this.canvas.width / (2 * this.scale), halfHeight = this.height / 2;
    return { minX: this.cx - halfWidth, minY: this.cy - halfHeight, maxX: this.cx + halfWidth, maxY: this.cy + halfHeight };
  }
}

/**
 * Draws the world with the flags the page's toggles set (drawFlags, World.draw's
 * options), culled to the view, then extras(drawer) for what is not in the world.
 */
export function drawFrame(drawer, world, drawFlags, extras) {
  drawer.begin();
  world.draw(drawer, { ...drawFlags, drawingBounds: drawer.camera.visibleBounds() });
  extras(drawer);
}
