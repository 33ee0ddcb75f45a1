// SPDX-License-Identifier: MIT
// TypeScript declarations for the impulse2d WebAssembly package.

/** A point or vector: {x, y} or [x, y]. Units are metres; y points up. */
export type Vec2Like = { x: number; y: number } | readonly [number, number];
export interface Vec2 { x: number; y: number; }
export interface Transform { x: number; y: number; c: number; s: number; }
export interface AABB { minX: number; minY: number; maxX: number; maxY: number; }

export type BodyType = 'static' | 'kinematic' | 'dynamic';
export type ShapeType = 'circle' | 'capsule' | 'segment' | 'polygon';
export type JointType = 'distance' | 'filter' | 'motor' | 'mouse' | 'prismatic' | 'revolute' | 'weld' | 'wheel';
export type StatusName =
  | 'I2D_ERR_INVALID_ARGUMENT' | 'I2D_ERR_INVALID_HANDLE' | 'I2D_ERR_WORLD_LOCKED'
  | 'I2D_ERR_CAPACITY' | 'I2D_ERR_OUT_OF_MEMORY' | 'I2D_ERR_INTERNAL' | 'I2D_ERR_INVALID_SNAPSHOT';

/** Thrown for every call the library refuses; message is i2d_last_error_message(). */
export class Impulse2dError extends Error {
  readonly status: StatusName;
  readonly code: number;
}

export interface WorldOptions {
  gravity?: Vec2Like;              // default (0, -10)
  contactHertz?: number;           // default 60
  restitutionThreshold?: number;   // default 1 m/s
  enableSleep?: boolean;           // default true
  /** The world's length unit, per metre ([1e-3, 1e4], default 1): lengths and speeds of
   *  every call on the world are in it, and the other defaults are scaled to it
   *  (i2d_default_world_def_in_units). */
  lengthUnitsPerMeter?: number;
  /** The contact kernels (default 'automatic': 'wasm128' in the SIMD build, else
   *  'scalar'); every path gives the same bits. One the build lacks is refused. */
  simdPath?: SimdPathName | number;
  /** Workers stepping the world (default 1). Above 1 only in the threads build, whose
   *  Impulse2d.threads workers all worlds share; such a world cannot have JavaScript
   *  hooks. Same bits at every count. */
  workerCount?: number;
}

/** i2d_simd_path's names, in its order. */
export type SimdPathName = 'automatic' | 'scalar' | 'sse2' | 'avx2' | 'avx512' | 'neon' | 'wasm128';
export const SIMD_PATH_NAMES: readonly SimdPathName[];

/** A world's settings (i2d_world_def), lengths in its units. */
export interface WorldSettings {
  gravity: Vec2;
  contactSlop: number;
  contactHertz: number;
  contactDampingRatio: number;
  contactPushMaxSpeed: number;
  restitutionThreshold: number;
  maximumLinearSpeed: number;
  enableSleep: boolean;
  sleepSpeedThreshold: number;
  timeToSleep: number;
  enableContactRecycling: boolean;
  jointHertz: number;
  jointDampingRatio: number;
  enableContinuous: boolean;
  enableImpactChains: boolean;
  hitEventThreshold: number;
  lengthUnitsPerMeter: number;
  simdPath: SimdPathName;
}

/** kg, centre of mass in the body frame, kg m^2 about it. */
export interface MassData { mass: number; center: Vec2; rotationalInertia: number; }
export interface MassDataLike { mass: number; center?: Vec2Like; rotationalInertia: number; }

export interface SurfaceMaterial {
  friction: number;
  restitution: number;
  rollingResistance: number;
  tangentSpeed: number;            // m/s
}

/** A touching contact as the last step left it (i2d_contact_data): normal from A to B,
 *  impulses (N s) of the step's last substep at each point. */
export interface ContactData {
  shapeA: Shape | bigint;
  shapeB: Shape | bigint;
  normal: Vec2;
  points: { point: Vec2; penetration: number; id: number; normalImpulse: number; tangentImpulse: number }[];
}

/** A contact's manifold as the pre-solve hook sees it (i2d_manifold): unit normal from A
 *  to B and the touching points, one or two. */
export interface Manifold {
  normal: Vec2;
  points: { point: Vec2; penetration: number; id: number }[];
}

/** World.setCustomFilter's hook: false and the two shapes never touch. Shapes the package
 *  did not make come as ids. */
export type CustomFilterFn = (shapeA: Shape | bigint, shapeB: Shape | bigint) => boolean;
/** World.setPreSolve's hook: false and the contact is off for this step. */
export type PreSolveFn = (shapeA: Shape | bigint, shapeB: Shape | bigint, manifold: Manifold) => boolean;

/** A blast (i2d_explosion_def); a setting it does not have is a TypeError. */
export interface ExplosionOptions {
  position: Vec2Like;
  radius?: number;                 // full strength within it; default 1, in [0, 1e6]
  falloff?: number;                // fading linearly to nothing beyond the radius; default 0
  impulsePerLength?: number;       // N s per length of outline facing the blast; default 1; negative pulls
  maskBits?: number | bigint;      // categories pushed; default every bit
}

/** Category and mask bits (64 wide: a number up to 2^53, or a BigInt). A query, or a
 *  character move, sees a shape when its maskBits meet the shape's category and the
 *  shape's mask meets its categoryBits. */
export interface QueryFilter { categoryBits?: number | bigint; maskBits?: number | bigint; }
/** A shape's collision filter (i2d_filter): defaults category 1, every mask bit, group 0. */
export interface ShapeFilter extends QueryFilter { groupIndex?: number; }

/** A capsule: every point within radius of the segment center1-center2. */
export interface Capsule { center1: Vec2Like; center2: Vec2Like; radius: number; }

/** How World.moveCharacter moves a character (i2d_character_def); left out, the default. */
export interface CharacterSettings {
  maxSlopeAngle?: number;          // rad in [0, pi/2); default pi/4: steeper ground is a wall
  stepHeight?: number;             // default 0.25: ledges up to this are stepped onto
  snapDistance?: number;           // default 0.2: keeps the feet on the ground going down
  skin?: number;                   // default 0.01, > 0: the gap kept to every surface
  maxIterations?: number;          // default 5, in [1, 64]: cast-and-slide rounds
  pushMass?: number;               // kg, default 80; 0 pushes nothing (the move is then a query)
  filter?: QueryFilter;            // default every shape
}
/** Impulse2d.defaultCharacterDef(): every setting, the filter's bits as BigInts. */
export interface CharacterDef extends Required<Omit<CharacterSettings, 'filter'>> {
  filter: { categoryBits: bigint; maskBits: bigint };
}
export interface MoveCharacterOptions extends CharacterSettings {
  /** In the character's frame: position places its origin. */
  capsule: Capsule;
  position: Vec2Like;
  velocity: Vec2Like;
  timeStep: number;                // s, in [0, 1000]
}
export interface CharacterResult {
  position: Vec2;
  /** The velocity asked for less what runs into walls and ceilings (and into the ground,
   *  its downward part); without groundVelocity. */
  velocity: Vec2;
  onGround: boolean;
  groundNormal: Vec2;              // zero when not on the ground
  groundShape: Shape | bigint | null;
  /** The ground's velocity at the feet: add it to the next move to ride a platform. */
  groundVelocity: Vec2;
  hitCount: number;
}

/** A plane the mover touches (i2d_collision_plane): normal from the shape toward the
 *  mover, offset its separation (negative when overlapping). Moved by d, the mover keeps
 *  clear while offset + dot(normal, d) >= 0. */
export interface CollisionPlane {
  normal: Vec2;
  offset: number;
  /** How far the plane may push; a rigid plane's is FLT_MAX (3.4028234663852886e38). */
  pushLimit: number;
  push: number;
  clipVelocity: boolean;
}
/** A plane for solvePlanes and clipVector: pushLimit left out or Infinity is rigid,
 *  clipVelocity defaults to true, push is ignored. */
export interface CollisionPlaneLike {
  normal: Vec2Like;
  offset: number;
  pushLimit?: number;
  push?: number;
  clipVelocity?: boolean;
}
export interface PlaneSolution { translation: Vec2; iterationCount: number; pushes: number[]; }

/** A colour, 0xRRGGBB. */
export type DrawColor = number;
/**
 * What World.draw hands the world to: any of these methods (kinds without one are not
 * drawn). Vertices are a Float32Array of x, y pairs viewing the module's memory, valid
 * during the call only; transforms are {x, y, c, s}; coordinates in world units, y up.
 */
export interface Drawer {
  /** A closed outline, world vertices counter-clockwise (bounds, islands: four). */
  drawPolygon?(vertices: Float32Array, color: DrawColor): void;
  /** A filled polygon: local vertices placed by transform, grown by radius. */
  drawSolidPolygon?(transform: Transform, vertices: Float32Array, radius: number, color: DrawColor): void;
  /** A circle outline (a revolute joint's motor, with drawJointExtras). */
  drawCircle?(center: Vec2, radius: number, color: DrawColor): void;
  /** A filled circle at transform's origin; transform's rotation shows it turning. */
  drawSolidCircle?(transform: Transform, radius: number, color: DrawColor): void;
  drawSolidCapsule?(p1: Vec2, p2: Vec2, radius: number, color: DrawColor): void;
  /** Segment shapes, joints, contact normals and impulses. */
  drawSegment?(p1: Vec2, p2: Vec2, color: DrawColor): void;
  /** A body's centre of mass and rotation (drawMass). */
  drawTransform?(transform: Transform): void;
  /** A dot of size pixels, whatever the view's scale. */
  drawPoint?(p: Vec2, size: number, color: DrawColor): void;
  /** Text at a point (a body's mass, with drawMass). */
  drawString?(p: Vec2, text: string, color: DrawColor): void;
}
/** World.draw's options (i2d_debug_draw); an option it does not have is a TypeError. */
export interface DrawOptions {
  drawShapes?: boolean;            // default true; coloured by body state (DRAW_COLORS)
  drawJoints?: boolean;            // default true
  drawJointExtras?: boolean;       // limits, motors, springs
  drawBounds?: boolean;            // shapes' fattened bounds
  drawMass?: boolean;              // dynamic bodies' centres of mass and masses
  drawContacts?: boolean;          // contact points
  drawContactNormals?: boolean;    // 0.3 m along each normal
  drawContactImpulses?: boolean;   // 10 m per N s along the normal
  drawFrictionImpulses?: boolean;  // 10 m per N s along the tangent
  drawGraphColors?: boolean;       // contact points in their solver colour (GRAPH_COLORS)
  drawIslands?: boolean;           // awake islands' bounds
  /** Cull to this box: only shapes whose bounds overlap it, and their bodies' extras. */
  drawingBounds?: AABB | null;
}

/** The colours World.draw gives (include/impulse2d/toolkit.h's I2D_COLOR_*). */
export const DRAW_COLORS: Readonly<{
  quarantined: number; disabled: number; sensor: number; static: number; kinematic: number; bullet: number;
  awake: number; asleep: number; joint: number; jointAnchor: number; jointLimit: number; jointMotor: number;
  jointSpring: number; bounds: number; island: number; mass: number; contact: number; speculative: number;
  contactNormal: number; contactImpulse: number; frictionImpulse: number; graphOverflow: number;
}>;
/** The solver's constraint colour k is drawn as GRAPH_COLORS[k % 12]. */
export const GRAPH_COLORS: readonly number[];
/** 0xRRGGBB as '#rrggbb', or 'rgba(r, g, b, alpha)' for alpha below 1. */
export function colorToCss(color: DrawColor, alpha?: number): string;

/** A convex shape for Impulse2d.shapeDistance: 1 to 8 points (its own frame), rounded by radius. */
export interface DistanceShape { points: Vec2Like[]; radius?: number; position?: Vec2Like; angle?: number; }
export interface DistanceResult { pointA: Vec2; pointB: Vec2; normal: Vec2; distance: number; }

export interface BodyOptions {
  type?: BodyType;                 // default 'static'
  position?: Vec2Like;
  angle?: number;                  // radians
  linearVelocity?: Vec2Like;
  angularVelocity?: number;
  linearDamping?: number;
  angularDamping?: number;
  gravityScale?: number;
  fixedRotation?: boolean;
  enableSleep?: boolean;
}

export interface ShapeOptions {
  density?: number;                // default 1 kg/m^2
  friction?: number;               // default 0.6
  restitution?: number;            // default 0
  isSensor?: boolean;
  enableContactEvents?: boolean;
  /** Pairs with this shape reach World.setCustomFilter's hook. */
  enableCustomFiltering?: boolean;
  /** Touching contacts of this shape reach World.setPreSolve's hook. */
  enablePreSolveEvents?: boolean;
  /** Who it collides with, and which queries and character moves see it. */
  filter?: ShapeFilter;
}

export type Geometry =
  | { type: 'circle'; center: Vec2; radius: number }
  | { type: 'polygon'; vertices: Vec2[]; radius: number }
  | { type: 'capsule'; center1: Vec2; center2: Vec2; radius: number }
  | { type: 'segment'; point1: Vec2; point2: Vec2 };

/** What every joint kind takes (i2d_joint_base). Anchors are in each body's frame,
 *  relative to its origin (Body.getLocalPoint turns a world point into one). */
export interface JointOptions {
  localAnchorA?: Vec2Like;         // m, default (0, 0)
  localAnchorB?: Vec2Like;
  collideConnected?: boolean;      // default false: the two bodies do not collide
  forceThreshold?: number;         // N; passing it lists the joint in jointEvents(); default FLT_MAX (never)
  torqueThreshold?: number;        // N m; likewise
}

export interface RevoluteJointOptions extends JointOptions {
  referenceAngle?: number;         // rad: angle of B minus A's when the joint angle is 0
  enableLimit?: boolean;
  lowerAngle?: number;             // rad, within [-0.99 pi, 0.99 pi], lower <= upper
  upperAngle?: number;
  enableMotor?: boolean;
  motorSpeed?: number;             // rad/s
  maxMotorTorque?: number;         // N m, >= 0
  enableSpring?: boolean;          // a spring toward targetAngle
  hertz?: number;                  // Hz, [0, 1e5]
  dampingRatio?: number;           // [0, 1e5]
  targetAngle?: number;            // rad
}

export interface PrismaticJointOptions extends JointOptions {
  localAxisA?: Vec2Like;           // default (1, 0); stored at unit length, must not be zero
  referenceAngle?: number;
  enableLimit?: boolean;
  lowerTranslation?: number;       // m, lower <= upper
  upperTranslation?: number;
  enableMotor?: boolean;
  motorSpeed?: number;             // m/s
  maxMotorForce?: number;          // N, >= 0
  enableSpring?: boolean;
  hertz?: number;
  dampingRatio?: number;
  targetTranslation?: number;      // m
}

export interface DistanceJointOptions extends JointOptions {
  length?: number;                 // rest length, m; default 1; [0.005, 1e5]
  enableLimit?: boolean;           // with enableSpring and hertz 0: a rope
  minLength?: number;              // m, 0 <= min <= max; stored clamped to [0.005, 1e5]
  maxLength?: number;
  enableSpring?: boolean;          // default false: a rigid rod
  hertz?: number;
  dampingRatio?: number;
  enableMotor?: boolean;
  motorSpeed?: number;             // m/s, positive lengthens
  maxMotorForce?: number;          // N
}

export interface WeldJointOptions extends JointOptions {
  referenceAngle?: number;
  linearHertz?: number;            // default 0: rigid
  angularHertz?: number;           // default 0: rigid
  linearDampingRatio?: number;     // default 1
  angularDampingRatio?: number;    // default 1
}

export interface WheelJointOptions extends JointOptions {
  localAxisA?: Vec2Like;           // the suspension's axis in A; default (0, 1)
  enableSpring?: boolean;          // default true
  hertz?: number;                  // default 1
  dampingRatio?: number;           // default 0.7
  enableLimit?: boolean;
  lowerTranslation?: number;       // m
  upperTranslation?: number;
  enableMotor?: boolean;
  motorSpeed?: number;             // rad/s, of the wheel's turning
  maxMotorTorque?: number;         // N m
}

export interface MotorJointOptions extends JointOptions {
  linearOffset?: Vec2Like;         // m: B's origin in A's frame to drive toward
  angularOffset?: number;          // rad
  maxForce?: number;               // N, default 1
  maxTorque?: number;              // N m, default 1
  correctionFactor?: number;       // share of the pose error removed per step, [0, 1]; default 0.3
}

export interface MouseJointOptions extends JointOptions {
  target?: Vec2Like;               // m, world
  hertz?: number;                  // default 4
  dampingRatio?: number;           // default 1
  maxForce?: number;               // N, default 1000
}

export interface Counters { bodyCount: number; shapeCount: number; contactCount: number; awakeBodyCount: number; }
export interface RayHit { shape: Shape; point: Vec2; normal: Vec2; fraction: number; }

export class Shape {
  readonly body: Body;
  readonly id: bigint;
  userData: unknown;
  isValid(): boolean;
  readonly type: ShapeType;
  aabb(): AABB;
  friction: number;
  restitution: number;
  /** kg/m^2; setting it updates the body's mass. */
  density: number;
  setDensity(density: number, updateBodyMass?: boolean): void;
  /** Set all four at once. */
  material: SurfaceMaterial;
  sensorEventsEnabled: boolean;
  contactEventsEnabled: boolean;
  hitEventsEnabled: boolean;
  /** Whether its touching contacts reach World.setPreSolve's hook (from the next step). */
  preSolveEventsEnabled: boolean;
  geometry(): Geometry;
  /** New geometry in the body frame (the kind may change); the body's mass is made again. */
  setCircle(radius: number, center?: Vec2Like): void;
  setCapsule(center1: Vec2Like, center2: Vec2Like, radius: number): void;
  setSegment(point1: Vec2Like, point2: Vec2Like): void;
  /** The convex hull of 3 to 8 points, rounded by radius. */
  setPolygon(points: Vec2Like[], radius?: number): void;
  /** The point of the shape closest to target (world coordinates). */
  closestPoint(target: Vec2Like): Vec2;
  contactData(): ContactData[];
  /** The shapes visiting this sensor as of the last step; throws for a non-sensor. */
  sensorOverlaps(): (Shape | bigint)[];
  destroy(): void;
}

export class Body {
  readonly world: World;
  readonly id: bigint;
  /** The body's number in its world, carried by its move events. */
  readonly index: number;
  readonly shapes: Shape[];
  /** Joints this body is one of the two bodies of. */
  readonly joints: Joint[];
  userData: unknown;
  isValid(): boolean;
  readonly type: BodyType;
  readonly position: Vec2;
  readonly angle: number;
  transform(): Transform;
  setTransform(position: Vec2Like, angle?: number): void;
  /** A world point in the body's frame: how joint anchors are given. */
  getLocalPoint(worldPoint: Vec2Like): Vec2;
  getWorldPoint(localPoint: Vec2Like): Vec2;
  get linearVelocity(): Vec2;
  set linearVelocity(v: Vec2Like);
  setLinearVelocity(v: Vec2Like): void;
  angularVelocity: number;
  readonly mass: number;
  readonly worldCenterOfMass: Vec2;
  awake: boolean;
  applyLinearImpulse(impulse: Vec2Like, point?: Vec2Like, wake?: boolean): void;
  applyForceToCenter(force: Vec2Like, wake?: boolean): void;
  /** Setting it overrides the mass the shapes give a dynamic body. */
  get massData(): MassData;
  set massData(data: MassDataLike);
  setMassData(data: MassDataLike): void;
  applyMassFromShapes(): void;
  /** A disabled body is out of the world (no contacts, queries or joints) until enabled. */
  disable(): void;
  enable(): void;
  enabled: boolean;
  /** A kinematic body's velocities set so that it reaches the pose in timeStep seconds. */
  setTargetTransform(position: Vec2Like, angle: number, timeStep: number): void;
  bullet: boolean;
  sleepEnabled: boolean;
  /** World length units per second. */
  sleepThreshold: number;
  gravityScale: number;
  linearDamping: number;
  angularDamping: number;
  fixedRotation: boolean;
  contactData(): ContactData[];
  createBox(halfWidth: number, halfHeight: number, options?: ShapeOptions): Shape;
  createOffsetBox(halfWidth: number, halfHeight: number, center: Vec2Like, angle?: number, options?: ShapeOptions): Shape;
  createCircle(radius: number, options?: ShapeOptions & { center?: Vec2Like }): Shape;
  createPolygon(points: Vec2Like[], options?: ShapeOptions): Shape;
  createCapsule(center1: Vec2Like, center2: Vec2Like, radius: number, options?: ShapeOptions): Shape;
  createSegment(point1: Vec2Like, point2: Vec2Like, options?: ShapeOptions): Shape;
  /** Destroys the body, its shapes and its joints. */
  destroy(): void;
}

/** What every joint kind has. Setters check their value as creation does, throw
 *  Impulse2dError on a refusal (the joint keeps what it had) and wake both bodies. */
export class Joint {
  readonly world: World;
  readonly id: bigint;
  readonly bodyA: Body;
  readonly bodyB: Body;
  userData: unknown;
  isValid(): boolean;
  readonly type: JointType;
  get localAnchorA(): Vec2;
  set localAnchorA(v: Vec2Like);
  get localAnchorB(): Vec2;
  set localAnchorB(v: Vec2Like);
  collideConnected: boolean;
  forceThreshold: number;
  torqueThreshold: number;
  /** The force the joint applied to body B in the last step, N (on A: its negative). */
  readonly reactionForce: Vec2;
  /** The torque the joint applied to body B in the last step, N m. */
  readonly reactionTorque: number;
  wakeBodies(): void;
  /** Destroys the joint and wakes its bodies. */
  destroy(): void;
}

export class RevoluteJoint extends Joint {
  readonly type: 'revolute';
  /** rad, of B relative to A minus the reference angle, in (-pi, pi]. */
  readonly angle: number;
  /** The motor's torque in the last step, N m. */
  readonly motorTorque: number;
  referenceAngle: number;
  enableLimit: boolean;
  lowerAngle: number;
  upperAngle: number;
  /** Both limits at once (one at a time is refused when it would pass the other). */
  setLimits(lower: number, upper: number): void;
  enableMotor: boolean;
  motorSpeed: number;
  maxMotorTorque: number;
  enableSpring: boolean;
  hertz: number;
  dampingRatio: number;
  targetAngle: number;
}

export class PrismaticJoint extends Joint {
  readonly type: 'prismatic';
  /** m along the axis, of B's anchor from A's. */
  readonly translation: number;
  /** m/s along the axis. */
  readonly speed: number;
  /** The motor's force in the last step, N. */
  readonly motorForce: number;
  get localAxisA(): Vec2;
  set localAxisA(v: Vec2Like);
  referenceAngle: number;
  enableLimit: boolean;
  lowerTranslation: number;
  upperTranslation: number;
  setLimits(lower: number, upper: number): void;
  enableMotor: boolean;
  motorSpeed: number;
  maxMotorForce: number;
  enableSpring: boolean;
  hertz: number;
  dampingRatio: number;
  targetTranslation: number;
}

export class DistanceJoint extends Joint {
  readonly type: 'distance';
  /** m, between the two anchors now. */
  readonly currentLength: number;
  /** The motor's force in the last step, N. */
  readonly motorForce: number;
  length: number;
  enableLimit: boolean;
  minLength: number;
  maxLength: number;
  setLengthRange(minLength: number, maxLength: number): void;
  enableSpring: boolean;
  hertz: number;
  dampingRatio: number;
  enableMotor: boolean;
  motorSpeed: number;
  maxMotorForce: number;
}

export class WeldJoint extends Joint {
  readonly type: 'weld';
  referenceAngle: number;
  linearHertz: number;
  angularHertz: number;
  linearDampingRatio: number;
  angularDampingRatio: number;
}

export class WheelJoint extends Joint {
  readonly type: 'wheel';
  /** m along the axis: the suspension's travel. */
  readonly translation: number;
  /** The motor's torque in the last step, N m. */
  readonly motorTorque: number;
  get localAxisA(): Vec2;
  set localAxisA(v: Vec2Like);
  enableSpring: boolean;
  hertz: number;
  dampingRatio: number;
  enableLimit: boolean;
  lowerTranslation: number;
  upperTranslation: number;
  setLimits(lower: number, upper: number): void;
  enableMotor: boolean;
  motorSpeed: number;
  maxMotorTorque: number;
}

export class MotorJoint extends Joint {
  readonly type: 'motor';
  get linearOffset(): Vec2;
  set linearOffset(v: Vec2Like);
  angularOffset: number;
  maxForce: number;
  maxTorque: number;
  correctionFactor: number;
}

export class MouseJoint extends Joint {
  readonly type: 'mouse';
  get target(): Vec2;
  set target(v: Vec2Like);
  hertz: number;
  dampingRatio: number;
  maxForce: number;
}

export class FilterJoint extends Joint {
  readonly type: 'filter';
}

/** The last step's body move events, viewed in the module's memory (no copy). Valid
 *  until the next step or any call that may grow the memory. */
export class BodyMoves {
  readonly count: number;
  /** Floats (and 32-bit words) per event. */
  readonly stride: number;
  /** Event i's transform: floats[i * stride + transformWord + 0..3] = x, y, cosine, sine. */
  readonly floats: Float32Array;
  /** Event i's body index: words[i * stride + userDataWord]. */
  readonly words: Uint32Array;
  readonly transformWord: number;
  readonly userDataWord: number;
  bodyIndex(i: number): number;
  body(i: number): Body;
  x(i: number): number;
  y(i: number): number;
  angle(i: number): number;
  fellAsleep(i: number): boolean;
}

/** Snapshot or rollback-state bytes; a Node Buffer is a Uint8Array. */
export type SnapshotBytes = Uint8Array | ArrayBuffer;

export class World {
  /**
   * A new world from a snapshot's bytes: it steps on bit for bit as the saved world would,
   * whichever build saved it (x86-64, AArch64, WebAssembly). For bytes takeSnapshot returned
   * it gets new Body, Shape and Joint objects for what the saved world held (same indices,
   * userData copied); for other bytes (a file, a copy, another process) it has none, since
   * the C API cannot list a world's bodies: step it, hash it, snapshot it. Throws
   * Impulse2dError I2D_ERR_INVALID_SNAPSHOT for a refused buffer. WebAssembly has no host
   * wiring to choose (one thread, scalar kernels), so there are no options.
   */
  static fromSnapshot(impulse2d: Impulse2d, bytes: SnapshotBytes): World;
  readonly id: bigint;
  /** Live bodies by index (slot 0 is never used). */
  readonly bodyByIndex: (Body | undefined)[];
  readonly bodies: Body[];
  isValid(): boolean;
  /** Throws, once the step is done, the first error a contact hook threw during it. */
  step(timeStep?: number, substeps?: number): void;
  /** Sets (null clears) the hook asked whether two shapes may ever touch, for pairs where
   *  either has enableCustomFiltering. Hooks run inside step(), on its thread; any call on
   *  the world from one throws I2D_ERR_WORLD_LOCKED; an error one throws gives the pair
   *  true and is thrown by step(). */
  setCustomFilter(fn: CustomFilterFn | null): void;
  /** Sets (null clears) the hook asked every step whether a touching contact takes part,
   *  for pairs where either shape has enablePreSolveEvents. As setCustomFilter otherwise. */
  setPreSolve(fn: PreSolveFn | null): void;
  /** Pushes every dynamic body with a shape within radius + falloff of position away from
   *  it and wakes it (i2d_world_explode). */
  explode(options: ExplosionOptions): void;
  /** Moves a character (i2d_world_move_character); changes nothing in the world but the
   *  pushes it gives dynamic bodies (none with pushMass 0). */
  moveCharacter(options: MoveCharacterOptions): CharacterResult;
  /** The fraction in [0, 1] of translation the capsule (world coordinates) can move. */
  castMover(capsule: Capsule, translation: Vec2Like, filter?: QueryFilter): number;
  /** A plane per shape within the contact slop of the capsule (world coordinates). */
  collideMover(capsule: Capsule, filter?: QueryFilter): CollisionPlane[];
  /** Draws the world through the drawer's methods before it returns; the first error a
   *  method throws ends the drawing and is thrown after. */
  draw(drawer: Drawer, options?: DrawOptions): void;
  get gravity(): Vec2;
  set gravity(g: Vec2Like);
  settings(): WorldSettings;
  /** Turning sleep off wakes every body. */
  enableSleeping(flag: boolean): void;
  enableContinuous(flag: boolean): void;
  /** Impacts passed from body to body within a step taken one at a time (on by default). */
  enableImpactChains(flag: boolean): void;
  setContactTuning(hertz: number, dampingRatio: number, pushMaxSpeed: number): void;
  setJointTuning(hertz: number, dampingRatio: number): void;
  setRestitutionThreshold(speed: number): void;
  setHitEventThreshold(speed: number): void;
  /** Every position the world keeps or reports becomes relative to newOrigin. */
  shiftOrigin(newOrigin: Vec2Like): void;
  createBody(options?: BodyOptions): Body;
  /** Joints between two bodies of this world, at least one dynamic. An option the kind
   *  does not have throws a TypeError; a value the library refuses, an Impulse2dError. */
  createRevoluteJoint(bodyA: Body, bodyB: Body, options?: RevoluteJointOptions): RevoluteJoint;
  createPrismaticJoint(bodyA: Body, bodyB: Body, options?: PrismaticJointOptions): PrismaticJoint;
  createDistanceJoint(bodyA: Body, bodyB: Body, options?: DistanceJointOptions): DistanceJoint;
  createWeldJoint(bodyA: Body, bodyB: Body, options?: WeldJointOptions): WeldJoint;
  createWheelJoint(bodyA: Body, bodyB: Body, options?: WheelJointOptions): WheelJoint;
  createMotorJoint(bodyA: Body, bodyB: Body, options?: MotorJointOptions): MotorJoint;
  /** bodyA is not moved (often a static body without shapes); bodyB must be dynamic. */
  createMouseJoint(bodyA: Body, bodyB: Body, options?: MouseJointOptions): MouseJoint;
  createFilterJoint(bodyA: Body, bodyB: Body, options?: JointOptions): FilterJoint;
  /** Live joints, in creation order. */
  readonly joints: Joint[];
  jointCount(): number;
  /** Joints whose reaction passed its force or torque threshold in the last step. */
  jointEvents(): Joint[];
  counters(): Counters;
  stateHash(): bigint;
  simdPath(): number;
  /** Workers stepping the world (createWorld's workerCount). */
  readonly workerCount: number;
  bodyMoves(): BodyMoves;
  contactEvents(): { begin: [Shape, Shape][]; end: [Shape | bigint, Shape | bigint][] };
  overlapAABB(minX: number, minY: number, maxX: number, maxY: number): Shape[];
  castRayClosest(origin: Vec2Like, translation: Vec2Like): RayHit | null;
  /** The whole world as portable bytes (include/impulse2d/snapshot.h), for restoreSnapshot,
   *  World.fromSnapshot, a file or another machine. */
  takeSnapshot(): Uint8Array;
  /** Replaces the world's state with a snapshot's; the world keeps its id. What existed at
   *  the save exists again (the same objects, for bytes this world's takeSnapshot returned),
   *  what was made since is gone. A refused buffer throws I2D_ERR_INVALID_SNAPSHOT and
   *  changes nothing. */
  restoreSnapshot(bytes: SnapshotBytes): void;
  /** A rollback state: what a step changes, for restoreState in this world only, while its
   *  bodies, shapes, joints, joint settings and gravity stay as they are. */
  saveState(): Uint8Array;
  /** Back to a state saveState took from this world; stepping on gives the bits stepping
   *  from then gave. Another world's state, one from before a structural change, and
   *  truncated or corrupted bytes throw I2D_ERR_INVALID_SNAPSHOT and change nothing. */
  restoreState(bytes: SnapshotBytes): void;
  /** Records the world: each record to write as it is made, or all of it kept for
   *  stopRecording. A write that throws is thrown by stopRecording. */
  startRecording(write?: (record: Uint8Array) => void): void;
  /** The recording's bytes when startRecording kept them, else undefined. */
  stopRecording(): Uint8Array | undefined;
  /** Throws for a replay's world: close the replay instead. */
  destroy(): void;
}

/** A recording replayed in a world of its own (Impulse2d.openReplay), every step's state
 *  hash checked against the recorded one. */
export class Replay {
  /** The replay's world, to read as the replay goes (it has no Body objects). */
  readonly world: World;
  /** Replays up to count (default 1) more steps; returns how many ran. */
  step(count?: number): number;
  readonly currentStep: number;
  readonly stepCount: number;
  /** The first step whose hash differed from the recording's (1 for the first), or null. */
  readonly divergentStep: number | null;
  /** Goes to step (0 to stepCount), backwards too. */
  seek(step: number): void;
  /** Closes the replay and destroys its world; closing twice is harmless. */
  close(): void;
}

export class Impulse2d {
  /** (major << 16) | (minor << 8) | patch */
  readonly version: number;
  /** Whether this is a WebAssembly SIMD build (4-lane contact kernels, 'wasm128'). */
  readonly simd: boolean;
  /** Worker threads the build lends worlds: 3 in the threads build, else 0. */
  readonly threads: number;
  createWorld(options?: WorldOptions): World;
  /** Steps the worlds in one call, each as world.step would; a bad one throws and none moves. */
  stepWorlds(worlds: Iterable<World>, timeStep?: number, substeps?: number): void;
  /** World.fromSnapshot(this, bytes). */
  worldFromSnapshot(bytes: SnapshotBytes): World;
  /** Opens a recording (World.startRecording's bytes) to replay it, checking every hash. */
  openReplay(bytes: SnapshotBytes): Replay;
  /** The default settings of a world in lengthUnitsPerMeter units (default 1). */
  defaultWorldSettings(lengthUnitsPerMeter?: number): WorldSettings;
  /** The character def's defaults, as World.moveCharacter takes them. */
  defaultCharacterDef(): CharacterDef;
  /** The move nearest targetDelta that runs into none of the rigid planes. */
  solvePlanes(targetDelta: Vec2Like, planes: CollisionPlaneLike[]): PlaneSolution;
  /** The vector less its part running into the planes with clipVelocity. */
  clipVector(vector: Vec2Like, planes: CollisionPlaneLike[]): Vec2;
  /** The closest points of two convex shapes, in metres. */
  shapeDistance(a: DistanceShape, b: DistanceShape): DistanceResult;
}

/** Loads the SIMD build where the engine has WebAssembly SIMD, else the scalar one;
 *  simd: true or false forces one (true throws without SIMD); threads: true loads the
 *  threads build. wasmBinary and wasmUrl must be the chosen build's. */
export function loadImpulse2d(options?: {
  wasmBinary?: ArrayBuffer | Uint8Array; wasmUrl?: string | URL; simd?: 'auto' | boolean;
  /** The threads build (default false; 'auto': where shared memory is available). */
  threads?: 'auto' | boolean;
}): Promise<Impulse2d>;
/** Whether this engine can run the threads build (node, or a cross-origin isolated page). */
export function wasmThreadsSupported(): boolean;
/** Whether this JavaScript engine runs WebAssembly SIMD modules. */
export function wasmSimdSupported(): boolean;
