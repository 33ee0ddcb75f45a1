// SPDX-License-Identifier: MIT
// The colours World.draw hands to a drawer, as include/impulse2d/toolkit.h defines them
// (0xRRGGBB numbers; the node tests compare every one with the header), and turning one
// into a CSS colour for a canvas.

/** I2D_COLOR_* by name: a shape's colour says its body's state; the rest mark joints,
 *  bounds, mass and contacts. */
export const DRAW_COLORS = Object.freeze({
  quarantined: 0xFF3333,    // a body the step quarantined (non-finite state)
  disabled: 0x666666,
  sensor: 0x33CCFF,
  static: 0x80E680,
  kinematic: 0x8080E6,
  bullet: 0xE6E64D,         // awake
  awake: 0xE6B380,          // dynamic
  asleep: 0x999999,
  joint: 0x7FB89A,
  jointAnchor: 0x2E8B57,
  jointLimit: 0xE05050,
  jointMotor: 0xB050E0,
  jointSpring: 0x50A0E0,
  bounds: 0xFFD700,
  island: 0xFF4500,
  mass: 0xF5F5F5,
  contact: 0x3366FF,        // a point within the contact slop
  speculative: 0xC8C8C8,    // a point farther apart
  contactNormal: 0x696969,
  contactImpulse: 0xFF00FF,
  frictionImpulse: 0xFFFF00,
  graphOverflow: 0xFFFFFF,
});

/** I2D_GRAPH_COLORS: the solver's constraint colour k is drawn as GRAPH_COLORS[k % 12]. */
export const GRAPH_COLORS = Object.freeze([
  0xFF0000, 0xFF8000, 0xFFFF00, 0x80FF00, 0x00FF00, 0x00FF80, 0x00FFFF, 0x0080FF, 0x0000FF, 0x8000FF, 0xFF00FF,
  0xFF0080,
]);

/** 0xRRGGBB as '#rrggbb', or as 'rgba(r, g, b, alpha)' when alpha is below 1. */
export function colorToCss(color, alpha = 1) {
  const rgb = color & 0xFFFFFF;
  if (alpha >= 1) return `#${rgb.toString(16).padStart(6, '0')}`;
  return `rgba(${rgb >> 16}, ${(rgb >> 8) & 0xFF}, ${rgb & 0xFF}, ${alpha})`;
}
