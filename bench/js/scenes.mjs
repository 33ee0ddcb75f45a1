// SPDX-License-Identifier: MIT
// The benchmark's scenes, built through an engine adapter (engines.mjs). Each returns
// its per-step hook (or null) and a sanity figure read after the run (given the steps run).

/** 100 rows of 1 m boxes on a ground box (scenes.md's large_pyramid), sleeping off. */
export const largePyramid = {
  name: 'large_pyramid',
  bodies: 5050,
  sleep: false,
  build(w) {
    w.staticBox(0, -1, 100, 1);
    let top = null;
    for (let i = 0; i < 100; i++) {
      for (let j = i; j < 100; j++) top = w.box(-50 + 0.5 * (i + 1) + (j - i), i + 0.5, 0.5, 0.5);
    }
    return {
      hook: null,
      sanity: () => `top sank ${(99.5 - w.position(top).y).toFixed(2)} m`,
    };
  },
};

/** Circles of 0.25 m raining into a 40 m bin: a row of 20 every 4th step, sleeping on. */
export const rainOfCircles = {
  name: 'rain_of_circles',
  bodies: 'up to 2 500',
  sleep: true,
  build(w) {
    w.staticBox(0, -0.5, 20, 0.5);
    w.staticBox(-20.5, 20, 0.5, 20.5);
    w.staticBox(20.5, 20, 0.5, 20.5);
    const circles = [];
    return {
      hook(step) {
        if (step % 4 !== 0) return;
        const shift = 0.3 * ((step / 4) % 5);
        for (let i = 0; i < 20; i++) circles.push(w.circle(-19.5 + 2 * i + shift, 35, 0.25));
      },
      sanity: () => {
        const lost = circles.filter((c) => {
          const p = w.position(c);
          return p.y < 0.2 || Math.abs(p.x) > 20;
        }).length;
        return `${circles.length} circles, ${lost} lost`;
      },
    };
  },
};

/** 50 boxes and circles dropped in a closed 10 m room, sleeping off: per-step overhead. */
export const smallScene = {
  name: 'small_50',
  bodies: 50,
  sleep: false,
  build(w) {
    w.staticBox(0, -0.5, 6, 0.5);
    w.staticBox(0, 10.5, 6, 0.5);
    w.staticBox(-5.5, 5, 0.5, 5);
    w.staticBox(5.5, 5, 0.5, 5);
    const bodies = [];
    for (let i = 0; i < 50; i++) {
      const x = -4 + (i % 10) * 0.9;
      const y = 1 + Math.floor(i / 10) * 1.1;
      bodies.push(i % 2 ? w.circle(x, y, 0.35) : w.box(x, y, 0.35, 0.35));
    }
    return {
      hook: null,
      sanity: () => {
        const out = bodies.filter((b) => {
          const p = w.position(b);
          return Math.abs(p.x) > 5 || p.y < 0 || p.y > 10;
        }).length;
        return `${out} outside the room`;
      },
    };
  },
};

// The tumbler as Box2D's benchmark and bench/scenes.c define it: the drum's sizes, density
// and motor; 45 x 45 boxes of 0.25 m.
const TUMBLER_CENTER = { x: 0, y: 10 };
const TUMBLER_SPEED = 25 * Math.PI / 180;   // rad/s, counter-clockwise
const TUMBLER_INNER_HALF = 9.5;              // m: walls centred at +-10, 1 m thick
const TUMBLER_GRID = 45;

/**
 * A 20 x 20 hollow drum of four 1 m thick boxes (density 50) turned at 25 deg/s about
 * (0, 10) by a revolute joint's motor of max torque 1e8 N m, 2025 boxes of 0.25 m inside,
 * sleeping on (scenes.md's tumbler). An engine without joint motors (matter-js) turns a
 * static drum itself at the same speed; its sanity figure says so.
 */
export const tumbler = {
  name: 'tumbler',
  bodies: TUMBLER_GRID * TUMBLER_GRID,
  sleep: true,
  build(w) {
    const drum = w.motorDrum({
      center: TUMBLER_CENTER,
      walls: [
        { x: 10, y: 0, hw: 0.5, hh: 10 }, { x: -10, y: 0, hw: 0.5, hh: 10 },
        { x: 0, y: 10, hw: 10, hh: 0.5 }, { x: 0, y: -10, hw: 10, hh: 0.5 },
      ],
      density: 50,
      speed: TUMBLER_SPEED,
      maxTorque: 1e8,
    });
    const boxes = [];
    for (let i = 0; i < TUMBLER_GRID; i++) {
      for (let j = 0; j < TUMBLER_GRID; j++) boxes.push(w.box(-9 + 0.4 * j, 1 + 0.4 * i, 0.125, 0.125));
    }
    return {
      hook: null,
      // As bench/scenes.c judges it: boxes inside the drum's hollow (in the drum's frame),
      // the drum's angle against 25 deg/s, its centre against the pivot.
      sanity: (steps) => {
        const angle = w.angle(drum.body);
        const c = Math.cos(angle);
        const s = Math.sin(angle);
        const centre = w.position(drum.body);
        const inside = boxes.filter((box) => {
          const p = w.position(box);
          const dx = p.x - centre.x;
          const dy = p.y - centre.y;
          return Math.abs(c * dx + s * dy) <= TUMBLER_INNER_HALF && Math.abs(-s * dx + c * dy) <= TUMBLER_INNER_HALF;
        }).length;
        const expected = TUMBLER_SPEED * steps / 60;
        const error = Math.atan2(Math.sin(angle - expected), Math.cos(angle - expected)) * 180 / Math.PI;
        const drift = Math.hypot(centre.x - TUMBLER_CENTER.x, centre.y - TUMBLER_CENTER.y);
        return `${inside} of ${boxes.length} inside, drum ${error.toFixed(3)} deg off, centre ${drift.toFixed(4)} m off; ` +
               `drum: ${drum.drive}`;
      },
    };
  },
};

export const SCENES = [largePyramid, rainOfCircles, smallScene, tumbler];
