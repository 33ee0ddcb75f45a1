// SPDX-License-Identifier: MIT
// The benchmark's scenes, built through an engine adapter (engines.mjs). Each returns
// its per-step hook (or null) and a sanity figure read after the run.

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

export const SCENES = [largePyramid, rainOfCircles, smallScene];
