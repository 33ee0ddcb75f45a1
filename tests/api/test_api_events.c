/* SPDX-License-Identifier: MIT */
/* C API events: contact begin/end, sensor begin/end and body moves, checked against closed form and bookkeeping. */
#include <impulse2d/impulse2d.h>

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "api_test_support.h"
#include "check.h"

/* ---- Small helpers ---------------------------------------------------------------- */

static i2d_shape_id add_circle(i2d_body_id body, const i2d_shape_def* def, float radius) {
    i2d_circle circle;
    circle.center = v2(0.0f, 0.0f);
    circle.radius = radius;
    return i2d_shape_create_circle(body, def, &circle);
}

/* The ground of most tests: a static box 20 m wide whose top is at y = 0. */
static i2d_shape_id make_ground(i2d_world_id world, const i2d_shape_def* def) {
    i2d_body_id ground = make_body(world, I2D_BODY_STATIC, 0.0f, -1.0f);
    return i2d_shape_create_box(ground, def, 10.0f, 1.0f);
}

/* ---- Closed form: free fall with the step's integration ----------------------------- */

/* Each substep h adds g h to the velocity, then moves by h v (symplectic Euler, the
 * order every substep of impulse2d integrates in). Returns the first substep count k
 * after which y(k) <= level, for a body starting at rest at y0; -1 within max substeps. */
static int first_substep_at_or_below(double y0, double g, double h, double level, int max) {
    double v = 0.0, y = y0;
    for (int k = 1; k <= max; ++k) {
        v += g * h;
        y += v * h;
        if (y <= level) {
            return k;
        }
    }
    return -1;
}

/* The step (1-based) that contains substep k (1-based). Whether a pipeline looks for
 * contacts at the start of each substep or after it moves the bodies, the contact that
 * appears at the end of substep k is seen in step ceil(k / n) as long as k is not the
 * last substep of a step; tests choose their heights so that it is not, or accept both
 * floor(k / n) + 1 and ceil(k / n). */
static int step_of_substep_ceil(int k) { return (k + SUBSTEPS - 1) / SUBSTEPS; }
static int step_of_substep_next(int k) { return k / SUBSTEPS + 1; }

/* ---- Contact begin on landing, none at rest, end when lifted ------------------------ */

/* A drop height for a ball of radius r onto y = 0 whose first touching substep is not
 * the last of a step and that penetrates by at least 1 mm at once (so float rounding
 * cannot move the touch to another substep). Returns the substep, 0 if none found. */
static int find_clean_drop(double r, double* out_y0) {
    const double h = (double)k_dt / SUBSTEPS;
    for (int i = 0; i < 200; ++i) {
        double y0 = 3.0 + 0.0037 * i;
        int k = first_substep_at_or_below(y0, -10.0, h, r, 100000);
        int k_early = first_substep_at_or_below(y0, -10.0, h, r + 1e-3, 100000);
        int k_late = first_substep_at_or_below(y0, -10.0, h, r - 1e-3, 100000);
        if (k > 0 && k_early == k && k_late == k && k % SUBSTEPS != 0) {
            *out_y0 = y0;
            return k;
        }
    }
    return 0;
}

static void run_landing(i2d_world_id world) {
    const float radius = 0.5f;
    double y0 = 0.0;
    int touch_substep = find_clean_drop(radius, &y0);
    I2D_REQUIRE(touch_substep > 0);
    const int touch_step = step_of_substep_ceil(touch_substep);

    i2d_shape_def def = i2d_default_shape_def();
    i2d_shape_id ground = make_ground(world, &def);
    i2d_body_id ball_body = make_body(world, I2D_BODY_DYNAMIC, 0.0f, (float)y0);
    i2d_shape_id ball = add_circle(ball_body, &def, radius);
    I2D_REQUIRE(!I2D_IS_NULL(ground) && !I2D_IS_NULL(ball));

    /* Before any step there is no event. */
    i2d_contact_events e = i2d_world_get_contact_events(world);
    I2D_CHECK(i2d_last_status() == I2D_OK);
    I2D_CHECK(e.begin_count == 0 && e.end_count == 0);

    g_reports_left = 10;
    int begins = 0;
    for (int step = 1; step <= touch_step + 120; ++step) {
        I2D_REQUIRE(step_ok(world));
        e = i2d_world_get_contact_events(world);
        I2D_CHECK(i2d_last_status() == I2D_OK);
        if (e.end_count != 0) {
            I2D_CHECK(e.end_events != NULL);
            report("landing: step %d has %d end events", step, (int)e.end_count);
            I2D_CHECK(e.end_count == 0);
        }
        if (step == touch_step) {
            /* The step where the ball first touches: exactly one begin, ball and ground. */
            if (e.begin_count != 1) {
                report("landing: step %d (the first touch) has %d begin events, expected 1", step, (int)e.begin_count);
            }
            I2D_CHECK(e.begin_count == 1);
            if (e.begin_count == 1) {
                I2D_REQUIRE(e.begin_events != NULL);
                I2D_CHECK(same_pair(e.begin_events[0].shape_a, e.begin_events[0].shape_b, ball, ground));
            }
        } else if (e.begin_count != 0) {
            report("landing: step %d has %d begin events; the ball first touches in step %d", step,
                   (int)e.begin_count, touch_step);
            I2D_CHECK(e.begin_count == 0);
        }
        begins += e.begin_count;
        /* Touching from the first touch on, never before. */
        i2d_world_counters c = i2d_world_get_counters(world);
        I2D_CHECK(c.contact_count == (step >= touch_step ? 1 : 0));
        I2D_CHECK(c.pair_count >= c.contact_count);
    }
    I2D_CHECK(begins == 1);
    /* At rest on the ground (the resting check has meaning only if it rests). */
    I2D_CHECK_NEAR(i2d_body_get_position(ball_body).y, radius, 0.02);

    /* Lifted far away: one end event in the next step, nothing after. */
    I2D_CHECK_STATUS(i2d_body_set_transform(ball_body, v2(0.0f, 50.0f), identity_rot()), I2D_OK);
    I2D_REQUIRE(step_ok(world));
    e = i2d_world_get_contact_events(world);
    I2D_CHECK(e.begin_count == 0);
    I2D_CHECK(e.end_count == 1);
    if (e.end_count == 1) {
        I2D_REQUIRE(e.end_events != NULL);
        I2D_CHECK(same_pair(e.end_events[0].shape_a, e.end_events[0].shape_b, ball, ground));
    }
    I2D_CHECK(i2d_world_get_counters(world).contact_count == 0);
    for (int step = 0; step < 10; ++step) {
        I2D_REQUIRE(step_ok(world));
        e = i2d_world_get_contact_events(world);
        I2D_CHECK(e.begin_count == 0 && e.end_count == 0);
    }
}

I2D_TEST(api_events_contact_landing) { run_in_world(-10.0f, run_landing); }

/* A box landing flat on the ground touches along a whole edge (two manifold points):
 * still one begin event for the pair. */
static void run_box_landing(i2d_world_id world) {
    const float half = 0.5f;
    double y0 = 0.0;
    int touch_substep = find_clean_drop(half, &y0);
    I2D_REQUIRE(touch_substep > 0);
    const int touch_step = step_of_substep_ceil(touch_substep);

    i2d_shape_def def = i2d_default_shape_def();
    i2d_shape_id ground = make_ground(world, &def);
    i2d_body_id body = make_body(world, I2D_BODY_DYNAMIC, 2.0f, (float)y0);
    i2d_shape_id crate = i2d_shape_create_box(body, &def, half, half);
    I2D_REQUIRE(!I2D_IS_NULL(ground) && !I2D_IS_NULL(crate));
    int begins = 0, ends = 0;
    for (int step = 1; step <= touch_step + 60; ++step) {
        I2D_REQUIRE(step_ok(world));
        i2d_contact_events e = i2d_world_get_contact_events(world);
        begins += e.begin_count;
        ends += e.end_count;
        if (step == touch_step) {
            I2D_CHECK(e.begin_count == 1);
            if (e.begin_count == 1) {
                I2D_CHECK(same_pair(e.begin_events[0].shape_a, e.begin_events[0].shape_b, crate, ground));
            }
        }
    }
    I2D_CHECK(begins == 1 && ends == 0);
    I2D_CHECK_NEAR(i2d_body_get_position(body).y, half, 0.02);
}

I2D_TEST(api_events_contact_box_landing) { run_in_world(-10.0f, run_box_landing); }

/* An elastic ball bounces: every impact begins a contact and every rebound ends it. */
static void run_bounce(i2d_world_id world) {
    const float radius = 0.5f;
    i2d_shape_def def = i2d_default_shape_def();
    def.restitution = 1.0f;
    i2d_shape_id ground = make_ground(world, &def);
    i2d_body_id ball_body = make_body(world, I2D_BODY_DYNAMIC, 0.0f, 3.0f);
    i2d_shape_id ball = add_circle(ball_body, &def, radius);
    I2D_REQUIRE(!I2D_IS_NULL(ground) && !I2D_IS_NULL(ball));

    g_reports_left = 10;
    int state = 0, begins = 0, ends = 0, rebounds_checked = 0;
    for (int step = 1; step <= 240; ++step) {
        I2D_REQUIRE(step_ok(world));
        i2d_contact_events e = i2d_world_get_contact_events(world);
        for (int i = 0; i < e.begin_count; ++i) {
            I2D_CHECK(same_pair(e.begin_events[i].shape_a, e.begin_events[i].shape_b, ball, ground));
        }
        for (int i = 0; i < e.end_count; ++i) {
            I2D_CHECK(same_pair(e.end_events[i].shape_a, e.end_events[i].shape_b, ball, ground));
        }
        begins += e.begin_count;
        ends += e.end_count;
        state += e.begin_count - e.end_count;
        if (state < 0 || state > 1) {
            report("bounce: step %d: %d begins and %d ends in all leave the pair in state %d", step, begins, ends,
                   state);
            I2D_CHECK(state == 0 || state == 1);
            return;
        }
        I2D_CHECK(i2d_world_get_counters(world).contact_count == state);
        if (e.end_count > 0 && state == 0) {
            /* Just ended: the ball is on its way up and clear of the ground. */
            i2d_vec2 p = i2d_body_get_position(ball_body);
            i2d_vec2 v = i2d_body_get_linear_velocity(ball_body);
            if (!(v.y > 0.0f) || !(p.y - radius > 0.0f)) {
                report("bounce: step %d: contact ended with the ball at y %g moving at %g", step, p.y, v.y);
                I2D_CHECK(v.y > 0.0f && p.y - radius > 0.0f);
            }
            ++rebounds_checked;
        }
    }
    /* Dropped 2.5 m, an elastic ball first lands after 0.71 s and then every 1.41 s:
     * three impacts in the 4 s simulated. */
    I2D_CHECK(begins >= 2);
    I2D_CHECK(ends >= 2);
    I2D_CHECK(rebounds_checked >= 2);
}

I2D_TEST(api_events_contact_bounce) { run_in_world(-10.0f, run_bounce); }

/* ---- Destroying touching shapes: end events with the next step ---------------------- */

enum { DESTROY_BALL_SHAPE, DESTROY_BALL_BODY, DESTROY_GROUND_BODY, DESTROY_AND_REPLACE, DESTROY_CASES };

static void run_destroy_touching(int how) {
    i2d_world_id world = make_world(-10.0f);
    I2D_REQUIRE(!I2D_IS_NULL(world));
    i2d_shape_def def = i2d_default_shape_def();
    i2d_shape_id ground = make_ground(world, &def);
    i2d_body_id ground_body = i2d_shape_get_body(ground);
    /* Starts 1 cm deep in the ground: touching from the first step. */
    i2d_body_id ball_body = make_body(world, I2D_BODY_DYNAMIC, 1.0f, 0.49f);
    i2d_shape_id ball = add_circle(ball_body, &def, 0.5f);
    if (I2D_IS_NULL(ground) || I2D_IS_NULL(ball)) {
        I2D_CHECK(!"scene");
        i2d_world_destroy(world);
        return;
    }
    I2D_CHECK(step_ok(world));
    i2d_contact_events e = i2d_world_get_contact_events(world);
    I2D_CHECK(e.begin_count == 1 && e.end_count == 0);
    for (int i = 0; i < 30; ++i) {
        I2D_CHECK(step_ok(world));
    }
    e = i2d_world_get_contact_events(world);
    I2D_CHECK(e.begin_count == 0 && e.end_count == 0);
    I2D_CHECK(i2d_world_get_counters(world).contact_count == 1);

    i2d_shape_id replacement = I2D_NULL_SHAPE_ID;
    i2d_shape_id gone = how == DESTROY_GROUND_BODY ? ground : ball;
    switch (how) {
    case DESTROY_BALL_SHAPE:
        I2D_CHECK_STATUS(i2d_shape_destroy(ball), I2D_OK);
        break;
    case DESTROY_BALL_BODY:
        I2D_CHECK_STATUS(i2d_body_destroy(ball_body), I2D_OK);
        break;
    case DESTROY_GROUND_BODY:
        I2D_CHECK_STATUS(i2d_body_destroy(ground_body), I2D_OK);
        break;
    default: {
        /* A new ball where the old one was: its slot may be reused, its id may not. */
        I2D_CHECK_STATUS(i2d_body_destroy(ball_body), I2D_OK);
        i2d_body_id fresh = make_body(world, I2D_BODY_DYNAMIC, 1.0f, 0.49f);
        replacement = add_circle(fresh, &def, 0.5f);
        I2D_CHECK(!I2D_IS_NULL(replacement));
        I2D_CHECK(!I2D_ID_EQUALS(replacement, ball));
        break;
    }
    }
    I2D_CHECK(!i2d_shape_is_valid(gone));

    /* The arrays still describe the last step until the next one. */
    e = i2d_world_get_contact_events(world);
    I2D_CHECK(e.begin_count == 0 && e.end_count == 0);

    I2D_CHECK(step_ok(world));
    e = i2d_world_get_contact_events(world);
    I2D_CHECK(e.end_count == 1);
    if (e.end_count == 1) {
        I2D_CHECK(same_pair(e.end_events[0].shape_a, e.end_events[0].shape_b, ball, ground));
        /* Stale ids in end events: the destroyed one is invalid. */
        I2D_CHECK(!i2d_shape_is_valid(e.end_events[0].shape_a) || !i2d_shape_is_valid(e.end_events[0].shape_b));
    }
    if (how == DESTROY_AND_REPLACE) {
        I2D_CHECK(e.begin_count == 1);
        if (e.begin_count == 1) {
            I2D_CHECK(same_pair(e.begin_events[0].shape_a, e.begin_events[0].shape_b, replacement, ground));
        }
        I2D_CHECK(i2d_world_get_counters(world).contact_count == 1);
    } else {
        I2D_CHECK(e.begin_count == 0);
        I2D_CHECK(i2d_world_get_counters(world).contact_count == 0);
    }

    /* Reported once. */
    I2D_CHECK(step_ok(world));
    e = i2d_world_get_contact_events(world);
    I2D_CHECK(e.end_count == 0);
    I2D_CHECK(e.begin_count == 0);
    i2d_world_destroy(world);
}

I2D_TEST(api_events_destroy_touching) {
    for (int how = 0; how < DESTROY_CASES; ++how) {
        int before = i2d_check_failures;
        run_destroy_touching(how);
        if (i2d_check_failures != before) {
            fprintf(stderr, "  (in destroy case %d)\n", how);
        }
    }
}

/* A shape destroyed while touching several others: one end event per pair. */
static void run_destroy_in_pile(i2d_world_id world) {
    i2d_shape_def def = i2d_default_shape_def();
    i2d_shape_id ground = make_ground(world, &def);
    /* A wide plank on the ground with three balls on it. */
    i2d_body_id plank_body = make_body(world, I2D_BODY_DYNAMIC, 0.0f, 0.245f);
    i2d_shape_id plank = i2d_shape_create_box(plank_body, &def, 3.0f, 0.25f);
    i2d_shape_id balls[3];
    for (int i = 0; i < 3; ++i) {
        balls[i] = add_circle(make_body(world, I2D_BODY_DYNAMIC, -2.0f + 2.0f * (float)i, 0.985f), &def, 0.5f);
        I2D_REQUIRE(!I2D_IS_NULL(balls[i]));
    }
    I2D_REQUIRE(!I2D_IS_NULL(ground) && !I2D_IS_NULL(plank));
    for (int i = 0; i < 30; ++i) {
        I2D_REQUIRE(step_ok(world));
    }
    I2D_REQUIRE(i2d_world_get_counters(world).contact_count == 4);
    I2D_CHECK_STATUS(i2d_shape_destroy(plank), I2D_OK);
    I2D_REQUIRE(step_ok(world));
    i2d_contact_events e = i2d_world_get_contact_events(world);
    I2D_CHECK(e.end_count == 4);
    bool seen[4] = {false, false, false, false};
    for (int i = 0; i < e.end_count; ++i) {
        int which = -1;
        for (int k = 0; k < 3; ++k) {
            which = same_pair(e.end_events[i].shape_a, e.end_events[i].shape_b, plank, balls[k]) ? k : which;
        }
        which = same_pair(e.end_events[i].shape_a, e.end_events[i].shape_b, plank, ground) ? 3 : which;
        I2D_CHECK(which >= 0);
        if (which >= 0) {
            I2D_CHECK(!seen[which]);
            seen[which] = true;
        }
    }
    /* The plank's contacts are gone; the balls now fall and touch the ground later. */
    I2D_CHECK(e.begin_count == 0);
}

I2D_TEST(api_events_destroy_in_pile) { run_in_world(-10.0f, run_destroy_in_pile); }

/* ---- enable_contact_events = false on either shape ---------------------------------- */

/* Drops a ball on the ground, lets it rest, lifts it away; counts events. The pair
 * still collides whatever the flags say: the ball rests on the ground. */
static void run_contact_flag(bool ball_events, bool ground_events) {
    i2d_world_id world = make_world(-10.0f);
    I2D_REQUIRE(!I2D_IS_NULL(world));
    i2d_shape_def def = i2d_default_shape_def();
    def.enable_contact_events = ground_events;
    i2d_shape_id ground = make_ground(world, &def);
    def.enable_contact_events = ball_events;
    i2d_body_id ball_body = make_body(world, I2D_BODY_DYNAMIC, 0.0f, 2.0f);
    i2d_shape_id ball = add_circle(ball_body, &def, 0.5f);
    /* A second ball with events on, so that the world reports something either way. */
    def.enable_contact_events = true;
    i2d_body_id other_body = make_body(world, I2D_BODY_DYNAMIC, 5.0f, 2.0f);
    i2d_shape_id other = add_circle(other_body, &def, 0.5f);
    if (I2D_IS_NULL(ground) || I2D_IS_NULL(ball) || I2D_IS_NULL(other)) {
        I2D_CHECK(!"scene");
        i2d_world_destroy(world);
        return;
    }
    const bool expect = ball_events && ground_events;
    int pair_begins = 0, pair_ends = 0, other_begins = 0;
    for (int step = 0; step < 90; ++step) {
        I2D_CHECK(step_ok(world));
        i2d_contact_events e = i2d_world_get_contact_events(world);
        for (int i = 0; i < e.begin_count; ++i) {
            pair_begins += same_pair(e.begin_events[i].shape_a, e.begin_events[i].shape_b, ball, ground) ? 1 : 0;
            other_begins += same_pair(e.begin_events[i].shape_a, e.begin_events[i].shape_b, other, ground) ? 1 : 0;
        }
        pair_ends += e.end_count;
    }
    I2D_CHECK_NEAR(i2d_body_get_position(ball_body).y, 0.5, 0.02);
    I2D_CHECK(i2d_world_get_counters(world).contact_count == 2);
    I2D_CHECK(pair_begins == (expect ? 1 : 0));
    I2D_CHECK(other_begins == (ground_events ? 1 : 0));
    I2D_CHECK(pair_ends == 0);

    I2D_CHECK_STATUS(i2d_body_set_transform(ball_body, v2(0.0f, 40.0f), identity_rot()), I2D_OK);
    I2D_CHECK(step_ok(world));
    i2d_contact_events e = i2d_world_get_contact_events(world);
    I2D_CHECK(e.end_count == (expect ? 1 : 0));
    I2D_CHECK(e.begin_count == 0);
    i2d_world_destroy(world);
}

I2D_TEST(api_events_contact_flag) {
    static const bool cases[4][2] = {{true, true}, {false, true}, {true, false}, {false, false}};
    for (int c = 0; c < 4; ++c) {
        int before = i2d_check_failures;
        run_contact_flag(cases[c][0], cases[c][1]);
        if (i2d_check_failures != before) {
            fprintf(stderr, "  (ball events %d, ground events %d)\n", cases[c][0], cases[c][1]);
        }
    }
}

/* ---- Event arrays stay valid and unchanged until the next step ---------------------- */

enum { COPY_MAX = 64 };

typedef struct event_copy {
    i2d_contact_events contact;
    i2d_sensor_events sensor;
    i2d_body_events body;
    i2d_contact_begin_event contact_begin[COPY_MAX];
    i2d_contact_end_event contact_end[COPY_MAX];
    i2d_sensor_begin_event sensor_begin[COPY_MAX];
    i2d_sensor_end_event sensor_end[COPY_MAX];
    i2d_body_move_event moves[COPY_MAX];
} event_copy;

static bool copy_events(i2d_world_id world, event_copy* c) {
    memset(c, 0, sizeof *c);
    c->contact = i2d_world_get_contact_events(world);
    c->sensor = i2d_world_get_sensor_events(world);
    c->body = i2d_world_get_body_events(world);
    if (c->contact.begin_count > COPY_MAX || c->contact.end_count > COPY_MAX || c->sensor.begin_count > COPY_MAX ||
        c->sensor.end_count > COPY_MAX || c->body.move_count > COPY_MAX) {
        return false;
    }
    if (c->contact.begin_count > 0) {
        memcpy(c->contact_begin, c->contact.begin_events, sizeof(i2d_contact_begin_event) * c->contact.begin_count);
    }
    if (c->contact.end_count > 0) {
        memcpy(c->contact_end, c->contact.end_events, sizeof(i2d_contact_end_event) * c->contact.end_count);
    }
    if (c->sensor.begin_count > 0) {
        memcpy(c->sensor_begin, c->sensor.begin_events, sizeof(i2d_sensor_begin_event) * c->sensor.begin_count);
    }
    if (c->sensor.end_count > 0) {
        memcpy(c->sensor_end, c->sensor.end_events, sizeof(i2d_sensor_end_event) * c->sensor.end_count);
    }
    if (c->body.move_count > 0) {
        /* Padding in the struct is not compared: copy field by field. */
        for (int i = 0; i < c->body.move_count; ++i) {
            c->moves[i].transform = c->body.move_events[i].transform;
            c->moves[i].body = c->body.move_events[i].body;
            c->moves[i].user_data = c->body.move_events[i].user_data;
            c->moves[i].fell_asleep = c->body.move_events[i].fell_asleep;
        }
    }
    return true;
}

static bool same_move(const i2d_body_move_event* a, const i2d_body_move_event* b) {
    return a->transform.p.x == b->transform.p.x && a->transform.p.y == b->transform.p.y &&
           a->transform.q.c == b->transform.q.c && a->transform.q.s == b->transform.q.s &&
           I2D_ID_EQUALS(a->body, b->body) && a->user_data == b->user_data && a->fell_asleep == b->fell_asleep;
}

/* The arrays the world handed out, read through their old pointers, still hold what
 * was copied; and the getters hand out the same arrays. */
static void check_events_unchanged(i2d_world_id world, const event_copy* c, const char* after) {
    int before = i2d_check_failures;
    i2d_contact_events ce = i2d_world_get_contact_events(world);
    i2d_sensor_events se = i2d_world_get_sensor_events(world);
    i2d_body_events be = i2d_world_get_body_events(world);
    I2D_CHECK(ce.begin_events == c->contact.begin_events && ce.begin_count == c->contact.begin_count);
    I2D_CHECK(ce.end_events == c->contact.end_events && ce.end_count == c->contact.end_count);
    I2D_CHECK(se.begin_events == c->sensor.begin_events && se.begin_count == c->sensor.begin_count);
    I2D_CHECK(se.end_events == c->sensor.end_events && se.end_count == c->sensor.end_count);
    I2D_CHECK(be.move_events == c->body.move_events && be.move_count == c->body.move_count);
    for (int i = 0; i < c->contact.begin_count; ++i) {
        I2D_CHECK(same_pair(c->contact.begin_events[i].shape_a, c->contact.begin_events[i].shape_b,
                            c->contact_begin[i].shape_a, c->contact_begin[i].shape_b));
        I2D_CHECK(I2D_ID_EQUALS(c->contact.begin_events[i].shape_a, c->contact_begin[i].shape_a));
    }
    for (int i = 0; i < c->contact.end_count; ++i) {
        I2D_CHECK(I2D_ID_EQUALS(c->contact.end_events[i].shape_a, c->contact_end[i].shape_a));
        I2D_CHECK(I2D_ID_EQUALS(c->contact.end_events[i].shape_b, c->contact_end[i].shape_b));
    }
    for (int i = 0; i < c->sensor.begin_count; ++i) {
        I2D_CHECK(I2D_ID_EQUALS(c->sensor.begin_events[i].sensor_shape, c->sensor_begin[i].sensor_shape));
        I2D_CHECK(I2D_ID_EQUALS(c->sensor.begin_events[i].visitor_shape, c->sensor_begin[i].visitor_shape));
    }
    for (int i = 0; i < c->sensor.end_count; ++i) {
        I2D_CHECK(I2D_ID_EQUALS(c->sensor.end_events[i].sensor_shape, c->sensor_end[i].sensor_shape));
        I2D_CHECK(I2D_ID_EQUALS(c->sensor.end_events[i].visitor_shape, c->sensor_end[i].visitor_shape));
    }
    for (int i = 0; i < c->body.move_count; ++i) {
        I2D_CHECK(same_move(&c->body.move_events[i], &c->moves[i]));
    }
    if (i2d_check_failures != before) {
        fprintf(stderr, "  (event arrays changed after %s)\n", after);
    }
}

static void run_arrays_stable(i2d_world_id world) {
    i2d_shape_def def = i2d_default_shape_def();
    i2d_shape_id ground = make_ground(world, &def);
    /* Three balls 1 cm deep in the ground; the middle one inside a sensor zone. */
    i2d_body_id balls[3];
    for (int i = 0; i < 3; ++i) {
        balls[i] = make_body(world, I2D_BODY_DYNAMIC, -4.0f + 4.0f * (float)i, 0.49f);
        I2D_REQUIRE(!I2D_IS_NULL(add_circle(balls[i], &def, 0.5f)));
    }
    i2d_shape_def sensor_def = i2d_default_shape_def();
    sensor_def.is_sensor = true;
    i2d_body_id zone = make_body(world, I2D_BODY_STATIC, 0.0f, 2.0f);
    i2d_shape_id sensor = i2d_shape_create_box(zone, &sensor_def, 1.5f, 2.0f);
    I2D_REQUIRE(!I2D_IS_NULL(ground) && !I2D_IS_NULL(sensor));
    I2D_REQUIRE(step_ok(world));

    /* Second step: one ball lifted away (end), a new one in the ground (begin), a new
     * one inside the zone (sensor begin); everything dynamic moves. */
    I2D_CHECK_STATUS(i2d_body_set_transform(balls[0], v2(-4.0f, 30.0f), identity_rot()), I2D_OK);
    I2D_REQUIRE(!I2D_IS_NULL(add_circle(make_body(world, I2D_BODY_DYNAMIC, 6.0f, 0.49f), &def, 0.5f)));
    I2D_REQUIRE(!I2D_IS_NULL(add_circle(make_body(world, I2D_BODY_DYNAMIC, 0.5f, 2.5f), &def, 0.25f)));
    I2D_REQUIRE(step_ok(world));

    static event_copy copy;
    I2D_REQUIRE(copy_events(world, &copy));
    /* Only meaningful with something in every array. */
    I2D_CHECK(copy.contact.begin_count >= 1 && copy.contact.end_count >= 1);
    I2D_CHECK(copy.sensor.begin_count >= 1);
    I2D_CHECK(copy.body.move_count >= 3);

    check_events_unchanged(world, &copy, "reading them again");

    /* Create bodies and shapes, some touching others. */
    for (int i = 0; i < 50; ++i) {
        i2d_body_id b = make_body(world, I2D_BODY_DYNAMIC, -8.0f + 0.3f * (float)i, 0.3f + 0.01f * (float)i);
        I2D_CHECK(!I2D_IS_NULL(add_circle(b, &def, 0.4f)));
    }
    check_events_unchanged(world, &copy, "creating bodies");
    /* Destroy a touching body, a shape, the sensor. */
    I2D_CHECK_STATUS(i2d_body_destroy(balls[2]), I2D_OK);
    I2D_CHECK_STATUS(i2d_shape_destroy(sensor), I2D_OK);
    check_events_unchanged(world, &copy, "destroying bodies and shapes");
    /* Teleports, filters, velocities, gravity, queries, counters, rebuilding the tree. */
    I2D_CHECK_STATUS(i2d_body_set_transform(balls[1], v2(3.0f, 9.0f), identity_rot()), I2D_OK);
    i2d_filter none = i2d_default_filter();
    none.mask_bits = 0;
    I2D_CHECK_STATUS(i2d_shape_set_filter(ground, none), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_set_linear_velocity(balls[1], v2(1.0f, 2.0f)), I2D_OK);
    I2D_CHECK_STATUS(i2d_world_set_gravity(world, v2(0.0f, -3.0f)), I2D_OK);
    i2d_shape_id ids[8];
    i2d_aabb everywhere = {{-100.0f, -100.0f}, {100.0f, 100.0f}};
    I2D_CHECK(i2d_world_overlap_aabb_ids(world, everywhere, i2d_default_query_filter(), ids, 8) > 0);
    (void)i2d_world_cast_ray_closest(world, v2(0.0f, 20.0f), v2(0.0f, -30.0f), i2d_default_query_filter());
    (void)i2d_world_get_counters(world);
    I2D_CHECK_STATUS(i2d_world_rebuild_static_tree(world), I2D_OK);
    check_events_unchanged(world, &copy, "setters, queries and a tree rebuild");
    /* A zero-length step "does nothing"; events are left to the next real step. Not
     * checked: a zero step may count as a step. Creating and destroying a second world
     * must not disturb this one's arrays. */
    i2d_world_id other = make_world(-10.0f);
    I2D_CHECK(!I2D_IS_NULL(other));
    if (!I2D_IS_NULL(other)) {
        i2d_shape_def other_def = i2d_default_shape_def();
        make_ground(other, &other_def);
        add_circle(make_body(other, I2D_BODY_DYNAMIC, 0.0f, 0.49f), &other_def, 0.5f);
        I2D_CHECK(step_ok(other));
        i2d_world_destroy(other);
    }
    check_events_unchanged(world, &copy, "stepping and destroying another world");
}

I2D_TEST(api_events_arrays_stable_until_step) { run_in_world(-10.0f, run_arrays_stable); }

/* ---- Every begin has its end: a long random scene ------------------------------------ */

/* Open pairs, keyed by the unordered pair of shape ids, in an open-addressing table. */
enum { PAIR_TABLE = 1 << 15 };

typedef struct pair_entry {
    uint64_t lo, hi; /* lo < hi; lo == hi == 0 marks an empty slot */
    int state;       /* begins - ends so far */
    int step_begins, step_ends;
    int touched_step; /* the step of the last change, to reset the per-step counts */
} pair_entry;

typedef struct pair_table {
    pair_entry entries[PAIR_TABLE];
    int used;
} pair_table;

static pair_entry* pair_find(pair_table* t, i2d_shape_id a, i2d_shape_id b, bool create) {
    uint64_t lo = a.bits < b.bits ? a.bits : b.bits, hi = a.bits < b.bits ? b.bits : a.bits;
    uint64_t h = (lo * UINT64_C(0x9E3779B97F4A7C15)) ^ (hi * UINT64_C(0xC2B2AE3D27D4EB4F));
    for (uint32_t i = (uint32_t)(h >> 49), n = 0; n < PAIR_TABLE; ++n, i = (i + 1) & (PAIR_TABLE - 1)) {
        pair_entry* e = &t->entries[i];
        if (e->lo == lo && e->hi == hi && (lo | hi) != 0) {
            return e;
        }
        if (e->lo == 0 && e->hi == 0) {
            if (!create || t->used >= PAIR_TABLE / 2) {
                return NULL;
            }
            ++t->used;
            e->lo = lo;
            e->hi = hi;
            e->touched_step = -1;
            return e;
        }
    }
    return NULL;
}

static void pair_touch(pair_entry* e, int step) {
    if (e->touched_step != step) {
        e->touched_step = step;
        e->step_begins = 0;
        e->step_ends = 0;
    }
}

typedef struct tracker {
    pair_table table;
    int total_begins, total_ends, bad;
} tracker;

/* Reads one step's contact events into the table and checks them:
 * - a begin names two live, distinct shapes;
 * - every event names a pair, and each pair's begins - ends stays 0 or 1;
 * - the open pairs are exactly as many as the touching pairs the counters report, and
 *   none of them names a destroyed shape (its end event is due with this step). */
static void tracker_read_step(tracker* t, i2d_world_id world, int step) {
    i2d_contact_events e = i2d_world_get_contact_events(world);
    if (i2d_last_status() != I2D_OK || e.begin_count < 0 || e.end_count < 0) {
        ++t->bad;
        report("step %d: get_contact_events status %s, counts %d %d", step, i2d_status_string(i2d_last_status()),
               (int)e.begin_count, (int)e.end_count);
        return;
    }
    for (int i = 0; i < e.begin_count; ++i) {
        i2d_shape_id a = e.begin_events[i].shape_a, b = e.begin_events[i].shape_b;
        if (!i2d_shape_is_valid(a) || !i2d_shape_is_valid(b) || I2D_ID_EQUALS(a, b)) {
            ++t->bad;
            report("step %d: begin event %d names a stale or repeated shape (0x%llx, 0x%llx)", step, i,
                   (unsigned long long)a.bits, (unsigned long long)b.bits);
            continue;
        }
        if (I2D_ID_EQUALS(i2d_shape_get_body(a), i2d_shape_get_body(b))) {
            ++t->bad;
            report("step %d: begin event %d pairs two shapes of one body", step, i);
        }
        pair_entry* p = pair_find(&t->table, a, b, true);
        if (p == NULL) {
            ++t->bad;
            report("pair table full");
            return;
        }
        pair_touch(p, step);
        ++p->step_begins;
        ++t->total_begins;
    }
    for (int i = 0; i < e.end_count; ++i) {
        i2d_shape_id a = e.end_events[i].shape_a, b = e.end_events[i].shape_b;
        pair_entry* p = pair_find(&t->table, a, b, false);
        if (p == NULL) {
            ++t->bad;
            report("step %d: end event %d for a pair that never began (0x%llx, 0x%llx)", step, i,
                   (unsigned long long)a.bits, (unsigned long long)b.bits);
            continue;
        }
        pair_touch(p, step);
        ++p->step_ends;
        ++t->total_ends;
    }
    /* Apply this step's changes and sum the open pairs. */
    int open = 0;
    for (int i = 0; i < PAIR_TABLE; ++i) {
        pair_entry* p = &t->table.entries[i];
        if (p->lo == 0 && p->hi == 0) {
            continue;
        }
        if (p->touched_step == step) {
            p->state += p->step_begins - p->step_ends;
            if (p->state < 0 || p->state > 1 || p->step_begins > 1 || p->step_ends > 1) {
                ++t->bad;
                report("step %d: pair (0x%llx, 0x%llx) got %d begins and %d ends, state now %d", step,
                       (unsigned long long)p->lo, (unsigned long long)p->hi, p->step_begins, p->step_ends, p->state);
                p->state = p->state < 0 ? 0 : 1;
            }
        }
        if (p->state == 1) {
            ++open;
            i2d_shape_id a, b;
            a.bits = p->lo;
            b.bits = p->hi;
            if (!i2d_shape_is_valid(a) || !i2d_shape_is_valid(b)) {
                ++t->bad;
                report("step %d: pair (0x%llx, 0x%llx) is open but one of its shapes was destroyed before the step",
                       step, (unsigned long long)p->lo, (unsigned long long)p->hi);
                p->state = 0; /* report once */
            }
        }
    }
    i2d_world_counters c = i2d_world_get_counters(world);
    if (open != c.contact_count) {
        ++t->bad;
        report("step %d: %d pairs begun and not ended, counters.contact_count %d", step, open, (int)c.contact_count);
    }
    if (c.pair_count < c.contact_count) {
        ++t->bad;
        report("step %d: pair_count %d < contact_count %d", step, (int)c.pair_count, (int)c.contact_count);
    }
}

enum { PILE_BODIES = 400 };

typedef struct pile {
    i2d_world_id world;
    i2d_body_id bodies[PILE_BODIES];
    bool alive[PILE_BODIES];
    int count;
    i2d_body_id statics[4];
    i2d_body_id movers[2];
} pile;

static void pile_spawn(pile* p, rng* r) {
    if (p->count >= PILE_BODIES) {
        return;
    }
    i2d_body_id b = make_body(p->world, I2D_BODY_DYNAMIC, rng_float(r, -17.0f, 17.0f), rng_float(r, 12.0f, 40.0f));
    i2d_shape_def def = i2d_default_shape_def();
    def.friction = rng_float(r, 0.0f, 1.0f);
    def.restitution = rng_int(r, 4) == 0 ? rng_float(r, 0.0f, 0.8f) : 0.0f;
    int kind = rng_int(r, 5);
    if (kind <= 1) {
        add_circle(b, &def, rng_float(r, 0.2f, 0.8f));
    } else if (kind <= 3) {
        i2d_shape_create_box(b, &def, rng_float(r, 0.2f, 0.8f), rng_float(r, 0.2f, 0.8f));
    } else {
        /* Two shapes on one body: they never make a pair with each other. */
        i2d_circle c;
        c.center = v2(rng_float(r, -0.5f, 0.5f), rng_float(r, -0.5f, 0.5f));
        c.radius = rng_float(r, 0.2f, 0.6f);
        i2d_shape_create_circle(b, &def, &c);
        i2d_shape_create_box(b, &def, rng_float(r, 0.2f, 0.6f), rng_float(r, 0.2f, 0.6f));
    }
    p->bodies[p->count] = b;
    p->alive[p->count] = !I2D_IS_NULL(b);
    ++p->count;
}

static int pile_random_alive(pile* p, rng* r) {
    if (p->count == 0) {
        return -1;
    }
    for (int tries = 0; tries < 20; ++tries) {
        int i = rng_int(r, p->count);
        if (p->alive[i]) {
            return i;
        }
    }
    return -1;
}

static void run_pile(pile* p, uint64_t seed, int steps) {
    static tracker t;
    memset(&t, 0, sizeof t);
    rng r = {seed};
    g_reports_left = 20;
    i2d_shape_def def = i2d_default_shape_def();
    /* A container: floor (top at y = 0) and two walls. */
    p->statics[0] = make_body(p->world, I2D_BODY_STATIC, 0.0f, -1.0f);
    i2d_shape_create_box(p->statics[0], &def, 21.0f, 1.0f);
    p->statics[1] = make_body(p->world, I2D_BODY_STATIC, -20.0f, 20.0f);
    i2d_shape_create_box(p->statics[1], &def, 1.0f, 20.0f);
    p->statics[2] = make_body(p->world, I2D_BODY_STATIC, 20.0f, 20.0f);
    i2d_shape_create_box(p->statics[2], &def, 1.0f, 20.0f);
    /* A ledge inside, destroyed half way through. */
    p->statics[3] = make_body(p->world, I2D_BODY_STATIC, -8.0f, 6.0f);
    i2d_shape_create_box(p->statics[3], &def, 4.0f, 0.3f);
    /* Two kinematic paddles sweeping through the pile. */
    for (int i = 0; i < 2; ++i) {
        i2d_body_def kdef = i2d_default_body_def();
        kdef.type = I2D_BODY_KINEMATIC;
        kdef.position = v2(i == 0 ? -15.0f : 15.0f, 1.5f + 3.0f * (float)i);
        kdef.linear_velocity = v2(i == 0 ? 4.0f : -4.0f, 0.0f);
        p->movers[i] = i2d_body_create(p->world, &kdef);
        i2d_shape_create_box(p->movers[i], &def, 0.5f, 0.5f);
    }

    int step = 0;
    for (; step < steps; ++step) {
        if (step < steps / 2) {
            pile_spawn(p, &r);
        }
        if (step % 7 == 3) { /* destroy a body */
            int i = pile_random_alive(p, &r);
            if (i >= 0 && i2d_body_destroy(p->bodies[i]) == I2D_OK) {
                p->alive[i] = false;
            }
        }
        if (step % 11 == 5) { /* destroy one shape of a body, keeping the body */
            int i = pile_random_alive(p, &r);
            i2d_shape_id shapes[2];
            if (i >= 0 && i2d_body_get_shapes(p->bodies[i], shapes, 2) == 2) {
                I2D_CHECK_STATUS(i2d_shape_destroy(shapes[rng_int(&r, 2)]), I2D_OK);
            }
        }
        if (step % 9 == 4) { /* teleport into the pile */
            int i = pile_random_alive(p, &r);
            if (i >= 0) {
                i2d_vec2 to = v2(rng_float(&r, -17.0f, 17.0f), rng_float(&r, 0.5f, 6.0f));
                I2D_CHECK_STATUS(i2d_body_set_transform(p->bodies[i], to, identity_rot()), I2D_OK);
            }
        }
        if (step % 13 == 6) { /* make a shape pass through everything, or collide again */
            int i = pile_random_alive(p, &r);
            i2d_shape_id shape;
            if (i >= 0 && i2d_body_get_shapes(p->bodies[i], &shape, 1) >= 1) {
                i2d_filter f = i2d_shape_get_filter(shape);
                f.mask_bits = f.mask_bits == 0 ? UINT64_MAX : 0;
                I2D_CHECK_STATUS(i2d_shape_set_filter(shape, f), I2D_OK);
            }
        }
        if (step % 60 == 59) { /* the paddles turn round */
            for (int i = 0; i < 2; ++i) {
                i2d_vec2 v = i2d_body_get_linear_velocity(p->movers[i]);
                i2d_body_set_linear_velocity(p->movers[i], v2(-v.x, v.y));
            }
        }
        if (step == steps / 2) {
            I2D_CHECK_STATUS(i2d_body_destroy(p->statics[3]), I2D_OK);
        }
        if (!step_ok(p->world)) {
            I2D_CHECK(!"step failed");
            return;
        }
        tracker_read_step(&t, p->world, step);
    }
    /* Destroy everything and step once: every open pair must end. */
    for (int i = 0; i < p->count; ++i) {
        if (p->alive[i]) {
            I2D_CHECK_STATUS(i2d_body_destroy(p->bodies[i]), I2D_OK);
            p->alive[i] = false;
        }
    }
    for (int i = 0; i < 3; ++i) {
        I2D_CHECK_STATUS(i2d_body_destroy(p->statics[i]), I2D_OK);
    }
    for (int i = 0; i < 2; ++i) {
        I2D_CHECK_STATUS(i2d_body_destroy(p->movers[i]), I2D_OK);
    }
    I2D_CHECK(step_ok(p->world));
    tracker_read_step(&t, p->world, step);
    int open = 0;
    for (int i = 0; i < PAIR_TABLE; ++i) {
        open += t.table.entries[i].state;
    }
    i2d_contact_events e = i2d_world_get_contact_events(p->world);
    I2D_CHECK(e.begin_count == 0);
    printf("events pile: %d pairs, %d begins, %d ends, %d open at the end, %d last ends\n", t.table.used,
           t.total_begins, t.total_ends, open, (int)e.end_count);
    I2D_CHECK(open == 0);
    I2D_CHECK(t.bad == 0);
    I2D_CHECK(t.total_begins == t.total_ends);
    /* The scene is busy enough for the bookkeeping to mean something. */
    I2D_CHECK(t.total_begins >= 300);
    I2D_CHECK(e.end_count >= 50);
    I2D_CHECK(i2d_world_get_counters(p->world).contact_count == 0);
}

I2D_TEST(api_events_every_begin_ends) {
    static pile p;
    memset(&p, 0, sizeof p);
    p.world = make_world(-10.0f);
    I2D_REQUIRE(!I2D_IS_NULL(p.world));
    run_pile(&p, 0xE7E7u, 500);
    i2d_world_destroy(p.world);
}

/* ---- Sensors ------------------------------------------------------------------------ */

/* The steps in which an event caused at substep k may be reported (see above). */
static bool step_allowed(int step, int k_early, int k_late) {
    return k_early > 0 && k_late > 0 && step >= step_of_substep_ceil(k_early) && step <= step_of_substep_next(k_late);
}

typedef struct sensor_scene {
    i2d_world_id world;
    i2d_body_id balls[3];
    i2d_shape_id ball_shapes[3]; /* 0: plain; 1: enable_sensor_events false; 2: enable_contact_events false */
    i2d_shape_id ground;
    i2d_shape_id sensor; /* null in the scene without it */
} sensor_scene;

/* Ground top at y = -20; three balls of radius 0.5 dropped from y = 10 at x = -3, 0, 3;
 * with_sensor: a static sensor box [-8, 8] x [-2, 2], created last. */
static bool sensor_scene_build(sensor_scene* s, bool with_sensor) {
    memset(s, 0, sizeof *s);
    s->world = make_world(-10.0f);
    if (I2D_IS_NULL(s->world)) {
        return false;
    }
    i2d_shape_def def = i2d_default_shape_def();
    i2d_body_id ground = make_body(s->world, I2D_BODY_STATIC, 0.0f, -21.0f);
    s->ground = i2d_shape_create_box(ground, &def, 10.0f, 1.0f);
    for (int i = 0; i < 3; ++i) {
        i2d_shape_def ball_def = i2d_default_shape_def();
        ball_def.enable_sensor_events = i != 1;
        ball_def.enable_contact_events = i != 2;
        s->balls[i] = make_body(s->world, I2D_BODY_DYNAMIC, -3.0f + 3.0f * (float)i, 10.0f);
        s->ball_shapes[i] = add_circle(s->balls[i], &ball_def, 0.5f);
        if (I2D_IS_NULL(s->ball_shapes[i])) {
            return false;
        }
    }
    if (with_sensor) {
        i2d_shape_def sensor_def = i2d_default_shape_def();
        sensor_def.is_sensor = true;
        i2d_body_id zone = make_body(s->world, I2D_BODY_STATIC, 0.0f, 0.0f);
        s->sensor = i2d_shape_create_box(zone, &sensor_def, 8.0f, 2.0f);
        if (I2D_IS_NULL(s->sensor) || !i2d_shape_is_sensor(s->sensor)) {
            return false;
        }
    }
    return !I2D_IS_NULL(s->ground);
}

/* A sensor event of the scene's sensor, counted (and its step kept) for the ball whose
 * shape visited; a visitor that is no ball fails. */
static void count_sensor_event(const sensor_scene* s, i2d_shape_id sensor, i2d_shape_id visitor, const char* kind,
                               int step, int* counts, int* steps) {
    I2D_CHECK(I2D_ID_EQUALS(sensor, s->sensor));
    int which = -1;
    for (int k = 0; k < 3; ++k) {
        which = I2D_ID_EQUALS(visitor, s->ball_shapes[k]) ? k : which;
    }
    if (which < 0) {
        report("step %d: sensor %s with an unknown visitor 0x%llx", step, kind, (unsigned long long)visitor.bits);
        I2D_CHECK(which >= 0);
        return;
    }
    ++counts[which];
    steps[which] = step;
}

static void run_sensor_zone(sensor_scene* with, sensor_scene* without) {
    const double h = (double)k_dt / SUBSTEPS;
    /* The ball overlaps the zone while its centre is within [-2.5, 2.5] (touching counts). */
    const int enter_early = first_substep_at_or_below(10.0, -10.0, h, 2.5 + 1e-4, 100000);
    const int enter_late = first_substep_at_or_below(10.0, -10.0, h, 2.5 - 1e-4, 100000);
    const int leave_early = first_substep_at_or_below(10.0, -10.0, h, -2.5 + 1e-4, 100000);
    const int leave_late = first_substep_at_or_below(10.0, -10.0, h, -2.5 - 1e-4, 100000);
    const int land = first_substep_at_or_below(10.0, -10.0, h, -19.5, 100000);
    I2D_REQUIRE(enter_early > 0 && leave_late > 0 && land > 0);

    g_reports_left = 20;
    int begin_step[3] = {-1, -1, -1}, end_step[3] = {-1, -1, -1};
    int begin_count[3] = {0, 0, 0}, end_count[3] = {0, 0, 0};
    int identical = 1;
    const int steps = step_of_substep_ceil(land) + 60;
    for (int step = 1; step <= steps; ++step) {
        I2D_REQUIRE(step_ok(with->world) && step_ok(without->world));
        /* The sensor does not touch the balls' motion: bit for bit the same. */
        for (int i = 0; i < 3; ++i) {
            i2d_vec2 a = i2d_body_get_position(with->balls[i]), b = i2d_body_get_position(without->balls[i]);
            i2d_vec2 va = i2d_body_get_linear_velocity(with->balls[i]);
            i2d_vec2 vb = i2d_body_get_linear_velocity(without->balls[i]);
            if (memcmp(&a, &b, sizeof a) != 0 || memcmp(&va, &vb, sizeof va) != 0) {
                if (identical) {
                    report("step %d: ball %d at (%.9g, %.9g) v (%.9g, %.9g) with the sensor, (%.9g, %.9g) v (%.9g, "
                           "%.9g) without",
                           step, i, a.x, a.y, va.x, va.y, b.x, b.y, vb.x, vb.y);
                }
                identical = 0;
            }
        }
        /* Sensors never make contacts: the same touching pairs as without the sensor. */
        i2d_world_counters cw = i2d_world_get_counters(with->world), co = i2d_world_get_counters(without->world);
        I2D_CHECK(cw.contact_count == co.contact_count);
        i2d_contact_events ce = i2d_world_get_contact_events(with->world);
        for (int i = 0; i < ce.begin_count; ++i) {
            I2D_CHECK(!I2D_ID_EQUALS(ce.begin_events[i].shape_a, with->sensor) &&
                      !I2D_ID_EQUALS(ce.begin_events[i].shape_b, with->sensor));
        }
        for (int i = 0; i < ce.end_count; ++i) {
            I2D_CHECK(!I2D_ID_EQUALS(ce.end_events[i].shape_a, with->sensor) &&
                      !I2D_ID_EQUALS(ce.end_events[i].shape_b, with->sensor));
        }
        /* The sensor-free world has no sensor events at all. */
        i2d_sensor_events none = i2d_world_get_sensor_events(without->world);
        I2D_CHECK(none.begin_count == 0 && none.end_count == 0);

        i2d_sensor_events se = i2d_world_get_sensor_events(with->world);
        I2D_CHECK(i2d_last_status() == I2D_OK);
        for (int i = 0; i < se.begin_count; ++i) {
            const i2d_sensor_begin_event* ev = &se.begin_events[i];
            count_sensor_event(with, ev->sensor_shape, ev->visitor_shape, "begin", step, begin_count, begin_step);
        }
        for (int i = 0; i < se.end_count; ++i) {
            const i2d_sensor_end_event* ev = &se.end_events[i];
            count_sensor_event(with, ev->sensor_shape, ev->visitor_shape, "end", step, end_count, end_step);
        }
    }
    I2D_CHECK(identical);
    printf("sensor zone: enter at substep %d-%d, leave at %d-%d; ball 0 began in step %d, ended in step %d\n",
           enter_early, enter_late, leave_early, leave_late, begin_step[0], end_step[0]);
    /* Balls 0 and 2 report (contact events do not matter to sensors); ball 1 opted out. */
    for (int k = 0; k < 3; k += 2) {
        I2D_CHECK(begin_count[k] == 1 && end_count[k] == 1);
        if (!step_allowed(begin_step[k], enter_early, enter_late)) {
            report("ball %d: sensor begin in step %d, expected step %d..%d", k, begin_step[k],
                   step_of_substep_ceil(enter_early), step_of_substep_next(enter_late));
            I2D_CHECK(step_allowed(begin_step[k], enter_early, enter_late));
        }
        if (!step_allowed(end_step[k], leave_early, leave_late)) {
            report("ball %d: sensor end in step %d, expected step %d..%d", k, end_step[k],
                   step_of_substep_ceil(leave_early), step_of_substep_next(leave_late));
            I2D_CHECK(step_allowed(end_step[k], leave_early, leave_late));
        }
    }
    I2D_CHECK(begin_count[1] == 0 && end_count[1] == 0);
    /* The balls reached the ground and rest there: the scene did collide (both worlds). */
    I2D_CHECK(i2d_world_get_counters(with->world).contact_count == 3);
    I2D_CHECK_NEAR(i2d_body_get_position(with->balls[0]).y, -19.5, 0.02);
}

I2D_TEST(api_events_sensor_zone) {
    static sensor_scene with, without;
    bool built = sensor_scene_build(&with, true) && sensor_scene_build(&without, false);
    if (built) {
        run_sensor_zone(&with, &without);
    } else {
        I2D_CHECK(!"sensor_scene_build");
    }
    if (!I2D_IS_NULL(with.world)) {
        i2d_world_destroy(with.world);
    }
    if (!I2D_IS_NULL(without.world)) {
        i2d_world_destroy(without.world);
    }
}

/* Sensor events from changes between steps: a visitor created inside, teleported out
 * and back, destroyed inside; the sensor itself destroyed with a visitor inside. */
static void run_sensor_changes(i2d_world_id world) {
    i2d_shape_def sensor_def = i2d_default_shape_def();
    sensor_def.is_sensor = true;
    i2d_body_id zone_body = make_body(world, I2D_BODY_STATIC, 0.0f, 0.0f);
    i2d_shape_id zone = add_circle(zone_body, &sensor_def, 3.0f);
    I2D_REQUIRE(!I2D_IS_NULL(zone));
    I2D_REQUIRE(step_ok(world));
    i2d_sensor_events e = i2d_world_get_sensor_events(world);
    I2D_CHECK(e.begin_count == 0 && e.end_count == 0);

    /* Zero gravity: visitors stay where they are put. */
    i2d_shape_def def = i2d_default_shape_def();
    i2d_body_id a_body = make_body(world, I2D_BODY_DYNAMIC, 1.0f, 0.0f);
    i2d_shape_id a = i2d_shape_create_box(a_body, &def, 0.5f, 0.5f);
    i2d_body_id b_body = make_body(world, I2D_BODY_DYNAMIC, -1.0f, 0.0f);
    i2d_shape_id b = add_circle(b_body, &def, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(a) && !I2D_IS_NULL(b));
    I2D_REQUIRE(step_ok(world));
    e = i2d_world_get_sensor_events(world);
    I2D_CHECK(e.begin_count == 2 && e.end_count == 0);
    bool seen_a = false, seen_b = false;
    for (int i = 0; i < e.begin_count && i < 2; ++i) {
        I2D_CHECK(I2D_ID_EQUALS(e.begin_events[i].sensor_shape, zone));
        seen_a = seen_a || I2D_ID_EQUALS(e.begin_events[i].visitor_shape, a);
        seen_b = seen_b || I2D_ID_EQUALS(e.begin_events[i].visitor_shape, b);
    }
    I2D_CHECK(seen_a && seen_b);
    /* Staying inside: nothing. */
    I2D_REQUIRE(step_ok(world));
    e = i2d_world_get_sensor_events(world);
    I2D_CHECK(e.begin_count == 0 && e.end_count == 0);
    /* No contact between the box and the sensor, nor any contact at all. */
    I2D_CHECK(i2d_world_get_counters(world).contact_count == 0);
    i2d_contact_events ce = i2d_world_get_contact_events(world);
    I2D_CHECK(ce.begin_count == 0 && ce.end_count == 0);

    /* Teleported out: end; back in: begin. */
    I2D_CHECK_STATUS(i2d_body_set_transform(a_body, v2(10.0f, 0.0f), identity_rot()), I2D_OK);
    I2D_REQUIRE(step_ok(world));
    e = i2d_world_get_sensor_events(world);
    I2D_CHECK(e.begin_count == 0 && e.end_count == 1);
    if (e.end_count == 1) {
        I2D_CHECK(I2D_ID_EQUALS(e.end_events[0].sensor_shape, zone));
        I2D_CHECK(I2D_ID_EQUALS(e.end_events[0].visitor_shape, a));
    }
    I2D_CHECK_STATUS(i2d_body_set_transform(a_body, v2(0.0f, 1.0f), identity_rot()), I2D_OK);
    I2D_REQUIRE(step_ok(world));
    e = i2d_world_get_sensor_events(world);
    I2D_CHECK(e.begin_count == 1 && e.end_count == 0);
    if (e.begin_count == 1) {
        I2D_CHECK(I2D_ID_EQUALS(e.begin_events[0].visitor_shape, a));
    }

    /* The visitor destroyed inside: end with a stale id. */
    I2D_CHECK_STATUS(i2d_shape_destroy(a), I2D_OK);
    I2D_REQUIRE(step_ok(world));
    e = i2d_world_get_sensor_events(world);
    I2D_CHECK(e.begin_count == 0 && e.end_count == 1);
    if (e.end_count == 1) {
        I2D_CHECK(I2D_ID_EQUALS(e.end_events[0].sensor_shape, zone));
        I2D_CHECK(I2D_ID_EQUALS(e.end_events[0].visitor_shape, a));
        I2D_CHECK(!i2d_shape_is_valid(e.end_events[0].visitor_shape));
    }

    /* The sensor destroyed with b inside: end with the sensor's stale id. */
    I2D_CHECK_STATUS(i2d_body_destroy(zone_body), I2D_OK);
    I2D_REQUIRE(step_ok(world));
    e = i2d_world_get_sensor_events(world);
    I2D_CHECK(e.begin_count == 0 && e.end_count == 1);
    if (e.end_count == 1) {
        I2D_CHECK(I2D_ID_EQUALS(e.end_events[0].sensor_shape, zone));
        I2D_CHECK(I2D_ID_EQUALS(e.end_events[0].visitor_shape, b));
    }
    I2D_REQUIRE(step_ok(world));
    e = i2d_world_get_sensor_events(world);
    I2D_CHECK(e.begin_count == 0 && e.end_count == 0);
}

I2D_TEST(api_events_sensor_changes) { run_in_world(0.0f, run_sensor_changes); }

/* A dynamic body whose only shape is a sensor falls through the ground as if it were
 * not there: bit for bit the trajectory of the same world without the ground. */
static void run_sensor_body_falls(i2d_world_id with_ground, i2d_world_id without_ground) {
    i2d_world_id worlds[2] = {with_ground, without_ground};
    i2d_body_id bodies[2];
    for (int w = 0; w < 2; ++w) {
        bodies[w] = make_body(worlds[w], I2D_BODY_DYNAMIC, 0.0f, 2.0f);
        i2d_shape_def def = i2d_default_shape_def();
        def.is_sensor = true;
        I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_box(bodies[w], &def, 0.5f, 0.5f)));
    }
    i2d_shape_def def = i2d_default_shape_def();
    I2D_REQUIRE(!I2D_IS_NULL(make_ground(with_ground, &def)));
    int identical = 1;
    for (int step = 0; step < 90; ++step) {
        I2D_REQUIRE(step_ok(with_ground) && step_ok(without_ground));
        i2d_vec2 a = i2d_body_get_position(bodies[0]), b = i2d_body_get_position(bodies[1]);
        identical = identical && memcmp(&a, &b, sizeof a) == 0;
        I2D_CHECK(i2d_world_get_counters(with_ground).contact_count == 0);
        i2d_contact_events ce = i2d_world_get_contact_events(with_ground);
        I2D_CHECK(ce.begin_count == 0 && ce.end_count == 0);
    }
    I2D_CHECK(identical);
    /* 1.5 s of free fall: well below the ground's top. */
    I2D_CHECK(i2d_body_get_position(bodies[0]).y < -5.0f);
}

I2D_TEST(api_events_sensor_never_pushes) {
    i2d_world_id a = make_world(-10.0f);
    i2d_world_id b = make_world(-10.0f);
    if (!I2D_IS_NULL(a) && !I2D_IS_NULL(b)) {
        run_sensor_body_falls(a, b);
    } else {
        I2D_CHECK(!"worlds");
    }
    i2d_world_destroy(a);
    i2d_world_destroy(b);
}

/* ---- Body move events ------------------------------------------------------------ */

enum { MOVE_BODIES = 9 };

static int k_tags[MOVE_BODIES];

static void run_body_moves(i2d_world_id world) {
    i2d_shape_def def = i2d_default_shape_def();
    i2d_body_id bodies[MOVE_BODIES];
    i2d_body_def bd = i2d_default_body_def();
    /* 0: static ground; 1: static without shapes, teleported between steps. */
    bd.position = v2(0.0f, -1.0f);
    bd.user_data = &k_tags[0];
    bodies[0] = i2d_body_create(world, &bd);
    i2d_shape_create_box(bodies[0], &def, 10.0f, 1.0f);
    bd.position = v2(20.0f, 0.0f);
    bd.user_data = &k_tags[1];
    bodies[1] = i2d_body_create(world, &bd);
    /* 2: kinematic moving; 3: kinematic at rest. */
    bd.type = I2D_BODY_KINEMATIC;
    bd.position = v2(-5.0f, 5.0f);
    bd.linear_velocity = v2(1.0f, 0.5f);
    bd.user_data = &k_tags[2];
    bodies[2] = i2d_body_create(world, &bd);
    i2d_shape_create_box(bodies[2], &def, 0.5f, 0.5f);
    bd.position = v2(5.0f, 5.0f);
    bd.linear_velocity = v2(0.0f, 0.0f);
    bd.user_data = &k_tags[3];
    bodies[3] = i2d_body_create(world, &bd);
    i2d_shape_create_box(bodies[3], &def, 0.5f, 0.5f);
    /* 4: a falling ball; 5: a falling body without shapes; 6: a floating body (no
     * gravity, no velocity); 7: a ball resting on the ground; 8: a static sensor. */
    bd.type = I2D_BODY_DYNAMIC;
    bd.position = v2(0.0f, 8.0f);
    bd.user_data = &k_tags[4];
    bodies[4] = i2d_body_create(world, &bd);
    add_circle(bodies[4], &def, 0.5f);
    bd.position = v2(-8.0f, 8.0f);
    bd.user_data = &k_tags[5];
    bodies[5] = i2d_body_create(world, &bd);
    bd.position = v2(8.0f, 8.0f);
    bd.gravity_scale = 0.0f;
    bd.user_data = &k_tags[6];
    bodies[6] = i2d_body_create(world, &bd);
    add_circle(bodies[6], &def, 0.5f);
    bd.gravity_scale = 1.0f;
    bd.position = v2(3.0f, 0.5f);
    bd.user_data = NULL;
    bodies[7] = i2d_body_create(world, &bd);
    add_circle(bodies[7], &def, 0.5f);
    bd = i2d_default_body_def();
    bd.position = v2(0.0f, 3.0f);
    bodies[8] = i2d_body_create(world, &bd);
    i2d_shape_def sensor_def = i2d_default_shape_def();
    sensor_def.is_sensor = true;
    i2d_shape_create_box(bodies[8], &sensor_def, 2.0f, 2.0f);
    for (int i = 0; i < MOVE_BODIES; ++i) {
        I2D_REQUIRE(!I2D_IS_NULL(bodies[i]));
    }

    /* Nothing before the first step. */
    i2d_body_events e = i2d_world_get_body_events(world);
    I2D_CHECK(i2d_last_status() == I2D_OK);
    I2D_CHECK(e.move_count == 0);

    g_reports_left = 20;
    int reported[MOVE_BODIES] = {0};
    static int k_new_tag;
    for (int step = 0; step < 60; ++step) {
        if (step == 20) {
            /* New user data is what the next events carry; a static teleport is no move. */
            I2D_CHECK_STATUS(i2d_body_set_user_data(bodies[4], &k_new_tag), I2D_OK);
            I2D_CHECK_STATUS(i2d_body_set_transform(bodies[1], v2(25.0f, 1.0f), identity_rot()), I2D_OK);
        }
        i2d_transform before[MOVE_BODIES];
        for (int i = 0; i < MOVE_BODIES; ++i) {
            before[i] = i2d_body_get_transform(bodies[i]);
        }
        I2D_REQUIRE(step_ok(world));
        e = i2d_world_get_body_events(world);
        I2D_CHECK(i2d_last_status() == I2D_OK);
        I2D_REQUIRE(e.move_count >= 0 && e.move_count <= MOVE_BODIES);
        bool in_events[MOVE_BODIES] = {false};
        for (int k = 0; k < e.move_count; ++k) {
            const i2d_body_move_event* ev = &e.move_events[k];
            int which = -1;
            for (int i = 0; i < MOVE_BODIES; ++i) {
                which = I2D_ID_EQUALS(ev->body, bodies[i]) ? i : which;
            }
            if (which < 0) {
                report("step %d: move event for an unknown body 0x%llx", step, (unsigned long long)ev->body.bits);
                I2D_CHECK(which >= 0);
                continue;
            }
            if (in_events[which]) {
                report("step %d: body %d reported twice", step, which);
                I2D_CHECK(!in_events[which]);
            }
            in_events[which] = true;
            ++reported[which];
            if (i2d_body_get_type(bodies[which]) == I2D_BODY_STATIC) {
                report("step %d: static body %d reported", step, which);
                I2D_CHECK(i2d_body_get_type(bodies[which]) != I2D_BODY_STATIC);
            }
            i2d_transform xf = i2d_body_get_transform(bodies[which]);
            if (xf.p.x != ev->transform.p.x || xf.p.y != ev->transform.p.y || xf.q.c != ev->transform.q.c ||
                xf.q.s != ev->transform.q.s) {
                report("step %d: body %d event transform (%.9g, %.9g; %g, %g), body (%.9g, %.9g; %g, %g)", step, which,
                       ev->transform.p.x, ev->transform.p.y, ev->transform.q.c, ev->transform.q.s, xf.p.x, xf.p.y,
                       xf.q.c, xf.q.s);
                I2D_CHECK(!"move event transform");
            }
            I2D_CHECK(ev->user_data == i2d_body_get_user_data(bodies[which]));
            /* fell_asleep is set exactly for the bodies the step put to sleep. */
            I2D_CHECK(ev->fell_asleep == !i2d_body_is_awake(bodies[which]));
        }
        /* Finite input never needs the non-finite quarantine. */
        I2D_CHECK(e.quarantine_count == 0 && e.quarantine_events == NULL);
        for (int i = 0; i < MOVE_BODIES; ++i) {
            I2D_CHECK(!i2d_body_is_quarantined(bodies[i]) && i2d_last_status() == I2D_OK);
        }
        /* Every body whose transform changed in the step is there. */
        for (int i = 0; i < MOVE_BODIES; ++i) {
            i2d_transform xf = i2d_body_get_transform(bodies[i]);
            bool moved = xf.p.x != before[i].p.x || xf.p.y != before[i].p.y;
            if (moved && !in_events[i]) {
                report("step %d: body %d moved from (%.9g, %.9g) to (%.9g, %.9g) but has no move event", step, i,
                       before[i].p.x, before[i].p.y, xf.p.x, xf.p.y);
                I2D_CHECK(!"moved body reported");
            }
        }
    }
    /* The moving ones were there every step. */
    I2D_CHECK(reported[2] == 60 && reported[4] == 60 && reported[5] == 60);
    I2D_CHECK(reported[0] == 0 && reported[1] == 0 && reported[8] == 0);
    /* The kinematic body moved by its velocity: 1 s at (1, 0.5). */
    i2d_vec2 p = i2d_body_get_position(bodies[2]);
    I2D_CHECK_NEAR(p.x, -4.0, 1e-4);
    I2D_CHECK_NEAR(p.y, 5.5, 1e-4);

    /* A destroyed body is not reported in the next step. */
    I2D_CHECK_STATUS(i2d_body_destroy(bodies[4]), I2D_OK);
    I2D_REQUIRE(step_ok(world));
    e = i2d_world_get_body_events(world);
    for (int k = 0; k < e.move_count; ++k) {
        I2D_CHECK(!I2D_ID_EQUALS(e.move_events[k].body, bodies[4]));
        I2D_CHECK(i2d_body_is_valid(e.move_events[k].body));
    }
    I2D_CHECK(e.move_count >= 2); /* bodies 2 and 5 still move */
}

I2D_TEST(api_events_body_moves) { run_in_world(-10.0f, run_body_moves); }

/* ---- Bad world ids ------------------------------------------------------------------ */

static void check_no_events(i2d_world_id world, const char* what) {
    int before = i2d_check_failures;
    i2d_contact_events ce = i2d_world_get_contact_events(world);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(ce.begin_count == 0 && ce.end_count == 0);
    i2d_sensor_events se = i2d_world_get_sensor_events(world);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(se.begin_count == 0 && se.end_count == 0);
    i2d_body_events be = i2d_world_get_body_events(world);
    I2D_CHECK(i2d_last_status() == I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(be.move_count == 0 && be.quarantine_count == 0);
    I2D_CHECK(i2d_world_rebuild_static_tree(world) == I2D_ERR_INVALID_HANDLE);
    if (i2d_check_failures != before) {
        fprintf(stderr, "  (with %s)\n", what);
    }
}

I2D_TEST(api_events_bad_world) {
    check_no_events(I2D_NULL_WORLD_ID, "the null world id");

    /* A world that had events, then was destroyed. */
    i2d_world_id world = make_world(-10.0f);
    I2D_REQUIRE(!I2D_IS_NULL(world));
    i2d_shape_def def = i2d_default_shape_def();
    make_ground(world, &def);
    i2d_body_id ball = make_body(world, I2D_BODY_DYNAMIC, 0.0f, 0.49f);
    add_circle(ball, &def, 0.5f);
    I2D_CHECK(step_ok(world));
    I2D_CHECK(i2d_world_get_contact_events(world).begin_count == 1);
    I2D_CHECK(i2d_world_get_body_events(world).move_count == 1);
    i2d_world_id body_as_world;
    body_as_world.bits = ball.bits;
    check_no_events(body_as_world, "a body id passed as a world id");
    I2D_CHECK_STATUS(i2d_world_destroy(world), I2D_OK);
    check_no_events(world, "a destroyed world's id");

    /* A new world, perhaps in the same slot: the old id still finds nothing. */
    i2d_world_id fresh = make_world(-10.0f);
    I2D_REQUIRE(!I2D_IS_NULL(fresh));
    check_no_events(world, "a destroyed world's id after a new world was created");
    i2d_contact_events ce = i2d_world_get_contact_events(fresh);
    I2D_CHECK(i2d_last_status() == I2D_OK);
    I2D_CHECK(ce.begin_count == 0 && ce.end_count == 0);
    i2d_world_destroy(fresh);
}
