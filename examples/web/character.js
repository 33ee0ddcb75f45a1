// SPDX-License-Identifier: MIT
// The platformer's character: not a body in the world but a capsule moved by game code,
// as a game moves one (docs/character_mover.md). Each frame the keys set the level speed,
// the game adds gravity while airborne and the jump, adds the ground's velocity to ride
// moving platforms, and World.moveCharacter slides the capsule along what it meets,
// climbs small steps and pushes crates.
//
// One-way platforms: the world's pre-solve hook lets bodies up through them, but a move
// is a query of the world, not a contact, so the hook never sees the character. The game
// makes the same decision itself: while the character rises, or its feet are below a
// platform's top, that platform's category is left out of the move's filter, so the move
// does not see it.

/** m/s: level walking speed. */
export const WALK_SPEED = 4;
/** m/s: a jump rises JUMP_SPEED^2 / (2 GRAVITY) = 3.2 m, above a 2.5 m platform. */
export const JUMP_SPEED = 8;
/** m/s^2: the game's gravity, the world's (0, -10). */
const GRAVITY = 10;
/** 1.8 m tall, 0.6 m wide, its origin at the feet. */
export const CAPSULE = { center1: { x: 0, y: 0.3 }, center2: { x: 0, y: 1.5 }, radius: 0.3 };
const COLOR = 0xFF7043;
const EYE_COLOR = 0x1B1E24;
const EYE_PIXELS = 5;
const EVERY_CATEGORY = (1n << 64n) - 1n;
const ZERO = Object.freeze({ x: 0, y: 0 });

export class Character {
  /** oneWays: [{category (a BigInt bit), top (m)}], the one-way platforms. */
  constructor(world, position, oneWays) {
    this.world = world;
    this.oneWays = oneWays;
    this.position = position;
    this.velocity = ZERO;
    this.onGround = false;
    this.groundShape = null;
    this.groundVelocity = ZERO;
    /** Whether the jump key was held last frame: a jump takes a fresh press. */
    this.jumpHeld = false;
    this.facing = 1;
  }

  /** One frame: actions {left, right, jump} from the keys. */
  update(actions, timeStep) {
    const input = (actions.right ? 1 : 0) - (actions.left ? 1 : 0);
    if (input !== 0) this.facing = input;
    const jump = actions.jump && !this.jumpHeld;
    this.jumpHeld = actions.jump;
    const vx = WALK_SPEED * input;
    const vy = this.onGround ? (jump ? JUMP_SPEED : 0) : this.velocity.y - GRAVITY * timeStep;
    const r = this.world.moveCharacter({
      capsule: CAPSULE, position: this.position, timeStep, filter: this.filterFor(vy),
      velocity: { x: vx + this.groundVelocity.x, y: vy + this.groundVelocity.y },
    });
    this.position = r.position;
    // The walk comes from the keys each frame; the vertical speed is what the ground or a
    // ceiling left of it.
    this.velocity = { x: vx, y: r.velocity.y };
    this.onGround = r.onGround;
    this.groundShape = r.groundShape;
    this.groundVelocity = r.onGround ? r.groundVelocity : ZERO;
  }

  /** The move's filter: every category but the one-way platforms it must pass through. */
  filterFor(vy) {
    let mask = EVERY_CATEGORY;
    for (const { category, top } of this.oneWays) {
      if (vy > 0 || this.position.y < top) mask &= ~category;
    }
    return { maskBits: mask };
  }

  /** What the rewind keeps per frame: the world's state does not hold the character. */
  save() {
    const { position, velocity, onGround, groundShape, groundVelocity, jumpHeld, facing } = this;
    return { position, velocity, onGround, groundShape, groundVelocity, jumpHeld, facing };
  }

  restore(saved) { Object.assign(this, saved); }

  /** Drawn with the world's drawer methods, as the world's shapes are. */
  draw(drawer) {
    const { x, y } = this.position;
    const at = (p) => ({ x: x + p.x, y: y + p.y });
    drawer.drawSolidCapsule(at(CAPSULE.center1), at(CAPSULE.center2), CAPSULE.radius, COLOR);
    drawer.drawPoint({ x: x + 0.15 * this.facing, y: y + 1.5 }, EYE_PIXELS, EYE_COLOR);
  }
}
