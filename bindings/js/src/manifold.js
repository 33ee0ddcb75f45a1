// SPDX-License-Identifier: MIT
// An i2d_manifold in the module's memory as {normal, points: [{point, penetration, id}]}:
// how contact data and the pre-solve hook show one.

export function readManifold(rt, at) {
  const pointCount = rt.i32[(at + rt.field('i2d_manifold.point_count')) >> 2];
  const first = at + rt.field('i2d_manifold.points');
  const stride = rt.size('i2d_manifold_point');
  const points = [];
  for (let j = 0; j < pointCount; j++) {
    const p = first + j * stride;
    points.push({
      point: rt.readVec2(p + rt.field('i2d_manifold_point.point')),
      penetration: rt.f32[(p + rt.field('i2d_manifold_point.penetration')) >> 2],
      id: rt.u32[(p + rt.field('i2d_manifold_point.id')) >> 2],
    });
  }
  return { normal: rt.readVec2(at + rt.field('i2d_manifold.normal')), points };
}
