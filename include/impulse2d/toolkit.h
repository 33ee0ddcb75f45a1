/* SPDX-License-Identifier: MIT */
/** @file toolkit.h
 *  The game toolkit: a character mover, contact hooks, explosions and debug drawing.
 *
 *  - The character mover moves a capsule by game code rather than by the solver: it walks,
 *    slides along walls, climbs slopes up to a limit and small steps, keeps to the ground
 *    going down, rides moving platforms and pushes dynamic bodies. The low-level calls
 *    (cast, collide, solve planes, clip) are here for movers of the caller's own design;
 *    i2d_world_move_character does the whole move in one call.
 *  - Contact hooks let game code decide, pair by pair, whether two shapes touch at all
 *    (custom filter) or in this step (pre-solve): one-way platforms, ghosts.
 *  - An explosion pushes every shape near it, by how much of its outline faces the blast.
 *  - Debug drawing hands the world to the caller's callbacks (SDL, raylib, a canvas, an
 *    editor): shapes coloured by their body's state, joints, bounds, contacts, islands. */
#ifndef IMPULSE2D_TOOLKIT_H
#define IMPULSE2D_TOOLKIT_H

#include "base.h"
#include "collision.h"
#include "id.h"
#include "types.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Character mover --------------------------------------------------------------- */

/** The plane of points x with dot(normal, x) = offset; normal is unit. */
typedef struct i2d_plane {
    i2d_vec2 normal;
    float offset;
} i2d_plane;

/** A plane the mover touches, as i2d_world_collide_mover reports it: the normal points
 *  from the shape toward the mover, and offset is the mover's signed separation along it
 *  (negative when overlapping). Moved by d, the mover keeps clear of the shape while
 *  offset + dot(normal, d) >= 0 (the plane standing in for the surface). */
typedef struct i2d_collision_plane {
    i2d_plane plane;
    /** How far the plane may push the mover; FLT_MAX for a rigid plane. */
    float push_limit;
    /** Output of i2d_solve_planes: how far the plane pushed. */
    float push;
    /** Whether i2d_clip_vector clips against this plane. */
    bool clip_velocity;
} i2d_collision_plane;

/** What i2d_solve_planes found: the translation that keeps every rigid plane's
 *  separation at least zero, and how many iterations it took. */
typedef struct i2d_plane_result {
    i2d_vec2 translation;
    int32_t iteration_count;
} i2d_plane_result;

/** The fraction of translation, in [0, 1], that the capsule (world coordinates) can move
 *  before it comes within the world's contact slop of a shape the filter sees (1: the
 *  whole way). It stops at a gap between a half and three quarters of the slop (the
 *  world def's contact_slop, at least the linear slop, 0.005 m in the world's units), so
 *  that i2d_world_collide_mover finds again what stopped it. Shapes it already touches
 *  (within that gap) or overlaps stop it only when it moves deeper into them: at once,
 *  fraction 0. It never passes through a shape however long the translation. Sensors are
 *  not seen. A query: allowed inside query callbacks. Bad input: 0 and a status. */
I2D_API float i2d_world_cast_mover(i2d_world_id world, const i2d_capsule* mover, i2d_vec2 translation,
                                   i2d_query_filter filter);

/** The planes of the shapes within the contact slop of the capsule (world coordinates,
 *  the slop as for i2d_world_cast_mover): touching, overlapping or slightly apart, one
 *  per shape, in a fixed order for the same world. Fills out with up to capacity planes
 *  (rigid: push_limit FLT_MAX, push 0, clip_velocity true) and returns how many there are
 *  (out may be NULL with capacity 0 to count). Sensors are not seen. Bad input: 0 and a
 *  status. */
I2D_API int32_t i2d_world_collide_mover(i2d_world_id world, const i2d_capsule* mover, i2d_query_filter filter,
                                        i2d_collision_plane* out, int32_t capacity);

/** Moves target_delta until every rigid plane's separation plus the move along its normal
 *  is at least zero (soft planes push at most push_limit), filling each plane's push:
 *  iterative projection, each plane pushing along its normal, never pulling, sweeps until
 *  the pushes settle (at most 32; iteration_count says how many, 0 without planes). Pure:
 *  needs no world. Refused (a zero translation, pushes untouched, a status): NaN or
 *  infinite input, a count below zero, NULL planes with a count, a normal not of unit
 *  length (within 1e-3), a push_limit below zero, an offset or a delta beyond 1e9. */
I2D_API i2d_plane_result i2d_solve_planes(i2d_vec2 target_delta, i2d_collision_plane* planes, int32_t count);

/** The vector with the part that runs into planes with clip_velocity set removed: the
 *  nearest vector that runs into none of them (in a corner of two, possibly zero). Pure;
 *  refused as i2d_solve_planes refuses, with a zero vector. */
I2D_API i2d_vec2 i2d_clip_vector(i2d_vec2 vector, const i2d_collision_plane* planes, int32_t count);

/** How i2d_world_move_character moves a character. Obtain with
 *  i2d_default_character_def(), then edit. */
typedef struct i2d_character_def {
    /** Radians in [0, pi/2); default 0.7854 (45 degrees). Steeper ground is a wall. */
    float max_slope_angle;
    /** Default 0.25 (world length units). Ledges up to this high are stepped onto. */
    float step_height;
    /** Default 0.2. Keeps the feet on the ground going down slopes and steps. */
    float snap_distance;
    /** Default 0.01. The gap kept to every surface; greater than 0. */
    float skin;
    /** Default 5, in [1, 64]. Cast-and-slide rounds per move. */
    int32_t max_iterations;
    /** kg, default 80. The mass the character pushes dynamic bodies with; 0: it does not
     *  push. */
    float push_mass;
    /** Which shapes the character meets; default every shape. */
    i2d_query_filter filter;
    /** Set by i2d_default_character_def(); do not set. */
    uint32_t internal_cookie;
} i2d_character_def;

/** Where a move left the character. */
typedef struct i2d_character_result {
    /** Where the capsule's local origin ends. */
    i2d_vec2 position;
    /** The velocity asked for, clipped by what the character ends up touching: walls and
     *  ceilings take away the part that runs into them (and a wall too steep to walk, the
     *  part that would rise along it); ground takes away only the downward part, so a
     *  level walk onto a ramp or a step stays level rather than turning into a climb that
     *  would carry the character off the top. It does not include ground_velocity: add
     *  that to ride a moving platform. */
    i2d_vec2 velocity;
    /** Whether a plane under the character has a normal within max_slope_angle of up
     *  (up is opposite the world's gravity; +y in a world without gravity). */
    bool on_ground;
    /** The ground's normal; zero when not on the ground. */
    i2d_vec2 ground_normal;
    /** The shape stood on; null when not on the ground. */
    i2d_shape_id ground_shape;
    /** The velocity of the ground's body at the feet. */
    i2d_vec2 ground_velocity;
    /** How many distinct shapes the move touched (counted up to 64). */
    int32_t hit_count;
} i2d_character_result;

I2D_API i2d_character_def i2d_default_character_def(void);

/** Moves the capsule (given in the character's local frame) from position by velocity *
 *  time_step: cast-and-slide against the shapes the filter sees (sensors not), keeping
 *  `skin` (plus at most the contact slop) from every surface, not climbing ground
 *  steeper than max_slope_angle, stepping onto ledges up to step_height and snapping
 *  down to ground within snap_distance (only when it was on the ground and is not moving
 *  up). It never passes through a shape however fast it moves. Each dynamic body it ends
 *  up touching and moving into gets an impulse, as from a body of push_mass meeting it
 *  in a plastic collision (and wakes); apart from those (push_mass > 0), it changes
 *  nothing in the world, and a move with push_mass 0 is a query, allowed inside query
 *  callbacks (one that pushes gets I2D_ERR_WORLD_LOCKED there). Allocates nothing. Bad
 *  input (NaN, inf, a negative time step, a move longer than 1e9, a bad id, NULL, an
 *  uninitialised def or one out of its ranges, a capsule radius outside [1e-4, 1e5]): a
 *  status, out zeroed and the world untouched. */
I2D_API i2d_status i2d_world_move_character(i2d_world_id world, const i2d_character_def* def,
                                            const i2d_capsule* capsule, i2d_vec2 position, i2d_vec2 velocity,
                                            float time_step, i2d_character_result* out);

/* ---- Contact hooks ----------------------------------------------------------------- */

/** Whether the two shapes may ever touch; false: they pass through each other. Called when
 *  their bounds first overlap, for pairs where either shape has enable_custom_filtering.
 *  Runs inside the step, possibly on several worker threads at once: it must be
 *  thread-safe, and every call on that world from inside it answers I2D_ERR_WORLD_LOCKED
 *  (getters too). The results do not depend on the worker count as long as the answer
 *  depends only on the arguments. */
typedef bool i2d_custom_filter_fn(i2d_shape_id shape_a, i2d_shape_id shape_b, void* context);

/** Whether the touching contact takes part in this step; false: it is off for this step
 *  (no impulse, no begin event until it is on again). Called every step the pair touches,
 *  after the narrowphase, with the manifold (normal from A to B), for pairs where either
 *  shape has enable_pre_solve_events. Threads and locking as for i2d_custom_filter_fn. */
typedef bool i2d_pre_solve_fn(i2d_shape_id shape_a, i2d_shape_id shape_b, const i2d_manifold* manifold,
                              void* context);

/** Sets (or with NULL clears) the world's custom filter. Pairs already in contact keep
 *  their contact until their bounds part. */
I2D_API i2d_status i2d_world_set_custom_filter_callback(i2d_world_id world, i2d_custom_filter_fn* fn,
                                                        void* context);
/** Sets (or with NULL clears) the world's pre-solve callback. */
I2D_API i2d_status i2d_world_set_pre_solve_callback(i2d_world_id world, i2d_pre_solve_fn* fn, void* context);

/** Turns a shape's pre-solve opt-in (i2d_shape_def.enable_pre_solve_events) on or off;
 *  its contacts follow from the next step. */
I2D_API i2d_status i2d_shape_enable_pre_solve_events(i2d_shape_id shape, bool flag);
I2D_API bool i2d_shape_are_pre_solve_events_enabled(i2d_shape_id shape);

/* ---- Explosions -------------------------------------------------------------------- */

/** A blast. Obtain with i2d_default_explosion_def(), then edit. */
typedef struct i2d_explosion_def {
    /** Shapes whose category_bits meet it are pushed; default every bit. */
    uint64_t mask_bits;
    i2d_vec2 position;
    /** Full strength within it; default 1, >= 0. */
    float radius;
    /** Fading linearly to zero over this much beyond the radius; default 0, >= 0. */
    float falloff;
    /** N s per length unit of the shape's outline that faces the blast; default 1.
     *  Negative pulls (an implosion). */
    float impulse_per_length;
} i2d_explosion_def;

I2D_API i2d_explosion_def i2d_default_explosion_def(void);

/** Pushes every dynamic body with a shape within radius + falloff of the blast (measured
 *  to the shape's closest point), away from it, at that point; wakes what it pushes.
 *  Sensors are not pushed. */
I2D_API i2d_status i2d_world_explode(i2d_world_id world, const i2d_explosion_def* def);

/* ---- Debug draw -------------------------------------------------------------------- */

/** A colour, 0xRRGGBB. */
typedef uint32_t i2d_color;

/* A shape's colour says its body's state; these are the values i2d_world_draw gives.
 * When several hold, the first in this list wins (a sensor on a disabled body is drawn
 * disabled, a bullet asleep is drawn asleep). */
#define I2D_COLOR_QUARANTINED 0xFF3333u /**< a body the step quarantined (non-finite state): red */
#define I2D_COLOR_DISABLED 0x666666u    /**< a disabled body: dark grey */
#define I2D_COLOR_SENSOR 0x33CCFFu      /**< a sensor shape, on an enabled body of any type: sky blue */
#define I2D_COLOR_STATIC 0x80E680u      /**< a static body's shapes: pale green */
#define I2D_COLOR_KINEMATIC 0x8080E6u   /**< kinematic: blue-violet */
#define I2D_COLOR_BULLET 0xE6E64Du      /**< a bullet, awake: yellow */
#define I2D_COLOR_AWAKE 0xE6B380u       /**< a dynamic body awake: tan */
#define I2D_COLOR_ASLEEP 0x999999u      /**< a dynamic body asleep: grey */

/* Joints (draw_joints; the last three with draw_joint_extras). */
#define I2D_COLOR_JOINT 0x7FB89Au        /**< segments from the body origins to the anchors and between them */
#define I2D_COLOR_JOINT_ANCHOR 0x2E8B57u /**< a point at each anchor */
#define I2D_COLOR_JOINT_LIMIT 0xE05050u  /**< limits: angle lines, ticks across an axis, length points */
#define I2D_COLOR_JOINT_MOTOR 0xB050E0u  /**< motors and targets (a mouse joint's, a motor joint's) */
#define I2D_COLOR_JOINT_SPRING 0x50A0E0u /**< a spring's rest angle, translation or length */

/* Boxes, bodies and contacts. */
#define I2D_COLOR_BOUNDS 0xFFD700u           /**< draw_bounds: a shape's fattened bounds (gold) */
#define I2D_COLOR_ISLAND 0xFF4500u           /**< draw_islands: an awake island's bounds */
#define I2D_COLOR_MASS 0xF5F5F5u             /**< draw_mass: the text of a body's mass */
#define I2D_COLOR_CONTACT 0x3366FFu          /**< a contact point within the contact slop */
#define I2D_COLOR_SPECULATIVE 0xC8C8C8u      /**< a contact point farther apart than the slop */
#define I2D_COLOR_CONTACT_NORMAL 0x696969u   /**< draw_contact_normals */
#define I2D_COLOR_CONTACT_IMPULSE 0xFF00FFu  /**< draw_contact_impulses */
#define I2D_COLOR_FRICTION_IMPULSE 0xFFFF00u /**< draw_friction_impulses */

/* draw_graph_colors: the solver's constraint colour k of a contact is drawn as
 * I2D_GRAPH_COLORS[k % I2D_GRAPH_COLOR_COUNT]; its overflow colour (contacts solved last,
 * in sequence) as I2D_COLOR_GRAPH_OVERFLOW, with a larger point. */
#define I2D_GRAPH_COLOR_COUNT 12
#define I2D_GRAPH_COLORS                                                                               \
    {0xFF0000u, 0xFF8000u, 0xFFFF00u, 0x80FF00u, 0x00FF00u, 0x00FF80u, 0x00FFFFu, 0x0080FFu, 0x0000FFu, \
     0x8000FFu, 0xFF00FFu, 0xFF0080u}
#define I2D_COLOR_GRAPH_OVERFLOW 0xFFFFFFu

/* The drawing callbacks' types (context is i2d_debug_draw.context). Every coordinate is in
 * world units, y up; every value handed over is finite. */
/** A closed polygon outline, world vertices, counter-clockwise (bounds come here, four
 *  vertices from the lower left). */
typedef void i2d_draw_polygon_fn(const i2d_vec2* vertices, int32_t count, i2d_color color, void* context);
/** A filled polygon: local vertices (counter-clockwise) placed by transform, grown by
 *  radius (a rounded polygon when radius > 0). The vertices are valid during the call. */
typedef void i2d_draw_solid_polygon_fn(i2d_transform transform, const i2d_vec2* vertices, int32_t count,
                                       float radius, i2d_color color, void* context);
/** A circle outline (a revolute joint's motor, with draw_joint_extras). */
typedef void i2d_draw_circle_fn(i2d_vec2 center, float radius, i2d_color color, void* context);
/** A filled circle; transform.p is its centre, transform.q its body's rotation (draw a
 *  radius along transform.q's x axis to show it turning). */
typedef void i2d_draw_solid_circle_fn(i2d_transform transform, float radius, i2d_color color, void* context);
/** A filled capsule: every point within radius of the segment p1-p2. */
typedef void i2d_draw_solid_capsule_fn(i2d_vec2 p1, i2d_vec2 p2, float radius, i2d_color color, void* context);
/** A line: segments and chain segments, joints, contact normals and impulses. */
typedef void i2d_draw_segment_fn(i2d_vec2 p1, i2d_vec2 p2, i2d_color color, void* context);
/** A frame: a body's centre of mass and rotation (draw_mass). */
typedef void i2d_draw_transform_fn(i2d_transform transform, void* context);
/** A dot; size is in pixels, whatever the view's scale (joint anchors, contact points). */
typedef void i2d_draw_point_fn(i2d_vec2 p, float size, i2d_color color, void* context);
/** Text at a point (a body's mass, with draw_mass); the text is valid during the call. */
typedef void i2d_draw_string_fn(i2d_vec2 p, const char* text, i2d_color color, void* context);

/** The caller's drawing callbacks and what to draw. Obtain with i2d_default_debug_draw(),
 *  then set the callbacks and flags. Any callback may be NULL: that kind is then not drawn
 *  (the rest is). */
typedef struct i2d_debug_draw {
    i2d_draw_polygon_fn* draw_polygon;
    i2d_draw_solid_polygon_fn* draw_solid_polygon;
    i2d_draw_circle_fn* draw_circle;
    i2d_draw_solid_circle_fn* draw_solid_circle;
    i2d_draw_solid_capsule_fn* draw_solid_capsule;
    i2d_draw_segment_fn* draw_segment;
    i2d_draw_transform_fn* draw_transform;
    i2d_draw_point_fn* draw_point;
    i2d_draw_string_fn* draw_string;
    /** Cull to this box when use_drawing_bounds is set: only shapes whose bounds overlap it
     *  are drawn, and only the mass, joints, contacts and islands of their bodies. Finite,
     *  min <= max; default +-1e9. */
    i2d_aabb drawing_bounds;
    bool use_drawing_bounds;     /**< default false: the whole world */
    bool draw_shapes;            /**< default true; coloured by body state (I2D_COLOR_STATIC...) */
    bool draw_joints;            /**< default true; joints with a disabled body are not drawn */
    bool draw_joint_extras;      /**< limits, motors, springs (0.5 m marks) */
    bool draw_bounds;            /**< shapes' fattened bounds (draw_polygon, four vertices) */
    bool draw_mass;              /**< dynamic bodies' centres of mass (draw_transform, draw_string) */
    bool draw_contacts;          /**< contact points (draw_point) */
    bool draw_contact_normals;   /**< 0.3 m along each point's normal, from shape A to B */
    /** Along the normal, 10 m per N s of the point's normal impulse (last substep). */
    bool draw_contact_impulses;
    /** Along the tangent (the normal turned a quarter counter-clockwise), 10 m per N s. */
    bool draw_friction_impulses;
    bool draw_graph_colors;      /**< contact points in their constraint colour (drawn even
                                      without draw_contacts) */
    bool draw_islands;           /**< awake islands' bounds (draw_polygon) */
    void* context;               /**< handed to every callback */
    /** Set by i2d_default_debug_draw(); do not set. */
    uint32_t internal_cookie;
} i2d_debug_draw;

/** No callbacks; draw_shapes and draw_joints on, every other flag off. */
I2D_API i2d_debug_draw i2d_default_debug_draw(void);

/** Draws the world through the callbacks, on the calling thread, before it returns:
 *  shapes first (static, kinematic, dynamic trees in turn when culled; in creation-slot
 *  order when not), then per body its mass, joints, contacts and island. The world is
 *  locked while they run, as in a query's callback: calls that change it answer
 *  I2D_ERR_WORLD_LOCKED; getters, queries and i2d_world_draw work. Lengths scale with the
 *  world's length_units_per_meter. Bad input (a NULL or uninitialised draw, a NaN or
 *  inverted drawing_bounds when used, a bad id): a status, no callback called, the world
 *  untouched. */
I2D_API i2d_status i2d_world_draw(i2d_world_id world, const i2d_debug_draw* draw);

#ifdef __cplusplus
}
#endif

#endif
