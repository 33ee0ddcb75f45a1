/* SPDX-License-Identifier: MIT */
/* The demo: a small scene that shows what impulse2d does today, reported as text and drawn as SVG.
 *
 * Usage: impulse2d_demo [output.svg]   (default: impulse2d_demo.svg in the working directory)
 *
 * The scene, left to right, on a static ground between two static walls:
 * - four balls dropped from the same height, restitution 0, 0.3, 0.6 and 0.9, onto a ground of
 *   restitution 1 (a contact takes the minimum, so each ball's own value decides); they drift
 *   sideways slowly and without friction, so that their paths draw each bounce as an arc;
 * - a stack of five 1 m boxes;
 * - a 4 kg box sliding without friction into a 1 kg box at rest, both of restitution 1;
 * - a kinematic platform moving right at constant speed, with a box riding on it.
 * Each part prints what happened beside what closed-form physics predicts. */

/* clock_gettime and CLOCK_MONOTONIC are POSIX, not C99. */
#define _POSIX_C_SOURCE 199309L

#include <impulse2d/impulse2d.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

/* ---- Scene constants ------------------------------------------------------------- */

#define TIME_STEP (1.0f / 60.0f)
#define SUBSTEPS 4
#define STEP_COUNT 240 /* 4 s */
#define GRAVITY 10.0f  /* the default world's |g|, m/s^2 */

#define GROUND_HALF_WIDTH 16.0f
#define WALL_X 15.5f /* wall centres; inner faces at +-15 m */
#define WALL_HALF_HEIGHT 3.0f

#define BALL_COUNT 4
#define BALL_RADIUS 0.3f
#define BALL_DROP_HEIGHT 4.0f /* gap between a ball's bottom and the ground at the start, m */
#define BALL_DRIFT 0.4f       /* sideways speed, m/s: spreads each path out in the picture */
static const float ball_restitution[BALL_COUNT] = {0.0f, 0.3f, 0.6f, 0.9f};

#define STACK_COUNT 5
#define STACK_X (-4.0f)

#define SLIDER_HEAVY_DENSITY 4.0f /* a 1 m box: 4 kg */
#define SLIDER_SPEED 2.0f

#define PLATFORM_SPEED 1.5f
#define PLATFORM_Y 2.5f
#define PLATFORM_HALF_WIDTH 2.0f
#define PLATFORM_HALF_HEIGHT 0.2f
#define DEFAULT_FRICTION 0.6f /* i2d_default_shape_def().friction; the rider and platform keep it */

#define MAX_BODIES 32
#define MAX_SHAPES_PER_BODY 4

/* ---- What the demo keeps ---------------------------------------------------------- */

/* A dropped ball and what it did: its path, and the top of its first bounce. */
typedef struct ball {
    i2d_body_id body;
    float restitution;
    i2d_vec2 path[STEP_COUNT + 1];
    int path_count;
    int bounced;       /* 1 once the ball has moved up after falling */
    int apex_found;    /* 1 once it turned down again after that */
    float apex;        /* highest bottom height above the ground after the first bounce, m */
} ball;

typedef struct demo {
    i2d_world_id world;
    i2d_body_id bodies[MAX_BODIES]; /* every body, for drawing */
    int body_count;

    ball balls[BALL_COUNT];
    i2d_body_id stack[STACK_COUNT];

    i2d_body_id heavy, light;
    i2d_vec2 heavy_start, light_start;
    float momentum_before;               /* kg m/s, along x */
    float heavy_v_before;
    int collided, separated;             /* the light box has started to move / the gap opened */
    float momentum_after, heavy_v_after, light_v_after;

    i2d_body_id platform, rider;
    i2d_vec2 platform_start, rider_start;

    float contact_slop;                  /* the world's allowed resting penetration, m */
    double step_seconds;                 /* wall time spent in i2d_world_step */
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
static void check_last(const char* what) {
    if (i2d_last_status() != I2D_OK) {
        fail(what);
    }
}

static i2d_vec2 vec2(float x, float y) {
    i2d_vec2 v;
    v.x = x;
    v.y = y;
    return v;
}

static i2d_vec2 position(i2d_body_id body) {
    i2d_vec2 p = i2d_body_get_position(body);
    check_last("i2d_body_get_position");
    return p;
}

static i2d_vec2 velocity(i2d_body_id body) {
    i2d_vec2 v = i2d_body_get_linear_velocity(body);
    check_last("i2d_body_get_linear_velocity");
    return v;
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

/* ---- Building the scene ------------------------------------------------------------- */

static i2d_body_id add_body(demo* d, i2d_body_type type, i2d_vec2 p, i2d_vec2 v) {
    i2d_body_def def = i2d_default_body_def();
    i2d_body_id body;
    def.type = type;
    def.position = p;
    def.linear_velocity = v;
    body = i2d_body_create(d->world, &def);
    if (I2D_IS_NULL(body)) {
        fail("i2d_body_create");
    }
    if (d->body_count == MAX_BODIES) {
        fprintf(stderr, "impulse2d_demo: more than %d bodies\n", MAX_BODIES);
        exit(EXIT_FAILURE);
    }
    d->bodies[d->body_count++] = body;
    return body;
}

static i2d_shape_def shape_def(float density, float friction, float restitution) {
    i2d_shape_def def = i2d_default_shape_def();
    def.density = density;
    def.friction = friction;
    def.restitution = restitution;
    return def;
}

static void add_box(i2d_body_id body, const i2d_shape_def* def, float half_width, float half_height) {
    if (I2D_IS_NULL(i2d_shape_create_box(body, def, half_width, half_height))) {
        fail("i2d_shape_create_box");
    }
}

static void add_circle(i2d_body_id body, const i2d_shape_def* def, float radius) {
    i2d_circle circle;
    circle.center = vec2(0.0f, 0.0f);
    circle.radius = radius;
    if (I2D_IS_NULL(i2d_shape_create_circle(body, def, &circle))) {
        fail("i2d_shape_create_circle");
    }
}

/* Ground top at y = 0, walls standing on it. Restitution 1 so that the other shape of each
 * contact decides how bouncy it is. */
static void build_ground(demo* d) {
    i2d_shape_def def = shape_def(1.0f, DEFAULT_FRICTION, 1.0f);
    i2d_body_id ground = add_body(d, I2D_BODY_STATIC, vec2(0.0f, -0.5f), vec2(0.0f, 0.0f));
    i2d_body_id left = add_body(d, I2D_BODY_STATIC, vec2(-WALL_X, WALL_HALF_HEIGHT), vec2(0.0f, 0.0f));
    i2d_body_id right = add_body(d, I2D_BODY_STATIC, vec2(WALL_X, WALL_HALF_HEIGHT), vec2(0.0f, 0.0f));
    add_box(ground, &def, GROUND_HALF_WIDTH, 0.5f);
    add_box(left, &def, 0.5f, WALL_HALF_HEIGHT);
    add_box(right, &def, 0.5f, WALL_HALF_HEIGHT);
}

static void build_balls(demo* d) {
    int i;
    for (i = 0; i < BALL_COUNT; ++i) {
        ball* b = &d->balls[i];
        /* Friction 0 keeps the drift through the bounces; it does not touch the vertical motion. */
        i2d_shape_def def = shape_def(1.0f, 0.0f, ball_restitution[i]);
        i2d_vec2 start = vec2(-13.5f + 2.0f * (float)i, BALL_DROP_HEIGHT + BALL_RADIUS);
        b->restitution = ball_restitution[i];
        b->body = add_body(d, I2D_BODY_DYNAMIC, start, vec2(BALL_DRIFT, 0.0f));
        add_circle(b->body, &def, BALL_RADIUS);
        b->path[b->path_count++] = start;
    }
}

/* Boxes start exactly touching, so the top box's centre rests at 4.5 m if nothing sinks. */
static void build_stack(demo* d) {
    i2d_shape_def def = shape_def(1.0f, DEFAULT_FRICTION, 0.0f);
    int i;
    for (i = 0; i < STACK_COUNT; ++i) {
        d->stack[i] = add_body(d, I2D_BODY_DYNAMIC, vec2(STACK_X, 0.5f + (float)i), vec2(0.0f, 0.0f));
        add_box(d->stack[i], &def, 0.5f, 0.5f);
    }
}

/* Friction 0 (the geometric mean with the ground's is then 0) so that momentum along x is
 * conserved exactly; restitution 1 on both so the collision is elastic. */
static void build_sliders(demo* d) {
    i2d_shape_def heavy_def = shape_def(SLIDER_HEAVY_DENSITY, 0.0f, 1.0f);
    i2d_shape_def light_def = shape_def(1.0f, 0.0f, 1.0f);
    d->heavy_start = vec2(-1.0f, 0.5f);
    d->light_start = vec2(2.0f, 0.5f);
    d->heavy = add_body(d, I2D_BODY_DYNAMIC, d->heavy_start, vec2(SLIDER_SPEED, 0.0f));
    d->light = add_body(d, I2D_BODY_DYNAMIC, d->light_start, vec2(0.0f, 0.0f));
    add_box(d->heavy, &heavy_def, 0.5f, 0.5f);
    add_box(d->light, &light_def, 0.5f, 0.5f);
}

/* The platform flies above the sliders' lane; the rider starts at rest on it, so friction
 * must first bring it up to the platform's speed. */
static void build_platform(demo* d) {
    i2d_shape_def def = shape_def(1.0f, DEFAULT_FRICTION, 0.0f);
    d->platform_start = vec2(5.0f, PLATFORM_Y);
    d->rider_start = vec2(5.0f, PLATFORM_Y + PLATFORM_HALF_HEIGHT + 0.5f);
    d->platform = add_body(d, I2D_BODY_KINEMATIC, d->platform_start, vec2(PLATFORM_SPEED, 0.0f));
    d->rider = add_body(d, I2D_BODY_DYNAMIC, d->rider_start, vec2(0.0f, 0.0f));
    add_box(d->platform, &def, PLATFORM_HALF_WIDTH, PLATFORM_HALF_HEIGHT);
    add_box(d->rider, &def, 0.5f, 0.5f);
}

static void build_scene(demo* d) {
    i2d_world_def def = i2d_default_world_def();
    d->contact_slop = def.contact_slop;
    d->world = i2d_world_create(&def);
    if (I2D_IS_NULL(d->world)) {
        fail("i2d_world_create");
    }
    build_ground(d);
    build_balls(d);
    build_stack(d);
    build_sliders(d);
    build_platform(d);
    d->momentum_before = mass(d->heavy) * velocity(d->heavy).x + mass(d->light) * velocity(d->light).x;
    d->heavy_v_before = velocity(d->heavy).x;
}

/* ---- Watching it run ------------------------------------------------------------------ */

/* Follows a ball through its first bounce: falling, then rising, then the turn at the top. */
static void watch_ball(ball* b) {
    i2d_vec2 p = position(b->body);
    i2d_vec2 v = velocity(b->body);
    float bottom = p.y - BALL_RADIUS;
    b->path[b->path_count++] = p;
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
    i2d_vec2 ph, pl, vh, vl;
    if (d->separated) {
        return;
    }
    vl = velocity(d->light);
    if (!d->collided) {
        d->collided = vl.x > 0.01f;
        return;
    }
    ph = position(d->heavy);
    pl = position(d->light);
    vh = velocity(d->heavy);
    if (pl.x - ph.x > 1.0f + 0.01f) {
        d->separated = 1;
        d->heavy_v_after = vh.x;
        d->light_v_after = vl.x;
        d->momentum_after = mass(d->heavy) * vh.x + mass(d->light) * vl.x;
    }
}

static void run(demo* d) {
    int step, i;
    for (step = 0; step < STEP_COUNT; ++step) {
        double t0 = seconds_now();
        check(i2d_world_step(d->world, TIME_STEP, SUBSTEPS), "i2d_world_step");
        d->step_seconds += seconds_now() - t0;
        for (i = 0; i < BALL_COUNT; ++i) {
            watch_ball(&d->balls[i]);
        }
        watch_sliders(d);
    }
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

static void report_stack(const demo* d) {
    float rest = 0.5f + (float)(STACK_COUNT - 1);
    float top = position(d->stack[STACK_COUNT - 1]).y;
    /* Each of the stack's contacts may rest up to the slop deep. */
    printf("stack of %d boxes: top box centre at %.4f m, rest height %.4f m: sank %.1f mm"
           " (slop allows %d x %.1f mm)\n",
           STACK_COUNT, top, rest, 1000.0f * (rest - top), STACK_COUNT, 1000.0f * d->contact_slop);
}

static void report_sliders(const demo* d) {
    float m1 = mass(d->heavy), m2 = mass(d->light), v1 = d->heavy_v_before;
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
    float moved = position(d->platform).x - d->platform_start.x;
    float carried = position(d->rider).x - d->rider_start.x;
    /* The rider slides until friction (deceleration mu g) brings it up to the platform's speed. */
    float slip = PLATFORM_SPEED * PLATFORM_SPEED / (2.0f * DEFAULT_FRICTION * GRAVITY);
    printf("kinematic platform moved %.3f m (%.3f expected); box on it moved %.3f m at %.3f m/s,\n", moved,
           PLATFORM_SPEED * (float)STEP_COUNT * TIME_STEP, carried, velocity(d->rider).x);
    printf("  slipping %.3f m before friction caught it up (v^2 / (2 mu g) = %.3f m)\n", moved - carried, slip);
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
    report_stack(d);
    report_sliders(d);
    report_platform(d);
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
#define VIEW_MIN_Y (-1.2f)
#define VIEW_MAX_Y 6.6f
#define VIEW_SCALE 36.0f   /* pixels per metre */
#define CAPTION_HEIGHT 56.0f

static float px(const view* v, float x) { return (x - v->min_x) * v->scale; }
static float py(const view* v, float y) { return (v->max_y - y) * v->scale; }

typedef struct palette {
    const char* fill;
    const char* stroke;
} palette;

static palette body_palette(i2d_body_type type) {
    palette p;
    switch (type) {
    case I2D_BODY_STATIC: p.fill = "#b4b4b4"; p.stroke = "#6c6c6c"; break;
    case I2D_BODY_KINEMATIC: p.fill = "#5b9bd5"; p.stroke = "#2e5f8f"; break;
    default: p.fill = "#f5a045"; p.stroke = "#a85a12"; break;
    }
    return p;
}

static void draw_shape(FILE* f, const view* v, i2d_body_id body, i2d_shape_id shape, palette pal) {
    i2d_shape_type type = i2d_shape_get_type(shape);
    check_last("i2d_shape_get_type");
    if (type == I2D_SHAPE_CIRCLE) {
        i2d_circle c = i2d_shape_get_circle(shape);
        i2d_vec2 p;
        check_last("i2d_shape_get_circle");
        p = position(body);
        fprintf(f, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" fill=\"%s\" stroke=\"%s\" stroke-width=\"1.5\"/>\n",
                px(v, p.x + c.center.x), py(v, p.y + c.center.y), c.radius * v->scale, pal.fill, pal.stroke);
    } else {
        i2d_aabb b = i2d_shape_get_aabb(shape);
        check_last("i2d_shape_get_aabb");
        fprintf(f,
                "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"%s\" stroke=\"%s\""
                " stroke-width=\"1.5\"/>\n",
                px(v, b.min.x), py(v, b.max.y), (b.max.x - b.min.x) * v->scale, (b.max.y - b.min.y) * v->scale,
                pal.fill, pal.stroke);
    }
}

static void draw_bodies(FILE* f, const view* v, const demo* d) {
    int i, j;
    for (i = 0; i < d->body_count; ++i) {
        i2d_shape_id shapes[MAX_SHAPES_PER_BODY];
        i2d_body_type type = i2d_body_get_type(d->bodies[i]);
        int count;
        check_last("i2d_body_get_type");
        count = (int)i2d_body_get_shapes(d->bodies[i], shapes, MAX_SHAPES_PER_BODY);
        check_last("i2d_body_get_shapes");
        for (j = 0; j < count && j < MAX_SHAPES_PER_BODY; ++j) {
            draw_shape(f, v, d->bodies[i], shapes[j], body_palette(type));
        }
    }
}

/* Each ball's path, a dashed tick at its predicted apex, and its restitution above it. */
static void draw_ball_paths(FILE* f, const view* v, const demo* d) {
    int i, k;
    for (i = 0; i < BALL_COUNT; ++i) {
        const ball* b = &d->balls[i];
        float x = b->path[0].x;
        /* Predicted apex: e^2 h high, reached after the fall time plus e times it again. */
        float fall_time = sqrtf(2.0f * BALL_DROP_HEIGHT / GRAVITY);
        float apex_x = x + BALL_DRIFT * fall_time * (1.0f + b->restitution);
        float apex_y = b->restitution * b->restitution * BALL_DROP_HEIGHT + BALL_RADIUS;
        fprintf(f, "<polyline fill=\"none\" stroke=\"#c0392b\" stroke-width=\"1.2\" stroke-opacity=\"0.8\" points=\"");
        for (k = 0; k < b->path_count; ++k) {
            fprintf(f, "%s%.2f,%.2f", k ? " " : "", px(v, b->path[k].x), py(v, b->path[k].y));
        }
        fprintf(f, "\"/>\n");
        fprintf(f, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#333\" stroke-dasharray=\"3,2\"/>\n",
                px(v, apex_x - 0.6f), py(v, apex_y), px(v, apex_x + 0.6f), py(v, apex_y));
        fprintf(f, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\">e = %.1f</text>\n", px(v, x),
                py(v, BALL_DROP_HEIGHT + 2.0f * BALL_RADIUS + 0.3f), b->restitution);
    }
}

/* A dashed outline where a box started, so that the picture shows how far it went. */
static void draw_start(FILE* f, const view* v, i2d_vec2 center, float half_width, float half_height,
                       const char* stroke) {
    fprintf(f,
            "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"none\" stroke=\"%s\""
            " stroke-dasharray=\"4,3\"/>\n",
            px(v, center.x - half_width), py(v, center.y + half_height), 2.0f * half_width * v->scale,
            2.0f * half_height * v->scale, stroke);
}

static void draw_labels(FILE* f, const view* v, const demo* d) {
    i2d_vec2 heavy = position(d->heavy), light = position(d->light), rider = position(d->rider);
    fprintf(f, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\">stack of %d</text>\n", px(v, STACK_X),
            py(v, (float)STACK_COUNT + 0.35f), STACK_COUNT);
    fprintf(f, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\">%.0f kg, %.2f m/s</text>\n", px(v, heavy.x),
            py(v, heavy.y + 0.75f), mass(d->heavy), velocity(d->heavy).x);
    fprintf(f, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\">%.0f kg, %.2f m/s</text>\n", px(v, light.x),
            py(v, light.y + 0.75f), mass(d->light), velocity(d->light).x);
    fprintf(f, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\">box riding a kinematic platform, %.1f m/s</text>\n",
            px(v, rider.x), py(v, rider.y + 0.85f), PLATFORM_SPEED);
    draw_start(f, v, d->heavy_start, 0.5f, 0.5f, "#a85a12");
    draw_start(f, v, d->light_start, 0.5f, 0.5f, "#a85a12");
    draw_start(f, v, d->platform_start, PLATFORM_HALF_WIDTH, PLATFORM_HALF_HEIGHT, "#2e5f8f");
    draw_start(f, v, d->rider_start, 0.5f, 0.5f, "#a85a12");
}

/* One legend entry: a swatch (a filled square, or a line when fill is NULL) and its text. */
static void legend_entry(FILE* f, float x, float y, const char* fill, const char* stroke, const char* dash,
                         const char* text) {
    char dash_attribute[48] = "";
    if (dash) {
        snprintf(dash_attribute, sizeof dash_attribute, " stroke-dasharray=\"%s\"", dash);
    }
    if (fill) {
        fprintf(f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"14\" height=\"14\" fill=\"%s\" stroke=\"%s\"%s/>", x,
                y - 11.0f, fill, stroke, dash_attribute);
    } else {
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"1.5\"%s/>",
                x, y - 4.0f, x + 22.0f, y - 4.0f, stroke, dash_attribute);
    }
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\">%s</text>\n", x + 28.0f, y, text);
}

static void draw_legend(FILE* f, float top) {
    float y = top + 20.0f;
    legend_entry(f, 10.0f, y, "#b4b4b4", "#6c6c6c", NULL, "static");
    legend_entry(f, 95.0f, y, "#5b9bd5", "#2e5f8f", NULL, "kinematic");
    legend_entry(f, 205.0f, y, "#f5a045", "#a85a12", NULL, "dynamic");
    legend_entry(f, 305.0f, y, "none", "#555", "4,3", "start position");
    legend_entry(f, 445.0f, y, NULL, "#c0392b", NULL, "ball path");
    legend_entry(f, 560.0f, y, NULL, "#333", "3,2", "predicted first-bounce apex, e&#178; h");
    fprintf(f, "<text x=\"10\" y=\"%.1f\">impulse2d demo: the state after %.1f s (%d steps of 1/60 s, %d substeps"
               " each); y up, 1 m = %.0f px.</text>\n",
            y + 22.0f, (double)STEP_COUNT * TIME_STEP, STEP_COUNT, SUBSTEPS, VIEW_SCALE);
}

static void write_svg(const demo* d, const char* path) {
    view v;
    float width, height;
    int failed;
    FILE* f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "impulse2d_demo: cannot open %s for writing\n", path);
        exit(EXIT_FAILURE);
    }
    v.min_x = VIEW_MIN_X;
    v.max_y = VIEW_MAX_Y;
    v.scale = VIEW_SCALE;
    width = (VIEW_MAX_X - VIEW_MIN_X) * VIEW_SCALE;
    height = (VIEW_MAX_Y - VIEW_MIN_Y) * VIEW_SCALE;
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    fprintf(f,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\""
            " font-family=\"sans-serif\" font-size=\"13\">\n",
            width, height + CAPTION_HEIGHT, width, height + CAPTION_HEIGHT);
    fprintf(f, "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n");
    draw_ball_paths(f, &v, d);
    draw_bodies(f, &v, d);
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
    check(i2d_world_destroy(d.world), "i2d_world_destroy");
    printf("picture: %s\n", svg_path);
    return EXIT_SUCCESS;
}
