// SPDX-License-Identifier: MIT
// The explosion scene: a pile of boxes and discs in a closed room, blown apart by
// World.explode where the canvas is clicked (off any body) or, with the Blast button,
// under the middle of the pile. The blast's reach is drawn for a moment as two circles.

const ROOM = { halfWidth: 14, height: 16, wall: 0.5 };
const PILE_ROWS = 10;
const PIECE_HALF = 0.35;
/** Full strength within 2 m, fading to nothing 3 m further; 6 N s per metre of outline
 *  facing it gives a 0.7 m box (0.49 kg) about 8.6 m/s at full strength. */
export const BLAST = { radius: 2, falloff: 3, impulsePerLength: 6 };
const BLAST_AT = { x: 0, y: 0.5 };
const BLAST_COLOR = 0xFF4500;
const BLAST_SHOWN_STEPS = 20;

export function explosionScene(world) {
  room(world);
  pile(world);
  let last = null;  // the last blast: {at, shown: frames it is still drawn}
  const scene = {
    view: { x: 0, y: ROOM.height / 2 - 0.5, height: ROOM.height + 2 },
    room: ROOM,
    blasts: 0,
    /** The Blast button: under the middle of the pile. */
    action: { label: 'Blast', run: () => scene.click(BLAST_AT) },
    /** A click off every body blasts there. */
    click(at) {
      world.explode({ position: at, ...BLAST });
      scene.blasts++;
      last = { at, shown: BLAST_SHOWN_STEPS };
    },
    update() { if (last !== null && --last.shown <= 0) last = null; },
    drawExtras(drawer) {
      if (last === null) return;
      drawer.drawCircle(last.at, BLAST.radius, BLAST_COLOR);
      drawer.drawCircle(last.at, BLAST.radius + BLAST.falloff, BLAST_COLOR);
    },
  };
  return scene;
}

/** Floor, walls and ceiling: nothing the blast throws can leave. */
function room(world) {
  const { halfWidth, height, wall } = ROOM;
  const body = world.createBody();
  body.createOffsetBox(halfWidth + wall, wall / 2, [0, -wall / 2]);
  body.createOffsetBox(halfWidth + wall, wall / 2, [0, height + wall / 2]);
  for (const side of [-1, 1]) body.createOffsetBox(wall / 2, height / 2, [side * (halfWidth + wall / 2), height / 2]);
}

/** A pyramid of boxes with a disc at every third place. */
function pile(world) {
  const size = 2 * PIECE_HALF;
  for (let row = 0; row < PILE_ROWS; row++) {
    for (let i = 0; i < PILE_ROWS - row; i++) {
      const x = (i - (PILE_ROWS - row - 1) / 2) * size;
      const body = world.createBody({ type: 'dynamic', position: [x, PIECE_HALF + row * size] });
      if ((row + i) % 3 === 2) body.createCircle(PIECE_HALF);
      else body.createBox(PIECE_HALF, PIECE_HALF);
    }
  }
}

/** What the browser test reads back: the blasts and how the pieces move. */
export function explosionState(world, scene) {
  const { halfWidth, height } = scene.room;
  let fast = 0;
  let escaped = 0;
  for (const body of world.bodies) {
    if (body.type !== 'dynamic') continue;
    const v = body.linearVelocity, p = body.position;
    if (Math.hypot(v.x, v.y) > 2) fast++;
    if (Math.abs(p.x) > halfWidth || p.y < 0 || p.y > height) escaped++;
  }
  return { blasts: scene.blasts, fast, escaped };
}
