/* SPDX-License-Identifier: MIT */
/* impulse2d: a 2D rigid-body physics engine behind a C API.
 *
 * A short manual
 * - Units are metres, kilograms, seconds and radians; y points up. Scalars are float.
 *   A world may count lengths in other units (i2d_world_def.length_units_per_meter,
 *   pixels say): then every length and speed given to or read from that world is in
 *   them, and its tolerances follow; the pure functions of collision.h stay in metres.
 * - The world and everything in it are named by 8-byte value ids (id.h). The null id
 *   has bits == 0. A destroyed object's id, or an id of a destroyed world, stays
 *   detectably stale: calls answer I2D_ERR_INVALID_HANDLE.
 * - Creation takes a def from i2d_default_*_def(), edited by the caller. A def that did
 *   not come from the default function is refused.
 * - Calls that act return an i2d_status; calls that create return an id (null on
 *   failure); getters on a bad id return a zero value. Every call records its status
 *   and a message for this thread: i2d_last_status(), i2d_last_error_message().
 *   A refused call leaves the world exactly as it was.
 * - Query callbacks run on the calling thread while the world is locked: inside them,
 *   calls that change the world (create, destroy, step, every setter but user data,
 *   forces and impulses) answer I2D_ERR_WORLD_LOCKED; getters and queries work.
 * - A job system's enqueue_task and finish_task (types.h) run inside the step, while the
 *   world's other workers may be changing any of it: there every call that names the
 *   world or anything in it, getters and i2d_*_is_valid included, answers
 *   I2D_ERR_WORLD_LOCKED. Other worlds may be used.
 * - A world is used from one thread at a time; different worlds may be used from
 *   different threads at once.
 * - Limits: 4096 worlds alive at once (I2D_MAX_WORLDS; created and destroyed without
 *   limit: an id of a destroyed world stays stale until its slot has been reused 254
 *   times, about a million worlds later when few are alive); 16,777,215 bodies and as many shapes per world;
 *   shape sizes from 0.0001 to 100,000 m, and every point of a shape's geometry within
 *   100,000 m of its body's origin; positions within 1e9 m of the world origin. Past
 *   them calls answer I2D_ERR_CAPACITY or I2D_ERR_INVALID_ARGUMENT. */
#ifndef IMPULSE2D_H
#define IMPULSE2D_H

#include "base.h"
#include "batch.h"
#include "collision.h"
#include "id.h"
#include "joint.h"
#include "snapshot.h"
#include "toolkit.h"
#include "types.h"

/* ---- Definitions ---------------------------------------------------------------- */

I2D_API i2d_world_def i2d_default_world_def(void);
/** The default world def for a world in other length units (length_units_per_meter in
 *  [1e-3, 1e4]): every length-bearing default (slop, push speed, thresholds, maximum
 *  speed, gravity) scaled from metres to them. Out of range: the metre defaults and
 *  I2D_ERR_INVALID_ARGUMENT. */
I2D_API i2d_world_def i2d_default_world_def_in_units(float length_units_per_meter);
I2D_API i2d_body_def i2d_default_body_def(void);
I2D_API i2d_shape_def i2d_default_shape_def(void);
/** Every category and mask bit: a query filter that sees every shape (whose own
 *  mask_bits are not all zero). */
I2D_API i2d_query_filter i2d_default_query_filter(void);
/** Category 1, mask every bit, group 0. */
I2D_API i2d_filter i2d_default_filter(void);

/* ---- Rotations ------------------------------------------------------------------ */

/** The rotation by angle radians, counter-clockwise (angle finite). */
I2D_API i2d_rot i2d_make_rot(float angle);
/** The angle of a rotation in (-pi, pi]. */
I2D_API float i2d_rot_get_angle(i2d_rot rotation);

/* ---- World ---------------------------------------------------------------------- */

/** Creates a world. Null id with I2D_ERR_INVALID_ARGUMENT for a bad def, or
 *  I2D_ERR_CAPACITY when 256 worlds are alive. */
I2D_API i2d_world_id i2d_world_create(const i2d_world_def* def);
/** Destroys the world and everything in it; all its ids become stale. */
I2D_API i2d_status i2d_world_destroy(i2d_world_id world);
I2D_API bool i2d_world_is_valid(i2d_world_id world);
/** Advances the world by time_step seconds (0, which does nothing, or 1e-6 to 1000), split into
 *  substep_count equal substeps (1 to 1000); each substep finds contacts, resolves
 *  them and integrates. 1/60 s with 4 substeps is a good start. */
I2D_API i2d_status i2d_world_step(i2d_world_id world, float time_step, int32_t substep_count);
I2D_API i2d_status i2d_world_set_gravity(i2d_world_id world, i2d_vec2 gravity);
I2D_API i2d_vec2 i2d_world_get_gravity(i2d_world_id world);
I2D_API i2d_world_counters i2d_world_get_counters(i2d_world_id world);
/** Where the last step's time went: zeros before the first timed step. The first call
 *  turns timing on for the steps after it (or set the world def's enable_profile). */
I2D_API i2d_profile i2d_world_get_profile(i2d_world_id world);
/** A 64-bit hash of the bits of every body's transform and velocities and every
 *  contact's impulses: equal hashes mean equal states. Two runs of the same scene give
 *  the same hash on any machine, whatever the SIMD path. 0 for a bad id. */
I2D_API uint64_t i2d_world_get_state_hash(i2d_world_id world);
/** The SIMD path the world solves contacts with (never I2D_SIMD_AUTOMATIC); scalar
 *  for a bad id. */
I2D_API i2d_simd_path i2d_world_get_simd_path(i2d_world_id world);
/** The world def's worker_count; 0 for an invalid id. */
I2D_API int32_t i2d_world_get_worker_count(i2d_world_id world);
/** Any pointer, never read by the world; NULL by default. May be set inside callbacks. */
I2D_API i2d_status i2d_world_set_user_data(i2d_world_id world, void* user_data);
I2D_API void* i2d_world_get_user_data(i2d_world_id world);
/** The world's settings as a def (the values the setters below last gave, the rest as
 *  created), ready to create a world like it; a zero def for a bad id. */
I2D_API i2d_world_def i2d_world_get_settings(i2d_world_id world);
/* Settings after creation: each is checked as in i2d_world_def (refused with the world
 * untouched), takes effect at the next step and wakes what it must. */
/** Turning sleep off wakes every body. */
I2D_API i2d_status i2d_world_enable_sleeping(i2d_world_id world, bool flag);
I2D_API i2d_status i2d_world_enable_continuous(i2d_world_id world, bool flag);
I2D_API i2d_status i2d_world_enable_impact_chains(i2d_world_id world, bool flag);
I2D_API i2d_status i2d_world_set_contact_tuning(i2d_world_id world, float hertz, float damping_ratio,
                                                float push_max_speed);
I2D_API i2d_status i2d_world_set_joint_tuning(i2d_world_id world, float hertz, float damping_ratio);
I2D_API i2d_status i2d_world_set_restitution_threshold(i2d_world_id world, float speed);
I2D_API i2d_status i2d_world_set_hit_event_threshold(i2d_world_id world, float speed);
/** Moves the world's origin to new_origin (a point in the world's present coordinates):
 *  afterwards every position the world keeps or reports is relative to it (bodies, the
 *  shapes' boxes and the trees, mouse joint targets, the last step's events), each its
 *  old value less new_origin as float subtraction rounds it, so that a world kilometres
 *  across keeps its precision near the player. Nothing wakes and no contact is lost: the
 *  simulation goes on as it would have, shifted, to within the rounding of positions
 *  (coarser the farther from the origin). A rollback state saved before is refused after
 *  it (its positions are of the old origin); a recording replays it. Refused, the world
 *  untouched: a bad id (I2D_ERR_INVALID_HANDLE), inside a callback
 *  (I2D_ERR_WORLD_LOCKED), a new_origin that is not finite or lies beyond 1e9 m of the
 *  origin, or one that would put a body or a mouse joint's target beyond 1e9 m of itself
 *  (I2D_ERR_INVALID_ARGUMENT). */
I2D_API i2d_status i2d_world_shift_origin(i2d_world_id world, i2d_vec2 new_origin);
/** Whether this library on this CPU can run the path (I2D_SIMD_AUTOMATIC always can). */
I2D_API bool i2d_simd_path_supported(i2d_simd_path path);

/* ---- Bodies --------------------------------------------------------------------- */

/** Creates a body with no shapes. A dynamic body without shapes has a mass of 1 kg. */
I2D_API i2d_body_id i2d_body_create(i2d_world_id world, const i2d_body_def* def);
/** Destroys the body and its shapes. */
I2D_API i2d_status i2d_body_destroy(i2d_body_id body);
I2D_API bool i2d_body_is_valid(i2d_body_id body);
I2D_API i2d_world_id i2d_body_get_world(i2d_body_id body);
I2D_API i2d_body_type i2d_body_get_type(i2d_body_id body);
/** Makes the body static, kinematic or dynamic, at any time between steps. Its mass,
 *  rotational inertia and bounds follow the new type; a body made static stops (its
 *  velocities become 0) and a kinematic or static one drops its accumulated forces. Its
 *  contacts end (their end events come with the next step) and the next step finds the
 *  pairs the new type may have; the body and everything that touched it wake. */
I2D_API i2d_status i2d_body_set_type(i2d_body_id body, i2d_body_type type);
/** The body origin in world coordinates, m. */
I2D_API i2d_vec2 i2d_body_get_position(i2d_body_id body);
I2D_API i2d_rot i2d_body_get_rotation(i2d_body_id body);
I2D_API i2d_transform i2d_body_get_transform(i2d_body_id body);
/** Teleports the body origin to position, turned by rotation (normalised within 1e-3). */
I2D_API i2d_status i2d_body_set_transform(i2d_body_id body, i2d_vec2 position, i2d_rot rotation);
/** Velocity of the centre of mass, m/s. */
I2D_API i2d_vec2 i2d_body_get_linear_velocity(i2d_body_id body);
/** Finite values only; ignored for static bodies (which never move) but still checked.
 *  A speed above the world's maximum_linear_speed is scaled down to it at once (direction
 *  kept), as are body def velocities and the results of impulses. */
I2D_API i2d_status i2d_body_set_linear_velocity(i2d_body_id body, i2d_vec2 v);
/** rad/s, counter-clockwise positive. */
I2D_API float i2d_body_get_angular_velocity(i2d_body_id body);
/** Finite values only; ignored for static and fixed-rotation bodies but still checked.
 *  Spins beyond 1e5 rad/s are clamped to it at once (as are body def spins and the
 *  results of impulses); faster than a quarter turn per substep at the next step. */
I2D_API i2d_status i2d_body_set_angular_velocity(i2d_body_id body, float w);
/** kg; 0 for static and kinematic bodies. */
I2D_API float i2d_body_get_mass(i2d_body_id body);
/** Rotational inertia about the centre of mass, kg m^2; 0 for static, kinematic and
 *  fixed-rotation bodies. */
I2D_API float i2d_body_get_rotational_inertia(i2d_body_id body);
/** Centre of mass in world coordinates, m. */
I2D_API i2d_vec2 i2d_body_get_world_center_of_mass(i2d_body_id body);
/** Centre of mass in the body frame, m. */
I2D_API i2d_vec2 i2d_body_get_local_center_of_mass(i2d_body_id body);
/** A point given in the body frame, in world coordinates. */
I2D_API i2d_vec2 i2d_body_get_world_point(i2d_body_id body, i2d_vec2 local_point);
/** A world point, in the body frame. */
I2D_API i2d_vec2 i2d_body_get_local_point(i2d_body_id body, i2d_vec2 world_point);
/** Velocity of the body's material at a world point: v + w x (point - centre). */
I2D_API i2d_vec2 i2d_body_get_world_point_velocity(i2d_body_id body, i2d_vec2 world_point);
/** Adds a force (N) at a world point (within 1e9 m of the origin) for the next step;
 *  away from the centre of mass it also adds torque. Cleared after each step. Only
 *  dynamic bodies respond. A force that would make the accumulated total overflow is
 *  refused. wake = true wakes a sleeping body; with false, a sleeping body ignores it
 *  (as it does every apply_* call). */
I2D_API i2d_status i2d_body_apply_force(i2d_body_id body, i2d_vec2 force, i2d_vec2 point, bool wake);
/** Adds a force (N) at the centre of mass for the next step: no torque. */
I2D_API i2d_status i2d_body_apply_force_to_center(i2d_body_id body, i2d_vec2 force, bool wake);
/** Adds a torque (N m, counter-clockwise positive) for the next step. */
I2D_API i2d_status i2d_body_apply_torque(i2d_body_id body, float torque, bool wake);
/** Changes velocity at once by impulse / mass (N s), applied at a world point (within
 *  1e9 m of the origin): away from the centre of mass it also changes the spin by
 *  (r x impulse) / inertia. Only dynamic bodies respond; an impulse that would make a
 *  velocity overflow is refused. */
I2D_API i2d_status i2d_body_apply_linear_impulse(i2d_body_id body, i2d_vec2 impulse, i2d_vec2 point,
                                                 bool wake);
/** Changes the spin at once by impulse / inertia (N m s). */
I2D_API i2d_status i2d_body_apply_angular_impulse(i2d_body_id body, float impulse, bool wake);
/** False for static bodies and for sleeping ones. A body falls asleep with everything
 *  touching it once all of them have rested for the world's time_to_sleep. It wakes
 *  (with them) when an awake body starts or stops touching it, when a body or shape
 *  touching it is destroyed, and when its velocity, transform or shapes change
 *  or a force, torque or impulse is applied with wake = true. */
I2D_API bool i2d_body_is_awake(i2d_body_id body);
/** True after a step found the body's state non-finite and froze it (see
 *  i2d_body_quarantine_event); false again once its type is set. */
I2D_API bool i2d_body_is_quarantined(i2d_body_id body);
/** Wakes the body and everything touching it, or puts them all to sleep at once
 *  (awake = false; static bodies are refused with I2D_ERR_INVALID_ARGUMENT). */
I2D_API i2d_status i2d_body_set_awake(i2d_body_id body, bool awake);
I2D_API void* i2d_body_get_user_data(i2d_body_id body);
I2D_API i2d_status i2d_body_set_user_data(i2d_body_id body, void* user_data);
I2D_API int32_t i2d_body_get_shape_count(i2d_body_id body);
/** Fills out with up to capacity shape ids; returns how many the body has. */
I2D_API int32_t i2d_body_get_shapes(i2d_body_id body, i2d_shape_id* out, int32_t capacity);

/* ---- Changing a body at run time ------------------------------------------------- */
/* Every setter refuses a stale id, a locked world and a bad value (NaN, infinite, out of
 * range: I2D_ERR_INVALID_ARGUMENT) with the world untouched, and takes effect at the next
 * step. Getters give a zero value for a bad id. */

/** The body's mass, centre of mass (body frame) and rotational inertia about it. */
I2D_API i2d_mass_data i2d_body_get_mass_data(i2d_body_id body);
/** Overrides the mass its shapes give a dynamic body: mass > 0 kg, inertia >= 0 (0 turns
 *  off rotation unless fixed_rotation says otherwise), center within 1e5 m of the body's
 *  origin. Later shape changes keep the override until i2d_body_apply_mass_from_shapes.
 *  Static and kinematic bodies are refused (they have no mass). Wakes the body. */
I2D_API i2d_status i2d_body_set_mass_data(i2d_body_id body, i2d_mass_data data);
/** Drops an override: the mass comes from the shapes' densities again. */
I2D_API i2d_status i2d_body_apply_mass_from_shapes(i2d_body_id body);
/** A disabled body is out of the world: its shapes leave the broadphase (no contacts, no
 *  queries, no sensor visits), its contacts end (with end events, as when a shape is
 *  destroyed, and what touched it wakes), its joints are not solved and do not hold
 *  islands together, it does not move and neither sleeps nor wakes (i2d_body_is_awake
 *  gives false, i2d_body_set_awake does nothing to it). It keeps its shapes, joints,
 *  velocity, forces, user data and ids, and every getter and setter still works on it:
 *  a pose set moves it at once (without waking anything), shapes and joints can be made
 *  on it, and what it is given waits for it to come back: a velocity set or an impulse
 *  applied changes the velocity it keeps, a force or torque acts in its first step back
 *  (whatever `wake` says). Static bodies can be disabled too. Enabling brings it back where
 *  it stands, awake: its pairs are found at the next step and its joints solved again.
 *  Each is a no-op when already so (not a change for rollback states); otherwise each is
 *  a structural change (rollback states saved before are refused). I2D_ERR_INVALID_HANDLE
 *  for a bad id, I2D_ERR_WORLD_LOCKED inside a callback; i2d_body_is_enabled gives false
 *  for a bad id. */
I2D_API i2d_status i2d_body_disable(i2d_body_id body);
I2D_API i2d_status i2d_body_enable(i2d_body_id body);
I2D_API bool i2d_body_is_enabled(i2d_body_id body);
/** Sets a kinematic body's velocities so that it reaches target (rotation normalised
 *  within 1e-3) in time_step seconds (> 0): the way to move a scripted platform and have
 *  what rides it follow. Its centre of mass arrives exactly; its angle as the step's
 *  integrator turns it, short of a turn theta by about theta^3 / (3 n^2) for n substeps
 *  (under 1e-5 rad for 0.05 rad in 4 substeps). The turn is the short way round. Static
 *  and dynamic bodies are refused. Wakes it if it moves. */
I2D_API i2d_status i2d_body_set_target_transform(i2d_body_id body, i2d_transform target, float time_step);
I2D_API i2d_status i2d_body_set_bullet(i2d_body_id body, bool flag);
I2D_API bool i2d_body_is_bullet(i2d_body_id body);
/** False keeps the body (and whatever touches it) awake, and wakes it now. */
I2D_API i2d_status i2d_body_enable_sleep(i2d_body_id body, bool flag);
I2D_API bool i2d_body_is_sleep_enabled(i2d_body_id body);
/** The speed below which the body counts as resting, in the world's length units per
 *  second; [0, 1e5]. A body starts with the world def's sleep_speed_threshold. */
I2D_API i2d_status i2d_body_set_sleep_threshold(i2d_body_id body, float speed);
I2D_API float i2d_body_get_sleep_threshold(i2d_body_id body);
/** Finite, may be negative; wakes the body. */
I2D_API i2d_status i2d_body_set_gravity_scale(i2d_body_id body, float scale);
I2D_API float i2d_body_get_gravity_scale(i2d_body_id body);
/** 1/s, >= 0 (as i2d_body_def). */
I2D_API i2d_status i2d_body_set_linear_damping(i2d_body_id body, float damping);
I2D_API float i2d_body_get_linear_damping(i2d_body_id body);
I2D_API i2d_status i2d_body_set_angular_damping(i2d_body_id body, float damping);
I2D_API float i2d_body_get_angular_damping(i2d_body_id body);
/** A fixed-rotation body never turns; setting it stops its spin. Wakes the body. */
I2D_API i2d_status i2d_body_set_fixed_rotation(i2d_body_id body, bool flag);
I2D_API bool i2d_body_is_fixed_rotation(i2d_body_id body);

/* ---- Contact data: what touches what now ------------------------------------------ */

/* Getters: they read what the last step left (a contact destroyed between steps, with a
 * shape, a body or a filter change, is gone at once; new ones come with the next step)
 * and work inside query callbacks. Each fills out with up to capacity entries and returns how many there
 * are, so that a call with capacity 0 (out may be NULL) sizes the array. A bad id gives
 * 0 and I2D_ERR_INVALID_HANDLE; out NULL with capacity > 0, or capacity < 0, gives 0 and
 * I2D_ERR_INVALID_ARGUMENT. */

/** The body's touching contacts (within the contact slop when the last step ended;
 *  sensors' visits excluded), in no documented order but the same for the same world. */
I2D_API int32_t i2d_body_get_contact_data(i2d_body_id body, i2d_contact_data* out, int32_t capacity);
/** The same for one shape: the body's contacts that involve it. */
I2D_API int32_t i2d_shape_get_contact_data(i2d_shape_id shape, i2d_contact_data* out, int32_t capacity);
/** The shapes visiting the sensor shape as of the last step: the visitors whose sensor
 *  begin event came and whose end event has not, so only visitors with sensor events
 *  enabled. A sensor on any body type sees the non-sensor shapes of dynamic and kinematic
 *  bodies, and of static ones unless it is static itself. A shape that is not a sensor is
 *  refused (I2D_ERR_INVALID_ARGUMENT). */
I2D_API int32_t i2d_shape_get_sensor_overlaps(i2d_shape_id sensor, i2d_shape_id* out, int32_t capacity);

/* ---- Bulk state: many bodies per call ------------------------------------------- */
/* For bindings and tools that read or write thousands of bodies per frame: one call
 * instead of one per body. Every call takes `count` body ids of `world` and arrays of at
 * least `count` elements; it reads and writes only the first `count` elements. Each id is
 * checked first: a null, stale or foreign id (of another world) or a wrong kind stops
 * the call with I2D_ERR_INVALID_HANDLE and a message naming its index ("bodies[7]: ..."),
 * and a bad value stops it with I2D_ERR_INVALID_ARGUMENT naming the element. A refused
 * call writes nothing at all: neither the output arrays nor the world. count 0 does
 * nothing (the pointers may then be NULL); a negative count is refused. */

/** Copies the transforms of bodies[0..count) into out[0..count). */
I2D_API i2d_status i2d_world_get_body_transforms(i2d_world_id world, const i2d_body_id* bodies, int32_t count,
                                                 i2d_transform* out);
/** Copies the velocities of bodies[0..count): linear (m/s, of the centre of mass) into
 *  linear, angular (rad/s) into angular. Either array may be NULL to skip it. */
I2D_API i2d_status i2d_world_get_body_velocities(i2d_world_id world, const i2d_body_id* bodies, int32_t count,
                                                 i2d_vec2* linear, float* angular);
/** Sets the velocities of bodies[0..count), as i2d_body_set_linear_velocity and
 *  i2d_body_set_angular_velocity do one by one: finite values only, ignored for static
 *  (and, for spin, fixed-rotation) bodies but still checked, a non-zero velocity wakes a
 *  sleeping body. Either array may be NULL to leave that part unchanged. A body listed
 *  twice gets its last values. Refused inside a query callback (I2D_ERR_WORLD_LOCKED). */
I2D_API i2d_status i2d_world_set_body_velocities(i2d_world_id world, const i2d_body_id* bodies, int32_t count,
                                                 const i2d_vec2* linear, const float* angular);
/** Teleports bodies[0..count) as i2d_body_set_transform does one by one: positions
 *  within 1e9 m of the origin, rotations normalised within 1e-3 (stored exactly
 *  normalised); each moved body wakes with what touches it. Refused inside a query
 *  callback. */
I2D_API i2d_status i2d_world_set_body_transforms(i2d_world_id world, const i2d_body_id* bodies, int32_t count,
                                                 const i2d_transform* in);

/* ---- Shapes --------------------------------------------------------------------- */

/** A circle in the body frame. Radius in [0.0001, 100000] m. */
I2D_API i2d_shape_id i2d_shape_create_circle(i2d_body_id body, const i2d_shape_def* def,
                                             const i2d_circle* circle);
/** A box axis-aligned in the body's frame, centred on the body origin (it turns with the
 *  body). On a fixed-rotation body it is the seed's AABB. Half sizes in [0.0001, 100000] m. */
I2D_API i2d_shape_id i2d_shape_create_box(i2d_body_id body, const i2d_shape_def* def, float half_width,
                                          float half_height);
/** A box centred at `center` in the body frame, turned by `rotation` there. */
I2D_API i2d_shape_id i2d_shape_create_offset_box(i2d_body_id body, const i2d_shape_def* def, float half_width,
                                                 float half_height, i2d_vec2 center, i2d_rot rotation);
/** The convex hull of 3 to 8 points in the body frame. Collinear, duplicate (closer
 *  than 0.005 m) or tiny input is refused with a message that says which. */
I2D_API i2d_shape_id i2d_shape_create_polygon(i2d_body_id body, const i2d_shape_def* def,
                                              const i2d_vec2* points, int32_t count);
/** A polygon made by i2d_make_polygon, i2d_make_box or i2d_make_offset_box, which may be
 *  rounded; it is checked to be convex, counter-clockwise and consistent. */
I2D_API i2d_shape_id i2d_shape_create_polygon_from(i2d_body_id body, const i2d_shape_def* def,
                                                   const i2d_polygon* polygon);
/** Every point within radius of the segment center1-center2 (body frame). The centres
 *  must be at least 0.005 m apart (else use a circle); radius in [0.0001, 100000] m. */
I2D_API i2d_shape_id i2d_shape_create_capsule(i2d_body_id body, const i2d_shape_def* def, i2d_vec2 center1,
                                              i2d_vec2 center2, float radius);
/** A two-sided line segment (body frame), at least 0.005 m long. It has no mass: meant
 *  for static geometry; dynamic bodies need other shapes for mass. */
I2D_API i2d_shape_id i2d_shape_create_segment(i2d_body_id body, const i2d_shape_def* def, i2d_vec2 point1,
                                              i2d_vec2 point2);
/** Destroys the shape; its body's mass is updated. */
I2D_API i2d_status i2d_shape_destroy(i2d_shape_id shape);
I2D_API bool i2d_shape_is_valid(i2d_shape_id shape);
I2D_API i2d_body_id i2d_shape_get_body(i2d_shape_id shape);
I2D_API i2d_shape_type i2d_shape_get_type(i2d_shape_id shape);
/** The circle in the body frame; zero for another kind (I2D_ERR_INVALID_ARGUMENT). */
I2D_API i2d_circle i2d_shape_get_circle(i2d_shape_id shape);
/** The polygon in the body frame (boxes are polygons); zero for another kind
 *  (I2D_ERR_INVALID_ARGUMENT). */
I2D_API i2d_polygon i2d_shape_get_polygon(i2d_shape_id shape);
/** The capsule in the body frame; zero for another kind (I2D_ERR_INVALID_ARGUMENT). */
I2D_API i2d_capsule i2d_shape_get_capsule(i2d_shape_id shape);
/** The segment in the body frame (of a segment or a chain segment); zero for another kind
 *  (I2D_ERR_INVALID_ARGUMENT). */
I2D_API i2d_segment i2d_shape_get_segment(i2d_shape_id shape);
/** Tight world-space bounds. */
I2D_API i2d_aabb i2d_shape_get_aabb(i2d_shape_id shape);
I2D_API float i2d_shape_get_density(i2d_shape_id shape);
I2D_API float i2d_shape_get_friction(i2d_shape_id shape);
I2D_API i2d_status i2d_shape_set_friction(i2d_shape_id shape, float friction);
I2D_API float i2d_shape_get_restitution(i2d_shape_id shape);
I2D_API i2d_status i2d_shape_set_restitution(i2d_shape_id shape, float restitution);
I2D_API i2d_filter i2d_shape_get_filter(i2d_shape_id shape);
I2D_API i2d_status i2d_shape_set_filter(i2d_shape_id shape, i2d_filter filter);
I2D_API bool i2d_shape_is_sensor(i2d_shape_id shape);
I2D_API void* i2d_shape_get_user_data(i2d_shape_id shape);
I2D_API i2d_status i2d_shape_set_user_data(i2d_shape_id shape, void* user_data);

/* ---- Changing a shape at run time ------------------------------------------------- */
/* As the body setters: refused with the world untouched on a bad id, a locked world or a
 * bad value; in effect at the next step. */

/** New geometry, checked as at creation; the shape's kind may change (a chain's segments
 *  are refused). The body's mass is made again from its shapes (unless
 *  i2d_body_set_mass_data overrode it), its contacts are made afresh at the next step,
 *  and it wakes. */
I2D_API i2d_status i2d_shape_set_circle(i2d_shape_id shape, const i2d_circle* circle);
I2D_API i2d_status i2d_shape_set_capsule(i2d_shape_id shape, const i2d_capsule* capsule);
I2D_API i2d_status i2d_shape_set_segment(i2d_shape_id shape, const i2d_segment* segment);
I2D_API i2d_status i2d_shape_set_polygon(i2d_shape_id shape, const i2d_polygon* polygon);
/** kg/m^2 in [0, 1e10]; update_body_mass false leaves the body's mass until the next
 *  shape change or i2d_body_apply_mass_from_shapes. */
I2D_API i2d_status i2d_shape_set_density(i2d_shape_id shape, float density, bool update_body_mass);
/** Friction, restitution, rolling resistance and tangent speed at once (ranges as in
 *  i2d_shape_def); touching contacts take the new values at the next step. */
I2D_API i2d_status i2d_shape_set_material(i2d_shape_id shape, i2d_surface_material material);
I2D_API i2d_surface_material i2d_shape_get_material(i2d_shape_id shape);
/** As the shape def's flags of the same names; sensor events apply to visits that begin
 *  after the call. */
I2D_API i2d_status i2d_shape_enable_sensor_events(i2d_shape_id shape, bool flag);
I2D_API bool i2d_shape_are_sensor_events_enabled(i2d_shape_id shape);
I2D_API i2d_status i2d_shape_enable_contact_events(i2d_shape_id shape, bool flag);
I2D_API bool i2d_shape_are_contact_events_enabled(i2d_shape_id shape);
I2D_API i2d_status i2d_shape_enable_hit_events(i2d_shape_id shape, bool flag);
I2D_API bool i2d_shape_are_hit_events_enabled(i2d_shape_id shape);
/** The point of the shape (its outline grown by its radius, inside included) closest to
 *  target, in world coordinates, where its body is now: target itself when the shape holds
 *  it. A getter (works inside query callbacks). (0, 0) for a bad id (I2D_ERR_INVALID_HANDLE)
 *  or a target that is not finite or beyond 1e9 m (I2D_ERR_INVALID_ARGUMENT). */
I2D_API i2d_vec2 i2d_shape_get_closest_point(i2d_shape_id shape, i2d_vec2 target);

/* ---- Chains --------------------------------------------------------------------- */

I2D_API i2d_chain_def i2d_default_chain_def(void);
/** Creates the chain's segments as shapes (I2D_SHAPE_CHAIN_SEGMENT) of a static or
 *  kinematic body; returns the null id on failure: I2D_ERR_INVALID_ARGUMENT for a def not
 *  from i2d_default_chain_def, NULL points, too few or too many points, NaN or infinite
 *  or out-of-range values, consecutive points closer than 0.005 m, a material count that
 *  is neither 0, 1 nor the segment count, or a dynamic body; I2D_ERR_INVALID_HANDLE for a
 *  bad body; I2D_ERR_WORLD_LOCKED inside a query callback. Its segments are destroyed
 *  with it (i2d_shape_destroy refuses them) and with their body. */
I2D_API i2d_chain_id i2d_chain_create(i2d_body_id body, const i2d_chain_def* def);
I2D_API i2d_status i2d_chain_destroy(i2d_chain_id chain);
I2D_API bool i2d_chain_is_valid(i2d_chain_id chain);
/** The chain's segment shapes in chain order: fills out with up to capacity ids and
 *  returns the segment count; -1 on error. */
I2D_API int32_t i2d_chain_get_segments(i2d_chain_id chain, i2d_shape_id* out, int32_t capacity);
/** The chain a segment shape belongs to; the null id for other shapes. */
I2D_API i2d_chain_id i2d_shape_get_chain(i2d_shape_id shape);

/* ---- Queries -------------------------------------------------------------------- */

/** Return false to stop the query. Runs on the calling thread with the world locked. */
typedef bool i2d_overlap_fn(i2d_shape_id shape, void* context);

/** Calls fn for every shape whose geometry overlaps or touches aabb, in a fixed order. */
I2D_API i2d_status i2d_world_overlap_aabb(i2d_world_id world, i2d_aabb aabb, i2d_query_filter filter,
                                          i2d_overlap_fn* fn, void* context);
/** Calls fn for every shape that contains the point (boundary included). */
I2D_API i2d_status i2d_world_overlap_point(i2d_world_id world, i2d_vec2 point, i2d_query_filter filter,
                                           i2d_overlap_fn* fn, void* context);
/** The same as i2d_world_overlap_aabb without a callback, for FFI: fills out with up to
 *  capacity ids and returns the total found (so a second call can size the buffer);
 *  -1 on error. out may be NULL when capacity is 0. */
I2D_API int32_t i2d_world_overlap_aabb_ids(i2d_world_id world, i2d_aabb aabb, i2d_query_filter filter,
                                           i2d_shape_id* out, int32_t capacity);

typedef struct i2d_ray_result {
    i2d_shape_id shape;
    i2d_vec2 point;   /**< where the ray enters the shape */
    i2d_vec2 normal;  /**< unit surface normal there */
    float fraction;   /**< point = origin + fraction * translation, in [0, 1] */
    bool hit;
} i2d_ray_result;

/** The first shape along origin + t * translation, t in [0, 1]. A shape that contains
 *  the origin is not hit (the ray starts inside it). Zero translation hits nothing.
 *  Refused (I2D_ERR_INVALID_ARGUMENT), as by every ray cast of the world: NaN or
 *  infinite values, an origin beyond 1e9 m of the world origin on either axis, or a
 *  translation longer than 1e9 m (its length; exactly 1e9 m is taken). */
I2D_API i2d_ray_result i2d_world_cast_ray_closest(i2d_world_id world, i2d_vec2 origin, i2d_vec2 translation,
                                                  i2d_query_filter filter);

/** Called for each shape a ray hits, in no particular order. Return -1 to ignore this
 *  shape (the ray goes on), 0 to stop the cast, `fraction` to clip the ray there (the
 *  closest hit is then found last), or 1 to go on unclipped. Runs with the world locked. */
typedef float i2d_cast_result_fn(i2d_shape_id shape, i2d_vec2 point, i2d_vec2 normal, float fraction,
                                 void* context);

/** Casts a ray through the world and reports hits to fn (see i2d_cast_result_fn). */
I2D_API i2d_status i2d_world_cast_ray(i2d_world_id world, i2d_vec2 origin, i2d_vec2 translation,
                                      i2d_query_filter filter, i2d_cast_result_fn* fn, void* context);

/** Every shape the ray hits, for FFI: fills out with up to capacity results sorted by
 *  fraction (nearest first; ties in a fixed order) and returns the total number of hits
 *  (more than capacity when it was too small); -1 on error. out may be NULL when
 *  capacity is 0. */
I2D_API int32_t i2d_world_cast_ray_all(i2d_world_id world, i2d_vec2 origin, i2d_vec2 translation,
                                       i2d_query_filter filter, i2d_ray_result* out, int32_t capacity);
/** i2d_world_overlap_point without a callback: up to capacity ids, returns the total
 *  found; -1 on error. */
I2D_API int32_t i2d_world_overlap_point_ids(i2d_world_id world, i2d_vec2 point, i2d_query_filter filter,
                                            i2d_shape_id* out, int32_t capacity);

/** Sweeps the proxy (world space, see i2d_make_proxy) along translation and reports each
 *  shape it would touch to fn: the fraction of the translation at which they first touch
 *  (to within 1.25 mm, times the world's length_units_per_meter), the point on that
 *  shape's surface and its outward normal there; fn's return value works as for rays. A shape the proxy overlaps at the start is hit at
 *  fraction 0, whatever the translation, with a point inside both and the unit normal
 *  along which the proxy leaves the shape soonest (the shape's outward side; back along
 *  the translation when a circle proxy's centre is the circle shape's). Refused
 *  (I2D_ERR_INVALID_ARGUMENT): a proxy of count 0 or outside 1..8, NaN or infinite
 *  values, a zero translation (use i2d_world_overlap_shape) or one longer than 1e9 m
 *  (its length; exactly 1e9 m is taken). Runs with the world locked. */
I2D_API i2d_status i2d_world_cast_shape(i2d_world_id world, const i2d_shape_proxy* proxy, i2d_vec2 translation,
                                        i2d_query_filter filter, i2d_cast_result_fn* fn, void* context);
/** The closest shape the swept proxy touches; .hit false when none. */
I2D_API i2d_ray_result i2d_world_cast_shape_closest(i2d_world_id world, const i2d_shape_proxy* proxy,
                                                    i2d_vec2 translation, i2d_query_filter filter);
/** Calls fn for every shape whose geometry overlaps or touches the proxy (world space). */
I2D_API i2d_status i2d_world_overlap_shape(i2d_world_id world, const i2d_shape_proxy* proxy, i2d_query_filter filter,
                                           i2d_overlap_fn* fn, void* context);
/** i2d_world_overlap_shape without a callback: up to capacity ids, returns the total
 *  found; -1 on error. */
I2D_API int32_t i2d_world_overlap_shape_ids(i2d_world_id world, const i2d_shape_proxy* proxy,
                                            i2d_query_filter filter, i2d_shape_id* out, int32_t capacity);

/* ---- Events --------------------------------------------------------------------- */
/* The arrays belong to the world and describe the last step. They stay valid until the
 * next i2d_world_step or i2d_world_destroy, whatever else the caller does meanwhile.
 * End events caused between steps (destroying a touching shape or its body) are
 * reported with the next step's events. Ids in end events may be stale. Empty arrays
 * (count 0) on a bad world id. */

I2D_API i2d_contact_events i2d_world_get_contact_events(i2d_world_id world);
I2D_API i2d_sensor_events i2d_world_get_sensor_events(i2d_world_id world);
/** Every body that moved during the last step: one call per frame instead of one per
 *  body; and every body the step quarantined (i2d_body_quarantine_event). */
I2D_API i2d_body_events i2d_world_get_body_events(i2d_world_id world);

/** Rebuilds the static tree top-down for the best query cost; worth calling once after
 *  creating a large static level. */
I2D_API i2d_status i2d_world_rebuild_static_tree(i2d_world_id world);

#endif
