/* SPDX-License-Identifier: MIT */
/* The demo: a small scene that shows what impulse2d does, reported as text and drawn as SVG
 * through the debug draw (i2d_world_draw with callbacks that write SVG elements).
 *
 * Usage: impulse2d_demo [output.svg]   (default: impulse2d_demo.svg in the working directory)
 *
 * Two floors in one world, each a static ground between two static walls.
 * Top, bodies that only need to move (nothing turns them):
 * - four balls dropped from the same height, restitution 0, 0.3, 0.6 and 0.9, onto a ground of
 *   restitution 1 (a contact takes the minimum, so each ball's own value decides); they drift
 *   sideways slowly and without friction, so that their paths draw each bounce as an arc;
 * - a stack of five 1 m boxes;
 * - a 4 kg box sliding without friction into a 1 kg box at rest, both of restitution 1;
 * - a kinematic platform moving right at constant speed, with a box riding on it.
 * Bottom, bodies that turn:
 * - a box on a ledge with its centre of mass past the edge, which tips over and falls;
 * - a disc launched along the ground without spin, which friction brings to rolling;
 * - a capsule rolling down a slope (a static segment) into a catch ramp (a turned static box);
 * - a pyramid of ten boxes;
 * - a triangle, a pentagon, a rounded rectangle and a box dropped tilted, which land flat.
 * Third floor, bodies held by joints:
 * - a chain bridge of 20 planks on revolute joints, hung between two posts with some slack;
 * - a ragdoll (bench/ragdoll.c: the benchmark's, 11 capsules on 10 revolute joints with limits,
 *   springs and joint friction) dropped onto the bridge;
 * - a car whose wheels hang from its chassis on wheel joints (sprung suspension, motors on the
 *   wheels), driving over a bump.
 * Fourth floor, fast bodies and level geometry:
 * - a rolling landscape built as one chain of 60 one-sided segments, with a box and a ball
 *   sliding and rolling over its hills (no seam catches them);
 * - a bullet fired at 300 m/s at a 2 cm wall: continuous collision stops it, where the same
 *   shot in a world without it (stepped beside, not drawn) passes through.
 * Each part prints what happened beside what closed-form physics predicts. Halfway through, the
 * world is saved as a snapshot; after the run it is restored from it and run to the end again,
 * and the state hash must come out the same. */

/* clock_gettime and CLOCK_MONOTONIC are POSIX, not C99. */
#define _POSIX_C_SOURCE 199309L

#include <impulse2d/impulse2d.h>

#include "ragdoll.h" /* bench/ragdoll.c: the benchmark's ragdoll */

#include <inttypes.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* ---- Scene constants ------------------------------------------------------------- */

#define TIME_STEP (1.0f / 60.0f)
#define SUBSTEPS 4
#define STEP_COUNT 240 /* 4 s */
#define SNAPSHOT_STEP (STEP_COUNT / 2) /* the step after which the world is saved */
#define GRAVITY 10.0f  /* the default world's |g|, m/s^2 */
#define PI 3.14159265f
#define DEG (180.0f / PI)
#define FRICTION 0.6f  /* i2d_default_shape_def().friction; most shapes keep it */

#define GROUND_HALF_WIDTH 16.0f
#define WALL_X 15.5f   /* wall centres; inner faces at +-15 m */
#define ROW2_Y (-6.5f) /* the second floor's ground top; the top floor's is at 0 */
#define ROW3_Y (-14.0f) /* the joint floor's ground top: low enough that the dropped ragdoll's head
                           stays under the second floor's ground */
#define ROW4_Y (-19.5f) /* the chain level's mean height, below the joint floor's ground */

#define CHAIN_POINTS 61      /* 60 segments of 0.5 m from x = 15 to x = -15, plus two ghosts */
#define HILL_HEIGHT 0.8f     /* m: the landscape is ROW4_Y + HILL_HEIGHT cos(HILL_WAVE x) */
#define HILL_WAVE 0.35f      /* rad/m */
#define BULLET_SPEED 300.0f  /* m/s: 5 m per step */
#define BULLET_RADIUS 0.05f
#define THIN_WALL_X 12.0f
#define THIN_WALL_HALF 0.01f /* a 2 cm wall */
#define BULLET_START_X 2.0f
#define BULLET_HEIGHT 1.2f   /* the wall's half height; the bullet meets the wall's middle */
#define BULLET_ANGLE 0.25f   /* rad below the horizontal: a glancing shot, which a contact alone
                                lets through */

#define BALL_COUNT 4
#define BALL_RADIUS 0.3f
#define BALL_DROP_HEIGHT 4.0f /* gap between a ball's bottom and the ground at the start, m */
#define BALL_DRIFT 0.4f       /* sideways speed, m/s: spreads each path out in the picture */
static const float ball_restitution[BALL_COUNT] = {0.0f, 0.3f, 0.6f, 0.9f};

#define STACK_COUNT 5
#define STACK_X (-4.0f)
#define SLIDER_SPEED 2.0f
#define PLATFORM_SPEED 1.5f
#define PLATFORM_Y 2.5f
#define PLATFORM_HALF_WIDTH 2.0f
#define PLATFORM_HALF_HEIGHT 0.2f

/* Bottom floor: x as on the top floor, heights above its own ground (see row2()). */
#define LEDGE_EDGE_X (-12.5f) /* the ledge reaches from the wall to here */
#define LEDGE_HEIGHT 2.0f
#define TIP_OVERHANG 0.2f     /* the tipping 1 m box's centre lies this far past the edge */
#define DISC_X (-9.5f)
#define DISC_RADIUS 0.4f
#define DISC_SPEED 1.2f
#define PYRAMID_ROWS 4
#define PYRAMID_X (-3.0f)
#define PYRAMID_GAP 0.05f     /* between neighbours in a row */
#define SLOPE_TOP_X 7.0f
#define SLOPE_TOP_Y 2.0f
#define SLOPE_FOOT_X 12.0f
#define CATCH_START_X 12.5f   /* the catch ramp rises from here to the wall */
#define CATCH_TOP_Y 1.5f
#define CAPSULE_HALF_LENGTH 0.1f
#define CAPSULE_RADIUS 0.35f

/* Third floor: x as on the others, heights above its own ground (see row3()). */
#define BRIDGE_PLANKS 20
#define PLANK_HALF_LENGTH 0.25f
#define PLANK_HALF_THICKNESS 0.06f
#define PLANK_DENSITY 4.0f
#define BRIDGE_LEFT_X (-13.0f) /* the left post's top corner, where the bridge hangs from */
#define BRIDGE_TOP 2.5f        /* the posts' height */
#define BRIDGE_DIP 1.0f        /* built as a V whose middle is this far below its ends: slack */
#define POST_HALF_WIDTH 0.25f
#define RAGDOLL_FEET 4.0f      /* the ragdoll's feet start this high, above the bridge's middle */
#define CAR_X 0.5f
#define CAR_HALF_WIDTH 1.0f
#define CAR_HALF_HEIGHT 0.2f
#define WHEEL_RADIUS 0.35f
#define AXLE_X 0.7f            /* the wheels' distance from the chassis centre, each side */
#define AXLE_DROP 0.4f         /* and below it */
#define SUSPENSION_HERTZ 5.0f
#define SUSPENSION_DAMPING 0.7f
#define WHEEL_SPEED 6.0f       /* rad/s, clockwise: the car drives right */
#define WHEEL_TORQUE 5.0f      /* N m per wheel */
#define BUMP_X 5.0f
#define BUMP_RADIUS 0.5f      /* buried in the 1 m thick ground but for its top */
#define BUMP_HEIGHT 0.15f      /* how far the bump (a static disc) stands out of the ground */


static const i2d_vec2 still = {0.0f, 0.0f};

/* ---- What the demo keeps ---------------------------------------------------------- */

/* A body followed through the run: where it started, its path and how far it turned. */
typedef struct tracked {
    i2d_body_id body;
    i2d_transform start;
    i2d_rot last;
    float turned; /* rad, counter-clockwise, summed step by step (not wrapped) */
    i2d_vec2 path[STEP_COUNT + 1];
    int path_count;
} tracked;

/* A dropped ball and the top of its first bounce. */
typedef struct ball {
    tracked t;
    float restitution;
    int bounced;    /* 1 once the ball has moved up after falling */
    int apex_found; /* 1 once it turned down again after that */
    float apex;     /* highest bottom height above the ground after the first bounce, m */
} ball;

/* The bodies followed by name. */
enum {
    T_HEAVY, T_LIGHT, T_PLATFORM, T_RIDER, /* top floor */
    T_TIPPER, T_DISC, T_CAPSULE,           /* bottom floor; then the dropped shapes: */
    T_TRIANGLE, T_PENTAGON, T_ROUNDED, T_TILTED,
    T_COUNT
};

typedef struct demo {
    i2d_world_id world;
    tracked t[T_COUNT];
    ball balls[BALL_COUNT];
    i2d_body_id stack_top, pyramid_top;
    i2d_vec2 pyramid_top_start;
    float momentum_before, heavy_v_before; /* kg m/s and m/s, along x */
    int collided, separated;               /* the light box has started to move / the gap opened */
    float momentum_after, heavy_v_after, light_v_after;
    float tip_spin_up;            /* the tipping box's angular acceleration in the first step */
    i2d_vec2 rim[STEP_COUNT + 1]; /* the path of a point on the disc's rim */
    int rim_count;
    float capsule_time;           /* when it passed the foot of the slope (0: not yet), s */
    float capsule_distance, capsule_turned;
    float contact_slop;           /* the world's allowed resting penetration, m */
    /* Third floor. */
    bench_ragdoll ragdoll;
    i2d_body_id planks[BRIDGE_PLANKS];
    i2d_joint_id bridge_joints[BRIDGE_PLANKS + 1];
    float bridge_middle_start;    /* height of the bridge's middle joint above its ground, m */
    float widest_gap;             /* the widest any joint's anchors came apart during the run, m */
    i2d_body_id chassis, wheels[2];
    i2d_joint_id suspension[2];
    float chassis_start_x;
    float most_compressed;        /* the suspension's largest travel during the run, m */
    /* Fourth floor. */
    i2d_body_id bullet, chain_box, chain_ball;
    float bullet_max_x;           /* the farthest right the bullet got, m */
    float control_max_x;          /* the same shot in a world without continuous collision */
    float chain_box_max_vy;       /* the chain box's fastest vertical speed while on flat ground */
    float chain_box_start_x;
    double step_seconds;          /* wall time spent in i2d_world_step */
    /* The snapshot saved after step SNAPSHOT_STEP, and the state hash at the end of the run. */
    void* snapshot;
    size_t snapshot_size;
    /* The world as built, before the first step: the picture draws it dashed (start outlines). */
    void* start;
    size_t start_size;
    uint64_t end_hash;
} demo;

/* ---- Checked calls ------------------------------------------------------------------ */

/* Reports the failed call with the library's own message and stops. */
static void fail(const char* what) {
    /* Read the status and copy the message before the next i2d_ call replaces them. */
    i2d_status status = i2d_last_status();
    char message[256];
    snprintf(message, sizeof message, "%s", i2d_last_error_message());
    fprintf(stderr, "impulse2d_demo: %s failed: %s: %s\n", what, i2d_status_string(status), message);
    exit(EXIT_FAILURE);
}

static void check(i2d_status status, const char* what) {
    if (status != I2D_OK) {
        fail(what);
    }
}

/* Getters return a zero value on failure, so look at the recorded status after each. */
static void check_last(const char* what) { check(i2d_last_status(), what); }

/* Creators return a null id on failure. */
static void check_shape(i2d_shape_id shape, const char* what) {
    if (I2D_IS_NULL(shape)) {
        fail(what);
    }
}

static i2d_joint_id check_joint(i2d_joint_id joint, const char* what) {
    if (I2D_IS_NULL(joint)) {
        fail(what);
    }
    return joint;
}

static i2d_vec2 vec2(float x, float y) {
    i2d_vec2 v = {x, y};
    return v;
}

/* A point of the second floor, given relative to its ground. */
static i2d_vec2 row2(float x, float y) { return vec2(x, ROW2_Y + y); }

/* A point of the third floor, given relative to its ground. */
static i2d_vec2 row3(float x, float y) { return vec2(x, ROW3_Y + y); }

static i2d_vec2 rotate(i2d_rot q, i2d_vec2 v) { return vec2(q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y); }

/* A point given in a body's frame, in the world, the body placed by xf. */
static i2d_vec2 place(i2d_transform xf, i2d_vec2 v) {
    i2d_vec2 r = rotate(xf.q, v);
    return vec2(xf.p.x + r.x, xf.p.y + r.y);
}

static i2d_transform transform(i2d_body_id body) {
    i2d_transform xf = i2d_body_get_transform(body);
    check_last("i2d_body_get_transform");
    return xf;
}

static i2d_vec2 position(i2d_body_id body) { return transform(body).p; }

static i2d_rot rot(float angle) {
    i2d_rot q = i2d_make_rot(angle);
    check_last("i2d_make_rot");
    return q;
}

static float degrees(i2d_rot q) {
    float angle = i2d_rot_get_angle(q);
    check_last("i2d_rot_get_angle");
    return DEG * angle;
}

static i2d_vec2 velocity(i2d_body_id body) {
    i2d_vec2 v = i2d_body_get_linear_velocity(body);
    check_last("i2d_body_get_linear_velocity");
    return v;
}

static float spin(i2d_body_id body) {
    float w = i2d_body_get_angular_velocity(body);
    check_last("i2d_body_get_angular_velocity");
    return w;
}

static float mass(i2d_body_id body) {
    float m = i2d_body_get_mass(body);
    check_last("i2d_body_get_mass");
    return m;
}

static double seconds_now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The world as it is, as a snapshot in a buffer of its own (i2d_world_save_snapshot: everything
 * it simulates); its size goes to *size. */
static void* save_world(i2d_world_id world, size_t* size) {
    void* bytes;
    *size = i2d_world_get_snapshot_size(world);
    check_last("i2d_world_get_snapshot_size");
    bytes = malloc(*size);
    if (bytes == NULL) {
        fprintf(stderr, "impulse2d_demo: out of memory for a %zu-byte snapshot\n", *size);
        exit(EXIT_FAILURE);
    }
    check(i2d_world_save_snapshot(world, bytes, *size, NULL), "i2d_world_save_snapshot");
    return bytes;
}

/* ---- Building the scene ------------------------------------------------------------- */

static i2d_body_id add_body(demo* d, i2d_body_type type, i2d_vec2 p, float angle, i2d_vec2 v) {
    i2d_body_def def = i2d_default_body_def();
    i2d_body_id body;
    def.type = type;
    def.position = p;
    def.rotation = rot(angle);
    def.linear_velocity = v;
    body = i2d_body_create(d->world, &def);
    if (I2D_IS_NULL(body)) {
        fail("i2d_body_create");
    }
    return body;
}

/* A body followed by name (see the enum), dynamic unless it is the platform. */
static i2d_body_id add_tracked(demo* d, int which, i2d_vec2 p, float angle, i2d_vec2 v) {
    tracked* t = &d->t[which];
    t->body = add_body(d, which == T_PLATFORM ? I2D_BODY_KINEMATIC : I2D_BODY_DYNAMIC, p, angle, v);
    t->start = transform(t->body);
    t->last = t->start.q;
    t->path[t->path_count++] = p;
    return t->body;
}

static i2d_shape_def shape_def(float density, float friction, float restitution) {
    i2d_shape_def def = i2d_default_shape_def();
    def.density = density;
    def.friction = friction;
    def.restitution = restitution;
    return def;
}

static void add_box(i2d_body_id body, const i2d_shape_def* def, float half_width, float half_height) {
    check_shape(i2d_shape_create_box(body, def, half_width, half_height), "i2d_shape_create_box");
}

static void add_circle(i2d_body_id body, const i2d_shape_def* def, float radius) {
    i2d_circle circle;
    circle.center = still;
    circle.radius = radius;
    check_shape(i2d_shape_create_circle(body, def, &circle), "i2d_shape_create_circle");
}

/* Ground top at `y`, walls standing on it. Restitution 1 so that the other shape of each
 * contact decides how bouncy it is. */
static void build_floor(demo* d, float y, float wall_half_height) {
    i2d_shape_def def = shape_def(1.0f, FRICTION, 1.0f);
    add_box(add_body(d, I2D_BODY_STATIC, vec2(0.0f, y - 0.5f), 0.0f, still), &def, GROUND_HALF_WIDTH, 0.5f);
    add_box(add_body(d, I2D_BODY_STATIC, vec2(-WALL_X, y + wall_half_height), 0.0f, still), &def, 0.5f,
            wall_half_height);
    add_box(add_body(d, I2D_BODY_STATIC, vec2(WALL_X, y + wall_half_height), 0.0f, still), &def, 0.5f,
            wall_half_height);
}

static void build_balls(demo* d) {
    int i;
    for (i = 0; i < BALL_COUNT; ++i) {
        ball* b = &d->balls[i];
        /* Friction 0 keeps the drift through the bounces; it does not touch the vertical motion. */
        i2d_shape_def def = shape_def(1.0f, 0.0f, ball_restitution[i]);
        i2d_vec2 start = vec2(-13.5f + 2.0f * (float)i, BALL_DROP_HEIGHT + BALL_RADIUS);
        b->restitution = ball_restitution[i];
        b->t.body = add_body(d, I2D_BODY_DYNAMIC, start, 0.0f, vec2(BALL_DRIFT, 0.0f));
        add_circle(b->t.body, &def, BALL_RADIUS);
        b->t.path[b->t.path_count++] = start;
    }
}

/* Rows of 1 m boxes centred on x, standing on the ground at floor_y: a stack, or a pyramid
 * whose rows shrink by one box, each box resting on two below. Boxes start exactly touching
 * the boxes below them, so nothing should sink but the contact slop. Returns the top box. */
static i2d_body_id build_pile(demo* d, float x, float floor_y, int rows, int pyramid) {
    i2d_shape_def def = i2d_default_shape_def();
    i2d_body_id top = I2D_NULL_BODY_ID;
    int row, i;
    for (row = 0; row < rows; ++row) {
        int count = pyramid ? rows - row : 1;
        for (i = 0; i < count; ++i) {
            float offset = ((float)i - 0.5f * (float)(count - 1)) * (1.0f + PYRAMID_GAP);
            top = add_body(d, I2D_BODY_DYNAMIC, vec2(x + offset, floor_y + 0.5f + (float)row), 0.0f, still);
            add_box(top, &def, 0.5f, 0.5f);
        }
    }
    return top;
}

/* Sliders: friction 0 (the geometric mean with the ground's is then 0) so that momentum along
 * x is conserved exactly, restitution 1 on both so the collision is elastic; they meet face to
 * face, so nothing turns them. The platform flies above their lane; its rider starts at rest,
 * so friction must first bring it up to the platform's speed (too gently to tip it over). */
static void build_movers(demo* d) {
    i2d_shape_def heavy = shape_def(4.0f, 0.0f, 1.0f), light = shape_def(1.0f, 0.0f, 1.0f);
    i2d_shape_def def = i2d_default_shape_def();
    add_box(add_tracked(d, T_HEAVY, vec2(-1.0f, 0.5f), 0.0f, vec2(SLIDER_SPEED, 0.0f)), &heavy, 0.5f, 0.5f);
    add_box(add_tracked(d, T_LIGHT, vec2(2.0f, 0.5f), 0.0f, still), &light, 0.5f, 0.5f);
    add_box(add_tracked(d, T_PLATFORM, vec2(5.0f, PLATFORM_Y), 0.0f, vec2(PLATFORM_SPEED, 0.0f)), &def,
            PLATFORM_HALF_WIDTH, PLATFORM_HALF_HEIGHT);
    add_box(add_tracked(d, T_RIDER, vec2(5.0f, PLATFORM_Y + PLATFORM_HALF_HEIGHT + 0.5f), 0.0f, still), &def,
            0.5f, 0.5f);
}

/* A static ledge against the left wall with a 1 m box on it, overhanging the edge; and a disc
 * resting on the ground, sliding without turning: friction slows its centre and spins it up
 * until its contact point stops slipping. */
static void build_ledge_and_disc(demo* d) {
    i2d_shape_def def = i2d_default_shape_def();
    float half_width = 0.5f * (LEDGE_EDGE_X + 15.0f);
    add_box(add_body(d, I2D_BODY_STATIC, row2(LEDGE_EDGE_X - half_width, 0.5f * LEDGE_HEIGHT), 0.0f, still), &def,
            half_width, 0.5f * LEDGE_HEIGHT);
    add_box(add_tracked(d, T_TIPPER, row2(LEDGE_EDGE_X + TIP_OVERHANG, LEDGE_HEIGHT + 0.5f), 0.0f, still), &def,
            0.5f, 0.5f);
    add_circle(add_tracked(d, T_DISC, row2(DISC_X, DISC_RADIUS), 0.0f, vec2(DISC_SPEED, 0.0f)), &def,
               DISC_RADIUS);
}

/* A static segment sloping down to the right, a catch ramp (a turned box 0.2 m thick) rising
 * from the ground to the right wall, and a short, fat capsule lying near the slope's top. */
static void build_slope(demo* d) {
    i2d_shape_def def = i2d_default_shape_def();
    i2d_body_id slope = add_body(d, I2D_BODY_STATIC, row2(0.0f, 0.0f), 0.0f, still);
    float down = atan2f(SLOPE_TOP_Y, SLOPE_FOOT_X - SLOPE_TOP_X), up = atan2f(CATCH_TOP_Y, 15.0f - CATCH_START_X);
    float ramp_half_length = 0.5f * hypotf(CATCH_TOP_Y, 15.0f - CATCH_START_X);
    i2d_vec2 ramp_center = vec2(0.5f * (CATCH_START_X + 15.0f) + 0.1f * sinf(up), 0.5f * CATCH_TOP_Y - 0.1f * cosf(up));
    /* 0.6 m down the slope, one radius above it. */
    i2d_vec2 start = row2(SLOPE_TOP_X + 0.6f * cosf(down) + CAPSULE_RADIUS * sinf(down),
                          SLOPE_TOP_Y - 0.6f * sinf(down) + CAPSULE_RADIUS * cosf(down));
    i2d_body_id capsule = add_tracked(d, T_CAPSULE, start, -down, still);
    check_shape(i2d_shape_create_segment(slope, &def, vec2(SLOPE_TOP_X, SLOPE_TOP_Y), vec2(SLOPE_FOOT_X, 0.0f)),
                "i2d_shape_create_segment");
    check_shape(i2d_shape_create_offset_box(slope, &def, ramp_half_length, 0.1f, ramp_center, rot(up)),
                "i2d_shape_create_offset_box");
    check_shape(i2d_shape_create_capsule(capsule, &def, vec2(-CAPSULE_HALF_LENGTH, 0.0f),
                                         vec2(CAPSULE_HALF_LENGTH, 0.0f), CAPSULE_RADIUS),
                "i2d_shape_create_capsule");
}

/* A regular polygon around the body origin, given as points; a face is down when level. */
static void add_regular_polygon(i2d_body_id body, const i2d_shape_def* def, int count, float radius) {
    i2d_vec2 points[I2D_MAX_POLYGON_VERTICES];
    int k;
    for (k = 0; k < count; ++k) {
        float a = PI * (2.0f * (float)k + 1.0f) / (float)count - 0.5f * PI;
        points[k] = vec2(radius * cosf(a), radius * sinf(a));
    }
    check_shape(i2d_shape_create_polygon(body, def, points, count), "i2d_shape_create_polygon");
}

/* Dropped from 1 m, each tilted so that it lands on a corner: a triangle, a pentagon, a
 * rectangle rounded by 0.15 m and a box. */
static void build_dropped(demo* d) {
    static const i2d_vec2 corners[4] = {{-0.4f, -0.22f}, {0.4f, -0.22f}, {0.4f, 0.22f}, {-0.4f, 0.22f}};
    i2d_shape_def def = i2d_default_shape_def();
    i2d_polygon rounded;
    i2d_body_id body;
    check(i2d_make_polygon(corners, 4, 0.15f, &rounded), "i2d_make_polygon");
    add_regular_polygon(add_tracked(d, T_TRIANGLE, row2(0.5f, 1.6f), 20.0f / DEG, still), &def, 3, 0.6f);
    add_regular_polygon(add_tracked(d, T_PENTAGON, row2(2.05f, 1.6f), 15.0f / DEG, still), &def, 5, 0.55f);
    body = add_tracked(d, T_ROUNDED, row2(3.6f, 1.6f), 25.0f / DEG, still);
    check_shape(i2d_shape_create_polygon_from(body, &def, &rounded), "i2d_shape_create_polygon_from");
    add_box(add_tracked(d, T_TILTED, row2(5.15f, 1.6f), 30.0f / DEG, still), &def, 0.5f, 0.5f);
}

/* A revolute joint between a and b at a world point (each body's anchor is that point). */
static i2d_joint_id revolute_at(demo* d, i2d_body_id a, i2d_body_id b, i2d_vec2 at) {
    i2d_revolute_joint_def def = i2d_default_revolute_joint_def();
    def.base.body_a = a;
    def.base.body_b = b;
    def.base.local_anchor_a = i2d_body_get_local_point(a, at);
    def.base.local_anchor_b = i2d_body_get_local_point(b, at);
    check_last("i2d_body_get_local_point");
    return check_joint(i2d_joint_create_revolute(d->world, &def), "i2d_joint_create_revolute");
}

/* Two posts and 20 planks between them, built as a V (each half a straight line from a post's
 * top corner down to the middle), so that the chain starts slack and sags into its own curve.
 * Joint k joins plank k - 1 (or the left post) to plank k (or the right post) at point k. */
static void build_bridge(demo* d) {
    i2d_shape_def def = i2d_default_shape_def();
    float half_length = (float)(BRIDGE_PLANKS / 2) * 2.0f * PLANK_HALF_LENGTH;
    float half_span = sqrtf(half_length * half_length - BRIDGE_DIP * BRIDGE_DIP);
    i2d_vec2 points[BRIDGE_PLANKS + 1];
    i2d_body_id left, right;
    int k;
    for (k = 0; k <= BRIDGE_PLANKS; ++k) {
        /* Along the left half down to the middle, then up the right half. */
        float along = (float)k / (float)(BRIDGE_PLANKS / 2);
        float x = BRIDGE_LEFT_X + half_span * along;
        float y = BRIDGE_TOP - BRIDGE_DIP * (along <= 1.0f ? along : 2.0f - along);
        points[k] = row3(x, y);
    }
    left = add_body(d, I2D_BODY_STATIC, row3(BRIDGE_LEFT_X - POST_HALF_WIDTH, 0.5f * BRIDGE_TOP), 0.0f, still);
    right = add_body(d, I2D_BODY_STATIC, row3(BRIDGE_LEFT_X + 2.0f * half_span + POST_HALF_WIDTH, 0.5f * BRIDGE_TOP),
                     0.0f, still);
    add_box(left, &def, POST_HALF_WIDTH, 0.5f * BRIDGE_TOP);
    add_box(right, &def, POST_HALF_WIDTH, 0.5f * BRIDGE_TOP);
    def.density = PLANK_DENSITY;
    for (k = 0; k < BRIDGE_PLANKS; ++k) {
        i2d_vec2 a = points[k], b = points[k + 1];
        d->planks[k] = add_body(d, I2D_BODY_DYNAMIC, vec2(0.5f * (a.x + b.x), 0.5f * (a.y + b.y)),
                                atan2f(b.y - a.y, b.x - a.x), still);
        add_box(d->planks[k], &def, PLANK_HALF_LENGTH, PLANK_HALF_THICKNESS);
    }
    for (k = 0; k <= BRIDGE_PLANKS; ++k) {
        d->bridge_joints[k] = revolute_at(d, k == 0 ? left : d->planks[k - 1],
                                          k == BRIDGE_PLANKS ? right : d->planks[k], points[k]);
    }
    d->bridge_middle_start = points[BRIDGE_PLANKS / 2].y - ROW3_Y;
}

/* The benchmark's ragdoll, standing with its feet RAGDOLL_FEET above the bridge's middle. */
static void build_ragdoll(demo* d) {
    float middle_x = i2d_body_get_world_point(d->planks[BRIDGE_PLANKS / 2], vec2(-PLANK_HALF_LENGTH, 0.0f)).x;
    /* The feet are 0.275 m above the spawn point (scenes.md). */
    bench_ragdoll_def def = bench_default_ragdoll_def(row3(middle_x, RAGDOLL_FEET - 0.275f), 1);
    if (!bench_ragdoll_create(d->world, &def, &d->ragdoll)) {
        fail("bench_ragdoll_create");
    }
}

/* A chassis with a wheel at each end on a wheel joint: the wheel slides on a spring along the
 * chassis' vertical axis (the suspension) and turns freely but for its motor. The chassis starts
 * level with the springs unloaded; a static disc half buried in the ground ahead is the bump. */
static void build_car(demo* d) {
    i2d_shape_def def = i2d_default_shape_def();
    i2d_vec2 chassis_at = row3(CAR_X, WHEEL_RADIUS + AXLE_DROP);
    int side;
    d->chassis = add_body(d, I2D_BODY_DYNAMIC, chassis_at, 0.0f, still);
    add_box(d->chassis, &def, CAR_HALF_WIDTH, CAR_HALF_HEIGHT);
    d->chassis_start_x = chassis_at.x;
    for (side = 0; side < 2; ++side) {
        i2d_vec2 axle = row3(CAR_X + (side ? AXLE_X : -AXLE_X), WHEEL_RADIUS);
        i2d_wheel_joint_def wheel = i2d_default_wheel_joint_def();
        d->wheels[side] = add_body(d, I2D_BODY_DYNAMIC, axle, 0.0f, still);
        add_circle(d->wheels[side], &def, WHEEL_RADIUS);
        wheel.base.body_a = d->chassis;
        wheel.base.body_b = d->wheels[side];
        wheel.base.local_anchor_a = i2d_body_get_local_point(d->chassis, axle);
        wheel.local_axis_a = vec2(0.0f, 1.0f);
        wheel.enable_spring = true;
        wheel.hertz = SUSPENSION_HERTZ;
        wheel.damping_ratio = SUSPENSION_DAMPING;
        wheel.enable_motor = true;
        wheel.motor_speed = -WHEEL_SPEED;
        wheel.max_motor_torque = WHEEL_TORQUE;
        d->suspension[side] = check_joint(i2d_joint_create_wheel(d->world, &wheel), "i2d_joint_create_wheel");
    }
    add_circle(add_body(d, I2D_BODY_STATIC, row3(BUMP_X, BUMP_HEIGHT - BUMP_RADIUS), 0.0f, still), &def, BUMP_RADIUS);
}

static float hill(float x) { return ROW4_Y + HILL_HEIGHT * cosf(HILL_WAVE * x); }

/* The landscape, listed right to left so that the segments' solid side is below them. */
static void build_chain_ground(i2d_body_id body) {
    i2d_vec2 points[CHAIN_POINTS + 2];
    i2d_chain_def def = i2d_default_chain_def();
    int i;
    points[0] = vec2(15.5f, hill(15.5f)); /* ghost */
    for (i = 0; i < CHAIN_POINTS; ++i) {
        float x = 15.0f - 30.0f * (float)i / (float)(CHAIN_POINTS - 1);
        points[i + 1] = vec2(x, hill(x));
    }
    points[CHAIN_POINTS + 1] = vec2(-15.5f, hill(-15.5f)); /* ghost */
    def.points = points;
    def.count = CHAIN_POINTS + 2;
    if (I2D_IS_NULL(i2d_chain_create(body, &def))) {
        fail("i2d_chain_create");
    }
}

/* The thin wall and a bullet fired at it; the bullet is a circle of 5 cm radius. */
static i2d_body_id build_wall_and_bullet(i2d_world_id world) {
    i2d_body_def wall_def = i2d_default_body_def(), bullet_def = i2d_default_body_def();
    i2d_shape_def shape = shape_def(1.0f, FRICTION, 0.0f);
    i2d_body_id wall, bullet;
    float y = hill(THIN_WALL_X) + BULLET_HEIGHT;
    wall_def.position = vec2(THIN_WALL_X, y);
    bullet_def.type = I2D_BODY_DYNAMIC;
    bullet_def.position = vec2(BULLET_START_X, y + (THIN_WALL_X - BULLET_START_X) * tanf(BULLET_ANGLE));
    bullet_def.linear_velocity = vec2(BULLET_SPEED * cosf(BULLET_ANGLE), -BULLET_SPEED * sinf(BULLET_ANGLE));
    bullet_def.is_bullet = true;
    wall = i2d_body_create(world, &wall_def);
    bullet = i2d_body_create(world, &bullet_def);
    if (I2D_IS_NULL(wall) || I2D_IS_NULL(bullet)) {
        fail("i2d_body_create");
    }
    add_box(wall, &shape, THIN_WALL_HALF, BULLET_HEIGHT);
    add_circle(bullet, &shape, BULLET_RADIUS);
    return bullet;
}

static void build_chain_level(demo* d) {
    i2d_shape_def slick = shape_def(1.0f, 0.1f, 0.0f);
    i2d_body_id ground = add_body(d, I2D_BODY_STATIC, vec2(0.0f, 0.0f), 0.0f, still);
    build_chain_ground(ground);
    d->chain_box_start_x = -13.0f;
    d->chain_box = add_body(d, I2D_BODY_DYNAMIC, vec2(d->chain_box_start_x, hill(-13.0f) + 0.6f), 0.0f,
                            vec2(6.0f, 0.0f));
    add_box(d->chain_box, &slick, 0.4f, 0.25f);
    d->chain_ball = add_body(d, I2D_BODY_DYNAMIC, vec2(-5.0f, hill(-5.0f) + 1.0f), 0.0f, vec2(3.0f, 0.0f));
    add_circle(d->chain_ball, &slick, 0.35f);
    d->bullet = build_wall_and_bullet(d->world);
    d->bullet_max_x = position(d->bullet).x;
}

/* The same wall and shot alone in a world without continuous collision. */
static void run_control_shot(demo* d) {
    i2d_world_def def = i2d_default_world_def();
    i2d_world_id world;
    i2d_body_id bullet;
    int step;
    def.enable_continuous = false;
    world = i2d_world_create(&def);
    if (I2D_IS_NULL(world)) {
        fail("i2d_world_create");
    }
    bullet = build_wall_and_bullet(world);
    d->control_max_x = position(bullet).x;
    for (step = 0; step < 30; ++step) {
        check(i2d_world_step(world, TIME_STEP, SUBSTEPS), "i2d_world_step");
        d->control_max_x = fmaxf(d->control_max_x, position(bullet).x);
    }
    check(i2d_world_destroy(world), "i2d_world_destroy");
}

static void build_scene(demo* d) {
    i2d_world_def def = i2d_default_world_def();
    d->contact_slop = def.contact_slop;
    d->world = i2d_world_create(&def);
    if (I2D_IS_NULL(d->world)) {
        fail("i2d_world_create");
    }
    build_floor(d, 0.0f, 3.0f);
    build_balls(d);
    d->stack_top = build_pile(d, STACK_X, 0.0f, STACK_COUNT, 0);
    build_movers(d);
    build_slope(d); /* before the floor, which is drawn over the catch ramp's buried corner */
    build_floor(d, ROW2_Y, 2.25f);
    build_ledge_and_disc(d);
    d->pyramid_top = build_pile(d, PYRAMID_X, ROW2_Y, PYRAMID_ROWS, 1);
    d->pyramid_top_start = position(d->pyramid_top);
    build_dropped(d);
    build_bridge(d);
    build_ragdoll(d);
    build_car(d);
    build_floor(d, ROW3_Y, 3.0f); /* after the bump, so that the ground is drawn over its buried part */
    build_chain_level(d);
    d->momentum_before = mass(d->t[T_HEAVY].body) * velocity(d->t[T_HEAVY].body).x +
                         mass(d->t[T_LIGHT].body) * velocity(d->t[T_LIGHT].body).x;
    d->heavy_v_before = velocity(d->t[T_HEAVY].body).x;
    d->start = save_world(d->world, &d->start_size);
}

/* ---- Watching it run ------------------------------------------------------------------ */

/* Adds a point to the path and the turn since the last step to the angle turned through. */
static void follow(tracked* t) {
    i2d_transform xf = transform(t->body);
    t->path[t->path_count++] = xf.p;
    t->turned += atan2f(xf.q.s * t->last.c - xf.q.c * t->last.s, xf.q.c * t->last.c + xf.q.s * t->last.s);
    t->last = xf.q;
}

/* Follows a ball through its first bounce: falling, then rising, then the turn at the top. */
static void watch_ball(ball* b) {
    i2d_vec2 v = velocity(b->t.body);
    float bottom;
    follow(&b->t);
    bottom = b->t.path[b->t.path_count - 1].y - BALL_RADIUS;
    if (b->apex_found) {
        return;
    }
    if (!b->bounced) {
        /* A rising ball near the ground has bounced; the height test ignores the start. */
        if (v.y > 0.0f && bottom < 0.5f * BALL_DROP_HEIGHT) {
            b->bounced = 1;
            b->apex = bottom;
        }
        return;
    }
    if (bottom > b->apex) {
        b->apex = bottom;
    }
    if (v.y <= 0.0f) {
        b->apex_found = 1;
    }
}

/* Records momentum once the boxes have collided and the gap between them has opened. */
static void watch_sliders(demo* d) {
    i2d_body_id heavy = d->t[T_HEAVY].body, light = d->t[T_LIGHT].body;
    i2d_vec2 vh, vl;
    if (d->separated) {
        return;
    }
    vl = velocity(light);
    if (!d->collided) {
        d->collided = vl.x > 0.01f;
        return;
    }
    vh = velocity(heavy);
    if (position(light).x - position(heavy).x > 1.0f + 0.01f) {
        d->separated = 1;
        d->heavy_v_after = vh.x;
        d->light_v_after = vl.x;
        d->momentum_after = mass(heavy) * vh.x + mass(light) * vl.x;
    }
}

/* The point of the disc's rim that started level with its centre, in front. */
static void follow_rim(demo* d) {
    d->rim[d->rim_count++] = i2d_body_get_world_point(d->t[T_DISC].body, vec2(DISC_RADIUS, 0.0f));
    check_last("i2d_body_get_world_point");
}

/* The tipping box's first spin (while still level) and the capsule's arrival at the foot. */
static void watch_turning(demo* d, int step) {
    const tracked* c = &d->t[T_CAPSULE];
    i2d_vec2 at = c->path[c->path_count - 1];
    if (step == 1) {
        d->tip_spin_up = spin(d->t[T_TIPPER].body) / TIME_STEP;
    }
    if (d->capsule_time == 0.0f && at.x > SLOPE_FOOT_X) {
        d->capsule_time = (float)step * TIME_STEP;
        d->capsule_distance = hypotf(at.x - c->path[0].x, at.y - c->path[0].y);
        d->capsule_turned = c->turned;
    }
}

/* How far apart a joint's two anchors are in the world, m (0 for a joint that holds exactly). */
static float joint_gap(i2d_joint_id joint) {
    i2d_vec2 a = i2d_body_get_world_point(i2d_joint_get_body_a(joint), i2d_joint_get_local_anchor_a(joint));
    i2d_vec2 b = i2d_body_get_world_point(i2d_joint_get_body_b(joint), i2d_joint_get_local_anchor_b(joint));
    check_last("reading a joint's anchors");
    return hypotf(a.x - b.x, a.y - b.y);
}

/* The widest joint gap of the bridge and the ragdoll, and the suspension's largest travel. */
static void watch_joints(demo* d) {
    int k;
    for (k = 0; k <= BRIDGE_PLANKS; ++k) {
        d->widest_gap = fmaxf(d->widest_gap, joint_gap(d->bridge_joints[k]));
    }
    for (k = 1; k < BENCH_BONE_COUNT; ++k) {
        d->widest_gap = fmaxf(d->widest_gap, joint_gap(d->ragdoll.joints[k]));
    }
    for (k = 0; k < 2; ++k) {
        float travel = i2d_wheel_joint_get_translation(d->suspension[k]);
        check_last("i2d_wheel_joint_get_translation");
        d->most_compressed = fmaxf(d->most_compressed, travel);
    }
}

static void save_snapshot(demo* d) { d->snapshot = save_world(d->world, &d->snapshot_size); }

static void run(demo* d) {
    int step, i;
    follow_rim(d);
    for (step = 1; step <= STEP_COUNT; ++step) {
        double t0 = seconds_now();
        check(i2d_world_step(d->world, TIME_STEP, SUBSTEPS), "i2d_world_step");
        d->step_seconds += seconds_now() - t0;
        for (i = 0; i < BALL_COUNT; ++i) {
            watch_ball(&d->balls[i]);
        }
        for (i = 0; i < T_COUNT; ++i) {
            follow(&d->t[i]);
        }
        follow_rim(d);
        watch_sliders(d);
        watch_turning(d, step);
        watch_joints(d);
        d->bullet_max_x = fmaxf(d->bullet_max_x, position(d->bullet).x);
        if (step == SNAPSHOT_STEP) {
            save_snapshot(d);
        }
    }
    d->end_hash = i2d_world_get_state_hash(d->world);
    check_last("i2d_world_get_state_hash");
    run_control_shot(d);
}

/* Brings the world back to the snapshot saved halfway and runs the second half again: a
 * deterministic engine ends in the same state, bit for bit. Returns whether it did. */
static int rerun_from_snapshot(demo* d) {
    int step;
    uint64_t hash;
    check(i2d_world_restore_snapshot(d->world, d->snapshot, d->snapshot_size), "i2d_world_restore_snapshot");
    for (step = SNAPSHOT_STEP + 1; step <= STEP_COUNT; ++step) {
        check(i2d_world_step(d->world, TIME_STEP, SUBSTEPS), "i2d_world_step");
    }
    hash = i2d_world_get_state_hash(d->world);
    check_last("i2d_world_get_state_hash");
    free(d->snapshot);
    d->snapshot = NULL;
    if (hash != d->end_hash) {
        printf("snapshot: restored at step %d, hash after %d more steps DIFFERS (%016" PRIx64 ", first run %016" PRIx64
               ")\n", SNAPSHOT_STEP, STEP_COUNT - SNAPSHOT_STEP, hash, d->end_hash);
        return 0;
    }
    printf("snapshot: restored at step %d (%zu bytes), hash after %d more steps matches (%016" PRIx64 ")\n",
           SNAPSHOT_STEP, d->snapshot_size, STEP_COUNT - SNAPSHOT_STEP, hash);
    return 1;
}

/* ---- Reporting -------------------------------------------------------------------------- */

static void report_balls(const demo* d) {
    int i;
    printf("balls dropped %.1f m onto the ground; first bounce apex (ball bottom) vs e^2 h:\n", BALL_DROP_HEIGHT);
    for (i = 0; i < BALL_COUNT; ++i) {
        const ball* b = &d->balls[i];
        float predicted = b->restitution * b->restitution * BALL_DROP_HEIGHT;
        if (!b->bounced) {
            printf("  e = %.1f: no bounce              predicted %.3f m\n", b->restitution, predicted);
        } else {
            printf("  e = %.1f: apex %.3f m%s  predicted %.3f m\n", b->restitution, b->apex,
                   b->apex_found ? "          " : " (rising)", predicted);
        }
    }
}

static void report_stack_and_sliders(const demo* d) {
    float rest = 0.5f + (float)(STACK_COUNT - 1), top = position(d->stack_top).y;
    float m1 = mass(d->t[T_HEAVY].body), m2 = mass(d->t[T_LIGHT].body), v1 = d->heavy_v_before;
    /* Each of the stack's contacts may rest up to the slop deep. */
    printf("stack of %d boxes: top box centre at %.4f m, rest height %.4f m: sank %.1f mm"
           " (slop allows %d x %.1f mm)\n",
           STACK_COUNT, top, rest, 1000.0f * (rest - top), STACK_COUNT, 1000.0f * d->contact_slop);
    if (!d->separated) {
        printf("sliding boxes: %s\n", d->collided ? "collided but never separated" : "never collided");
        return;
    }
    /* Elastic collision of m1 moving at v1 with m2 at rest. */
    printf("sliding boxes, %.0f kg at %.1f m/s into %.0f kg at rest (no friction, e = 1):\n", m1, v1, m2);
    printf("  momentum before %.3f kg m/s, after %.3f kg m/s\n", d->momentum_before, d->momentum_after);
    printf("  velocities after %.3f and %.3f m/s, elastic prediction %.3f and %.3f m/s\n", d->heavy_v_after,
           d->light_v_after, (m1 - m2) / (m1 + m2) * v1, 2.0f * m1 / (m1 + m2) * v1);
}

static void report_platform(const demo* d) {
    const tracked *platform = &d->t[T_PLATFORM], *rider = &d->t[T_RIDER];
    float moved = position(platform->body).x - platform->start.p.x;
    float carried = position(rider->body).x - rider->start.p.x;
    /* The rider slides until friction (deceleration mu g) brings it up to the platform's speed. */
    float slip = PLATFORM_SPEED * PLATFORM_SPEED / (2.0f * FRICTION * GRAVITY);
    printf("kinematic platform moved %.3f m (%.3f expected); box on it moved %.3f m at %.3f m/s,\n", moved,
           PLATFORM_SPEED * (float)STEP_COUNT * TIME_STEP, carried, velocity(rider->body).x);
    printf("  slipping %.3f m before friction caught it up (v^2 / (2 mu g) = %.3f m)\n", moved - carried, slip);
}

/* How far a body that lies flat at angles 0, period, 2 period, ... (degrees) is from the
 * nearest of them. */
static float tilt(i2d_body_id body, float period) {
    float angle = degrees(transform(body).q);
    return angle - period * roundf(angle / period);
}

static void report_tipper_and_disc(const demo* d) {
    i2d_body_id disc = d->t[T_DISC].body;
    /* Pivoting on the ledge's corner: m g d = (I_centre + m r^2) alpha, with I_centre = m (1 + 1) / 12
     * for the 1 m box and r^2 = d^2 + 0.5^2. A uniform disc rolls at v0 / (1 + I / (m r^2)) = 2/3 v0. */
    float predicted = GRAVITY * TIP_OVERHANG / (1.0f / 6.0f + TIP_OVERHANG * TIP_OVERHANG + 0.25f);
    printf("box with its centre %.2f m past a ledge: spin-up %.2f rad/s^2 (g d / (1/6 + d^2 + 1/4) = %.2f),\n",
           TIP_OVERHANG, -d->tip_spin_up, predicted);
    printf("  turned through %.1f deg clockwise as it fell; it lies %.1f deg from flat\n",
           -DEG * d->t[T_TIPPER].turned, tilt(d->t[T_TIPPER].body, 90.0f));
    printf("disc launched at %.2f m/s without spin: rolls at %.3f m/s (2/3 v0 = %.3f), -w r = %.3f m/s\n",
           DISC_SPEED, velocity(disc).x, 2.0f / 3.0f * DISC_SPEED, -spin(disc) * DISC_RADIUS);
}

static void report_capsule(const demo* d) {
    /* Rolling without slipping, a convex shape advances one perimeter per turn. */
    float perimeter = 2.0f * PI * CAPSULE_RADIUS + 4.0f * CAPSULE_HALF_LENGTH;
    float turns = -d->capsule_turned / (2.0f * PI);
    if (d->capsule_time == 0.0f) {
        printf("capsule on the slope: never reached its foot\n");
        return;
    }
    printf("capsule rolled %.3f m down a %.1f deg slope in %.2f s, %.2f turns: %.3f m a turn"
           " (its perimeter: %.3f m)\n",
           d->capsule_distance, DEG * atan2f(SLOPE_TOP_Y, SLOPE_FOOT_X - SLOPE_TOP_X), d->capsule_time, turns,
           d->capsule_distance / turns, perimeter);
}

static void report_resting(const demo* d) {
    i2d_vec2 top = position(d->pyramid_top);
    printf("pyramid of %d rows: top box moved %.1f mm sideways, %.1f mm down, turned %.2f deg\n", PYRAMID_ROWS,
           1000.0f * (top.x - d->pyramid_top_start.x), 1000.0f * (d->pyramid_top_start.y - top.y),
           degrees(transform(d->pyramid_top).q));
    printf("dropped tilted, angle from lying flat: triangle %.1f deg, pentagon %.1f deg, rounded box %.1f deg;\n",
           tilt(d->t[T_TRIANGLE].body, 120.0f), tilt(d->t[T_PENTAGON].body, 72.0f), tilt(d->t[T_ROUNDED].body, 90.0f));
    printf("  box dropped at %.0f deg now at %.1f deg\n", degrees(d->t[T_TILTED].start.q),
           degrees(transform(d->t[T_TILTED].body).q));
}

static void report_joints(const demo* d) {
    i2d_vec2 middle = i2d_body_get_world_point(d->planks[BRIDGE_PLANKS / 2], vec2(-PLANK_HALF_LENGTH, 0.0f));
    i2d_vec2 hip = position(d->ragdoll.bodies[BENCH_BONE_HIP]);
    float m = mass(d->chassis), m_wheel = mass(d->wheels[0]);
    float driven = position(d->chassis).x - d->chassis_start_x;
    float travel[2];
    int k, asleep = 0;
    for (k = 0; k < 2; ++k) {
        travel[k] = i2d_wheel_joint_get_translation(d->suspension[k]);
        check_last("i2d_wheel_joint_get_translation");
    }
    for (k = 0; k < BENCH_BONE_COUNT; ++k) {
        asleep += !i2d_body_is_awake(d->ragdoll.bodies[k]);
    }
    printf("chain bridge of %d planks on %d revolute joints: its middle from %.3f m to %.3f m above the ground"
           " with a ragdoll on it (%d of %d ragdoll bodies asleep, hip %.2f m up)\n",
           BRIDGE_PLANKS, BRIDGE_PLANKS + 1, d->bridge_middle_start, middle.y - ROW3_Y, asleep, BENCH_BONE_COUNT,
           hip.y - ROW3_Y);
    printf("  widest joint gap (anchors apart) in the bridge and the ragdoll during the run: %.2f mm\n",
           1000.0f * d->widest_gap);
    /* Rolling without slipping at the motor's speed: v = w r. */
    printf("car on wheel joints (%.1f kg chassis, %.2f kg wheels, %.0f Hz springs): drove %.2f m, now %.3f m/s,"
           " %.1f %% of the motors' w r = %.3f m/s;\n",
           m, m_wheel, SUSPENSION_HERTZ, driven, velocity(d->chassis).x,
           100.0f * velocity(d->chassis).x / (WHEEL_SPEED * WHEEL_RADIUS), WHEEL_SPEED * WHEEL_RADIUS);
    printf("  suspension travel now %.1f and %.1f mm, at most %.1f mm over the %.2f m bump\n", 1000.0f * travel[0],
           1000.0f * travel[1], 1000.0f * d->most_compressed, BUMP_HEIGHT);
}

static void report_chain_level(const demo* d) {
    i2d_vec2 box = position(d->chain_box), ball = position(d->chain_ball);
    printf("chain level (60 one-sided segments): the box slid from x = %.1f to x = %.2f, %.2f m above the"
           " ground under it; the ball rolled to x = %.2f, %.2f m above it (its radius: 0.35)\n",
           (double)d->chain_box_start_x, (double)box.x, (double)(box.y - hill(box.x)), (double)ball.x,
           (double)(ball.y - hill(ball.x)));
    printf("bullet at %.0f m/s at a %.0f cm wall (x = %.1f): got to x = %.3f, %s; without continuous collision"
           " it got to x = %.1f, %s\n",
           (double)BULLET_SPEED, (double)(200.0f * THIN_WALL_HALF), (double)THIN_WALL_X, (double)d->bullet_max_x,
           d->bullet_max_x < THIN_WALL_X ? "stopped by the wall" : "THROUGH THE WALL", (double)d->control_max_x,
           d->control_max_x > THIN_WALL_X ? "through the wall" : "stopped");
}

static void report(const demo* d) {
    uint32_t v = i2d_version();
    i2d_world_counters counters = i2d_world_get_counters(d->world);
    check_last("i2d_world_get_counters");
    printf("impulse2d %u.%u.%u demo: %d bodies, %d shapes, %d steps of 1/60 s x %d substeps (%.1f s simulated),"
           " stepped in %.2f ms of wall time\n",
           (unsigned)(v >> 16), (unsigned)((v >> 8) & 0xffu), (unsigned)(v & 0xffu), (int)counters.body_count,
           (int)counters.shape_count, STEP_COUNT, SUBSTEPS, (double)STEP_COUNT * TIME_STEP,
           1000.0 * d->step_seconds);
    report_balls(d);
    report_stack_and_sliders(d);
    report_platform(d);
    report_tipper_and_disc(d);
    report_capsule(d);
    report_resting(d);
    report_joints(d);
    report_chain_level(d);
    printf("contacts touching at the end: %d (candidate pairs %d)\n", (int)counters.contact_count,
           (int)counters.pair_count);
}

/* ---- The picture -------------------------------------------------------------------------- */

/* World (m, y up) to SVG pixels (y down). */
typedef struct view {
    float min_x, max_y, scale;
} view;

#define VIEW_MIN_X (-16.5f)
#define VIEW_MAX_X 16.5f
#define VIEW_MIN_Y (ROW4_Y - 1.4f)
#define VIEW_MAX_Y 6.6f
#define VIEW_SCALE 36.0f /* pixels per metre */
#define CAPTION_HEIGHT 74.0f

static float px(const view* v, float x) { return (x - v->min_x) * v->scale; }
static float py(const view* v, float y) { return (v->max_y - y) * v->scale; }

/* An SVG backend of the debug draw: i2d_world_draw hands it the world through these callbacks
 * (shapes in colours that say their bodies' state, joints, as toolkit.h lists them), and it
 * writes each as an SVG element. A dashed canvas draws outlines only, of what moves. */
typedef struct canvas {
    FILE* f;
    const view* v;
    int dashed; /* start outlines: no fill, a dashed line, static shapes left out */
} canvas;

#define STROKE_SHADE 0.6f /* the outline is the fill's colour this much as bright */
#define SHAPE_STROKE 1.5f /* px */
#define LINE_STROKE 3.0f  /* px: segments, which have no inside */
#define JOINT_STROKE 1.0f /* px */

static void svg_color(FILE* f, i2d_color color, float shade) {
    unsigned r = (unsigned)((float)((color >> 16) & 0xffu) * shade);
    unsigned g = (unsigned)((float)((color >> 8) & 0xffu) * shade);
    unsigned b = (unsigned)((float)(color & 0xffu) * shade);
    fprintf(f, "#%02x%02x%02x", r, g, b);
}

/* Ends a shape's element: filled in its colour with a darker outline, or a dashed outline. */
static void paint(const canvas* c, i2d_color color) {
    fprintf(c->f, " fill=\"");
    if (c->dashed) {
        fprintf(c->f, "none");
    } else {
        svg_color(c->f, color, 1.0f);
    }
    fprintf(c->f, "\" stroke=\"");
    svg_color(c->f, color, STROKE_SHADE);
    fprintf(c->f, "\" stroke-width=\"%.1f\"%s/>\n", SHAPE_STROKE, c->dashed ? " stroke-dasharray=\"4,3\"" : "");
}

static void svg_point(FILE* f, const view* v, const char* before, i2d_vec2 p) {
    fprintf(f, "%s%.2f,%.2f", before, px(v, p.x), py(v, p.y));
}

static void svg_line(const canvas* c, i2d_vec2 a, i2d_vec2 b, i2d_color color, float width) {
    fprintf(c->f, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"", px(c->v, a.x), py(c->v, a.y),
            px(c->v, b.x), py(c->v, b.y));
    svg_color(c->f, color, STROKE_SHADE);
    fprintf(c->f, "\" stroke-width=\"%.1f\" stroke-linecap=\"round\"%s/>\n", width,
            c->dashed ? " stroke-dasharray=\"4,3\"" : "");
}

/* What a dashed canvas leaves out: static shapes, which never left their start. */
static int skipped(const canvas* c, i2d_color color) { return c->dashed && color == I2D_COLOR_STATIC; }

/* Every point within radius of a convex polygon (a capsule is the 2-gon of its two centres):
 * each edge pushed out along its normal, the gaps closed by arcs around the corners. Points in
 * the world; the normals are the edges' outward ones. */
static void svg_rounded(const canvas* c, const i2d_vec2* points, const i2d_vec2* normals, int count, float radius,
                        i2d_color color) {
    int i;
    fprintf(c->f, "<path d=\"");
    for (i = 0; i < count; ++i) {
        i2d_vec2 p = points[i], q = points[(i + 1) % count], n = normals[i];
        i2d_vec2 m = normals[(i + count - 1) % count];
        if (i == 0) {
            svg_point(c->f, c->v, "M", vec2(p.x + radius * m.x, p.y + radius * m.y));
        }
        /* Counter-clockwise in the world stays counter-clockwise on the screen, which with y
         * down is the negative-angle direction: sweep flag 0. */
        fprintf(c->f, " A%.2f,%.2f 0 0 0", radius * c->v->scale, radius * c->v->scale);
        svg_point(c->f, c->v, " ", vec2(p.x + radius * n.x, p.y + radius * n.y));
        svg_point(c->f, c->v, " L", vec2(q.x + radius * n.x, q.y + radius * n.y));
    }
    fprintf(c->f, " Z\"");
    paint(c, color);
}

/* The outward normal of the counter-clockwise edge a -> b. */
static i2d_vec2 edge_normal(i2d_vec2 a, i2d_vec2 b) {
    float dx = b.x - a.x, dy = b.y - a.y, length = hypotf(dx, dy);
    return vec2(dy / length, -dx / length);
}

static void on_solid_polygon(i2d_transform xf, const i2d_vec2* vertices, int32_t count, float radius,
                             i2d_color color, void* context) {
    const canvas* c = (const canvas*)context;
    i2d_vec2 placed[I2D_MAX_POLYGON_VERTICES], normals[I2D_MAX_POLYGON_VERTICES];
    int i;
    if (skipped(c, color)) {
        return;
    }
    for (i = 0; i < count; ++i) {
        placed[i] = place(xf, vertices[i]);
    }
    if (radius > 0.0f) {
        for (i = 0; i < count; ++i) {
            normals[i] = edge_normal(placed[i], placed[(i + 1) % count]);
        }
        svg_rounded(c, placed, normals, count, radius, color);
        return;
    }
    fprintf(c->f, "<polygon points=\"");
    for (i = 0; i < count; ++i) {
        svg_point(c->f, c->v, i ? " " : "", placed[i]);
    }
    fprintf(c->f, "\"");
    paint(c, color);
}

static void on_solid_capsule(i2d_vec2 p1, i2d_vec2 p2, float radius, i2d_color color, void* context) {
    const canvas* c = (const canvas*)context;
    i2d_vec2 points[2], normals[2];
    if (skipped(c, color)) {
        return;
    }
    points[0] = p1;
    points[1] = p2;
    normals[0] = edge_normal(p1, p2);
    normals[1] = vec2(-normals[0].x, -normals[0].y);
    svg_rounded(c, points, normals, 2, radius, color);
}

/* A circle with a radius line along its body's x axis, so that its turning shows. */
static void on_solid_circle(i2d_transform xf, float radius, i2d_color color, void* context) {
    const canvas* c = (const canvas*)context;
    if (skipped(c, color)) {
        return;
    }
    fprintf(c->f, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\"", px(c->v, xf.p.x), py(c->v, xf.p.y),
            radius * c->v->scale);
    paint(c, color);
    svg_line(c, xf.p, vec2(xf.p.x + radius * xf.q.c, xf.p.y + radius * xf.q.s), color, SHAPE_STROKE);
}

/* Segments and chain segments are shapes (thick); the joints' lines are thin. */
static void on_segment(i2d_vec2 p1, i2d_vec2 p2, i2d_color color, void* context) {
    const canvas* c = (const canvas*)context;
    if (skipped(c, color)) {
        return;
    }
    svg_line(c, p1, p2, color, color == I2D_COLOR_JOINT ? JOINT_STROKE : LINE_STROKE);
}

/* A dot (a joint's anchors): size is its diameter in pixels. */
static void on_point(i2d_vec2 p, float size, i2d_color color, void* context) {
    const canvas* c = (const canvas*)context;
    fprintf(c->f, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" fill=\"", px(c->v, p.x), py(c->v, p.y), 0.5f * size);
    svg_color(c->f, color, STROKE_SHADE);
    fprintf(c->f, "\" stroke=\"none\"/>\n");
}

/* The world through the SVG callbacks: every shape and joint as they are now. */
static void draw_world(FILE* f, const view* v, i2d_world_id world, int dashed) {
    canvas c;
    i2d_debug_draw draw = i2d_default_debug_draw(); /* shapes and joints */
    c.f = f;
    c.v = v;
    c.dashed = dashed;
    draw.draw_solid_polygon = on_solid_polygon;
    draw.draw_solid_capsule = on_solid_capsule;
    draw.draw_solid_circle = on_solid_circle;
    draw.draw_segment = on_segment;
    draw.draw_point = on_point;
    draw.draw_joints = !dashed;
    draw.context = &c;
    check(i2d_world_draw(world, &draw), "i2d_world_draw");
}

/* Dashed outlines of what moves, where it started: the world as built, loaded from the snapshot
 * taken before the first step and drawn. */
static void draw_start(FILE* f, const view* v, const demo* d) {
    i2d_world_id start = i2d_world_create_from_snapshot(d->start, d->start_size, NULL);
    if (I2D_IS_NULL(start)) {
        fail("i2d_world_create_from_snapshot");
    }
    draw_world(f, v, start, 1);
    check(i2d_world_destroy(start), "i2d_world_destroy");
}

/* The colours of the paths and marks the demo draws itself. */
#define BALL_PATH_COLOR 0xC0392Bu
#define APEX_COLOR 0x333333u
#define CENTRE_PATH_COLOR 0x7D3C98u
#define RIM_PATH_COLOR 0x1E8449u

static void draw_path(FILE* f, const view* v, const i2d_vec2* path, int count, i2d_color stroke) {
    int k;
    fprintf(f, "<polyline fill=\"none\" stroke=\"");
    svg_color(f, stroke, 1.0f);
    fprintf(f, "\" stroke-width=\"1.2\" stroke-opacity=\"0.8\" points=\"");
    for (k = 0; k < count; ++k) {
        svg_point(f, v, k ? " " : "", path[k]);
    }
    fprintf(f, "\"/>\n");
}

/* Centred text at a world point, printf style. */
static void draw_text(FILE* f, const view* v, i2d_vec2 at, const char* format, ...) {
    va_list args;
    fprintf(f, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\">", px(v, at.x), py(v, at.y));
    va_start(args, format);
    vfprintf(f, format, args);
    va_end(args);
    fprintf(f, "</text>\n");
}

/* Each ball's path, a dashed tick at its predicted apex, and its restitution above it; the
 * centres of the bodies that turn on their way, and the disc's rim point (a cycloid). */
static void draw_paths(FILE* f, const view* v, const demo* d) {
    int i;
    for (i = 0; i < BALL_COUNT; ++i) {
        const ball* b = &d->balls[i];
        float x = b->t.path[0].x;
        /* Predicted apex: e^2 h high, reached after the fall time plus e times it again. */
        float fall_time = sqrtf(2.0f * BALL_DROP_HEIGHT / GRAVITY);
        float apex_x = x + BALL_DRIFT * fall_time * (1.0f + b->restitution);
        float apex_y = b->restitution * b->restitution * BALL_DROP_HEIGHT + BALL_RADIUS;
        draw_path(f, v, b->t.path, b->t.path_count, BALL_PATH_COLOR);
        fprintf(f, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"", px(v, apex_x - 0.6f),
                py(v, apex_y), px(v, apex_x + 0.6f), py(v, apex_y));
        svg_color(f, APEX_COLOR, 1.0f);
        fprintf(f, "\" stroke-dasharray=\"3,2\"/>\n");
        draw_text(f, v, vec2(x, BALL_DROP_HEIGHT + 2.0f * BALL_RADIUS + 0.3f), "e = %.1f", b->restitution);
    }
    for (i = T_TIPPER; i <= T_CAPSULE; ++i) {
        draw_path(f, v, d->t[i].path, d->t[i].path_count, CENTRE_PATH_COLOR);
    }
    draw_path(f, v, d->rim, d->rim_count, RIM_PATH_COLOR);
}

static void draw_labels(FILE* f, const view* v, const demo* d) {
    i2d_vec2 heavy = position(d->t[T_HEAVY].body), light = position(d->t[T_LIGHT].body);
    i2d_vec2 rider = position(d->t[T_RIDER].body);
    draw_text(f, v, vec2(STACK_X, (float)STACK_COUNT + 0.35f), "stack of %d", STACK_COUNT);
    draw_text(f, v, vec2(heavy.x, heavy.y + 0.75f), "%.0f kg, %.2f m/s", mass(d->t[T_HEAVY].body),
              velocity(d->t[T_HEAVY].body).x);
    draw_text(f, v, vec2(light.x, light.y + 0.75f), "%.0f kg, %.2f m/s", mass(d->t[T_LIGHT].body),
              velocity(d->t[T_LIGHT].body).x);
    draw_text(f, v, vec2(rider.x, rider.y + 0.85f), "box riding a kinematic platform, %.1f m/s", PLATFORM_SPEED);
    draw_text(f, v, row2(LEDGE_EDGE_X - 0.6f, LEDGE_HEIGHT + 1.4f), "box tips off a ledge");
    draw_text(f, v, row2(DISC_X + 1.6f, 1.5f), "disc launched at %.1f m/s, no spin", DISC_SPEED);
    draw_text(f, v, row2(PYRAMID_X, (float)PYRAMID_ROWS + 0.35f), "pyramid of %d rows", PYRAMID_ROWS);
    draw_text(f, v, row2(2.8f, 2.65f), "dropped tilted, land flat");
    draw_text(f, v, row2(10.0f, SLOPE_TOP_Y + 1.0f), "capsule rolls down a slope");
    draw_text(f, v, row3(BRIDGE_LEFT_X + 4.9f, BRIDGE_TOP + 0.6f), "ragdoll dropped on a chain bridge of %d planks",
              BRIDGE_PLANKS);
    draw_text(f, v, row3(position(d->chassis).x, 2.0f), "car on wheel joints, %.0f rad/s", WHEEL_SPEED);
    draw_text(f, v, vec2(-8.0f, ROW4_Y + 2.3f), "a chain of %d one-sided segments: nothing catches on a seam",
              CHAIN_POINTS - 1);
    draw_text(f, v, vec2(8.0f, hill(THIN_WALL_X) + 2.0f * BULLET_HEIGHT + 0.9f),
              "a %.0f m/s bullet stopped by a %.0f cm wall (without continuous collision: x = %.0f m)",
              (double)BULLET_SPEED, (double)(200.0f * THIN_WALL_HALF), (double)d->control_max_x);
}

/* How a legend entry is painted: a filled swatch in a colour, a dashed outline, or a line. */
typedef enum swatch_kind { SWATCH_FILL, SWATCH_DASHED, SWATCH_LINE } swatch_kind;

/* One legend entry: a swatch (a square, or a line) and its text. Returns where the next entry
 * starts. */
static float legend_entry(FILE* f, float x, float y, swatch_kind kind, i2d_color color, const char* dash,
                          const char* text) {
    if (kind == SWATCH_LINE) {
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"", x, y - 4.0f, x + 22.0f, y - 4.0f);
        svg_color(f, color, 1.0f);
        fprintf(f, "\" stroke-width=\"1.5\"%s%s%s/>\n", dash ? " stroke-dasharray=\"" : "", dash ? dash : "",
                dash ? "\"" : "");
    } else {
        fprintf(f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"14\" height=\"14\" fill=\"", x, y - 11.0f);
        if (kind == SWATCH_DASHED) {
            fprintf(f, "none");
        } else {
            svg_color(f, color, 1.0f);
        }
        fprintf(f, "\" stroke=\"");
        svg_color(f, color, STROKE_SHADE);
        fprintf(f, "\" stroke-width=\"1.5\"%s/>\n", kind == SWATCH_DASHED ? " stroke-dasharray=\"4,3\"" : "");
    }
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\">%s</text>\n", x + 28.0f, y, text);
    return x + 50.0f + 7.0f * (float)strlen(text); /* about 7 px a character */
}

static void draw_legend(FILE* f, float top) {
    float y = top + 20.0f, x = 10.0f;
    x = legend_entry(f, x, y, SWATCH_FILL, I2D_COLOR_STATIC, NULL, "static");
    x = legend_entry(f, x, y, SWATCH_FILL, I2D_COLOR_KINEMATIC, NULL, "kinematic");
    x = legend_entry(f, x, y, SWATCH_FILL, I2D_COLOR_AWAKE, NULL, "awake");
    x = legend_entry(f, x, y, SWATCH_FILL, I2D_COLOR_ASLEEP, NULL, "asleep");
    x = legend_entry(f, x, y, SWATCH_DASHED, I2D_COLOR_AWAKE, NULL, "start position");
    x = legend_entry(f, x, y, SWATCH_LINE, BALL_PATH_COLOR, NULL, "ball path");
    x = legend_entry(f, x, y, SWATCH_LINE, APEX_COLOR, "3,2", "apex, e\xc2\xb2 h");
    x = legend_entry(f, x, y, SWATCH_LINE, CENTRE_PATH_COLOR, NULL, "centre path");
    legend_entry(f, x, y, SWATCH_LINE, RIM_PATH_COLOR, NULL, "rim point path");
    fprintf(f, "<text x=\"10\" y=\"%.1f\">impulse2d demo: the state after %.1f s (%d steps of 1/60 s, %d substeps"
               " each); y up, 1 m = %.0f px. Top: bodies that only move; middle: bodies that turn (a circle's line"
               " is a radius);</text>\n",
            y + 22.0f, (double)STEP_COUNT * TIME_STEP, STEP_COUNT, SUBSTEPS, VIEW_SCALE);
    fprintf(f, "<text x=\"10\" y=\"%.1f\">third: bodies held by joints (lines to each joint's anchors, a dot at"
               " each); bottom: a chain landscape and a bullet fired at a thin wall. Drawn by i2d_world_draw.</text>\n",
            y + 40.0f);
}

static void write_svg(const demo* d, const char* path) {
    view v = {VIEW_MIN_X, VIEW_MAX_Y, VIEW_SCALE};
    float width = (VIEW_MAX_X - VIEW_MIN_X) * VIEW_SCALE, height = (VIEW_MAX_Y - VIEW_MIN_Y) * VIEW_SCALE;
    int failed;
    FILE* f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "impulse2d_demo: cannot open %s for writing\n", path);
        exit(EXIT_FAILURE);
    }
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    fprintf(f,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\""
            " font-family=\"sans-serif\" font-size=\"13\">\n",
            width, height + CAPTION_HEIGHT, width, height + CAPTION_HEIGHT);
    fprintf(f, "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n");
    draw_paths(f, &v, d);
    draw_start(f, &v, d);
    draw_world(f, &v, d->world, 0);
    draw_labels(f, &v, d);
    draw_legend(f, height);
    fprintf(f, "</svg>\n");
    failed = ferror(f) != 0;
    failed |= fclose(f) != 0;
    if (failed) {
        fprintf(stderr, "impulse2d_demo: writing %s failed\n", path);
        exit(EXIT_FAILURE);
    }
}

int main(int argc, char** argv) {
    /* Large (path arrays), so static rather than on the stack. */
    static demo d;
    int same;
    const char* svg_path = argc > 1 ? argv[1] : "impulse2d_demo.svg";
    if (i2d_version() != (uint32_t)I2D_VERSION) {
        fprintf(stderr, "impulse2d_demo: built against impulse2d %d.%d.%d but loaded a different version\n",
                I2D_VERSION_MAJOR, I2D_VERSION_MINOR, I2D_VERSION_PATCH);
        return EXIT_FAILURE;
    }
    build_scene(&d);
    run(&d);
    report(&d);
    write_svg(&d, svg_path);
    free(d.start);
    same = rerun_from_snapshot(&d);
    check(i2d_world_destroy(d.world), "i2d_world_destroy");
    printf("picture: %s\n", svg_path);
    return same ? EXIT_SUCCESS : EXIT_FAILURE;
}
