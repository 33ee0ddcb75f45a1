// SPDX-License-Identifier: MIT
// The page's scenes. Each builds its bodies in a fresh world and says how to judge a
// run: check(world, start) returns the figures the browser test reads back.

const DEG = Math.PI / 180;

/** Rows of 1 m boxes on a ground box, as the benchmark's large_pyramid but smaller. */
function pyramid(world, rows = 20) {
  const ground = world.createBody({ position: [0, -1] });
  ground.createBox(40, 1);
  let top = null;
  for (let i = 0; i < rows; i++) {
    for (let j = i; j < rows; j++) {
      const x = -rows / 2 + 0.5 * (i + 1) + (j - i);
      top = world.createBody({ type: 'dynamic', position: [x, i + 0.5] });
      top.createBox(0.5, 0.5);
    }
  }
  return { view: { x: 0, y: rows / 2, height: rows + 6 }, top, topStartY: top.position.y };
}

/** Boxes, circles, capsules and triangles dropped in a walled bin. */
function mixedShapes(world, count = 240) {
  const ground = world.createBody();
  ground.createOffsetBox(15, 0.5, [0, -0.5]);
  ground.createOffsetBox(0.5, 10, [-15.5, 9.5]);
  ground.createOffsetBox(0.5, 10, [15.5, 9.5]);
  ground.createOffsetBox(4, 0.25, [-6, 6], -20 * DEG);
  ground.createOffsetBox(4, 0.25, [6, 9], 20 * DEG);
  for (let i = 0; i < count; i++) {
    const x = -12 + (i % 24) * 1.05 + 0.2 * ((i * 7) % 3);
    const y = 14 + Math.floor(i / 24) * 1.2;
    const body = world.createBody({ type: 'dynamic', position: [x, y], angle: (i % 11) * 0.3 });
    switch (i % 4) {
      case 0: body.createBox(0.4, 0.3); break;
      case 1: body.createCircle(0.4, { restitution: 0.2 }); break;
      case 2: body.createCapsule([-0.3, 0], [0.3, 0], 0.2); break;
      default: body.createPolygon([[-0.45, -0.35], [0.45, -0.35], [0, 0.45]]); break;
    }
  }
  return { view: { x: 0, y: 10, height: 24 }, floorY: -1 };
}

/** A 20 m hollow drum turning at 25 deg/s (kinematic: joints are not there yet) with small boxes. */
function tumbler(world, side = 30) {
  const drum = world.createBody({ type: 'kinematic', position: [0, 10], angularVelocity: 25 * DEG });
  drum.createOffsetBox(0.5, 10, [10, 0]);
  drum.createOffsetBox(0.5, 10, [-10, 0]);
  drum.createOffsetBox(10, 0.5, [0, 10]);
  drum.createOffsetBox(10, 0.5, [0, -10]);
  for (let i = 0; i < side; i++) {
    for (let j = 0; j < side; j++) {
      world.createBody({ type: 'dynamic', position: [-7 + 0.5 * j, 3 + 0.5 * i] }).createBox(0.125, 0.125);
    }
  }
  return { view: { x: 0, y: 10, height: 32 }, drum, center: { x: 0, y: 10 }, radius: 15 };
}

export const SCENES = {
  pyramid: {
    title: 'Pyramid (20 rows, 210 boxes)',
    build: (world) => pyramid(world),
    worldOptions: { enableSleep: false },
    check: (world, scene) => ({ topDrop: scene.topStartY - scene.top.position.y }),
  },
  mixed: {
    title: 'Falling mixed shapes (240)',
    build: (world) => mixedShapes(world),
    worldOptions: {},
    check: (world, scene) => ({
      below: world.bodies.filter((b) => b.type === 'dynamic' && b.position.y < scene.floorY).length,
    }),
  },
  tumbler: {
    title: 'Tumbler (900 boxes, kinematic drum)',
    build: (world) => tumbler(world),
    worldOptions: {},
    check: (world, scene) => ({
      escaped: world.bodies.filter((b) => {
        const p = b.position;
        return b.type === 'dynamic' && Math.hypot(p.x - scene.center.x, p.y - scene.center.y) > scene.radius;
      }).length,
      drumAngle: scene.drum.angle,
    }),
  },
};
