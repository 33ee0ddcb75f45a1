/* SPDX-License-Identifier: MIT */
/* i2d_world_draw through counting callbacks: each shape once through its callback in the
 * colour of its body's state, joints, bounds, mass, contacts and islands only when asked,
 * culling, NULL callbacks, the world locked while the callbacks run, and bad input refused
 * with the world untouched. */
#include <impulse2d/impulse2d.h>

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "api_test_support.h"
#include "check.h"

/* ---- The recorder: every callback call, in order ------------------------------------- */

typedef enum draw_kind {
    K_POLYGON,
    K_SOLID_POLYGON,
    K_CIRCLE,
    K_SOLID_CIRCLE,
    K_SOLID_CAPSULE,
    K_SEGMENT,
    K_TRANSFORM,
    K_POINT,
    K_STRING,
    K_COUNT
} draw_kind;

enum { MAX_CALLS = 4096 };

/* One call: its kind, colour, a point that places it (a polygon's first world vertex, a
 * circle's centre, a segment's first end) and a second one (a segment's other end, a box's
 * upper corner), the vertex count and the radius or point size. */
typedef struct draw_call {
    draw_kind kind;
    i2d_color color;
    i2d_vec2 p, q;
    int32_t count;
    float size;
} draw_call;

typedef struct recorder {
    draw_call calls[MAX_CALLS];
    int call_count;
    int per_kind[K_COUNT];
    int non_finite; /* values that were NaN or infinite */
    /* Set by a test that probes the world from inside its callbacks (lock_probe). */
    void (*probe)(struct recorder* r);
    i2d_world_id world;
} recorder;

static bool finite_v(i2d_vec2 v) { return isfinite(v.x) && isfinite(v.y); }

static i2d_vec2 place(i2d_transform xf, i2d_vec2 v) {
    return v2(xf.q.c * v.x - xf.q.s * v.y + xf.p.x, xf.q.s * v.x + xf.q.c * v.y + xf.p.y);
}

static void record(void* context, draw_kind kind, i2d_color color, i2d_vec2 p, i2d_vec2 q, int32_t count, float size) {
    recorder* r = (recorder*)context;
    ++r->per_kind[kind];
    if (!finite_v(p) || !finite_v(q) || !isfinite(size)) {
        ++r->non_finite;
    }
    if (r->call_count < MAX_CALLS) {
        draw_call c;
        c.kind = kind;
        c.color = color;
        c.p = p;
        c.q = q;
        c.count = count;
        c.size = size;
        r->calls[r->call_count++] = c;
    }
    if (r->probe) {
        r->probe(r);
    }
}

/* A box's outline: p its lower and q its upper corner, from the four vertices. */
static void on_polygon(const i2d_vec2* v, int32_t count, i2d_color color, void* context) {
    i2d_vec2 lo = v[0], hi = v[0];
    int32_t i;
    for (i = 1; i < count; ++i) {
        lo = v2(fminf(lo.x, v[i].x), fminf(lo.y, v[i].y));
        hi = v2(fmaxf(hi.x, v[i].x), fmaxf(hi.y, v[i].y));
    }
    record(context, K_POLYGON, color, lo, hi, count, 0.0f);
}

static void on_solid_polygon(i2d_transform xf, const i2d_vec2* v, int32_t count, float radius, i2d_color color,
                             void* context) {
    record(context, K_SOLID_POLYGON, color, xf.p, place(xf, v[0]), count, radius);
}

static void on_circle(i2d_vec2 center, float radius, i2d_color color, void* context) {
    record(context, K_CIRCLE, color, center, center, 0, radius);
}

static void on_solid_circle(i2d_transform xf, float radius, i2d_color color, void* context) {
    record(context, K_SOLID_CIRCLE, color, xf.p, xf.p, 0, radius);
}

static void on_solid_capsule(i2d_vec2 p1, i2d_vec2 p2, float radius, i2d_color color, void* context) {
    record(context, K_SOLID_CAPSULE, color, p1, p2, 0, radius);
}

static void on_segment(i2d_vec2 p1, i2d_vec2 p2, i2d_color color, void* context) {
    record(context, K_SEGMENT, color, p1, p2, 0, 0.0f);
}

static void on_transform(i2d_transform xf, void* context) {
    record(context, K_TRANSFORM, 0u, xf.p, v2(xf.q.c, xf.q.s), 0, 0.0f);
}

static void on_point(i2d_vec2 p, float size, i2d_color color, void* context) {
    record(context, K_POINT, color, p, p, 0, size);
}

static void on_string(i2d_vec2 p, const char* text, i2d_color color, void* context) {
    record(context, K_STRING, color, p, p, text != NULL ? (int32_t)strlen(text) : -1, 0.0f);
}

/* The default def with every callback pointed at the recorder. */
static i2d_debug_draw counting_draw(recorder* r) {
    i2d_debug_draw d = i2d_default_debug_draw();
    memset(r, 0, sizeof *r);
    d.draw_polygon = on_polygon;
    d.draw_solid_polygon = on_solid_polygon;
    d.draw_circle = on_circle;
    d.draw_solid_circle = on_solid_circle;
    d.draw_solid_capsule = on_solid_capsule;
    d.draw_segment = on_segment;
    d.draw_transform = on_transform;
    d.draw_point = on_point;
    d.draw_string = on_string;
    d.context = r;
    return d;
}

/* Forgets what was recorded, keeping the probe. */
static void clear(recorder* r) {
    void (*probe)(recorder*) = r->probe;
    i2d_world_id world = r->world;
    memset(r, 0, sizeof *r);
    r->probe = probe;
    r->world = world;
}

/* How many calls of the kind were placed at p (within 1e-4) in the colour. */
static int calls_at(const recorder* r, draw_kind kind, i2d_vec2 p, i2d_color color) {
    int n = 0, i;
    for (i = 0; i < r->call_count; ++i) {
        const draw_call* c = &r->calls[i];
        if (c->kind == kind && c->color == color && fabsf(c->p.x - p.x) < 1e-4f && fabsf(c->p.y - p.y) < 1e-4f) {
            ++n;
        }
    }
    return n;
}

static int calls_in_color(const recorder* r, draw_kind kind, i2d_color color) {
    int n = 0, i;
    for (i = 0; i < r->call_count; ++i) {
        n += r->calls[i].kind == kind && r->calls[i].color == color;
    }
    return n;
}

static int total_calls(const recorder* r) {
    int n = 0, k;
    for (k = 0; k < K_COUNT; ++k) {
        n += r->per_kind[k];
    }
    return n;
}

/* ---- Scenes ---------------------------------------------------------------------------- */

static i2d_body_id body_at(i2d_world_id world, i2d_body_type type, float x, float y) {
    i2d_body_id b = make_body(world, type, x, y);
    I2D_CHECK(!I2D_IS_NULL(b));
    return b;
}

static void add_box(i2d_body_id body, float half) {
    i2d_shape_def def = i2d_default_shape_def();
    I2D_CHECK(!I2D_IS_NULL(i2d_shape_create_box(body, &def, half, half)));
}

static void add_circle(i2d_body_id body, float radius, bool sensor) {
    i2d_shape_def def = i2d_default_shape_def();
    i2d_circle c;
    def.is_sensor = sensor;
    c.center = v2(0.0f, 0.0f);
    c.radius = radius;
    I2D_CHECK(!I2D_IS_NULL(i2d_shape_create_circle(body, &def, &c)));
}

/* ---- Tests ------------------------------------------------------------------------------ */

I2D_TEST(api_debug_draw_default_def) {
    i2d_debug_draw d = i2d_default_debug_draw();
    I2D_CHECK(i2d_last_status() == I2D_OK);
    I2D_CHECK(d.draw_shapes && d.draw_joints);
    I2D_CHECK(!d.draw_joint_extras && !d.draw_bounds && !d.draw_mass && !d.draw_contacts);
    I2D_CHECK(!d.draw_contact_normals && !d.draw_contact_impulses && !d.draw_friction_impulses);
    I2D_CHECK(!d.draw_graph_colors && !d.draw_islands && !d.use_drawing_bounds);
    I2D_CHECK(d.draw_polygon == NULL && d.draw_solid_polygon == NULL && d.draw_circle == NULL);
    I2D_CHECK(d.draw_solid_circle == NULL && d.draw_solid_capsule == NULL && d.draw_segment == NULL);
    I2D_CHECK(d.draw_transform == NULL && d.draw_point == NULL && d.draw_string == NULL && d.context == NULL);
    I2D_CHECK(d.drawing_bounds.min.x <= d.drawing_bounds.max.x && d.drawing_bounds.min.y <= d.drawing_bounds.max.y);
    I2D_CHECK(d.internal_cookie != 0);
}

/* One shape of each state at its own x: each is drawn once, through its kind's callback,
 * in its state's colour. */
static void run_shapes_by_state(i2d_world_id world) {
    static recorder r;
    i2d_debug_draw d = counting_draw(&r);
    i2d_body_id ground = body_at(world, I2D_BODY_STATIC, 0.0f, 0.0f);
    i2d_body_id mover = body_at(world, I2D_BODY_KINEMATIC, 10.0f, 0.0f);
    i2d_body_id awake = body_at(world, I2D_BODY_DYNAMIC, 20.0f, 0.0f);
    i2d_body_id asleep = body_at(world, I2D_BODY_DYNAMIC, 30.0f, 0.0f);
    i2d_body_id bullet = body_at(world, I2D_BODY_DYNAMIC, 40.0f, 0.0f);
    i2d_body_id sensor = body_at(world, I2D_BODY_DYNAMIC, 50.0f, 0.0f);
    i2d_body_id disabled = body_at(world, I2D_BODY_DYNAMIC, 60.0f, 0.0f);
    i2d_body_id chain_body = body_at(world, I2D_BODY_STATIC, 0.0f, -10.0f);
    i2d_shape_def def = i2d_default_shape_def();
    i2d_chain_def chain = i2d_default_chain_def();
    const i2d_vec2 chain_points[5] = {{-3.0f, 0.0f}, {-2.0f, 0.0f}, {0.0f, 0.0f}, {2.0f, 0.0f}, {3.0f, 0.0f}};
    add_box(ground, 1.0f);
    I2D_CHECK(!I2D_IS_NULL(i2d_shape_create_segment(ground, &def, v2(-2.0f, 2.0f), v2(2.0f, 2.0f))));
    I2D_CHECK(!I2D_IS_NULL(i2d_shape_create_capsule(mover, &def, v2(-0.5f, 0.0f), v2(0.5f, 0.0f), 0.25f)));
    add_circle(awake, 0.5f, false);
    add_box(asleep, 0.5f);
    add_circle(bullet, 0.1f, false);
    add_circle(sensor, 0.5f, true);
    add_box(sensor, 0.25f); /* a solid shape on the sensor's body: drawn awake */
    add_box(disabled, 0.5f);
    chain.points = chain_points;
    chain.count = 5;
    I2D_CHECK(!I2D_IS_NULL(i2d_chain_create(chain_body, &chain)));
    I2D_CHECK(i2d_body_set_awake(asleep, false) == I2D_OK);
    I2D_CHECK(i2d_body_set_bullet(bullet, true) == I2D_OK);
    I2D_CHECK(i2d_body_disable(disabled) == I2D_OK);

    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    /* 4 polygons (ground, asleep, sensor's box, disabled), 3 circles, 1 capsule, the
     * segment and the chain's 2 segments; no joints, so nothing else. */
    I2D_CHECK(r.per_kind[K_SOLID_POLYGON] == 4);
    I2D_CHECK(r.per_kind[K_SOLID_CIRCLE] == 3);
    I2D_CHECK(r.per_kind[K_SOLID_CAPSULE] == 1);
    I2D_CHECK(r.per_kind[K_SEGMENT] == 3);
    I2D_CHECK(total_calls(&r) == 11 && r.non_finite == 0);
    I2D_CHECK(calls_at(&r, K_SOLID_POLYGON, v2(0.0f, 0.0f), I2D_COLOR_STATIC) == 1);
    I2D_CHECK(calls_at(&r, K_SEGMENT, v2(-2.0f, 2.0f), I2D_COLOR_STATIC) == 1);
    I2D_CHECK(calls_in_color(&r, K_SEGMENT, I2D_COLOR_STATIC) == 3);
    I2D_CHECK(calls_at(&r, K_SOLID_CAPSULE, v2(9.5f, 0.0f), I2D_COLOR_KINEMATIC) == 1);
    I2D_CHECK(calls_at(&r, K_SOLID_CIRCLE, v2(20.0f, 0.0f), I2D_COLOR_AWAKE) == 1);
    I2D_CHECK(calls_at(&r, K_SOLID_POLYGON, v2(30.0f, 0.0f), I2D_COLOR_ASLEEP) == 1);
    I2D_CHECK(calls_at(&r, K_SOLID_CIRCLE, v2(40.0f, 0.0f), I2D_COLOR_BULLET) == 1);
    I2D_CHECK(calls_at(&r, K_SOLID_CIRCLE, v2(50.0f, 0.0f), I2D_COLOR_SENSOR) == 1);
    I2D_CHECK(calls_at(&r, K_SOLID_POLYGON, v2(50.0f, 0.0f), I2D_COLOR_AWAKE) == 1);
    I2D_CHECK(calls_at(&r, K_SOLID_POLYGON, v2(60.0f, 0.0f), I2D_COLOR_DISABLED) == 1);

    /* A polygon comes with its local vertices and radius: the first placed where the box's
     * corner is. */
    I2D_CHECK(calls_at(&r, K_SOLID_POLYGON, v2(0.0f, 0.0f), I2D_COLOR_STATIC) == 1);
    {
        int i;
        for (i = 0; i < r.call_count; ++i) {
            const draw_call* c = &r.calls[i];
            if (c->kind == K_SOLID_POLYGON) {
                I2D_CHECK(c->count == 4 && c->size == 0.0f);
                I2D_CHECK(fabsf(fabsf(c->q.x - c->p.x) - fabsf(c->q.y - c->p.y)) < 1e-5f); /* a square's corner */
            }
        }
    }

    /* A bullet asleep is drawn asleep; woken again, it is a bullet. */
    I2D_CHECK(i2d_body_set_awake(bullet, false) == I2D_OK);
    clear(&r);
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    I2D_CHECK(calls_at(&r, K_SOLID_CIRCLE, v2(40.0f, 0.0f), I2D_COLOR_ASLEEP) == 1);

    /* Shapes off: nothing of them. */
    d.draw_shapes = false;
    clear(&r);
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    I2D_CHECK(total_calls(&r) == 0);
}

I2D_TEST(api_debug_draw_shapes_by_state) { run_in_world(0.0f, run_shapes_by_state); }

/* Two boxes on a revolute joint and a ball: joints, bounds, mass and islands appear only
 * when their flag is set. */
static void run_flags(i2d_world_id world) {
    static recorder r;
    i2d_debug_draw d = counting_draw(&r);
    i2d_body_id ground = body_at(world, I2D_BODY_STATIC, 0.0f, 0.0f);
    i2d_body_id arm = body_at(world, I2D_BODY_DYNAMIC, 2.0f, 0.0f);
    i2d_body_id ball = body_at(world, I2D_BODY_DYNAMIC, 10.0f, 0.0f);
    i2d_revolute_joint_def joint = i2d_default_revolute_joint_def();
    i2d_shape_id shapes[3];
    int i;
    add_box(ground, 0.5f);
    add_box(arm, 0.5f);
    add_circle(ball, 0.5f, false);
    joint.base.body_a = ground;
    joint.base.body_b = arm;
    joint.base.local_anchor_a = v2(1.0f, 0.0f);
    joint.base.local_anchor_b = v2(-1.0f, 0.0f);
    joint.enable_limit = true;
    joint.lower_angle = -0.5f;
    joint.upper_angle = 0.5f;
    joint.enable_motor = true;
    I2D_REQUIRE(!I2D_IS_NULL(i2d_joint_create_revolute(world, &joint)));

    /* Defaults: shapes and the joint's links (3 segments, 2 anchor points) only. */
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    I2D_CHECK(r.per_kind[K_SOLID_POLYGON] == 2 && r.per_kind[K_SOLID_CIRCLE] == 1);
    I2D_CHECK(r.per_kind[K_SEGMENT] == 3 && calls_in_color(&r, K_SEGMENT, I2D_COLOR_JOINT) == 3);
    I2D_CHECK(r.per_kind[K_POINT] == 2 && calls_in_color(&r, K_POINT, I2D_COLOR_JOINT_ANCHOR) == 2);
    I2D_CHECK(calls_at(&r, K_POINT, v2(1.0f, 0.0f), I2D_COLOR_JOINT_ANCHOR) == 2); /* both anchors at (1, 0) */
    I2D_CHECK(r.per_kind[K_POLYGON] == 0 && r.per_kind[K_TRANSFORM] == 0 && r.per_kind[K_CIRCLE] == 0);

    /* Extras: two limit lines, B's axis and the motor's circle. */
    d.draw_joint_extras = true;
    clear(&r);
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    I2D_CHECK(calls_in_color(&r, K_SEGMENT, I2D_COLOR_JOINT_LIMIT) == 2);
    I2D_CHECK(calls_in_color(&r, K_SEGMENT, I2D_COLOR_JOINT) == 4);
    I2D_CHECK(calls_in_color(&r, K_CIRCLE, I2D_COLOR_JOINT_MOTOR) == 1);

    /* No joints: no segments, no points (the scene has no segment shapes). */
    d.draw_joints = false;
    clear(&r);
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    I2D_CHECK(r.per_kind[K_SEGMENT] == 0 && r.per_kind[K_POINT] == 0 && r.per_kind[K_CIRCLE] == 0);
    I2D_CHECK(r.per_kind[K_SOLID_POLYGON] == 2 && r.per_kind[K_SOLID_CIRCLE] == 1);

    /* Bounds: a four-vertex outline per shape, holding the shape's bounds. */
    d.draw_bounds = true;
    clear(&r);
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    I2D_CHECK(r.per_kind[K_POLYGON] == 3 && calls_in_color(&r, K_POLYGON, I2D_COLOR_BOUNDS) == 3);
    I2D_CHECK(i2d_body_get_shapes(ground, shapes, 1) == 1 && i2d_body_get_shapes(arm, shapes + 1, 1) == 1 &&
              i2d_body_get_shapes(ball, shapes + 2, 1) == 1);
    for (i = 0; i < 3; ++i) {
        i2d_aabb tight = i2d_shape_get_aabb(shapes[i]);
        int k, holding = 0;
        for (k = 0; k < r.call_count; ++k) {
            const draw_call* c = &r.calls[k];
            holding += c->kind == K_POLYGON && c->count == 4 && c->p.x <= tight.min.x && c->p.y <= tight.min.y &&
                       c->q.x >= tight.max.x && c->q.y >= tight.max.y && c->q.x - c->p.x < 2.0f;
        }
        I2D_CHECK(holding == 1);
    }

    /* Mass: a frame at each dynamic body's centre of mass, and its mass as text. */
    d.draw_bounds = false;
    d.draw_mass = true;
    clear(&r);
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    I2D_CHECK(r.per_kind[K_TRANSFORM] == 2 && r.per_kind[K_STRING] == 2 && r.per_kind[K_POLYGON] == 0);
    I2D_CHECK(calls_at(&r, K_TRANSFORM, i2d_body_get_world_center_of_mass(arm), 0u) == 1);
    I2D_CHECK(calls_at(&r, K_STRING, i2d_body_get_world_center_of_mass(ball), I2D_COLOR_MASS) == 1);

    /* Islands: a joint to a static body links no island, so the arm and the ball are each
     * an awake island of its own. Asleep, an island is not drawn. */
    d.draw_mass = false;
    d.draw_islands = true;
    clear(&r);
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    I2D_CHECK(calls_in_color(&r, K_POLYGON, I2D_COLOR_ISLAND) == 2);
    I2D_CHECK(i2d_body_set_awake(ball, false) == I2D_OK);
    clear(&r);
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    I2D_CHECK(calls_in_color(&r, K_POLYGON, I2D_COLOR_ISLAND) == 1);
    I2D_CHECK(r.non_finite == 0);
}

I2D_TEST(api_debug_draw_flags) { run_in_world(0.0f, run_flags); }

/* A box resting on the ground: its contact points, normals and impulses when asked. */
static void run_contacts(i2d_world_id world) {
    static recorder r;
    i2d_debug_draw d = counting_draw(&r);
    i2d_body_id ground = body_at(world, I2D_BODY_STATIC, 0.0f, -0.5f);
    i2d_body_id box_body = body_at(world, I2D_BODY_DYNAMIC, 0.0f, 0.5f);
    i2d_contact_data data[4];
    int32_t n, i, k;
    { /* a wide ground */
        i2d_shape_def def = i2d_default_shape_def();
        I2D_CHECK(!I2D_IS_NULL(i2d_shape_create_box(ground, &def, 5.0f, 0.5f)));
    }
    add_box(box_body, 0.5f);
    /* Settled, and still awake (it would sleep after half a second at rest). */
    for (i = 0; i < 10; ++i) {
        I2D_REQUIRE(step_ok(world));
    }
    n = i2d_body_get_contact_data(box_body, data, 4);
    I2D_REQUIRE(n == 1 && i2d_body_is_awake(box_body));

    /* Defaults: no contact points. */
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    I2D_CHECK(r.per_kind[K_POINT] == 0);

    /* Points where the contact data puts them, touching. */
    d.draw_contacts = true;
    clear(&r);
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    for (k = 0; k < n; ++k) {
        for (i = 0; i < data[k].manifold.point_count; ++i) {
            I2D_CHECK(calls_at(&r, K_POINT, data[k].manifold.points[i].point, I2D_COLOR_CONTACT) == 1);
        }
    }
    I2D_CHECK(r.per_kind[K_POINT] >= 2);

    /* Normals: 0.3 m up from each point (from the ground, A, to the box, B). Impulses: up
     * too, as the ground pushes. */
    d.draw_contacts = false;
    d.draw_contact_normals = true;
    d.draw_contact_impulses = true;
    clear(&r);
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    I2D_CHECK(r.per_kind[K_POINT] == 0);
    I2D_CHECK(calls_in_color(&r, K_SEGMENT, I2D_COLOR_CONTACT_NORMAL) >= 2);
    I2D_CHECK(calls_in_color(&r, K_SEGMENT, I2D_COLOR_CONTACT_NORMAL) ==
              calls_in_color(&r, K_SEGMENT, I2D_COLOR_CONTACT_IMPULSE));
    for (i = 0; i < r.call_count; ++i) {
        const draw_call* c = &r.calls[i];
        if (c->kind == K_SEGMENT && c->color == I2D_COLOR_CONTACT_NORMAL) {
            I2D_CHECK_NEAR(c->q.y - c->p.y, 0.3, 1e-4);
            I2D_CHECK_NEAR(c->q.x - c->p.x, 0.0, 1e-4);
        }
        if (c->kind == K_SEGMENT && c->color == I2D_COLOR_CONTACT_IMPULSE) {
            I2D_CHECK(c->q.y > c->p.y);
        }
    }

    /* Graph colours: each point in a colour of the palette (the box moves: every contact
     * of it was coloured by the last step). */
    d.draw_contact_normals = false;
    d.draw_contact_impulses = false;
    d.draw_graph_colors = true;
    clear(&r);
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    I2D_CHECK(r.per_kind[K_POINT] >= 2);
    {
        static const i2d_color palette[I2D_GRAPH_COLOR_COUNT] = I2D_GRAPH_COLORS;
        for (i = 0; i < r.call_count; ++i) {
            bool in_palette = false;
            for (k = 0; k < I2D_GRAPH_COLOR_COUNT; ++k) {
                in_palette = in_palette || r.calls[i].color == palette[k];
            }
            I2D_CHECK(r.calls[i].kind != K_POINT || in_palette);
        }
    }
    I2D_CHECK(r.non_finite == 0);
}

I2D_TEST(api_debug_draw_contacts) { run_in_world(-10.0f, run_contacts); }

/* A grid of circles and boxes 4 m apart: culled to a box, exactly the shapes whose bounds
 * overlap it are drawn, disabled ones included. */
enum { GRID = 21 };

static void run_culling(i2d_world_id world) {
    static recorder r;
    static i2d_shape_id shapes[GRID * GRID];
    i2d_debug_draw d = counting_draw(&r);
    const i2d_aabb view = box(-9.0f, -5.2f, 6.1f, 7.0f);
    int i, j, expected = 0, shape_count = 0;
    static const i2d_body_type types[3] = {I2D_BODY_STATIC, I2D_BODY_KINEMATIC, I2D_BODY_DYNAMIC};
    for (i = 0; i < GRID; ++i) {
        for (j = 0; j < GRID; ++j) {
            int k = i * GRID + j;
            i2d_body_id b = body_at(world, types[k % 3], 4.0f * (float)(i - GRID / 2), 4.0f * (float)(j - GRID / 2));
            i2d_shape_def def = i2d_default_shape_def();
            i2d_circle c = {{0.0f, 0.0f}, 0.75f};
            shapes[k] = k % 2 ? i2d_shape_create_circle(b, &def, &c) : i2d_shape_create_box(b, &def, 0.6f, 0.6f);
            I2D_REQUIRE(!I2D_IS_NULL(shapes[k]));
            if (k % 5 == 0) {
                I2D_REQUIRE(i2d_body_disable(b) == I2D_OK);
            }
            ++shape_count;
        }
    }
    d.draw_joints = false;
    d.draw_bounds = true;
    d.use_drawing_bounds = true;
    d.drawing_bounds = view;
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    for (i = 0; i < shape_count; ++i) {
        i2d_aabb a = i2d_shape_get_aabb(shapes[i]);
        bool near = !(a.max.x < view.min.x || a.min.x > view.max.x || a.max.y < view.min.y || a.min.y > view.max.y);
        i2d_vec2 at = i2d_body_get_position(i2d_shape_get_body(shapes[i]));
        int drawn = 0, k;
        for (k = 0; k < r.call_count; ++k) {
            const draw_call* c = &r.calls[k];
            drawn += (c->kind == K_SOLID_CIRCLE || c->kind == K_SOLID_POLYGON) && fabsf(c->p.x - at.x) < 1e-4f &&
                     fabsf(c->p.y - at.y) < 1e-4f;
        }
        expected += near;
        if (drawn != (near ? 1 : 0)) {
            ++i2d_check_failures;
            fprintf(stderr, "%s: the shape at (%g, %g) was drawn %d times; expected %d\n", __FILE__, (double)at.x,
                    (double)at.y, drawn, near ? 1 : 0);
        }
    }
    I2D_CHECK(expected > 4 && expected < shape_count / 4);
    I2D_CHECK(r.per_kind[K_SOLID_CIRCLE] + r.per_kind[K_SOLID_POLYGON] == expected);
    /* A bounds outline for each shape drawn but the disabled ones (out of the broadphase). */
    I2D_CHECK(r.per_kind[K_POLYGON] == expected - calls_in_color(&r, K_SOLID_CIRCLE, I2D_COLOR_DISABLED) -
                                           calls_in_color(&r, K_SOLID_POLYGON, I2D_COLOR_DISABLED));
    I2D_CHECK(calls_in_color(&r, K_SOLID_CIRCLE, I2D_COLOR_DISABLED) +
                  calls_in_color(&r, K_SOLID_POLYGON, I2D_COLOR_DISABLED) > 0);

    /* Unculled, all of them; a box far away, none. */
    d.use_drawing_bounds = false;
    clear(&r);
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    I2D_CHECK(r.per_kind[K_SOLID_CIRCLE] + r.per_kind[K_SOLID_POLYGON] == shape_count);
    d.use_drawing_bounds = true;
    d.drawing_bounds = box(1000.0f, 1000.0f, 1001.0f, 1001.0f);
    clear(&r);
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    I2D_CHECK(total_calls(&r) == 0);
}

I2D_TEST(api_debug_draw_culling) { run_in_world(0.0f, run_culling); }

/* Every flag on and no callback, or one callback alone: fine, and only that kind comes. */
static void run_null_callbacks(i2d_world_id world) {
    static recorder r;
    i2d_debug_draw d = i2d_default_debug_draw();
    i2d_body_id ground = body_at(world, I2D_BODY_STATIC, 0.0f, -0.5f);
    i2d_body_id ball = body_at(world, I2D_BODY_DYNAMIC, 0.0f, 0.45f);
    i2d_body_id box_body = body_at(world, I2D_BODY_DYNAMIC, 2.0f, 0.45f);
    i2d_distance_joint_def joint = i2d_default_distance_joint_def();
    int i;
    add_box(ground, 5.0f);
    add_circle(ball, 0.5f, false);
    add_box(box_body, 0.5f);
    joint.base.body_a = ball;
    joint.base.body_b = box_body;
    joint.length = 2.0f;
    joint.enable_limit = true;
    joint.min_length = 1.0f;
    joint.max_length = 3.0f;
    I2D_REQUIRE(!I2D_IS_NULL(i2d_joint_create_distance(world, &joint)));
    for (i = 0; i < 5; ++i) {
        I2D_REQUIRE(step_ok(world));
    }
    d.draw_joint_extras = d.draw_bounds = d.draw_mass = d.draw_contacts = true;
    d.draw_contact_normals = d.draw_contact_impulses = d.draw_friction_impulses = true;
    d.draw_graph_colors = d.draw_islands = true;
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    d.use_drawing_bounds = true;
    d.drawing_bounds = box(-1.0f, -1.0f, 1.0f, 1.0f);
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);

    /* Only circles wanted. */
    memset(&r, 0, sizeof r);
    d.use_drawing_bounds = false;
    d.draw_solid_circle = on_solid_circle;
    d.context = &r;
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    I2D_CHECK(r.per_kind[K_SOLID_CIRCLE] == 1 && total_calls(&r) == 1);
    /* Only points: joint anchors, limits and contact points, every one finite. */
    memset(&r, 0, sizeof r);
    d.draw_solid_circle = NULL;
    d.draw_point = on_point;
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    I2D_CHECK(r.per_kind[K_POINT] >= 4 && total_calls(&r) == r.per_kind[K_POINT]);
    I2D_CHECK(calls_in_color(&r, K_POINT, I2D_COLOR_JOINT_LIMIT) == 2 && r.non_finite == 0);
}

I2D_TEST(api_debug_draw_null_callbacks) { run_in_world(-10.0f, run_null_callbacks); }

/* ---- Inside the callbacks the world is locked ----------------------------------------- */

typedef struct lock_results {
    bool probed;
    i2d_status create, step, set_velocity, destroy_world, nested_draw, overlap;
    bool created;
    bool getter_ok;
} lock_results;

static lock_results g_lock;
static i2d_body_id g_probe_body;

static bool count_overlap(i2d_shape_id shape, void* context) {
    (void)shape;
    ++*(int*)context;
    return true;
}

static void lock_probe(recorder* r) {
    i2d_body_def def = i2d_default_body_def();
    i2d_debug_draw nested = i2d_default_debug_draw();
    i2d_vec2 p;
    int found = 0;
    if (g_lock.probed) {
        return;
    }
    g_lock.probed = true;
    g_lock.created = !I2D_IS_NULL(i2d_body_create(r->world, &def));
    g_lock.create = i2d_last_status();
    g_lock.step = i2d_world_step(r->world, k_dt, SUBSTEPS);
    g_lock.set_velocity = i2d_body_set_linear_velocity(g_probe_body, v2(1.0f, 0.0f));
    g_lock.destroy_world = i2d_world_destroy(r->world);
    p = i2d_body_get_position(g_probe_body);
    g_lock.getter_ok = i2d_last_status() == I2D_OK && p.x == 3.0f && p.y == 1.0f;
    g_lock.nested_draw = i2d_world_draw(r->world, &nested); /* no callbacks: draws nothing */
    g_lock.overlap = i2d_world_overlap_aabb(r->world, box(-10.0f, -10.0f, 10.0f, 10.0f),
                                            i2d_default_query_filter(), count_overlap, &found);
    g_lock.getter_ok = g_lock.getter_ok && found == 2;
}

static void run_locked(i2d_world_id world) {
    static recorder r;
    i2d_debug_draw d = counting_draw(&r);
    i2d_body_id ground = body_at(world, I2D_BODY_STATIC, 0.0f, -1.0f);
    i2d_body_def def = i2d_default_body_def();
    uint64_t hash;
    i2d_world_counters before, after;
    add_box(ground, 2.0f);
    g_probe_body = body_at(world, I2D_BODY_DYNAMIC, 3.0f, 1.0f);
    add_circle(g_probe_body, 0.5f, false);
    hash = i2d_world_get_state_hash(world);
    before = i2d_world_get_counters(world);
    memset(&g_lock, 0, sizeof g_lock);
    r.probe = lock_probe;
    r.world = world;
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    I2D_CHECK(g_lock.probed);
    I2D_CHECK(!g_lock.created && g_lock.create == I2D_ERR_WORLD_LOCKED);
    I2D_CHECK(g_lock.step == I2D_ERR_WORLD_LOCKED);
    I2D_CHECK(g_lock.set_velocity == I2D_ERR_WORLD_LOCKED);
    I2D_CHECK(g_lock.destroy_world == I2D_ERR_WORLD_LOCKED);
    I2D_CHECK(g_lock.nested_draw == I2D_OK && g_lock.overlap == I2D_OK && g_lock.getter_ok);
    /* The draw ends with its own status, whatever the callbacks met; the world is as it was. */
    I2D_CHECK(i2d_last_status() == I2D_OK);
    I2D_CHECK(i2d_world_get_state_hash(world) == hash);
    after = i2d_world_get_counters(world);
    I2D_CHECK(after.body_count == before.body_count && after.shape_count == before.shape_count);
    I2D_CHECK(r.per_kind[K_SOLID_POLYGON] == 1 && r.per_kind[K_SOLID_CIRCLE] == 1);
    /* Unlocked again afterwards. */
    I2D_CHECK(!I2D_IS_NULL(i2d_body_create(world, &def)));
    I2D_CHECK(step_ok(world));
}

I2D_TEST(api_debug_draw_locks_the_world) { run_in_world(-10.0f, run_locked); }

/* ---- Bad input: a status, no callback, the world untouched ------------------------------- */

#define CHECK_REFUSED(what, call, expected) check_refused_at(__FILE__, __LINE__, what, (call), (expected))

static void run_bad_input(i2d_world_id world) {
    static recorder r;
    i2d_debug_draw d = counting_draw(&r);
    i2d_debug_draw zeroed;
    i2d_body_id b = body_at(world, I2D_BODY_DYNAMIC, 0.0f, 0.0f);
    const float nan = nanf("");
    uint64_t hash;
    i2d_world_def def = i2d_default_world_def();
    i2d_world_id gone;
    add_box(b, 0.5f);
    I2D_REQUIRE(step_ok(world));
    hash = i2d_world_get_state_hash(world);

    CHECK_REFUSED("NULL draw", i2d_world_draw(world, NULL), I2D_ERR_INVALID_ARGUMENT);
    memset(&zeroed, 0, sizeof zeroed);
    zeroed.draw_solid_polygon = on_solid_polygon;
    zeroed.draw_shapes = true;
    zeroed.context = &r;
    CHECK_REFUSED("a zeroed def", i2d_world_draw(world, &zeroed), I2D_ERR_INVALID_ARGUMENT);
    d.use_drawing_bounds = true;
    d.drawing_bounds = box(nan, 0.0f, 1.0f, 1.0f);
    CHECK_REFUSED("NaN bounds", i2d_world_draw(world, &d), I2D_ERR_INVALID_ARGUMENT);
    d.drawing_bounds = box(0.0f, 0.0f, 1.0f, INFINITY);
    CHECK_REFUSED("infinite bounds", i2d_world_draw(world, &d), I2D_ERR_INVALID_ARGUMENT);
    d.drawing_bounds = box(1.0f, 0.0f, -1.0f, 1.0f);
    CHECK_REFUSED("inverted bounds", i2d_world_draw(world, &d), I2D_ERR_INVALID_ARGUMENT);
    {
        i2d_world_id null_world = {0};
        i2d_world_id foreign;
        foreign.bits = b.bits;
        CHECK_REFUSED("null world", i2d_world_draw(null_world, &d), I2D_ERR_INVALID_HANDLE);
        CHECK_REFUSED("a body's id", i2d_world_draw(foreign, &d), I2D_ERR_INVALID_HANDLE);
    }
    gone = i2d_world_create(&def);
    I2D_REQUIRE(i2d_world_destroy(gone) == I2D_OK);
    d.use_drawing_bounds = false;
    CHECK_REFUSED("a destroyed world", i2d_world_draw(gone, &d), I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(total_calls(&r) == 0);
    I2D_CHECK(i2d_world_get_state_hash(world) == hash);

    /* NaN bounds that are not used are not read. */
    d.drawing_bounds = box(nan, nan, nan, nan);
    I2D_CHECK_STATUS(i2d_world_draw(world, &d), I2D_OK);
    I2D_CHECK(r.per_kind[K_SOLID_POLYGON] == 1);
    I2D_CHECK(i2d_world_get_state_hash(world) == hash);
}

I2D_TEST(api_debug_draw_bad_input) { run_in_world(-10.0f, run_bad_input); }
