// SPDX-License-Identifier: MIT
// TypeScript declarations for the impulse2d WebAssembly package.

/** A point or vector: {x, y} or [x, y]. Units are metres; y points up. */
export type Vec2Like = { x: number; y: number } | readonly [number, number];
export interface Vec2 { x: number; y: number; }
export interface Transform { x: number; y: number; c: number; s: number; }
export interface AABB { minX: number; minY: number; maxX: number; maxY: number; }

export type BodyType = 'static' | 'kinematic' | 'dynamic';
export type ShapeType = 'circle' | 'capsule' | 'segment' | 'polygon';
export type StatusName =
  | 'I2D_ERR_INVALID_ARGUMENT' | 'I2D_ERR_INVALID_HANDLE' | 'I2D_ERR_WORLD_LOCKED'
  | 'I2D_ERR_CAPACITY' | 'I2D_ERR_OUT_OF_MEMORY';

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
}

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
}

export type Geometry =
  | { type: 'circle'; center: Vec2; radius: number }
  | { type: 'polygon'; vertices: Vec2[]; radius: number }
  | { type: 'capsule'; center1: Vec2; center2: Vec2; radius: number }
  | { type: 'segment'; point1: Vec2; point2: Vec2 };

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
  readonly density: number;
  geometry(): Geometry;
  destroy(): void;
}

export class Body {
  readonly world: World;
  readonly id: bigint;
  /** The body's number in its world, carried by its move events. */
  readonly index: number;
  readonly shapes: Shape[];
  userData: unknown;
  isValid(): boolean;
  readonly type: BodyType;
  readonly position: Vec2;
  readonly angle: number;
  transform(): Transform;
  setTransform(position: Vec2Like, angle?: number): void;
  get linearVelocity(): Vec2;
  set linearVelocity(v: Vec2Like);
  setLinearVelocity(v: Vec2Like): void;
  angularVelocity: number;
  readonly mass: number;
  readonly worldCenterOfMass: Vec2;
  awake: boolean;
  applyLinearImpulse(impulse: Vec2Like, point?: Vec2Like, wake?: boolean): void;
  applyForceToCenter(force: Vec2Like, wake?: boolean): void;
  createBox(halfWidth: number, halfHeight: number, options?: ShapeOptions): Shape;
  createOffsetBox(halfWidth: number, halfHeight: number, center: Vec2Like, angle?: number, options?: ShapeOptions): Shape;
  createCircle(radius: number, options?: ShapeOptions & { center?: Vec2Like }): Shape;
  createPolygon(points: Vec2Like[], options?: ShapeOptions): Shape;
  createCapsule(center1: Vec2Like, center2: Vec2Like, radius: number, options?: ShapeOptions): Shape;
  createSegment(point1: Vec2Like, point2: Vec2Like, options?: ShapeOptions): Shape;
  destroy(): void;
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

export class World {
  readonly id: bigint;
  /** Live bodies by index (slot 0 is never used). */
  readonly bodyByIndex: (Body | undefined)[];
  readonly bodies: Body[];
  isValid(): boolean;
  step(timeStep?: number, substeps?: number): void;
  get gravity(): Vec2;
  set gravity(g: Vec2Like);
  createBody(options?: BodyOptions): Body;
  counters(): Counters;
  stateHash(): bigint;
  simdPath(): number;
  bodyMoves(): BodyMoves;
  contactEvents(): { begin: [Shape, Shape][]; end: [Shape | bigint, Shape | bigint][] };
  overlapAABB(minX: number, minY: number, maxX: number, maxY: number): Shape[];
  castRayClosest(origin: Vec2Like, translation: Vec2Like): RayHit | null;
  destroy(): void;
}

export class Impulse2d {
  /** (major << 16) | (minor << 8) | patch */
  readonly version: number;
  createWorld(options?: WorldOptions): World;
}

export function loadImpulse2d(options?: { wasmBinary?: ArrayBuffer | Uint8Array; wasmUrl?: string | URL }): Promise<Impulse2d>;
