/* SPDX-License-Identifier: MIT */
/* C API collision filtering: the category/mask/group truth table with real collisions, body-type rules, filter changes. */
#include <impulse2d/impulse2d.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "api_test_support.h"
#include "check.h"

/* ---- Small helpers ---------------------------------------------------------------- */

static i2d_filter filter(uint64_t category_bits, uint64_t mask_bits, int32_t group_index) {
    i2d_filter f;
    f.category_bits = category_bits;
    f.mask_bits = mask_bits;
    f.group_index = group_index;
    return f;
}

static i2d_shape_id add_box(i2d_body_id body, i2d_filter f, float hw, float hh) {
    i2d_shape_def def = i2d_default_shape_def();
    def.filter = f;
    return i2d_shape_create_box(body, &def, hw, hh);
}

static bool same_vec(i2d_vec2 a, i2d_vec2 b) { return a.x == b.x && a.y == b.y; }

/* The rule as types.h states it: each side's category meets the other's mask, unless
 * both share a group: a shared positive group always collides, a shared negative
 * group never does. Group 0 is no group. */
static bool rule(i2d_filter a, i2d_filter b) {
    if (a.group_index == b.group_index && a.group_index != 0) {
        return a.group_index > 0;
    }
    return (a.category_bits & b.mask_bits) != 0 && (b.category_bits & a.mask_bits) != 0;
}

/* ---- The truth table with two real boxes ------------------------------------------- */

/* What one step of two overlapping boxes shows. */
typedef struct pair_outcome {
    bool ok;          /* the scene was built and stepped */
    int contacts;     /* counters.contact_count */
    int begins;       /* begin events naming the pair */
    int other_events; /* any other contact event */
    bool b_moved;     /* the dynamic box was pushed */
} pair_outcome;

/* Box A (half 1 x 1) at the origin, static or dynamic; dynamic box B (half 1 x 1) at
 * (1.5, 0): they overlap by 0.5 m on x. No gravity, so B moves only if the pair collides. */
static pair_outcome two_boxes(i2d_filter fa, i2d_filter fb, bool a_dynamic) {
    pair_outcome out;
    memset(&out, 0, sizeof out);
    i2d_world_id world = make_world(0.0f);
    if (I2D_IS_NULL(world)) {
        return out;
    }
    i2d_body_id a_body = make_body(world, a_dynamic ? I2D_BODY_DYNAMIC : I2D_BODY_STATIC, 0.0f, 0.0f);
    i2d_body_id b_body = make_body(world, I2D_BODY_DYNAMIC, 1.5f, 0.0f);
    i2d_shape_id a = add_box(a_body, fa, 1.0f, 1.0f);
    i2d_shape_id b = add_box(b_body, fb, 1.0f, 1.0f);
    if (!I2D_IS_NULL(a) && !I2D_IS_NULL(b) && step_ok(world)) {
        out.ok = true;
        out.contacts = i2d_world_get_counters(world).contact_count;
        i2d_contact_events e = i2d_world_get_contact_events(world);
        for (int i = 0; i < e.begin_count; ++i) {
            if (same_pair(e.begin_events[i].shape_a, e.begin_events[i].shape_b, a, b)) {
                ++out.begins;
            } else {
                ++out.other_events;
            }
        }
        out.other_events += e.end_count;
        i2d_vec2 p = i2d_body_get_position(b_body);
        out.b_moved = !(p.x == 1.5f && p.y == 0.0f);
    }
    i2d_world_destroy(world);
    return out;
}

static int g_reports_left;

/* Checks both orders (A, B) and (B, A) of one filter pair against the rule. */
static int check_filter_pair(i2d_filter fa, i2d_filter fb, bool a_dynamic) {
    const bool expected = rule(fa, fb);
    int bad = 0;
    for (int order = 0; order < 2; ++order) {
        i2d_filter first = order == 0 ? fa : fb, second = order == 0 ? fb : fa;
        pair_outcome o = two_boxes(first, second, a_dynamic);
        bool good = o.ok && o.other_events == 0 && o.contacts == (expected ? 1 : 0) &&
                    o.begins == (expected ? 1 : 0) && o.b_moved == expected;
        if (!good) {
            ++bad;
            if (g_reports_left-- > 0) {
                fprintf(stderr,
                        "%s: A {cat 0x%llx, mask 0x%llx, group %d} (%s) vs B {cat 0x%llx, mask 0x%llx, group %d}: "
                        "expected %s; got contact_count %d, %d begin events, %d other events, B %s\n",
                        __FILE__, (unsigned long long)first.category_bits, (unsigned long long)first.mask_bits,
                        (int)first.group_index, a_dynamic ? "dynamic" : "static",
                        (unsigned long long)second.category_bits, (unsigned long long)second.mask_bits,
                        (int)second.group_index, expected ? "a collision" : "no collision", o.contacts, o.begins,
                        o.other_events, o.b_moved ? "pushed" : "untouched");
            }
        }
    }
    return bad;
}

/* Hand-written rows, each a rule of the contract. */
I2D_TEST(api_filter_named_cases) {
    typedef struct named_case {
        const char* what;
        i2d_filter a, b;
        bool collide;
    } named_case;
    const uint64_t all = UINT64_MAX;
    const named_case cases[] = {
        {"defaults", {1, all, 0}, {1, all, 0}, true},
        {"each category meets the other's mask", {2, 1, 0}, {1, 2, 0}, true},
        {"A's category misses B's mask", {2, all, 0}, {1, 1, 0}, false},
        {"B's category misses A's mask", {1, 1, 0}, {2, all, 0}, false},
        {"both masks empty", {1, 0, 0}, {1, 0, 0}, false},
        {"one shared bit is enough", {6, 4, 0}, {12, 2, 0}, true},
        {"no category bits", {0, all, 0}, {1, all, 0}, false},
        {"same positive group, bits say no", {1, 0, 3}, {2, 0, 3}, true},
        {"same positive group, bits say yes", {1, all, 3}, {1, all, 3}, true},
        {"same negative group, bits say yes", {1, all, -3}, {1, all, -3}, false},
        {"same negative group, bits say no", {1, 0, -3}, {1, 0, -3}, false},
        {"different positive groups fall back to bits (no)", {1, 0, 3}, {1, 0, 4}, false},
        {"different positive groups fall back to bits (yes)", {1, all, 3}, {1, all, 4}, true},
        {"opposite groups fall back to bits (yes)", {1, all, 3}, {1, all, -3}, true},
        {"opposite groups fall back to bits (no)", {1, 2, 3}, {1, 2, -3}, false},
        {"different negative groups fall back to bits (yes)", {1, all, -3}, {1, all, -4}, true},
        {"group and no group fall back to bits (yes)", {1, all, -3}, {1, all, 0}, true},
        {"group and no group fall back to bits (no)", {1, 0, 3}, {1, all, 0}, false},
        {"high bits", {UINT64_C(1) << 63, UINT64_C(1) << 40, 0}, {UINT64_C(1) << 40, UINT64_C(1) << 63, 0}, true},
    };
    g_reports_left = 20;
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        /* The table above must agree with the rule as written (a typo guard). */
        I2D_CHECK(rule(cases[c].a, cases[c].b) == cases[c].collide);
        int bad = check_filter_pair(cases[c].a, cases[c].b, c % 2 == 1);
        if (bad != 0) {
            fprintf(stderr, "  (case \"%s\")\n", cases[c].what);
            I2D_CHECK(bad == 0);
        }
    }
}

/* Every combination of a few categories and masks, group 0. */
I2D_TEST(api_filter_bits_table) {
    static const uint64_t categories[] = {1, 2, 6};
    static const uint64_t masks[] = {0, 1, 2, 4, UINT64_MAX};
    enum { NC = sizeof categories / sizeof categories[0], NM = sizeof masks / sizeof masks[0] };
    g_reports_left = 20;
    int bad = 0, collide = 0, cases = 0;
    for (int ca = 0; ca < NC; ++ca) {
        for (int ma = 0; ma < NM; ++ma) {
            for (int cb = 0; cb < NC; ++cb) {
                for (int mb = 0; mb < NM; ++mb) {
                    i2d_filter fa = filter(categories[ca], masks[ma], 0);
                    i2d_filter fb = filter(categories[cb], masks[mb], 0);
                    bad += check_filter_pair(fa, fb, (ca + mb) % 2 == 1);
                    collide += rule(fa, fb) ? 1 : 0;
                    ++cases;
                }
            }
        }
    }
    printf("filter bits: %d combinations, %d collide by the rule\n", cases, collide);
    I2D_CHECK(bad == 0);
    I2D_CHECK(collide > cases / 5 && collide < cases * 4 / 5);
}

/* Every pair of groups in {-2, -1, 0, 1, 2} with bits that say yes, no on one side, no
 * on both sides. */
I2D_TEST(api_filter_groups_table) {
    static const int32_t groups[] = {-2, -1, 0, 1, 2};
    typedef struct bits {
        uint64_t ca, ma, cb, mb;
    } bits;
    static const bits bit_cases[] = {
        {1, UINT64_MAX, 1, UINT64_MAX}, /* yes */
        {1, UINT64_MAX, 2, 2},          /* B's mask misses A's category */
        {1, 0, 2, 0},                   /* no on both sides */
    };
    g_reports_left = 20;
    int bad = 0;
    for (int ga = 0; ga < 5; ++ga) {
        for (int gb = 0; gb < 5; ++gb) {
            for (int k = 0; k < 3; ++k) {
                i2d_filter fa = filter(bit_cases[k].ca, bit_cases[k].ma, groups[ga]);
                i2d_filter fb = filter(bit_cases[k].cb, bit_cases[k].mb, groups[gb]);
                bad += check_filter_pair(fa, fb, (ga + gb + k) % 2 == 0);
            }
        }
    }
    I2D_CHECK(bad == 0);
}

/* ---- Body rules ------------------------------------------------------------------------ */

/* Overlapping shapes on one body never collide, even in a shared positive group. */
static void run_same_body(i2d_world_id world) {
    i2d_body_id body = make_body(world, I2D_BODY_DYNAMIC, 2.0f, 3.0f);
    i2d_shape_def def = i2d_default_shape_def();
    def.filter = filter(1, UINT64_MAX, 5);
    i2d_shape_id box = i2d_shape_create_box(body, &def, 1.0f, 1.0f);
    i2d_circle circle = {{0.5f, 0.0f}, 1.0f};
    i2d_shape_id disc = i2d_shape_create_circle(body, &def, &circle);
    def.filter = i2d_default_filter();
    i2d_shape_id plain = i2d_shape_create_box(body, &def, 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(box) && !I2D_IS_NULL(disc) && !I2D_IS_NULL(plain));
    for (int step = 0; step < 20; ++step) {
        I2D_REQUIRE(step_ok(world));
        I2D_CHECK(i2d_world_get_counters(world).contact_count == 0);
        i2d_contact_events e = i2d_world_get_contact_events(world);
        I2D_CHECK(e.begin_count == 0 && e.end_count == 0);
    }
    I2D_CHECK(same_vec(i2d_body_get_position(body), v2(2.0f, 3.0f)));
    I2D_CHECK(same_vec(i2d_body_get_linear_velocity(body), v2(0.0f, 0.0f)));
}

I2D_TEST(api_filter_same_body_never_collides) { run_in_world(0.0f, run_same_body); }

/* A kinematic box sweeps through a static box, and two static boxes overlap: no
 * contacts, no events, and the kinematic body keeps its velocity. */
static void run_static_kinematic(i2d_world_id world) {
    i2d_body_id wall = make_body(world, I2D_BODY_STATIC, 0.0f, 0.0f);
    i2d_body_id wall2 = make_body(world, I2D_BODY_STATIC, 0.5f, 0.5f);
    i2d_body_def def = i2d_default_body_def();
    def.type = I2D_BODY_KINEMATIC;
    def.position = v2(-5.0f, 0.25f);
    def.linear_velocity = v2(5.0f, 0.0f);
    i2d_body_id mover = i2d_body_create(world, &def);
    /* A positive shared group would force a collision between any two shapes that may
     * collide at all: it must not make static and kinematic bodies collide. */
    I2D_REQUIRE(!I2D_IS_NULL(add_box(wall, filter(1, UINT64_MAX, 7), 1.0f, 1.0f)));
    I2D_REQUIRE(!I2D_IS_NULL(add_box(wall2, filter(1, UINT64_MAX, 7), 1.0f, 1.0f)));
    I2D_REQUIRE(!I2D_IS_NULL(add_box(mover, filter(1, UINT64_MAX, 7), 0.5f, 0.5f)));
    int contacts = 0, events = 0;
    for (int step = 1; step <= 120; ++step) {
        I2D_REQUIRE(step_ok(world));
        contacts += i2d_world_get_counters(world).contact_count;
        i2d_contact_events e = i2d_world_get_contact_events(world);
        events += e.begin_count + e.end_count;
    }
    I2D_CHECK(contacts == 0);
    I2D_CHECK(events == 0);
    /* 2 s at 5 m/s: from x = -5 through the walls to x = 5, unhindered. */
    i2d_vec2 p = i2d_body_get_position(mover);
    I2D_CHECK_NEAR(p.x, 5.0, 1e-3);
    I2D_CHECK(p.y == 0.25f);
    I2D_CHECK(same_vec(i2d_body_get_linear_velocity(mover), v2(5.0f, 0.0f)));
}

I2D_TEST(api_filter_static_kinematic_never_collide) { run_in_world(-10.0f, run_static_kinematic); }

/* The control for the test above: the same kinematic sweep does push a dynamic ball
 * (so "no contacts" above is not just a sweep that misses). */
static void run_kinematic_pushes(i2d_world_id world) {
    i2d_body_def def = i2d_default_body_def();
    def.type = I2D_BODY_KINEMATIC;
    def.position = v2(-5.0f, 0.25f);
    def.linear_velocity = v2(5.0f, 0.0f);
    i2d_body_id mover = i2d_body_create(world, &def);
    I2D_REQUIRE(!I2D_IS_NULL(add_box(mover, i2d_default_filter(), 0.5f, 0.5f)));
    i2d_body_id ball = make_body(world, I2D_BODY_DYNAMIC, 0.0f, 0.25f);
    i2d_shape_def shape_def = i2d_default_shape_def();
    i2d_circle circle = {{0.0f, 0.0f}, 0.5f};
    I2D_REQUIRE(!I2D_IS_NULL(i2d_shape_create_circle(ball, &shape_def, &circle)));
    int begins = 0;
    for (int step = 1; step <= 120; ++step) {
        I2D_REQUIRE(step_ok(world));
        begins += i2d_world_get_contact_events(world).begin_count;
    }
    I2D_CHECK(begins >= 1);
    I2D_CHECK(i2d_body_get_position(ball).x > 5.0f); /* pushed ahead of the mover */
}

I2D_TEST(api_filter_kinematic_pushes_dynamic) { run_in_world(0.0f, run_kinematic_pushes); }

/* ---- Changing filters of pairs that already overlap ----------------------------------- */

/* Steps once and returns the contact events naming {a, b}: +1 per begin, and the end
 * count in *ends; *others counts events for any other pair. */
static int step_and_count(i2d_world_id world, i2d_shape_id a, i2d_shape_id b, int* ends, int* others) {
    *ends = 0;
    *others = 0;
    if (!step_ok(world)) {
        return -1;
    }
    i2d_contact_events e = i2d_world_get_contact_events(world);
    int begins = 0;
    for (int i = 0; i < e.begin_count; ++i) {
        if (same_pair(e.begin_events[i].shape_a, e.begin_events[i].shape_b, a, b)) {
            ++begins;
        } else {
            ++*others;
        }
    }
    for (int i = 0; i < e.end_count; ++i) {
        if (same_pair(e.end_events[i].shape_a, e.end_events[i].shape_b, a, b)) {
            ++*ends;
        } else {
            ++*others;
        }
    }
    return begins;
}

/* Zero gravity. A pair that touches, whose bodies stay where they are (so the
 * broadphase sees no move): each filter change takes effect at the next step. */
static void run_set_filter_toggles(i2d_world_id world, bool change_static_side) {
    i2d_body_id a_body = make_body(world, I2D_BODY_STATIC, 0.0f, 0.0f);
    i2d_body_id b_body = make_body(world, I2D_BODY_DYNAMIC, 1.5f, 0.0f);
    i2d_shape_id a = add_box(a_body, i2d_default_filter(), 1.0f, 1.0f);
    i2d_shape_id b = add_box(b_body, i2d_default_filter(), 1.0f, 1.0f);
    I2D_REQUIRE(!I2D_IS_NULL(a) && !I2D_IS_NULL(b));
    i2d_shape_id changed = change_static_side ? a : b;
    int ends, others;
    I2D_CHECK(step_and_count(world, a, b, &ends, &others) == 1);
    /* Pushed out to rest within the slop: still touching, no longer moving. */
    for (int i = 0; i < 60; ++i) {
        I2D_REQUIRE(step_ok(world));
    }
    I2D_REQUIRE(i2d_world_get_counters(world).contact_count == 1);
    i2d_vec2 rest = i2d_body_get_position(b_body);
    I2D_CHECK(rest.x > 1.5f && rest.x < 2.0f);

    /* A filter change is checked and stored at once. */
    const i2d_filter no_bits = filter(1, 0, 0);
    I2D_CHECK_STATUS(i2d_shape_set_filter(changed, no_bits), I2D_OK);
    i2d_filter got = i2d_shape_get_filter(changed);
    I2D_CHECK(got.category_bits == 1 && got.mask_bits == 0 && got.group_index == 0);

    /* Allowed -> filtered: the contact ends at the next step. */
    I2D_CHECK(step_and_count(world, a, b, &ends, &others) == 0);
    I2D_CHECK(ends == 1 && others == 0);
    I2D_CHECK(i2d_world_get_counters(world).contact_count == 0);
    /* Nothing acts on B any more: held still, it stays where it is, overlapping A. */
    I2D_CHECK_STATUS(i2d_body_set_linear_velocity(b_body, v2(0.0f, 0.0f)), I2D_OK);
    i2d_vec2 held = i2d_body_get_position(b_body);
    for (int i = 0; i < 5; ++i) {
        I2D_CHECK(step_and_count(world, a, b, &ends, &others) == 0 && ends == 0);
    }
    I2D_CHECK(same_vec(i2d_body_get_position(b_body), held));
    /* The rest of the test needs the boxes still overlapping (they rest within the slop). */
    I2D_REQUIRE(i2d_shape_get_aabb(a).max.x > i2d_shape_get_aabb(b).min.x);

    /* Filtered -> allowed through a shared positive group: begins at the next step. */
    I2D_CHECK_STATUS(i2d_shape_set_filter(a, filter(1, 0, 4)), I2D_OK);
    I2D_CHECK_STATUS(i2d_shape_set_filter(b, filter(1, 0, 4)), I2D_OK);
    I2D_CHECK(step_and_count(world, a, b, &ends, &others) == 1);
    I2D_CHECK(ends == 0 && others == 0);
    I2D_CHECK(i2d_world_get_counters(world).contact_count == 1);

    /* Allowed -> filtered through a shared negative group though the bits say yes. */
    I2D_CHECK_STATUS(i2d_shape_set_filter(a, filter(1, UINT64_MAX, -4)), I2D_OK);
    I2D_CHECK_STATUS(i2d_shape_set_filter(b, filter(1, UINT64_MAX, -4)), I2D_OK);
    I2D_CHECK(step_and_count(world, a, b, &ends, &others) == 0);
    I2D_CHECK(ends == 1 && others == 0);
    I2D_CHECK(i2d_world_get_counters(world).contact_count == 0);
    I2D_CHECK_STATUS(i2d_body_set_linear_velocity(b_body, v2(0.0f, 0.0f)), I2D_OK);

    /* Filtered -> allowed: the changed side leaves the group (different groups: bits). */
    I2D_CHECK_STATUS(i2d_shape_set_filter(changed, filter(1, UINT64_MAX, 0)), I2D_OK);
    I2D_CHECK(step_and_count(world, a, b, &ends, &others) == 1);
    I2D_CHECK(ends == 0 && others == 0);
    I2D_CHECK(i2d_world_get_counters(world).contact_count == 1);

    /* Setting the same filter again changes nothing: the pair never stopped touching,
     * so there is neither an end nor a begin. */
    I2D_CHECK_STATUS(i2d_shape_set_filter(changed, filter(1, UINT64_MAX, 0)), I2D_OK);
    I2D_CHECK(step_and_count(world, a, b, &ends, &others) == 0);
    I2D_CHECK(ends == 0 && others == 0);
    I2D_CHECK(i2d_world_get_counters(world).contact_count == 1);

    /* A new filter under which the pair still collides: still touching, no events. */
    I2D_CHECK_STATUS(i2d_shape_set_filter(changed, filter(3, UINT64_MAX, 2)), I2D_OK);
    I2D_CHECK(step_and_count(world, a, b, &ends, &others) == 0);
    I2D_CHECK(ends == 0 && others == 0);
    I2D_CHECK(i2d_world_get_counters(world).contact_count == 1);
}

I2D_TEST(api_filter_set_filter_on_touching_pair) {
    for (int side = 0; side < 2; ++side) {
        i2d_world_id world = make_world(0.0f);
        I2D_REQUIRE(!I2D_IS_NULL(world));
        int before = i2d_check_failures;
        run_set_filter_toggles(world, side == 0);
        if (i2d_check_failures != before) {
            fprintf(stderr, "  (changing the %s shape's filter)\n", side == 0 ? "static" : "dynamic");
        }
        i2d_world_destroy(world);
    }
}

/* A pair created filtered, overlapping, never moving; allowed later: it starts to collide. */
static void run_filtered_then_allowed(i2d_world_id world) {
    i2d_body_id a_body = make_body(world, I2D_BODY_DYNAMIC, 0.0f, 0.0f);
    i2d_body_id b_body = make_body(world, I2D_BODY_DYNAMIC, 1.5f, 0.0f);
    i2d_shape_id a = add_box(a_body, filter(2, UINT64_MAX, 0), 1.0f, 1.0f);
    i2d_shape_id b = add_box(b_body, filter(1, 1, 0), 1.0f, 1.0f); /* misses A's category 2 */
    I2D_REQUIRE(!I2D_IS_NULL(a) && !I2D_IS_NULL(b));
    int ends, others;
    for (int i = 0; i < 10; ++i) {
        I2D_CHECK(step_and_count(world, a, b, &ends, &others) == 0);
        I2D_CHECK(ends == 0 && others == 0);
    }
    I2D_CHECK(i2d_world_get_counters(world).contact_count == 0);
    I2D_CHECK(same_vec(i2d_body_get_position(a_body), v2(0.0f, 0.0f)));
    I2D_CHECK(same_vec(i2d_body_get_position(b_body), v2(1.5f, 0.0f)));

    I2D_CHECK_STATUS(i2d_shape_set_filter(b, filter(1, 3, 0)), I2D_OK);
    I2D_CHECK(step_and_count(world, a, b, &ends, &others) == 1);
    I2D_CHECK(ends == 0 && others == 0);
    I2D_CHECK(i2d_world_get_counters(world).contact_count == 1);
    /* Pushed apart symmetrically (equal masses). */
    I2D_CHECK(i2d_body_get_position(a_body).x < 0.0f);
    I2D_CHECK(i2d_body_get_position(b_body).x > 1.5f);
}

I2D_TEST(api_filter_filtered_pair_becomes_allowed) { run_in_world(0.0f, run_filtered_then_allowed); }

/* With gravity: a box resting on the ground falls through it once filtered out. */
static void run_fall_through(i2d_world_id world) {
    i2d_body_id ground_body = make_body(world, I2D_BODY_STATIC, 0.0f, -1.0f);
    i2d_shape_id ground = add_box(ground_body, i2d_default_filter(), 10.0f, 1.0f);
    i2d_body_id crate_body = make_body(world, I2D_BODY_DYNAMIC, 0.0f, 0.6f);
    i2d_shape_id crate = add_box(crate_body, i2d_default_filter(), 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(ground) && !I2D_IS_NULL(crate));
    for (int i = 0; i < 60; ++i) {
        I2D_REQUIRE(step_ok(world));
    }
    I2D_CHECK_NEAR(i2d_body_get_position(crate_body).y, 0.5, 0.02);
    I2D_REQUIRE(i2d_world_get_counters(world).contact_count == 1);

    I2D_CHECK_STATUS(i2d_shape_set_filter(crate, filter(8, 8, 0)), I2D_OK); /* ground: category 1 */
    int ends, others;
    I2D_CHECK(step_and_count(world, ground, crate, &ends, &others) == 0);
    I2D_CHECK(ends == 1 && others == 0);
    for (int i = 0; i < 60; ++i) {
        I2D_REQUIRE(step_ok(world));
    }
    /* 1 s of free fall from rest: 5 m down (less a little for the first step). */
    I2D_CHECK(i2d_body_get_position(crate_body).y < -4.0f);
    I2D_CHECK(i2d_world_get_counters(world).contact_count == 0);

    /* Back on the ground: a teleport into it with the default filter collides again. */
    I2D_CHECK_STATUS(i2d_shape_set_filter(crate, i2d_default_filter()), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_set_transform(crate_body, v2(0.0f, 0.49f), identity_rot()), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_set_linear_velocity(crate_body, v2(0.0f, 0.0f)), I2D_OK);
    I2D_CHECK(step_and_count(world, ground, crate, &ends, &others) == 1);
    I2D_CHECK(ends == 0);
}

I2D_TEST(api_filter_set_filter_falls_through) { run_in_world(-10.0f, run_fall_through); }
