// SPDX-License-Identifier: MIT
// i2d_world_shift_origin: a world whose origin moved goes on as a copy that stayed,
// every position less the shift; the last step's events move with it; a rollback state
// from before is refused; bad ids, a locked world and origins out of range are refused
// with the world untouched.
#include <cmath>
#include <cstdio>
#include <vector>

#include "physics_fixture.hpp"

using namespace phys;

namespace {

/// The shift, and the steps before and after it.
constexpr i2d_vec2 shift{1000.0f, -500.0f};
constexpr int steps_before = 50, steps_after = 100;
/// How far a body may end from where the copy that was not shifted puts it, m.
constexpr double position_tolerance = 1e-4;
constexpr double angle_tolerance = 1e-4;

/// A level of 20 x 10 m whose ground's top middle is at `base`: a stack, a pendulum on a
/// revolute joint, a box dragged by a mouse joint, a box sliding and a ball that lands on
/// the ground after the shift (a pair the shifted trees must find). `moving` lists every
/// dynamic body, for comparison.
struct ShiftScene {
    Scene scene;
    std::vector<i2d_body_id> moving;
    i2d_joint_id mouse = I2D_NULL_JOINT_ID;
    i2d_vec2 base;

    explicit ShiftScene(i2d_vec2 level_base) : base(level_base) {}

    i2d_vec2 at(float x, float y) const { return i2d_vec2{base.x + x, base.y + y}; }

    bool build() {
        if (I2D_IS_NULL(scene.box(body_def(I2D_BODY_STATIC, at(0.0f, -0.5f)), 9.5f, 0.5f))) {
            return false;
        }
        for (int i = 0; i < 5; ++i) {
            moving.push_back(scene.dynamic_box(at(-6.0f, 0.5f + float(i)), 0.5f, 0.5f));
        }
        const i2d_body_id pivot = scene.anchor(at(4.0f, 6.0f));
        const i2d_body_id bob = scene.dynamic_circle(at(6.0f, 6.0f), 0.25f);
        i2d_revolute_joint_def hinge = i2d_default_revolute_joint_def();
        join_at(hinge, pivot, bob, at(4.0f, 6.0f));
        const bool hinged = !I2D_IS_NULL(i2d_joint_create_revolute(scene.world, &hinge));
        const i2d_body_id dragged = scene.dynamic_box(at(6.0f, 3.0f), 0.5f, 0.5f);
        i2d_mouse_joint_def drag = i2d_default_mouse_joint_def();
        drag.base.body_a = pivot;
        drag.base.body_b = dragged;
        drag.target = at(8.0f, 4.0f);
        mouse = i2d_joint_create_mouse(scene.world, &drag);
        const i2d_body_id slider = scene.dynamic_box(at(0.0f, 0.5f), 0.5f, 0.5f, Material{}, i2d_vec2{6, 0});
        const i2d_body_id ball = scene.dynamic_circle(at(-3.0f, 5.3f), 0.3f);
        for (const i2d_body_id b : {bob, dragged, slider, ball}) {
            moving.push_back(b);
        }
        for (const i2d_body_id b : moving) {
            if (I2D_IS_NULL(b)) {
                return false;
            }
        }
        return hinged && !I2D_IS_NULL(mouse);
    }
};

i2d_vec2 minus(i2d_vec2 a, i2d_vec2 b) { return i2d_vec2{a.x - b.x, a.y - b.y}; }

/// Two copies of the level at `base`, stepped steps_before, one shifted, both stepped
/// steps_after: the largest distance of a shifted body from its copy less the shift (m),
/// and the largest difference of angles (rad). Right after the shift every position and
/// the mouse target must be the copy's less the shift, as subtraction rounds it.
struct Drift {
    double position = INFINITY, angle = INFINITY;
};

Drift shifted_copy_drift(i2d_vec2 base) {
    ShiftScene stayed(base), shifted(base);
    Drift drift;
    if (!stayed.build() || !shifted.build() || !stayed.scene.step(steps_before) ||
        !shifted.scene.step(steps_before)) {
        ++i2d_check_failures;
        return drift;
    }
    I2D_CHECK_STATUS(i2d_world_shift_origin(shifted.scene.world, shift), I2D_OK);
    for (size_t i = 0; i < stayed.moving.size(); ++i) {
        I2D_CHECK(same_bits(position(shifted.moving[i]), minus(position(stayed.moving[i]), shift)));
    }
    I2D_CHECK(same_bits(i2d_mouse_joint_get_target(shifted.mouse),
                        minus(i2d_mouse_joint_get_target(stayed.mouse), shift)));
    if (!stayed.scene.step(steps_after) || !shifted.scene.step(steps_after)) {
        ++i2d_check_failures;
        return drift;
    }
    drift = Drift{0.0, 0.0};
    for (size_t i = 0; i < stayed.moving.size(); ++i) {
        const double off = distance(position(shifted.moving[i]), minus(position(stayed.moving[i]), shift));
        const double turn = std::fabs(wrap_angle(angle_of(shifted.moving[i]) - angle_of(stayed.moving[i])));
        drift.position = std::max(drift.position, off);
        drift.angle = std::max(drift.angle, turn);
        I2D_CHECK(i2d_body_is_awake(shifted.moving[i]) == i2d_body_is_awake(stayed.moving[i]));
    }
    return drift;
}

}  // namespace

// A level 500 m from the origin moved 1000 m to its mirror image: both copies' floats are
// as coarse (3e-5 m apart), the shift is a whole number of those steps, and every rounding
// of the shifted world is its copy's, shifted. It goes on as the copy does, bit for bit in
// practice; the check allows 1e-4 m.
I2D_TEST(phys_shift_origin_continues_as_unshifted_copy) {
    const Drift drift = shifted_copy_drift(i2d_vec2{500.0f, -255.0f});
    printf("    after %d more steps: positions within %.3g m, angles within %.3g rad of the copy's\n", steps_after,
           drift.position, drift.angle);
    I2D_CHECK(drift.position <= position_tolerance);
    I2D_CHECK(drift.angle <= angle_tolerance);
}

// The level at the origin moved 1000 m away: there floats are 6.1e-5 m apart, and every
// step rounds a moving body's position by up to half that, which the copy near the origin
// does not. Bodies that keep moving drift by a few of those steps in 100 steps (the
// pendulum, swinging from the horizontal, by about 2.6e-4 m); the rest match.
I2D_TEST(phys_shift_origin_away_from_origin_rounds_coarser) {
    constexpr double float_spacing_at_1000m = 6.1e-5;
    constexpr double allowed = 10 * float_spacing_at_1000m;
    const Drift drift = shifted_copy_drift(i2d_vec2{0.0f, 0.0f});
    printf("    after %d more steps: positions within %.3g m (allowed %.3g), angles within %.3g rad\n", steps_after,
           drift.position, allowed, drift.angle);
    I2D_CHECK(drift.position <= allowed);
    I2D_CHECK(drift.angle <= 1e-3);
}

// The last step's body move events are read after the shift in the new frame.
I2D_TEST(phys_shift_origin_moves_last_step_events) {
    ShiftScene scene(i2d_vec2{0.0f, 0.0f});
    I2D_REQUIRE(scene.build() && scene.scene.step(steps_before));
    const i2d_body_events before = i2d_world_get_body_events(scene.scene.world);
    std::vector<i2d_vec2> moved;
    for (int32_t i = 0; i < before.move_count; ++i) {
        moved.push_back(before.move_events[i].transform.p);
    }
    I2D_REQUIRE(!moved.empty());
    I2D_CHECK_STATUS(i2d_world_shift_origin(scene.scene.world, shift), I2D_OK);
    const i2d_body_events after = i2d_world_get_body_events(scene.scene.world);
    I2D_REQUIRE(after.move_count == int32_t(moved.size()));
    for (int32_t i = 0; i < after.move_count; ++i) {
        I2D_CHECK(same_bits(after.move_events[i].transform.p, minus(moved[size_t(i)], shift)));
        I2D_CHECK(same_bits(after.move_events[i].transform.p, position(after.move_events[i].body)));
    }
}

// A rollback state holds positions of the old origin: after the shift it is refused.
I2D_TEST(phys_shift_origin_refuses_older_rollback_state) {
    ShiftScene scene(i2d_vec2{0.0f, 0.0f});
    I2D_REQUIRE(scene.build() && scene.scene.step(10));
    std::vector<unsigned char> state(i2d_world_get_state_size(scene.scene.world));
    size_t written = 0;
    I2D_CHECK_STATUS(i2d_world_save_state(scene.scene.world, state.data(), state.size(), &written), I2D_OK);
    I2D_CHECK_STATUS(i2d_world_restore_state(scene.scene.world, state.data(), written), I2D_OK);
    I2D_CHECK_STATUS(i2d_world_shift_origin(scene.scene.world, shift), I2D_OK);
    const uint64_t hash = i2d_world_get_state_hash(scene.scene.world);
    I2D_CHECK(i2d_world_restore_state(scene.scene.world, state.data(), written) != I2D_OK);
    I2D_CHECK(i2d_world_get_state_hash(scene.scene.world) == hash);
}

namespace {

struct LockedCall {
    i2d_world_id world;
    i2d_status status;
};

bool shift_inside_query(i2d_shape_id, void* context) {
    LockedCall* call = static_cast<LockedCall*>(context);
    call->status = i2d_world_shift_origin(call->world, shift);
    return false;
}

}  // namespace

// Refused: a null, stale or foreign-kind id, a locked world, NaN, inf, an origin beyond
// 1e9 m, and one that would carry a body or a mouse target beyond 1e9 m; each leaves the
// world's state hash as it was.
I2D_TEST(phys_shift_origin_refuses_bad_input) {
    ShiftScene scene(i2d_vec2{0.0f, 0.0f});
    I2D_REQUIRE(scene.build() && scene.scene.step(5));
    const i2d_world_id world = scene.scene.world;
    const uint64_t hash = i2d_world_get_state_hash(world);
    const float nan = std::nanf(""), inf = INFINITY;

    I2D_CHECK_STATUS(i2d_world_shift_origin(I2D_NULL_WORLD_ID, shift), I2D_ERR_INVALID_HANDLE);
    const i2d_world_def def = i2d_default_world_def();
    const i2d_world_id gone = i2d_world_create(&def);
    I2D_REQUIRE(i2d_world_destroy(gone) == I2D_OK);
    I2D_CHECK_STATUS(i2d_world_shift_origin(gone, shift), I2D_ERR_INVALID_HANDLE);
    const i2d_world_id wrong_kind{scene.moving[0].bits};
    I2D_CHECK_STATUS(i2d_world_shift_origin(wrong_kind, shift), I2D_ERR_INVALID_HANDLE);

    LockedCall locked{world, I2D_OK};
    const i2d_aabb everywhere{{-100, -100}, {100, 100}};
    I2D_CHECK_STATUS(i2d_world_overlap_aabb(world, everywhere, i2d_default_query_filter(), shift_inside_query, &locked),
                     I2D_OK);
    I2D_CHECK(locked.status == I2D_ERR_WORLD_LOCKED);

    const i2d_vec2 bad[] = {{nan, 0}, {0, nan}, {inf, 0}, {0, -inf}, {2e9f, 0}, {0, -1.5e9f}};
    for (const i2d_vec2 origin : bad) {
        I2D_CHECK_STATUS(i2d_world_shift_origin(world, origin), I2D_ERR_INVALID_ARGUMENT);
    }
    I2D_CHECK(i2d_world_get_state_hash(world) == hash);

    // Each origin within range, but a second shift would carry the bodies (all within
    // 30 m of the first origin) twice 1e9 m from it.
    I2D_CHECK_STATUS(i2d_world_shift_origin(world, i2d_vec2{-1e9f, 0}), I2D_OK);
    const uint64_t far_out = i2d_world_get_state_hash(world);
    I2D_CHECK(far_out != hash);
    I2D_CHECK_STATUS(i2d_world_shift_origin(world, i2d_vec2{-1e9f, 0}), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_world_get_state_hash(world) == far_out);

    // A mouse target alone far out: the bodies fit, the target would not.
    ShiftScene far(i2d_vec2{0.0f, 0.0f});
    I2D_REQUIRE(far.build());
    I2D_CHECK_STATUS(i2d_mouse_joint_set_target(far.mouse, i2d_vec2{9e8f, 0}), I2D_OK);
    const uint64_t far_hash = i2d_world_get_state_hash(far.scene.world);
    I2D_CHECK_STATUS(i2d_world_shift_origin(far.scene.world, i2d_vec2{-5e8f, 0}), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_world_get_state_hash(far.scene.world) == far_hash);
    I2D_CHECK(same_bits(i2d_mouse_joint_get_target(far.mouse), i2d_vec2{9e8f, 0}));
}
