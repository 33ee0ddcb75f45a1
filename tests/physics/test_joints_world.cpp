// SPDX-License-Identifier: MIT
// What joints do to the rest of the world: joined bodies share an island (they sleep and
// wake together), joined bodies do not collide unless collide_connected says so (and do
// again once the joint is gone), and a breakable joint's event fires exactly when its
// reaction passes the threshold.
#include <impulse2d/impulse2d.h>

#include <cmath>
#include <cstdint>
#include <cstdio>

#include "check.h"
#include "physics_fixture.hpp"

namespace {

using namespace phys;

// Two 1 m boxes resting on the ground 3 m apart.
struct Pair {
    i2d_body_id a, b;
};

Pair resting_pair(Scene& s) {
    s.ground(0.0f);
    return {s.dynamic_box(i2d_vec2{-1.5f, 0.5f}, 0.5f, 0.5f), s.dynamic_box(i2d_vec2{1.5f, 0.5f}, 0.5f, 0.5f)};
}

// Steps until neither is awake (at most 5 s); the step count, or -1. `together` is cleared
// if at any step one was awake and the other not.
int sleep_pair(Scene& s, const Pair& p, bool& together) {
    for (int k = 1; k <= steps_for(5.0); ++k) {
        if (!s.step()) {
            return -1;
        }
        const bool a = i2d_body_is_awake(p.a), b = i2d_body_is_awake(p.b);
        together = together && a == b;
        if (!a && !b) {
            return k;
        }
    }
    return -1;
}

}  // namespace

// Two boxes apart on the ground, joined by a rod: they fall asleep at the same step, and a
// push on one wakes the other. Without the joint, the push wakes only the one pushed.
I2D_TEST(phys_joint_joined_bodies_sleep_and_wake_together) {
    for (const bool joined : {true, false}) {
        const int failures = i2d_check_failures;
        Scene s;
        const Pair p = resting_pair(s);
        I2D_REQUIRE(!I2D_IS_NULL(p.a) && !I2D_IS_NULL(p.b));
        if (joined) {
            i2d_distance_joint_def def = i2d_default_distance_joint_def();
            def.base.body_a = p.a;
            def.base.body_b = p.b;
            def.length = 3.0f;
            I2D_REQUIRE(!I2D_IS_NULL(i2d_joint_create_distance(s.world, &def)));
        }
        bool together = true;
        const int asleep = sleep_pair(s, p, together);
        I2D_CHECK(asleep > 0);
        // Unjoined, they are two islands that come to rest alike: asleep together or not, both
        // sleep, which is all the control needs.
        I2D_CHECK(!joined || together);
        I2D_CHECK_STATUS(i2d_body_apply_linear_impulse(p.a, i2d_vec2{0.5f, 0.0f}, position(p.a), true), I2D_OK);
        I2D_CHECK(i2d_body_is_awake(p.a));
        I2D_CHECK(i2d_body_is_awake(p.b) == joined);
        I2D_REQUIRE(s.step());
        I2D_CHECK(i2d_body_is_awake(p.b) == joined);
        fprintf(stderr, "    %s: asleep after %d steps%s; after a push on one, the other is %s\n",
                joined ? "joined" : "not joined", asleep, together ? ", together at every step" : "",
                i2d_body_is_awake(p.b) ? "awake" : "asleep");
        report_case(failures, joined ? "joined by a rod" : "not joined");
    }
}

namespace {

enum class Link { slack_rope, slack_rope_colliding, filter, none };
// What ends the joint's filtering before the second pass.
enum class Then { destroy, set_collide_connected };

// No gravity: box B slides at 2 m/s through where box A rests, 3 s, half a box to one side
// (so that the rope's two anchors never meet: a rope stops at its minimum length, as two
// bodies tied by a real one would on a line). Returns A's speed
// afterwards: 0 if B passed through it, about B's speed if they collided. The joint (if
// any) is then destroyed and B sent back: `after` gets A's speed from that second pass.
double pass_through(Link link, double& after, Then then = Then::destroy) {
    constexpr float lane = 0.5f;  // m: B's path is this far above A's centre
    Scene s(Scene::zero_gravity_def());
    const i2d_body_id a = s.dynamic_box(i2d_vec2{0.0f, 0.0f}, 0.5f, 0.5f);
    const i2d_body_id b = s.dynamic_box(i2d_vec2{-3.0f, lane}, 0.5f, 0.5f, Material{}, i2d_vec2{2.0f, 0.0f});
    i2d_joint_id joint = I2D_NULL_JOINT_ID;
    if (link == Link::slack_rope || link == Link::slack_rope_colliding) {
        // A rope that is slack over the whole run: a spring of no stiffness between limits
        // 0 and 10 m, so that the joint's only effect is on collision.
        i2d_distance_joint_def def = i2d_default_distance_joint_def();
        def.base.body_a = a;
        def.base.body_b = b;
        def.base.collide_connected = link == Link::slack_rope_colliding;
        def.length = 3.0f;
        def.enable_spring = true;
        def.hertz = 0.0f;
        def.enable_limit = true;
        def.min_length = 0.0f;
        def.max_length = 10.0f;
        joint = i2d_joint_create_distance(s.world, &def);
    } else if (link == Link::filter) {
        i2d_filter_joint_def def = i2d_default_filter_joint_def();
        def.base.body_a = a;
        def.base.body_b = b;
        joint = i2d_joint_create_filter(s.world, &def);
    }
    if (link != Link::none && I2D_IS_NULL(joint)) {
        ++i2d_check_failures;
        fprintf(stderr, "    joint creation failed: %s\n", i2d_last_error_message());
        return -1.0;
    }
    s.step(steps_for(3.0));
    const double first = speed(velocity(a));
    if (!I2D_IS_NULL(joint) && then == Then::destroy) {
        I2D_CHECK_STATUS(i2d_joint_destroy(joint), I2D_OK);
    } else if (!I2D_IS_NULL(joint)) {
        I2D_CHECK_STATUS(i2d_joint_set_collide_connected(joint, true), I2D_OK);
    }
    // Back the way it came, from the far side, at A again.
    i2d_body_set_transform(b, i2d_vec2{3.0f, lane}, i2d_make_rot(0.0f));
    i2d_body_set_linear_velocity(b, i2d_vec2{-2.0f, 0.0f});
    i2d_body_set_angular_velocity(b, 0.0f);
    i2d_body_set_transform(a, i2d_vec2{0.0f, 0.0f}, i2d_make_rot(0.0f));
    i2d_body_set_linear_velocity(a, i2d_vec2{0.0f, 0.0f});
    i2d_body_set_angular_velocity(a, 0.0f);
    s.step(steps_for(3.0));
    after = speed(velocity(a));
    return first;
}

}  // namespace

// collide_connected false (the default): the joined boxes pass through each other; once the
// joint is destroyed, or collide_connected set true, they collide. True from the start: they
// collide with the joint. Unjoined: they collide.
I2D_TEST(phys_joint_collide_connected_false_stops_collision_and_destroying_the_joint_restores_it) {
    constexpr double hit = 0.5;  // m/s: A was struck (a 2 m/s equal-mass hit passes most of it on)
    double after = 0.0;
    double first = pass_through(Link::slack_rope, after);
    fprintf(stderr, "    rope, collide_connected false: A at %.3f m/s after the pass, %.3f m/s after destroying\n",
            first, after);
    I2D_CHECK(first < 1e-4);
    I2D_CHECK(after > hit);
    first = pass_through(Link::slack_rope_colliding, after);
    fprintf(stderr, "    rope, collide_connected true: A at %.3f m/s\n", first);
    I2D_CHECK(first > hit);
    first = pass_through(Link::none, after);
    I2D_CHECK(first > hit);
    // Switched on for a joint that stays, collide_connected lets them collide again too.
    first = pass_through(Link::slack_rope, after, Then::set_collide_connected);
    fprintf(stderr, "    rope, collide_connected set true after the pass: A at %.3f m/s after the second\n", after);
    I2D_CHECK(first < 1e-4);
    I2D_CHECK(after > hit);
}

// A filter joint constrains nothing and only stops the collision.
I2D_TEST(phys_joint_filter_joint_only_stops_collision) {
    double after = 0.0;
    const double first = pass_through(Link::filter, after);
    fprintf(stderr, "    filter: A at %.3f m/s after the pass, %.3f m/s after destroying\n", first, after);
    I2D_CHECK(first < 1e-4);
    I2D_CHECK(after > 0.5);
}

namespace {

// The joint events of the last step: whether `joint` is listed, checking each event's
// user data against its joint's.
bool listed(i2d_world_id world, i2d_joint_id joint) {
    const i2d_joint_events events = i2d_world_get_joint_events(world);
    bool found = false;
    for (int32_t k = 0; k < events.count; ++k) {
        I2D_CHECK(events.events[k].user_data == i2d_joint_get_user_data(events.events[k].joint));
        found = found || events.events[k].joint.bits == joint.bits;
    }
    return found;
}

// How often each of two breakable joints, the first to break at 0.9 of its load and the
// second at 1.1, was listed over 2 s of steps; the second only once the load has settled
// (after 0.05 s).
struct Listings {
    int steps = steps_for(2.0), settling_steps = steps_for(0.05);
    int low = 0, high = 0, high_first = -1;  // high_first: the first step listing the second
};

bool count_listings(Scene& s, const i2d_joint_id (&joints)[2], Listings* out) {
    for (int k = 0; k < out->steps; ++k) {
        if (!s.step()) {
            return false;
        }
        out->low += listed(s.world, joints[0]);
        const bool high = k >= out->settling_steps && listed(s.world, joints[1]);
        out->high += high;
        if (high && out->high_first < 0) {
            out->high_first = k + 1;
        }
    }
    return true;
}

}  // namespace

// Two equal weights hang from revolute joints, one breakable at 0.9 m g, one at 1.1 m g.
// The first is listed after every step, the second never. Destroyed between steps, the
// first lets its weight fall freely (g t^2 / 2 in the next half second).
I2D_TEST(phys_joint_breakable_force_event_fires_above_the_threshold_and_not_below) {
    // Events come from the joints solved in a step: a sleeping weight's joint is not solved
    // (its reaction is that of its last awake step), so these scenes keep their bodies awake.
    Scene s(Scene::no_sleep_def());
    const double g = s.gravity();
    i2d_joint_id joints[2];
    i2d_body_id weights[2];
    const double factors[2] = {0.9, 1.1};
    for (int i = 0; i < 2; ++i) {
        const i2d_vec2 pivot{3.0f * float(i), 10.0f};
        const i2d_body_id ceiling = s.anchor(pivot);
        weights[i] = s.dynamic_box(i2d_vec2{pivot.x, pivot.y - 1.0f}, 0.5f, 0.5f);
        const double weight = double(i2d_body_get_mass(weights[i])) * g;
        i2d_revolute_joint_def def = i2d_default_revolute_joint_def();
        def.base.force_threshold = float(factors[i] * weight);
        def.base.user_data = reinterpret_cast<void*>(std::intptr_t(i + 1));
        joints[i] = i2d_joint_create_revolute(s.world, &join_at(def, ceiling, weights[i], pivot));
        I2D_REQUIRE(!I2D_IS_NULL(joints[i]));
    }
    Listings l;
    I2D_REQUIRE(count_listings(s, joints, &l));
    fprintf(stderr, "    threshold 0.9 m g listed after %d of %d steps, 1.1 m g after %d (first: step %d); reaction %.4f N, "
            "m g %.4f N\n",
            l.low, l.steps, l.high, l.high_first, speed(i2d_joint_get_reaction_force(joints[0])),
            double(i2d_body_get_mass(weights[0])) * g);
    I2D_CHECK(l.low == l.steps);
    I2D_CHECK(l.high == 0);
    // Broken between steps, as a game would on the event: the weight falls freely.
    const double y0 = position(weights[0]).y;
    I2D_CHECK_STATUS(i2d_joint_destroy(joints[0]), I2D_OK);
    const int fall_steps = steps_for(0.5);
    I2D_REQUIRE(s.step(fall_steps));
    const double t = fall_steps * double(time_step), fallen = y0 - double(position(weights[0]).y);
    I2D_CHECK_NEAR(fallen, 0.5 * g * t * t, 0.01 * 0.5 * g * t * t);
    I2D_CHECK(!listed(s.world, joints[0]));
    I2D_CHECK(i2d_world_get_joint_count(s.world) == 1);
}

// A bar welded to a wall by one end needs the torque m g d (d: the anchor to its centre);
// a torque threshold of 0.9 of that lists the joint at every step, 1.1 never once the load
// has settled. A soft weld takes a load that starts all at once with a transient (the bar
// starts in free fall): 1.44 m g d at the first step, 0.91 at the second, within 4 % from
// the third, 2026-11-24; a rigid joint would hold m g d from the start.
I2D_TEST(phys_joint_breakable_torque_event_fires_above_the_threshold_and_not_below) {
    Scene s(Scene::no_sleep_def());  // awake, as the test above says why
    const double g = s.gravity();
    i2d_joint_id joints[2];
    const double factors[2] = {0.9, 1.1};
    constexpr float half_length = 0.5f;
    for (int i = 0; i < 2; ++i) {
        const i2d_vec2 wall{0.0f, 5.0f + 2.0f * float(i)};
        const i2d_body_id ground = s.anchor(wall);
        const i2d_body_id bar = s.dynamic_box(i2d_vec2{wall.x + half_length, wall.y}, half_length, 0.1f);
        const double torque = double(i2d_body_get_mass(bar)) * g * half_length;
        i2d_weld_joint_def def = i2d_default_weld_joint_def();
        def.base.torque_threshold = float(factors[i] * torque);
        joints[i] = i2d_joint_create_weld(s.world, &join_at(def, ground, bar, wall));
        I2D_REQUIRE(!I2D_IS_NULL(joints[i]));
    }
    Listings l;
    I2D_REQUIRE(count_listings(s, joints, &l));
    fprintf(stderr, "    torque threshold 0.9 m g d listed after %d of %d steps, 1.1 m g d after %d once settled (first: step %d); "
            "reaction torque %.4f N m\n",
            l.low, l.steps, l.high, l.high_first, double(i2d_joint_get_reaction_torque(joints[0])));
    I2D_CHECK(l.low == l.steps);
    I2D_CHECK(l.high == 0);
}
