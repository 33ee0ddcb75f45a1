/* SPDX-License-Identifier: MIT */
/* Value types, definitions with defaults, filters and counters. */
#ifndef IMPULSE2D_TYPES_H
#define IMPULSE2D_TYPES_H

#include "base.h"
#include "id.h"

typedef struct i2d_vec2 { float x, y; } i2d_vec2;
/** A rotation as cosine and sine. Identity is (c = 1, s = 0). */
typedef struct i2d_rot { float c, s; } i2d_rot;
typedef struct i2d_transform { i2d_vec2 p; i2d_rot q; } i2d_transform;
/** Axis-aligned box; min is the lower-left corner (y points up). */
typedef struct i2d_aabb { i2d_vec2 min, max; } i2d_aabb;

typedef enum i2d_body_type {
    I2D_BODY_STATIC = 0, /**< never moves; infinite mass */
    I2D_BODY_KINEMATIC,  /**< moves by its velocity only; infinite mass; pushes dynamic bodies */
    I2D_BODY_DYNAMIC     /**< moved by gravity, forces and contacts */
} i2d_body_type;

typedef enum i2d_shape_type {
    I2D_SHAPE_CIRCLE = 0,
    I2D_SHAPE_CAPSULE, /**< two half discs joined by a rectangle */
    I2D_SHAPE_SEGMENT, /**< a two-sided line segment, no mass */
    I2D_SHAPE_POLYGON, /**< convex, up to 8 vertices, optionally rounded; boxes are polygons */
    I2D_SHAPE_CHAIN_SEGMENT /**< one segment of a chain (i2d_chain_create): one-sided, no mass */
} i2d_shape_type;

/** Which shapes collide. Two shapes collide when each one's category_bits meet the
 *  other's mask_bits, unless they share a group_index: a shared positive group always
 *  collides, a shared negative group never does. */
typedef struct i2d_filter {
    uint64_t category_bits; /**< default 1 */
    uint64_t mask_bits;     /**< default all bits */
    int32_t group_index;    /**< default 0 (no group) */
} i2d_filter;

/** Which shapes a query sees: those whose category_bits meet mask_bits and whose
 *  mask_bits meet category_bits. The default sees every shape. */
typedef struct i2d_query_filter {
    uint64_t category_bits;
    uint64_t mask_bits;
} i2d_query_filter;

/** How a contact combines the two shapes' friction or restitution. */
typedef enum i2d_mixing_rule {
    I2D_MIX_GEOMETRIC_MEAN = 0, /**< sqrt(a b): the default for friction */
    I2D_MIX_MINIMUM,            /**< min(a, b): the default for restitution (the seed's rule) */
    I2D_MIX_MAXIMUM,            /**< max(a, b) */
    I2D_MIX_AVERAGE,            /**< (a + b) / 2 */
    I2D_MIX_MULTIPLY            /**< a b */
} i2d_mixing_rule;

/** Which instruction set solves contacts. Every path gives bitwise the same results; the
 *  widest the CPU supports is the fastest. Check i2d_simd_path_supported() before asking
 *  for one. */
typedef enum i2d_simd_path {
    I2D_SIMD_AUTOMATIC = 0, /**< the widest this CPU supports (the default) */
    I2D_SIMD_SCALAR,        /**< one contact at a time, plain C++: every platform */
    I2D_SIMD_SSE2,          /**< 4 contacts at a time: every x86-64 CPU */
    I2D_SIMD_AVX2,          /**< 8 contacts at a time: x86-64 CPUs with AVX2 */
    I2D_SIMD_AVX512,        /**< 16 contacts at a time: x86-64 CPUs with AVX-512F */
    I2D_SIMD_NEON,          /**< 4 contacts at a time: every AArch64 CPU */
    I2D_SIMD_WASM128        /**< 4 contacts at a time: WebAssembly SIMD (the JavaScript package's SIMD module) */
} i2d_simd_path;

/** Most worlds alive at once; creating and destroying them is unlimited. */
#define I2D_MAX_WORLDS 4096

/** Most workers a world may have (i2d_world_def.worker_count). */
#define I2D_MAX_WORKERS 64

/** A piece of a step's work: items [start_index, end_index) on worker worker_index, which
 *  is in [0, worker_count) and names one thread at a time. */
typedef void i2d_task_fn(int32_t start_index, int32_t end_index, int32_t worker_index, void* task_context);
/** Your job system's entry: run task over the items [0, item_count), in ranges of at least
 *  min_range, on threads of yours, and return a handle for i2d_finish_task_fn; or run it
 *  all on the calling thread and return NULL. The engine enqueues one task per worker
 *  beyond the first and works as worker 0 itself; tasks may start in any order, late, or
 *  one after another: the step never waits for a task that has not started. */
typedef void* i2d_enqueue_task_fn(i2d_task_fn* task, int32_t item_count, int32_t min_range, void* task_context,
                                  void* user_task_context);
/** Waits until the task behind the handle has run to its end. Both callbacks run inside
 *  i2d_world_step: calls naming that world or anything in it are refused there
 *  (I2D_ERR_WORLD_LOCKED). */
typedef void i2d_finish_task_fn(void* user_task, void* user_task_context);

/** World settings. Obtain with i2d_default_world_def(), then edit. */
typedef struct i2d_world_def {
    /** m/s^2; default (0, -10). Finite. */
    i2d_vec2 gravity;
    /** Touching tolerance, m; default 0.005. Range [0, 1]. Shapes this close count as
     *  touching (contact begin/end events, counters), so that a resting contact, or a
     *  bounce stopped by a speculative contact exactly at the surface, is seen. */
    float contact_slop;
    /** Stiffness of contacts, Hz; default 60. Range [0.001, 1e5]. Overlap is removed like
     *  a damped spring of this frequency, capped at a quarter of the substep rate (60 Hz
     *  at 1/60 s and 4 substeps); contacts with static and kinematic bodies get twice the
     *  frequency. A contact carrying a load F settles at F / (m (2 pi hertz)^2) of
     *  overlap, m its effective mass: 0.14 mm for a 1 kg box on another, 0.65 cm
     *  summed down a column of ten. */
    float contact_hertz;
    /** Damping ratio of that spring; default 10 (heavily over-damped: no bounce from
     *  push-out). Range [0, 1e5]. */
    float contact_damping_ratio;
    /** Fastest speed at which overlap is pushed out, m/s; default 3. Range [0, 1e5].
     *  Bodies created overlapping separate gently rather than explode apart. */
    float contact_push_max_speed;
    /** Impacts slower than this (m/s) do not bounce; default 1. Range [0, 1e5]. */
    float restitution_threshold;
    /** Speed limit for every body, m/s; default 400. Range [1e-6, 1e5]. Guards the
     *  world against runaway values from huge forces or impulses. */
    float maximum_linear_speed;
    /** Default I2D_MIX_GEOMETRIC_MEAN. */
    i2d_mixing_rule friction_mixing;
    /** Default I2D_MIX_MINIMUM. */
    i2d_mixing_rule restitution_mixing;
    /** Lets resting bodies sleep; default true. A sleeping body costs nothing per step. */
    bool enable_sleep;
    /** A body is resting while its speed, and its spin times its largest extent, stay
     *  below this, m/s; default 0.05. Range [0, 1e5]. */
    float sleep_speed_threshold;
    /** Bodies touching one another fall asleep together once every one of them has
     *  rested this long, s; default 0.5. Range [0, 1e5]. */
    float time_to_sleep;
    /** Default I2D_SIMD_AUTOMATIC. A path the CPU does not support is refused. */
    i2d_simd_path simd_path;
    /** Default true. A contact whose two bodies moved less than 5 mm (2 mm if apart, both
     *  times length_units_per_meter; and turned less than 2 degrees) relative to each
     *  other since its manifold was made
     *  keeps that manifold, its points riding the bodies, instead of running the
     *  narrowphase again: resting stacks cost far less. False makes every contact's
     *  manifold afresh at every step. */
    bool enable_contact_recycling;
    /** Default false. Times every step's stages (i2d_world_get_profile) from the first
     *  step on. Without it timing starts at the first i2d_world_get_profile call: until
     *  then a step reads no clock. */
    bool enable_profile;
    /** Threads that share each step, in [1, I2D_MAX_WORKERS]; default 1. The results are
     *  the same bits for every count. A small world (fewer than a few hundred awake
     *  bodies) steps on the calling thread alone whatever the count. */
    int32_t worker_count;
    /** Your job system (both or neither). Neither with worker_count > 1: the world starts
     *  worker_count - 1 threads of its own at its first large step and stops them when it
     *  is destroyed. Default NULL. */
    i2d_enqueue_task_fn* enqueue_task;
    i2d_finish_task_fn* finish_task;
    /** Passed to enqueue_task and finish_task; default NULL. */
    void* user_task_context;
    /** Stiffness of the rigid parts of joints, Hz; default 60. Range [0.001, 1e5]. Like
     *  contact_hertz, capped at a quarter of the substep rate. Joints that hang a group of
     *  bodies from a body that does not move, closing at most four loops (a chain, a
     *  bridge hung at both ends), are solved exactly: for them this is only how fast
     *  position errors are pulled back. */
    float joint_hertz;
    /** Damping ratio of that stiffness; default 2. Range [0, 1e5]. */
    float joint_damping_ratio;
    /** Continuous collision; default true. A dynamic body that moves far for its size in
     *  a step (more than half its thinnest shape's inner radius) is swept from where the
     *  step began against static and kinematic shapes (along their own motion) and, if
     *  it would have passed through one, moved back to where it first touched, where
     *  the impact is solved as a contact would (no approach left, or the restitution's
     *  bounce; friction). Bullets (i2d_body_def.is_bullet) are swept against dynamic bodies
     *  too, other bullets included. Sensors report fast bodies that crossed them within
     *  a step (a begin and an end event in the same step). */
    bool enable_continuous;
    /** Impacts passed from body to body within one step taken one at a time; default
     *  true. A ball that strikes a row of balls standing a little apart (a Newton's
     *  cradle) hits the first, which hits the next within the same step: solved together,
     *  as the substeps solve every contact, the row shares the momentum; taken in the
     *  order the gaps close, each impact resolved alone (-restitution times its approach,
     *  Coulomb friction), the last ball leaves at the first one's speed. Only contacts of
     *  restitution 0.5 and more approaching faster than restitution_threshold take part,
     *  and only where an impact sets a neighbour moving into a third body: a lone bounce
     *  and a resting stack step as they would without it. */
    bool enable_impact_chains;
    /** Contact hit events are reported for impacts faster than this, m/s; default 1.
     *  Range [0, 1e5]. */
    float hit_event_threshold;
    /** The world's length unit: how many of them make a metre; default 1. Range
     *  [1e-3, 1e4]. A game in pixels at 50 per metre sets 50 and gives every length, speed
     *  and acceleration of every def and call on this world in pixels (densities per
     *  square pixel: divide them by 50^2 to keep the masses the metres would give). The
     *  engine's own tolerances scale with it: the linear slop (0.005 m: the manifolds'
     *  tie-breaks, the thinnest a shape counts for continuous collision, where a swept
     *  body stops, the tolerance of the world's shape casts), the speculative distance,
     *  the boxes' margins and the manifold-keeping distances of enable_contact_recycling.
     *  So the scene moves as the same scene in metres, scaled, within float rounding; at 1
     *  every result is the same bits as before there was a unit. The length-bearing fields
     *  of this def (contact_slop, contact_push_max_speed, restitution_threshold,
     *  maximum_linear_speed, sleep_speed_threshold, hit_event_threshold) are taken as
     *  given, in these units, and their ranges scale with it: start from
     *  i2d_default_world_def_in_units(50), which scales their defaults, not from
     *  i2d_default_world_def() with this field changed. Not scaled: the other defs'
     *  defaults (joints, shapes), the input limits of impulse2d.h's manual (shape sizes,
     *  core and edge lengths, positions: the same numbers in any unit) and the pure
     *  functions of collision.h, which know no world and work in metres. Each world has
     *  its own unit (Box2D has one setting for the whole process). */
    float length_units_per_meter;
    /** Set by i2d_default_world_def(); do not set. */
    uint32_t internal_cookie;
} i2d_world_def;

/** Body settings. Obtain with i2d_default_body_def(), then edit. */
typedef struct i2d_body_def {
    i2d_body_type type;        /**< default I2D_BODY_STATIC */
    /** Body origin in world, m; default (0, 0). Within 1e9 m of the origin. */
    i2d_vec2 position;
    /** Default identity. Must be normalised: c^2 + s^2 within 1e-3 of 1 (it is then
     *  normalised exactly); build it with i2d_make_rot(angle). */
    i2d_rot rotation;
    i2d_vec2 linear_velocity;  /**< m/s; default (0, 0). Finite. */
    /** rad/s, counter-clockwise positive; default 0. Finite. */
    float angular_velocity;
    /** 1/s; default 0. Range [0, inf). Each substep h scales velocity by 1/(1 + h c). */
    float linear_damping;
    /** 1/s; default 0. Range [0, inf). Each substep h scales angular velocity by 1/(1 + h c). */
    float angular_damping;
    float gravity_scale;       /**< default 1. Finite; may be negative. */
    /** Default false. A fixed-rotation body never turns (infinite rotational inertia):
     *  the seed's axis-aligned behaviour. */
    bool fixed_rotation;
    /** Default true. False keeps this body (and whatever touches it) awake. */
    bool enable_sleep;
    /** Default false. A bullet is a fast dynamic body swept against dynamic bodies too
     *  (bullets included), not only against static and kinematic ones (see
     *  i2d_world_def.enable_continuous). Costs more per step: use it for projectiles. */
    bool is_bullet;
    void* user_data;           /**< default NULL; returned by i2d_body_get_user_data */
    /** Set by i2d_default_body_def(); do not set. */
    uint32_t internal_cookie;
} i2d_body_def;

/** Shape settings. Obtain with i2d_default_shape_def(), then edit. */
typedef struct i2d_shape_def {
    /** kg/m^2; default 1. Range [0, 1e10]. Body mass is the sum of density x area. */
    float density;
    /** Coulomb friction coefficient; default 0.6. Range [0, inf). Mixed as the
     *  geometric mean of the two shapes'. */
    float friction;
    /** Bounciness; default 0. Range [0, 100] (1 = elastic, above 1 adds energy). A
     *  contact uses the minimum of the two shapes'. */
    float restitution;
    /** Rolling resistance coefficient; default 0. Range [0, 1e5]. A round shape (circle,
     *  capsule, rounded polygon) rolling on a surface feels a torque of at most this x
     *  its radius x the normal force, opposing the roll. A contact uses the larger of
     *  the two shapes' coefficient x radius. */
    float rolling_resistance;
    /** Speed of the shape's surface along its outline, m/s, counter-clockwise positive
     *  (the way a wheel spinning counter-clockwise moves its rim); default 0. Finite,
     *  |speed| <= 1e5. Friction drags touching bodies along: a conveyor belt. */
    float tangent_speed;
    /** Default false. A sensor detects overlaps but never pushes: it reports sensor
     *  begin/end events for shapes that enter and leave it. */
    bool is_sensor;
    /** Default true. Contact begin/end events are reported for a pair when both shapes
     *  enable them. */
    bool enable_contact_events;
    /** Default true. Whether sensors report this shape entering and leaving them. */
    bool enable_sensor_events;
    /** Default false. Contact hit events (i2d_contact_events.hit_events) for impacts of
     *  this shape faster than the world's hit_event_threshold; either shape of a pair
     *  may enable them. */
    bool enable_hit_events;
    /** Default false. Pairs with this shape reach the world's custom filter callback
     *  (toolkit.h) when their bounds first overlap. */
    bool enable_custom_filtering;
    /** Default false. Touching pairs with this shape reach the world's pre-solve callback
     *  (toolkit.h) every step. */
    bool enable_pre_solve_events;
    i2d_filter filter; /**< default: category 1, collides with everything, group 0 */
    void* user_data;   /**< default NULL */
    /** Set by i2d_default_shape_def(); do not set. */
    uint32_t internal_cookie;
} i2d_shape_def;

/** The material of a chain segment. */
typedef struct i2d_surface_material {
    float friction;           /**< as i2d_shape_def.friction; [0, inf) */
    float restitution;        /**< as i2d_shape_def.restitution; [0, 100] */
    float rolling_resistance; /**< as i2d_shape_def.rolling_resistance; [0, 1e5] */
    float tangent_speed;      /**< as i2d_shape_def.tangent_speed, m/s; |speed| <= 1e5 */
} i2d_surface_material;

/** Chain settings (level geometry). Obtain with i2d_default_chain_def(), then edit.
 *  Segments are one-sided: a shape collides with a segment from the right of the
 *  direction from point i to point i + 1 (where its normal points) and passes through it
 *  from the left. A floor is listed right to left; a closed loop listed clockwise keeps
 *  bodies inside it. Neighbouring segments know each other, so a box sliding along a
 *  flat chain never catches on a seam. */
typedef struct i2d_chain_def {
    /** The points, copied at creation; within 1e9 m of the origin, consecutive points at
     *  least 0.005 m apart. Open chains: at least 4, the first and the last being ghost
     *  points (they shape the ends' contacts but make no segment). Loops: at least 3. At
     *  most 1000000. Default NULL, 0. */
    const i2d_vec2* points;
    int32_t count;
    /** Default false. A loop joins the last point to the first. */
    bool is_loop;
    /** 0 materials: the shape def defaults (friction 0.6, restitution 0); 1: for every
     *  segment; one per segment (count - 3 open, count closed). Default NULL, 0. */
    const i2d_surface_material* materials;
    int32_t material_count;
    i2d_filter filter;          /**< default: category 1, collides with everything */
    bool enable_sensor_events;  /**< default true */
    void* user_data;            /**< default NULL; every segment shape gets it too */
    /** Set by i2d_default_chain_def(); do not set. */
    uint32_t internal_cookie;
} i2d_chain_def;

/** Sizes of a world, for tools and benchmarks. */
typedef struct i2d_world_counters {
    int32_t body_count;
    int32_t shape_count;
    int32_t contact_count;  /**< touching shape pairs (sensors excluded) after the last step */
    int32_t pair_count;     /**< contacts alive: shape pairs whose fat bounds overlap */
    int32_t static_tree_height;
    int32_t kinematic_tree_height;
    int32_t dynamic_tree_height;
    int32_t awake_body_count; /**< dynamic and kinematic bodies that are awake */
    int32_t sleeping_island_count; /**< groups of touching bodies asleep together */
} i2d_world_counters;

/** Where the last step's wall time went, ms, summed over its substeps. Timing only: it
 *  never changes results. Steps are timed once asked: from the first
 *  i2d_world_get_profile call, or from creation with the world def's enable_profile. */
typedef struct i2d_profile {
    float step;           /**< the whole i2d_world_step call */
    float pairs;          /**< broadphase: new pairs from shapes that moved */
    float collide;        /**< narrowphase: every contact's manifold */
    float solve;          /**< the soft step: integration, contact impulses, restitution */
    float update_bounds;  /**< shape bounds and tree re-insertions */
    float sleep;          /**< islands: which bodies fall asleep */
    float events;         /**< contact, sensor and body move events */
    float continuous;     /**< continuous collision: sweeping fast bodies */
} i2d_profile;

typedef struct i2d_manifold_point {
    i2d_vec2 point;    /**< world point midway between the two surfaces */
    float penetration; /**< > 0 overlapping, 0 touching; down to -0.02 m for speculative points */
    uint32_t id;       /**< feature key, stable from step to step for the same features */
} i2d_manifold_point;

/** Contact between two shapes. Moving B along normal by the largest penetration (or A
 *  against it) separates them. */
typedef struct i2d_manifold {
    i2d_vec2 normal;     /**< unit, points from shape A to shape B */
    int32_t point_count; /**< 0 = not touching; up to 2 */
    i2d_manifold_point points[2];
} i2d_manifold;

/** A touching contact: its shapes, its manifold as the last step left it (as a contact
 *  begin event shows one: world points where they are now, penetrations as the step's
 *  narrowphase measured them, normal from A to B) and the solver's impulses at each
 *  point. The impulses are those of the step's last substep (what the next step warm
 *  starts from, as Box2D's normalImpulse): divided by the substep, time_step /
 *  substep_count, they are the contact's force; times substep_count, the impulse of the
 *  whole step for a contact at rest (a box of mass m resting alone on the ground:
 *  normal impulses summing to m g time_step / substep_count). */
typedef struct i2d_contact_data {
    i2d_shape_id shape_a, shape_b; /**< in the order contact events name them */
    i2d_manifold manifold;
    /** N s per manifold point (0 past point_count), >= 0: on B along the normal, on A against it */
    float normal_impulses[2];
    /** N s per manifold point: on B along the normal turned 90 degrees counter-clockwise */
    float tangent_impulses[2];
} i2d_contact_data;

/* ---- Events: arrays owned by the world, valid until the next step or world change ---- */

/** Two shapes started touching during the last step (both enable contact events), with
 *  the contact's manifold: its normal (from A to B) and points (world, where they met,
 *  penetration at the start of the step). */
typedef struct i2d_contact_begin_event {
    i2d_shape_id shape_a, shape_b;
    i2d_manifold manifold;
} i2d_contact_begin_event;
/** Two shapes stopped touching, or one of them was destroyed while touching. The ids
 *  may be stale by the time you read them. */
typedef struct i2d_contact_end_event { i2d_shape_id shape_a, shape_b; } i2d_contact_end_event;
/** Two shapes met faster than the world's hit_event_threshold (one of them enables hit
 *  events): once per impact, in the step the impact is solved. */
typedef struct i2d_contact_hit_event {
    i2d_shape_id shape_a, shape_b;
    i2d_vec2 point;       /**< world, where the fastest point of the contact met */
    i2d_vec2 normal;      /**< unit, from shape A to shape B */
    float approach_speed; /**< m/s, along the normal, at impact (> 0) */
} i2d_contact_hit_event;
typedef struct i2d_contact_events {
    const i2d_contact_begin_event* begin_events;
    int32_t begin_count;
    const i2d_contact_end_event* end_events;
    int32_t end_count;
    const i2d_contact_hit_event* hit_events;
    int32_t hit_count;
} i2d_contact_events;

/** A shape (the visitor) started overlapping a sensor shape. */
typedef struct i2d_sensor_begin_event { i2d_shape_id sensor_shape, visitor_shape; } i2d_sensor_begin_event;
/** A visitor stopped overlapping a sensor, or one of the two was destroyed. */
typedef struct i2d_sensor_end_event { i2d_shape_id sensor_shape, visitor_shape; } i2d_sensor_end_event;
typedef struct i2d_sensor_events {
    const i2d_sensor_begin_event* begin_events;
    int32_t begin_count;
    const i2d_sensor_end_event* end_events;
    int32_t end_count;
} i2d_sensor_events;

/** A body that moved during the last step (dynamic and kinematic bodies). */
typedef struct i2d_body_move_event {
    i2d_transform transform;
    i2d_body_id body;
    void* user_data;
    bool fell_asleep; /**< the body fell asleep at the end of this step */
} i2d_body_move_event;
/** A body whose state (position, rotation or velocity) stopped being finite during the
 *  last step, which no accepted input should cause but an overflow somewhere still
 *  might. Instead of spreading NaN through the world, the step left it at the pose it
 *  started from (`transform`), made it static, ended its contacts and cleared its
 *  joints' impulses; every other body went on. A body that took the NaN from it within
 *  the same step (through a contact or a joint) is quarantined too. The body stays
 *  quarantined (i2d_body_is_quarantined) until its type is set again: give it a pose
 *  and velocity, then i2d_body_set_type(body, former_type) brings it back. */
typedef struct i2d_body_quarantine_event {
    i2d_transform transform;
    i2d_body_id body;
    void* user_data;
    i2d_body_type former_type; /**< its type before the quarantine made it static */
} i2d_body_quarantine_event;
typedef struct i2d_body_events {
    const i2d_body_move_event* move_events;
    int32_t move_count;
    const i2d_body_quarantine_event* quarantine_events;
    int32_t quarantine_count;
} i2d_body_events;

#endif
