// SPDX-License-Identifier: MIT
// i2d_debug_draw (include/impulse2d/toolkit.h) as the binding crosses it: each callback
// with the drawer method it reaches and its type in the wasm ABI, and each flag with the
// option that sets it. layout.js checks the module has these fields; debug_draw.js fills them.

/**
 * [C field, drawer method, wasm signature]. In the wasm C ABI a struct passed by value
 * (i2d_vec2, i2d_transform) arrives as a pointer to a copy, i2d_color as an i32, and the
 * last argument is always the context pointer.
 */
export const DRAW_CALLBACKS = [
  ['draw_polygon', 'drawPolygon', 'viiii'],             // vertices*, count, color, context
  ['draw_solid_polygon', 'drawSolidPolygon', 'viiifii'],  // transform*, vertices*, count, radius, color, context
  ['draw_circle', 'drawCircle', 'vifii'],               // center*, radius, color, context
  ['draw_solid_circle', 'drawSolidCircle', 'vifii'],    // transform*, radius, color, context
  ['draw_solid_capsule', 'drawSolidCapsule', 'viifii'], // p1*, p2*, radius, color, context
  ['draw_segment', 'drawSegment', 'viiii'],             // p1*, p2*, color, context
  ['draw_transform', 'drawTransform', 'vii'],           // transform*, context
  ['draw_point', 'drawPoint', 'vifii'],                 // p*, size, color, context
  ['draw_string', 'drawString', 'viiii'],               // p*, text*, color, context
];

export const DRAW_CALLBACK_FIELDS = DRAW_CALLBACKS.map(([field]) => field);

/** World.draw's flag options and the i2d_debug_draw fields they set. */
export const DRAW_FLAGS = {
  drawShapes: 'draw_shapes',
  drawJoints: 'draw_joints',
  drawJointExtras: 'draw_joint_extras',
  drawBounds: 'draw_bounds',
  drawMass: 'draw_mass',
  drawContacts: 'draw_contacts',
  drawContactNormals: 'draw_contact_normals',
  drawContactImpulses: 'draw_contact_impulses',
  drawFrictionImpulses: 'draw_friction_impulses',
  drawGraphColors: 'draw_graph_colors',
  drawIslands: 'draw_islands',
};

export const DRAW_FLAG_FIELDS = Object.values(DRAW_FLAGS);
