// SPDX-License-Identifier: MIT
// The contact hooks (toolkit.h) as a game uses them: a one-way platform made with the
// pre-solve hook, ghosts kept apart by the custom filter. Each scene runs once without
// its hook as the control, which must fail the same check.
#include <atomic>

#include "physics_fixture.hpp"

using namespace phys;

namespace {

// The one-way platform: a thin static box the player jumps through from below.
constexpr float platform_top = 3.0f;
constexpr float platform_half_width = 2.0f;
constexpr float platform_half_height = 0.1f;
constexpr float crate_half = 0.25f;
// A normal within about 18 degrees of straight up counts as landing from above.
constexpr float landing_normal_min_y = 0.95f;
// At rest on the platform: its top plus the crate's half height, within the slop.
constexpr double rest_tolerance = 0.01;  // m

struct OneWayPlatform {
    i2d_world_id world = I2D_NULL_WORLD_ID;
    i2d_shape_id platform = I2D_NULL_SHAPE_ID;
    std::atomic<int> calls{0};  // the hook may run on several workers at once
    i2d_status step_inside = I2D_OK;     // what a step called from inside the hook answered
    i2d_status getter_inside = I2D_OK;   // and a getter
};

// Lets the contact act only when it pushes the other shape up: the crate lands on the
// platform, and passes through it from below and from the side.
bool one_way(i2d_shape_id a, i2d_shape_id b, const i2d_manifold* manifold, void* context) {
    OneWayPlatform& p = *static_cast<OneWayPlatform*>(context);
    if (p.calls++ == 0) {
        i2d_world_step(p.world, time_step, substeps);
        p.step_inside = i2d_last_status();
        i2d_shape_get_aabb(b);
        p.getter_inside = i2d_last_status();
    }
    float sign = 0.0f;
    if (a.bits == p.platform.bits) {
        sign = 1.0f;  // the normal points from A, the platform, to the crate
    } else if (b.bits == p.platform.bits) {
        sign = -1.0f;
    }
    return sign * manifold->normal.y > landing_normal_min_y;
}

struct JumpResult {
    double highest = -INFINITY;  // the crate's centre, m
    i2d_vec2 end_position{0, 0};
    i2d_vec2 end_velocity{0, 0};
};

// A crate launched up from the ground at `speed` under the one-way platform, watched for
// `seconds`; with_hook false leaves the hook unset (the control).
JumpResult jump_through(OneWayPlatform& hook, bool with_hook, float speed, bool bullet, double seconds = 3.0) {
    Scene s;
    s.ground();
    hook.world = s.world;
    const i2d_body_def platform_def = body_def(I2D_BODY_STATIC, i2d_vec2{0, platform_top - platform_half_height});
    const i2d_body_id platform = i2d_body_create(s.world, &platform_def);
    i2d_shape_def sd = i2d_default_shape_def();
    sd.enable_pre_solve_events = true;
    hook.platform = i2d_shape_create_box(platform, &sd, platform_half_width, platform_half_height);
    if (with_hook) {
        i2d_world_set_pre_solve_callback(s.world, one_way, &hook);
    }
    i2d_body_def crate_def = body_def(I2D_BODY_DYNAMIC, i2d_vec2{0, crate_half}, i2d_vec2{0, speed});
    crate_def.is_bullet = bullet;
    const i2d_body_id crate = s.box(crate_def, crate_half, crate_half);
    JumpResult r;
    for (int k = 0; k < steps_for(seconds) && s.step(); ++k) {
        r.highest = std::max(r.highest, double(position(crate).y));
    }
    r.end_position = position(crate);
    r.end_velocity = velocity(crate);
    return r;
}

constexpr double rest_height = platform_top + crate_half;

}  // namespace

I2D_TEST(phys_hooks_one_way_platform_lets_a_crate_up_through_and_holds_it_on_top) {
    // 9 m/s from the ground rises v^2 / 2g = 4.05 m: well past the platform at 3 m.
    OneWayPlatform hook;
    const JumpResult r = jump_through(hook, true, 9.0f, false);
    I2D_CHECK(r.highest > rest_height + 0.5);
    I2D_CHECK_NEAR(r.end_position.y, rest_height, rest_tolerance);
    I2D_CHECK(speed(r.end_velocity) < 0.01);
    I2D_CHECK(hook.calls > 0);

    OneWayPlatform control;
    const JumpResult c = jump_through(control, false, 9.0f, false);
    I2D_CHECK(c.highest < platform_top - 2 * platform_half_height);  // stopped beneath it
    I2D_CHECK(control.calls == 0);
}

I2D_TEST(phys_hooks_one_way_platform_holds_for_bullets_too) {
    // 30 m/s moves 0.5 m a step, twice the platform's thickness and more than the crate:
    // the continuous stage must ask the hook as well, both going up and coming down.
    OneWayPlatform hook;
    const JumpResult r = jump_through(hook, true, 30.0f, true, 8.0);
    I2D_CHECK(r.highest > rest_height + 10.0);
    I2D_CHECK_NEAR(r.end_position.y, rest_height, rest_tolerance);

    OneWayPlatform control;
    const JumpResult c = jump_through(control, false, 30.0f, true, 8.0);
    I2D_CHECK(c.highest < platform_top - 2 * platform_half_height);
}

I2D_TEST(phys_hooks_are_locked_against_calls_on_their_world) {
    OneWayPlatform hook;
    jump_through(hook, true, 9.0f, false);
    I2D_CHECK(hook.calls > 0);
    I2D_CHECK(hook.step_inside == I2D_ERR_WORLD_LOCKED);
    I2D_CHECK(hook.getter_inside == I2D_ERR_WORLD_LOCKED);
}

I2D_TEST(phys_hooks_pre_solve_opt_in_can_change_after_creation) {
    // The platform opts out after creation: the hook is no longer asked and the crate is
    // stopped beneath it; opting in again lets it through.
    for (const bool opted_in : {false, true}) {
        Scene s;
        s.ground();
        OneWayPlatform hook;
        hook.world = s.world;
        const i2d_body_id platform = s.box(body_def(I2D_BODY_STATIC, i2d_vec2{0, platform_top - platform_half_height}),
                                           platform_half_width, platform_half_height);
        hook.platform = only_shape(platform);
        I2D_CHECK(!i2d_shape_are_pre_solve_events_enabled(hook.platform));
        I2D_CHECK(i2d_shape_enable_pre_solve_events(hook.platform, opted_in) == I2D_OK);
        I2D_CHECK(i2d_shape_are_pre_solve_events_enabled(hook.platform) == opted_in);
        i2d_world_set_pre_solve_callback(s.world, one_way, &hook);
        const i2d_body_id crate = s.dynamic_box(i2d_vec2{0, crate_half}, crate_half, crate_half, Material{},
                                                i2d_vec2{0, 9.0f});
        double highest = 0;
        for (int k = 0; k < steps_for(2.0) && s.step(); ++k) {
            highest = std::max(highest, double(position(crate).y));
        }
        I2D_CHECK((highest > rest_height) == opted_in);
        I2D_CHECK((hook.calls > 0) == opted_in);
    }
}

namespace {

// Ghosts: shapes in groups; two different groups pass through each other, a group meets
// itself and every shape in no group. The hook may use only its arguments (every call on
// the world is locked while it runs), so the groups are a table of its own.
struct GhostGroups {
    std::vector<std::pair<uint64_t, int>> group_of_shape;
    int group(i2d_shape_id shape) const {
        for (const auto& entry : group_of_shape) {
            if (entry.first == shape.bits) {
                return entry.second;
            }
        }
        return 0;
    }
};

bool same_ghost_group(i2d_shape_id a, i2d_shape_id b, void* context) {
    const GhostGroups& groups = *static_cast<const GhostGroups*>(context);
    const int ga = groups.group(a), gb = groups.group(b);
    return ga == 0 || gb == 0 || ga == gb;
}

struct Ghosts {
    double fallen_top = 0;   // the dropped crate's height when it came to rest, m
    double stacked_top = 0;  // the crate dropped on one of its own group
};

// A crate of group 1 dropped on a crate of group 2, and one of group 1 on one of group 1.
Ghosts drop_ghosts(bool with_filter) {
    Scene s;
    s.ground();
    GhostGroups groups;
    if (with_filter) {
        i2d_world_set_custom_filter_callback(s.world, same_ghost_group, &groups);
    }
    const auto tagged = [&](float x, float y, int group) {
        const i2d_body_def def = body_def(I2D_BODY_DYNAMIC, i2d_vec2{x, y});
        const i2d_body_id body = i2d_body_create(s.world, &def);
        i2d_shape_def sd = i2d_default_shape_def();
        sd.enable_custom_filtering = true;
        groups.group_of_shape.push_back({i2d_shape_create_box(body, &sd, 0.5f, 0.5f).bits, group});
        return body;
    };
    tagged(-3, 0.5f, 2);
    const i2d_body_id fallen = tagged(-3, 3.0f, 1);
    tagged(3, 0.5f, 1);
    const i2d_body_id stacked = tagged(3, 3.0f, 1);
    s.step(steps_for(3.0));
    return Ghosts{position(fallen).y, position(stacked).y};
}

}  // namespace

I2D_TEST(phys_hooks_custom_filter_lets_two_groups_pass_through_each_other) {
    const Ghosts g = drop_ghosts(true);
    I2D_CHECK_NEAR(g.fallen_top, 0.5, rest_tolerance);   // through the other group, on the ground
    I2D_CHECK_NEAR(g.stacked_top, 1.5, rest_tolerance);  // on its own group's crate
    const Ghosts control = drop_ghosts(false);
    I2D_CHECK_NEAR(control.fallen_top, 1.5, rest_tolerance);
    I2D_CHECK_NEAR(control.stacked_top, 1.5, rest_tolerance);
}

I2D_TEST(phys_hooks_reach_only_pairs_that_opted_in) {
    // A filter that refuses everything changes nothing for shapes that did not opt in.
    Scene s;
    s.ground();
    int calls = 0;
    i2d_world_set_custom_filter_callback(
        s.world,
        [](i2d_shape_id, i2d_shape_id, void* context) {
            ++*static_cast<int*>(context);
            return false;
        },
        &calls);
    const i2d_body_id crate = s.dynamic_box(i2d_vec2{0, 2}, 0.5f, 0.5f);
    s.step(steps_for(2.0));
    I2D_CHECK_NEAR(position(crate).y, 0.5, rest_tolerance);
    I2D_CHECK(calls == 0);
    // Cleared with NULL: pairs are no longer asked.
    I2D_CHECK(i2d_world_set_custom_filter_callback(s.world, nullptr, nullptr) == I2D_OK);
    I2D_CHECK(i2d_world_set_pre_solve_callback(s.world, nullptr, nullptr) == I2D_OK);
}

I2D_TEST(phys_hooks_opt_ins_travel_in_snapshots) {
    // Saved mid-jump and restored in place, the crate goes on exactly as it went: the
    // platform's opt-in came back with the snapshot (without it the crate would stop).
    Scene s;
    s.ground();
    OneWayPlatform hook;
    hook.world = s.world;
    const i2d_body_def platform_def = body_def(I2D_BODY_STATIC, i2d_vec2{0, platform_top - platform_half_height});
    const i2d_body_id platform = i2d_body_create(s.world, &platform_def);
    i2d_shape_def sd = i2d_default_shape_def();
    sd.enable_pre_solve_events = true;
    hook.platform = i2d_shape_create_box(platform, &sd, platform_half_width, platform_half_height);
    i2d_world_set_pre_solve_callback(s.world, one_way, &hook);
    const i2d_body_id crate = s.dynamic_box(i2d_vec2{0, crate_half}, crate_half, crate_half, Material{},
                                            i2d_vec2{0, 9.0f});
    s.step(5);
    std::vector<unsigned char> saved(i2d_world_get_snapshot_size(s.world));
    I2D_REQUIRE(i2d_world_save_snapshot(s.world, saved.data(), saved.size(), nullptr) == I2D_OK);
    i2d_shape_enable_pre_solve_events(hook.platform, false);  // undone by the restore
    s.step(steps_for(2.0));
    I2D_CHECK(position(crate).y < platform_top);  // the control: stopped beneath
    I2D_REQUIRE(i2d_world_restore_snapshot(s.world, saved.data(), saved.size()) == I2D_OK);
    I2D_CHECK(i2d_shape_are_pre_solve_events_enabled(hook.platform));
    s.step(steps_for(2.0));
    I2D_CHECK_NEAR(position(crate).y, rest_height, rest_tolerance);
}
