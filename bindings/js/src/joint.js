// SPDX-License-Identifier: MIT
// Joints: a thin handle over an i2d_joint_id, one class per kind, and their creation.
// Every setting of a kind's def is a property of its class, read and written through the
// library's getter and setter of that field (so a setter is checked as creation checks it,
// and wakes both bodies); the properties are made from the table in joint_kinds.js.
import { BASE_SETTINGS, FLAG, FLOAT, JOINT_KIND_NAMES, KIND_SETTINGS, POINT, camelCase } from './joint_kinds.js';
import { vx, vy } from './vectors.js';

/** Writes a value of each crossing into a def at address `at`. */
const WRITE_IN_DEF = {
  [FLOAT]: (rt, at, value) => { rt.f32[at >> 2] = value; },
  [FLAG]: (rt, at, value) => { rt.u8[at] = value ? 1 : 0; },
  [POINT]: (rt, at, value) => {
    rt.f32[at >> 2] = vx(value);
    rt.f32[(at >> 2) + 1] = vy(value);
  },
};

/** Reads a setting through the library's getter `fn`. */
const READ = {
  [FLOAT]: (joint, fn) => joint.read(fn),
  [FLAG]: (joint, fn) => joint.read(fn) !== 0,
  [POINT]: (joint, fn) => joint.readVec2(fn),
};

/** Changes a setting through the library's setter `fn`. */
const WRITE = {
  [FLOAT]: (joint, fn, value) => joint.rt.check(joint.rt.m[fn](joint.id, value)),
  [FLAG]: (joint, fn, value) => joint.rt.check(joint.rt.m[fn](joint.id, value ? 1 : 0)),
  [POINT]: (joint, fn, value) => joint.rt.check(joint.rt.m[fn](joint.id, joint.rt.vec2(0, vx(value), vy(value)))),
};

/** Gives cls a camelCase property per setting, over `_<prefix>get_<field>` and `_<prefix>set_<field>`. */
function defineSettings(cls, prefix, settings) {
  for (const [field, crossing] of Object.entries(settings)) {
    const getter = `_${prefix}get_${field}`;
    const setter = `_${prefix}set_${field}`;
    Object.defineProperty(cls.prototype, camelCase(field), {
      get() { return READ[crossing](this, getter); },
      set(value) { WRITE[crossing](this, setter, value); },
      configurable: true,
    });
  }
}

/** What every kind shares. Made by World's create<Kind>Joint methods. */
export class Joint {
  /** @internal */
  constructor(world, id, bodyA, bodyB) {
    this.world = world;
    this.id = id;
    this.bodyA = bodyA;
    this.bodyB = bodyB;
    /** Free for the caller's own use. */
    this.userData = undefined;
  }

  get rt() { return this.world.rt; }

  /** False once the joint, one of its bodies or its world was destroyed. */
  isValid() { return this.rt.m._i2d_joint_is_valid(this.id) !== 0; }

  /** 'revolute', 'prismatic', 'distance', 'weld', 'wheel', 'motor', 'mouse' or 'filter'. */
  get type() { return JOINT_KIND_NAMES[this.read('_i2d_joint_get_type')]; }

  /** The force the joint applied to body B in the last step, N (on A: its negative). */
  get reactionForce() { return this.readVec2('_i2d_joint_get_reaction_force'); }
  /** The torque the joint applied to body B in the last step, N m. */
  get reactionTorque() { return this.read('_i2d_joint_get_reaction_torque'); }

  wakeBodies() { this.rt.check(this.rt.m._i2d_joint_wake_bodies(this.id)); }

  /** Destroys the joint and wakes its bodies; they may collide again. */
  destroy() {
    this.rt.check(this.rt.m._i2d_joint_destroy(this.id));
    this.world.forgetJoint(this);
  }

  /** @internal A scalar getter: the library returns 0 and records why on a refusal. */
  read(fn) {
    const value = this.rt.m[fn](this.id);
    this.rt.checkLast();
    return value;
  }

  /** @internal An i2d_vec2 getter, whose result comes back through the scratch block. */
  readVec2(fn) {
    const rt = this.rt;
    rt.m[fn](rt.result(), this.id);
    rt.checkLast();
    return rt.readVec2(rt.result());
  }
}
defineSettings(Joint, 'i2d_joint_', BASE_SETTINGS);

/** A hinge: one shared point, free to turn. */
export class RevoluteJoint extends Joint {
  /** rad, of B relative to A minus the reference angle, in (-pi, pi]. */
  get angle() { return this.read('_i2d_revolute_joint_get_angle'); }
  /** The motor's torque in the last step, N m. */
  get motorTorque() { return this.read('_i2d_revolute_joint_get_motor_torque'); }
  /** Both angle limits at once (one at a time is refused when it would pass the other). */
  setLimits(lower, upper) { this.rt.check(this.rt.m._i2d_revolute_joint_set_limits(this.id, lower, upper)); }
}
defineSettings(RevoluteJoint, 'i2d_revolute_joint_', KIND_SETTINGS.revolute);

/** B slides along an axis fixed in A, without turning. */
export class PrismaticJoint extends Joint {
  /** m along the axis, of B's anchor from A's. */
  get translation() { return this.read('_i2d_prismatic_joint_get_translation'); }
  /** m/s along the axis. */
  get speed() { return this.read('_i2d_prismatic_joint_get_speed'); }
  /** The motor's force in the last step, N. */
  get motorForce() { return this.read('_i2d_prismatic_joint_get_motor_force'); }
  setLimits(lower, upper) { this.rt.check(this.rt.m._i2d_prismatic_joint_set_limits(this.id, lower, upper)); }
}
defineSettings(PrismaticJoint, 'i2d_prismatic_joint_', KIND_SETTINGS.prismatic);

/** Keeps two points `length` apart, springy, or within [minLength, maxLength] (a rope). */
export class DistanceJoint extends Joint {
  /** m, between the two anchors now. */
  get currentLength() { return this.read('_i2d_distance_joint_get_current_length'); }
  /** The motor's force in the last step, N. */
  get motorForce() { return this.read('_i2d_distance_joint_get_motor_force'); }
  setLengthRange(minLength, maxLength) {
    this.rt.check(this.rt.m._i2d_distance_joint_set_length_range(this.id, minLength, maxLength));
  }
}
defineSettings(DistanceJoint, 'i2d_distance_joint_', KIND_SETTINGS.distance);

/** Holds B's pose in A's frame, rigid (0 Hz) or springy. */
export class WeldJoint extends Joint {}
defineSettings(WeldJoint, 'i2d_weld_joint_', KIND_SETTINGS.weld);

/** A vehicle's wheel: B on a sprung axis of A, free to turn, a motor on the turning. */
export class WheelJoint extends Joint {
  /** m along the axis: the suspension's travel. */
  get translation() { return this.read('_i2d_wheel_joint_get_translation'); }
  /** The motor's torque in the last step, N m. */
  get motorTorque() { return this.read('_i2d_wheel_joint_get_motor_torque'); }
  setLimits(lower, upper) { this.rt.check(this.rt.m._i2d_wheel_joint_set_limits(this.id, lower, upper)); }
}
defineSettings(WheelJoint, 'i2d_wheel_joint_', KIND_SETTINGS.wheel);

/** Drives B toward an offset pose in A's frame with at most maxForce and maxTorque. */
export class MotorJoint extends Joint {}
defineSettings(MotorJoint, 'i2d_motor_joint_', KIND_SETTINGS.motor);

/** Pulls B's anchor (localAnchorB) toward a world target with a damped spring: dragging. */
export class MouseJoint extends Joint {}
defineSettings(MouseJoint, 'i2d_mouse_joint_', KIND_SETTINGS.mouse);

/** No constraint: only keeps its two bodies from colliding. */
export class FilterJoint extends Joint {}

const JOINT_CLASSES = {
  distance: DistanceJoint, filter: FilterJoint, motor: MotorJoint, mouse: MouseJoint,
  prismatic: PrismaticJoint, revolute: RevoluteJoint, weld: WeldJoint, wheel: WheelJoint,
};

/**
 * World.create<Kind>Joint's work: the kind's default def with `options` written in (named
 * as the properties are), then i2d_joint_create_<kind>. The library checks the bodies and
 * every value; an option name it does not have is a TypeError, as in the Python binding,
 * since a misspelt setting would otherwise be silently left at its default.
 */
export function createJoint(world, kind, bodyA, bodyB, options = {}) {
  const rt = world.rt;
  const settings = KIND_SETTINGS[kind];
  const fieldByName = new Map([...Object.keys(BASE_SETTINGS), ...Object.keys(settings)].map((f) => [camelCase(f), f]));
  for (const name of Object.keys(options)) {
    if (!fieldByName.has(name)) {
      throw new TypeError(`a ${kind} joint has no setting '${name}'; known: ${[...fieldByName.keys()].join(', ')}`);
    }
  }
  const defType = `i2d_${kind}_joint_def`;
  const def = rt.defBlock(`${kind}_joint`);
  try {
    const base = def + rt.field(`${defType}.base`);
    // Anything but a Body leaves the id null, which the library refuses naming the field.
    rt.u64[(base + rt.field('i2d_joint_base.body_a')) >> 3] = bodyA?.id ?? 0n;
    rt.u64[(base + rt.field('i2d_joint_base.body_b')) >> 3] = bodyB?.id ?? 0n;
    for (const [name, value] of Object.entries(options)) {
      if (value === undefined) continue;
      const field = fieldByName.get(name);
      const inBase = field in BASE_SETTINGS;
      const at = inBase ? base + rt.field(`i2d_joint_base.${field}`) : def + rt.field(`${defType}.${field}`);
      WRITE_IN_DEF[inBase ? BASE_SETTINGS[field] : settings[field]](rt, at, value);
    }
    const id = rt.checkId(rt.m[`_i2d_joint_create_${kind}`](world.id, def));
    return new JOINT_CLASSES[kind](world, id, bodyA, bodyB);
  } finally {
    rt.m._free(def);
  }
}
