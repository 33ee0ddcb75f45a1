// SPDX-License-Identifier: MIT
// Islands and sleeping through the public API: a resting pile falls asleep together
// after time_to_sleep (and reports it in the move events), stays bitwise still while
// asleep, and wakes exactly when the header says it does (impulses and forces with
// wake = true, setters, destroying a support, an awake body landing on it, a kinematic
// support starting to move, i2d_body_set_awake); it never sleeps when the world or one
// of its bodies disables sleep; the speed threshold and time to sleep are the world
// def's. Expectations are bounds from the settings and closed-form free fall and
// friction, never the engine's earlier output.
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <vector>

#include "physics_fixture.hpp"

using namespace phys;

namespace {

using Bodies = std::vector<i2d_body_id>;

bool all_valid(const Bodies& bodies) {
    for (i2d_body_id b : bodies) {
        if (I2D_IS_NULL(b)) {
            return false;
        }
    }
    return !bodies.empty();
}

bool all_awake(const Bodies& bodies) { return count_awake(bodies) == int(bodies.size()); }
bool none_awake(const Bodies& bodies) { return count_awake(bodies) == 0; }

Bodies join(const Bodies& a, const Bodies& b) {
    Bodies all = a;
    all.insert(all.end(), b.begin(), b.end());
    return all;
}

// Steps one at a time until none of `bodies` is awake; the time it took (s) or -1 when
// they were still awake after max_seconds.
double wait_asleep(Scene& scene, const Bodies& bodies, double max_seconds) {
    for (int s = 1; s <= steps_for(max_seconds); ++s) {
        if (!scene.step()) {
            return -1;
        }
        if (none_awake(bodies)) {
            return s * double(time_step);
        }
    }
    return -1;
}

// Piles of `height` unit boxes on the ground (its top at y = 0), one centred on each x,
// stepped until every box sleeps (within 3 s); none (and a message) when a box could not
// be made or they stayed awake.
std::vector<Bodies> sleeping_piles(Scene& scene, std::initializer_list<float> xs, int height) {
    if (I2D_IS_NULL(scene.ground(0.0f))) {
        return {};
    }
    std::vector<Bodies> piles;
    Bodies all;
    for (const float x : xs) {
        piles.push_back(scene.column(x, height));
        if (!all_valid(piles.back())) {
            return {};
        }
        all = join(all, piles.back());
    }
    if (wait_asleep(scene, all, 3.0) <= 0) {
        fprintf(stderr, "    piles still awake after 3 s\n");
        return {};
    }
    return piles;
}

// Every body's transform and velocities, for bitwise comparison.
struct Snapshot {
    std::vector<BodyState> states;
    explicit Snapshot(const Bodies& bodies) {
        for (i2d_body_id b : bodies) {
            states.push_back(BodyState::of(b));
        }
    }
    // Bodies whose transform (and, when with_velocity, velocity) differ bitwise from other's.
    int differ(const Snapshot& other, bool with_velocity = false) const {
        int n = 0;
        for (size_t i = 0; i < states.size(); ++i) {
            const BodyState &a = states[i], &b = other.states[i];
            n += (with_velocity ? a.same_bits(b) : a.same_pose(b)) ? 0 : 1;
        }
        return n;
    }
};

bool contains(const Bodies& bodies, i2d_body_id id) {
    for (i2d_body_id b : bodies) {
        if (I2D_ID_EQUALS(b, id)) {
            return true;
        }
    }
    return false;
}

}  // namespace

I2D_TEST(phys_sleep_pile_falls_asleep_with_events) {
    // Ten unit boxes piled on static ground as a 4-row pyramid (a tall column's own
    // stability is the soft-step tests' business), default world (time_to_sleep 0.5 s):
    // they rest from the start, so they fall asleep together, in one step, no sooner than
    // time_to_sleep and well within 3 s. Then the awake count is 0 and the ten are one
    // sleeping island. The move events of that very step flag the bodies that fell
    // asleep (at least one; every event of a pile body in that step has fell_asleep, no
    // earlier step has any), and no later step reports a move of theirs.
    const i2d_world_def def = i2d_default_world_def();
    I2D_CHECK(def.enable_sleep);
    I2D_CHECK_NEAR(def.time_to_sleep, 0.5, 1e-6);
    I2D_CHECK_NEAR(def.sleep_speed_threshold, 0.05, 1e-6);
    Scene scene(def);
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground(0.0f)));
    const Bodies pile = scene.pyramid(0.0f, 4);
    I2D_REQUIRE(all_valid(pile));
    I2D_CHECK(all_awake(pile));
    I2D_CHECK(i2d_world_get_counters(scene.world).awake_body_count == 10);

    double asleep_at = -1;
    int early_flags = 0, flagged = 0, unflagged = 0, foreign_flags = 0, partial_steps = 0;
    for (int s = 1; s <= steps_for(3.0) && asleep_at < 0; ++s) {
        I2D_REQUIRE(scene.step());
        const int awake = count_awake(pile);
        const i2d_body_events ev = i2d_world_get_body_events(scene.world);
        if (awake == 0) {
            asleep_at = s * double(time_step);
            for (int i = 0; i < ev.move_count; ++i) {
                const i2d_body_move_event& e = ev.move_events[i];
                if (!contains(pile, e.body)) {
                    foreign_flags += e.fell_asleep ? 1 : 0;
                } else if (e.fell_asleep) {
                    ++flagged;
                } else {
                    ++unflagged;
                }
            }
        } else {
            partial_steps += awake < 10 ? 1 : 0;  // some asleep, some not: not together
            for (int i = 0; i < ev.move_count; ++i) {
                early_flags += ev.move_events[i].fell_asleep ? 1 : 0;
            }
        }
    }
    const i2d_world_counters c = i2d_world_get_counters(scene.world);
    int later_moves = 0;
    for (int s = 0; s < steps_for(1.0); ++s) {
        I2D_REQUIRE(scene.step());
        const i2d_body_events ev = i2d_world_get_body_events(scene.world);
        for (int i = 0; i < ev.move_count; ++i) {
            later_moves += contains(pile, ev.move_events[i].body) ? 1 : 0;
        }
    }
    fprintf(stderr,
            "    pile of 10: asleep at %.4f s (time_to_sleep %.2f s); counters: %d awake, %d sleeping islands; events of "
            "that step: %d flagged fell_asleep, %d pile moves unflagged; %d flags before; %d moves reported in the "
            "next second\n",
            asleep_at, double(def.time_to_sleep), c.awake_body_count, c.sleeping_island_count, flagged, unflagged,
            early_flags, later_moves);
    I2D_CHECK(asleep_at >= def.time_to_sleep - time_step * 0.5);
    I2D_CHECK(asleep_at > 0 && asleep_at <= 3.0);
    I2D_CHECK(partial_steps == 0);
    I2D_CHECK(c.awake_body_count == 0);
    I2D_CHECK(c.sleeping_island_count == 1);
    I2D_CHECK(flagged >= 1);
    I2D_CHECK(unflagged == 0);
    I2D_CHECK(foreign_flags == 0);
    I2D_CHECK(early_flags == 0);
    I2D_CHECK(later_moves == 0);
}

I2D_TEST(phys_sleep_time_to_sleep_from_world_def) {
    // With time_to_sleep = 2 s the same resting pile (5 boxes) sleeps no sooner than 2 s
    // (and within 4 s).
    i2d_world_def def = i2d_default_world_def();
    def.time_to_sleep = 2.0f;
    Scene scene(def);
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground(0.0f)));
    const Bodies pile = scene.column(0.0f, 5);
    I2D_REQUIRE(all_valid(pile));
    const double t = wait_asleep(scene, pile, 4.0);
    fprintf(stderr, "    time_to_sleep 2 s: pile of 5 asleep at %.4f s\n", t);
    I2D_CHECK(t >= 2.0 - time_step * 0.5);
    I2D_CHECK(t > 0);
}

I2D_TEST(phys_sleep_sleeping_pile_is_bitwise_still) {
    // Once asleep, a pile's (10 boxes, 4-row pyramid) transforms and velocities stay bitwise the same over 2 s of
    // further steps, and the counters stay at 0 awake, 1 sleeping island.
    Scene scene;
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground(0.0f)));
    const Bodies pile = scene.pyramid(0.0f, 4);
    I2D_REQUIRE(all_valid(pile));
    I2D_REQUIRE(wait_asleep(scene, pile, 3.0) > 0);
    const Snapshot before(pile);
    int awake_steps = 0;
    for (int s = 0; s < steps_for(2.0); ++s) {
        I2D_REQUIRE(scene.step());
        const i2d_world_counters c = i2d_world_get_counters(scene.world);
        awake_steps += (c.awake_body_count != 0 || c.sleeping_island_count != 1) ? 1 : 0;
    }
    const Snapshot after(pile);
    const int differ = before.differ(after, true);
    fprintf(stderr, "    sleeping pile of 10 over 2 s: %d bodies changed bitwise, %d steps with other counters\n",
            differ, awake_steps);
    I2D_CHECK(differ == 0);
    I2D_CHECK(awake_steps == 0);
}

I2D_TEST(phys_sleep_impulse_wakes_only_its_pile) {
    // Two piles of 3, 40 m apart, asleep as two islands. An upward impulse of m x 2 m/s
    // with wake = true on the top box of pile A wakes pile A (the box at once, the pile by
    // the next step) and not pile B. After one step the box moves up at
    // 2 - g dt = 1.833 m/s (within 0.02).
    Scene scene;
    const std::vector<Bodies> piles = sleeping_piles(scene, {-20.0f, 20.0f}, 3);
    I2D_REQUIRE(piles.size() == 2);
    const Bodies &a = piles[0], &b = piles[1];
    const i2d_world_counters c0 = i2d_world_get_counters(scene.world);
    I2D_CHECK(c0.sleeping_island_count == 2);
    const Snapshot b_before(b);
    const i2d_body_id top = a.back();
    const double m = i2d_body_get_mass(top);
    I2D_CHECK_STATUS(i2d_body_apply_linear_impulse(top, i2d_vec2{0, float(2.0 * m)},
                                                    i2d_body_get_world_center_of_mass(top), true),
                     I2D_OK);
    const bool top_awake_now = i2d_body_is_awake(top);
    const bool b_asleep_now = none_awake(b);
    I2D_REQUIRE(scene.step());
    const double vy = velocity(top).y;
    const int a_awake = count_awake(a), b_awake = count_awake(b);
    const i2d_world_counters c1 = i2d_world_get_counters(scene.world);
    I2D_REQUIRE(scene.step(steps_for(0.2)));
    const int b_awake_later = count_awake(b);
    const int b_moved = b_before.differ(Snapshot(b), true);
    fprintf(stderr,
            "    impulse on pile A: top awake at once %d; after a step A %d/3 awake, B %d/3 awake (0.2 s later %d, %d "
            "moved); counters %d awake, %d sleeping islands; top vy %.4f m/s (expected %.4f)\n",
            top_awake_now, a_awake, b_awake, b_awake_later, b_moved, c1.awake_body_count, c1.sleeping_island_count, vy,
            2.0 - g * time_step);
    I2D_CHECK(top_awake_now);
    I2D_CHECK(b_asleep_now);
    I2D_CHECK(a_awake == 3);
    I2D_CHECK(b_awake == 0);
    I2D_CHECK(b_awake_later == 0);
    I2D_CHECK(b_moved == 0);
    I2D_CHECK(c1.awake_body_count == 3);
    I2D_CHECK(c1.sleeping_island_count == 1);
    I2D_CHECK_NEAR(vy, 2.0 - g * time_step, 0.02);
}

I2D_TEST(phys_sleep_no_wake_keeps_sleeping) {
    // wake = false on a sleeping body: an impulse, a force, a torque and an angular
    // impulse leave it (and its pile) asleep, and the pile does not move over 0.5 s.
    Scene scene;
    const std::vector<Bodies> piles = sleeping_piles(scene, {0.0f}, 3);
    I2D_REQUIRE(piles.size() == 1);
    const Bodies& pile = piles[0];
    const Snapshot before(pile);
    const i2d_body_id top = pile.back();
    const i2d_vec2 c = i2d_body_get_world_center_of_mass(top);
    I2D_CHECK_STATUS(i2d_body_apply_linear_impulse(top, i2d_vec2{0, 5}, c, false), I2D_OK);
    I2D_CHECK(!i2d_body_is_awake(top));
    I2D_CHECK_STATUS(i2d_body_apply_force(top, i2d_vec2{100, 0}, c, false), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_apply_force_to_center(top, i2d_vec2{0, 100}, false), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_apply_torque(top, 50.0f, false), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_apply_angular_impulse(top, 5.0f, false), I2D_OK);
    const bool awake_now = i2d_body_is_awake(top);
    I2D_REQUIRE(scene.step(steps_for(0.5)));
    const int awake = count_awake(pile);
    const int moved = before.differ(Snapshot(pile));
    fprintf(stderr, "    wake = false on a sleeping pile: top awake %d; after 0.5 s %d/3 awake, %d moved\n", awake_now,
            awake, moved);
    I2D_CHECK(!awake_now);
    I2D_CHECK(awake == 0);
    I2D_CHECK(moved == 0);
}

I2D_TEST(phys_sleep_setters_wake) {
    // Three sleeping piles of 3. Setting the top box's linear velocity (0, 1) wakes pile
    // A; setting the top box's transform (1 cm higher) wakes pile B; setting the top
    // box's angular velocity wakes pile C: each top box at once and its pile by the next
    // step, and the body then moves (A rises, B falls back, C tips about a bottom corner:
    // the box below stops the spin about its centre, so only a trace of it, more than
    // 1e-4 rad, is left after 3 steps). A force with
    // wake = true wakes a fourth pile D. The piles not touched stay asleep.
    Scene scene;
    const std::vector<Bodies> piles = sleeping_piles(scene, {-30.0f, -10.0f, 10.0f, 30.0f}, 3);
    I2D_REQUIRE(piles.size() == 4);
    const char* names[4] = {"set_linear_velocity", "set_transform", "set_angular_velocity", "apply_force wake"};
    for (int k = 0; k < 4; ++k) {
        const int before = i2d_check_failures;
        const Bodies& pile = piles[k];
        const i2d_body_id top = pile.back();
        const i2d_vec2 p0 = position(top);
        const double angle0 = angle_of(top);
        switch (k) {
            case 0:
                I2D_CHECK_STATUS(i2d_body_set_linear_velocity(top, i2d_vec2{0, 1}), I2D_OK);
                break;
            case 1:
                I2D_CHECK_STATUS(i2d_body_set_transform(top, i2d_vec2{p0.x, p0.y + 0.01f}, i2d_body_get_rotation(top)),
                                 I2D_OK);
                break;
            case 2:
                I2D_CHECK_STATUS(i2d_body_set_angular_velocity(top, 1.0f), I2D_OK);
                break;
            default:
                I2D_CHECK_STATUS(i2d_body_apply_force_to_center(top, i2d_vec2{0, float(60 * i2d_body_get_mass(top))}, true),
                                 I2D_OK);
                break;
        }
        const bool awake_now = i2d_body_is_awake(top);
        I2D_REQUIRE(scene.step());
        const int pile_awake = count_awake(pile);
        int others_awake = 0;
        for (int j = k + 1; j < 4; ++j) {
            others_awake += count_awake(piles[j]);
        }
        I2D_REQUIRE(scene.step(2));
        const i2d_vec2 p1 = position(top);
        const double turned = angle_of(top) - angle0;
        fprintf(stderr,
                "    %s: top awake at once %d, pile %d/3 awake after a step, untouched piles awake %d; after 3 steps "
                "moved by (%.4f, %.4f) m, turned %.4f rad\n",
                names[k], awake_now, pile_awake, others_awake, p1.x - p0.x, p1.y - p0.y, turned);
        I2D_CHECK(awake_now);
        I2D_CHECK(pile_awake == 3);
        I2D_CHECK(others_awake == 0);
        switch (k) {
            case 0:
                I2D_CHECK(p1.y - p0.y > 0.02);  // about 1 m/s x 3 steps minus gravity: 4.5 cm
                break;
            case 1:
                I2D_CHECK(p1.y < p0.y + 0.01f);  // fell back from 1 cm up
                break;
            case 2:
                I2D_CHECK(std::fabs(turned) > 1e-4);  // woken and simulated, not frozen
                break;
            default:
                I2D_CHECK(p1.y - p0.y > 0.01);  // 60 m/s^2 for a step, minus g: about 3 cm up
                break;
        }
        report_case(before, names[k]);
    }
}

I2D_TEST(phys_sleep_destroying_support_wakes) {
    // Box B rests on box A on the ground, both asleep. Destroying A wakes B at once; B
    // then falls freely: after 0.3 s it has dropped g t^2 / 2 = 0.45 m (within 3 %), and
    // after 1.5 s it rests on the ground (centre 0.5 m up, within the slop + 1 mm).
    // Destroying the supporting body's only shape instead wakes its load the same way.
    const double slop = i2d_default_world_def().contact_slop;
    for (bool shape_only : {false, true}) {
        const int before = i2d_check_failures;
        Scene scene;
        const std::vector<Bodies> piles = sleeping_piles(scene, {0.0f}, 2);
        I2D_REQUIRE(piles.size() == 1);
        const Bodies& pile = piles[0];
        const i2d_body_id a = pile[0], b = pile[1];
        const double y0 = position(b).y;
        if (shape_only) {
            const i2d_shape_id shape = only_shape(a);
            I2D_REQUIRE(!I2D_IS_NULL(shape));
            // A is left a 1 kg body without shapes: nothing of it can hold B.
            I2D_CHECK_STATUS(i2d_shape_destroy(shape), I2D_OK);
        } else {
            I2D_CHECK_STATUS(i2d_body_destroy(a), I2D_OK);
        }
        const bool b_awake = i2d_body_is_awake(b);
        const int n = steps_for(0.3);
        I2D_REQUIRE(scene.step(n));
        const double t = n * double(time_step);
        const double drop = y0 - position(b).y;
        I2D_REQUIRE(scene.step(steps_for(1.5) - n));
        const double y_end = position(b).y;
        fprintf(stderr,
                "    %s under a sleeping box: it is awake at once %d; dropped %.4f m in %.2f s (expected %.4f, %+.2f %%); "
                "rests at y %.4f\n",
                shape_only ? "destroying the shape" : "destroying the body", b_awake, drop, t, 0.5 * g * t * t,
                100 * (drop / (0.5 * g * t * t) - 1), y_end);
        I2D_CHECK(b_awake);
        I2D_CHECK_NEAR(drop, 0.5 * g * t * t, 0.03 * 0.5 * g * t * t);
        I2D_CHECK(y_end <= 0.5 + 1e-3 && y_end >= 0.5 - slop - 1e-3);
        report_case(before, shape_only ? "shape destroyed" : "body destroyed");
    }
}

I2D_TEST(phys_sleep_landing_body_wakes_pile) {
    // A box dropped from 2 m above a sleeping pile of 3 (its bottom 2 m above the pile's
    // top): creating it does not wake the pile, nor does its fall while it is more than
    // 0.5 m above the pile; the pile wakes when it lands, by the step after free fall
    // says it arrives (t = sqrt(2 h / g) = 0.632 s).
    Scene scene;
    const std::vector<Bodies> piles = sleeping_piles(scene, {0.0f}, 3);
    I2D_REQUIRE(piles.size() == 1);
    const Bodies& pile = piles[0];
    const double top = position(pile.back()).y + 0.5;
    const double h = 2.0;
    i2d_body_id falling = scene.dynamic_box(i2d_vec2{0, float(top + h + 0.5)}, 0.5f, 0.5f);
    I2D_REQUIRE(!I2D_IS_NULL(falling));
    const bool asleep_after_create = none_awake(pile);
    double woke_at = -1;
    int woke_early = 0;
    for (int s = 1; s <= steps_for(1.5); ++s) {
        I2D_REQUIRE(scene.step());
        const double gap = double(position(falling).y) - 0.5 - top;
        const bool awake = count_awake(pile) > 0;
        if (awake && woke_at < 0) {
            woke_at = s * double(time_step);
        }
        woke_early += (awake && gap > 0.5) ? 1 : 0;
    }
    const double t_hit = std::sqrt(2 * h / g);
    fprintf(stderr, "    box landing on a sleeping pile: asleep after create %d; woke at %.4f s (lands at %.4f s); %d "
                    "steps awake while > 0.5 m away\n",
            asleep_after_create, woke_at, t_hit, woke_early);
    I2D_CHECK(asleep_after_create);
    I2D_CHECK(woke_early == 0);
    I2D_CHECK(woke_at > 0 && woke_at <= t_hit + 2 * double(time_step));
}

I2D_TEST(phys_sleep_disabled_in_world) {
    // enable_sleep = false in the world def: a resting pile of 10 (a 4-row pyramid) stays awake for 3 s,
    // every step (awake count 10, no sleeping island). The same pile in a default world
    // sleeps within that time (so the setting, not the scene, keeps it awake).
    for (bool enabled : {false, true}) {
        i2d_world_def def = i2d_default_world_def();
        def.enable_sleep = enabled;
        Scene scene(def);
        I2D_REQUIRE(!I2D_IS_NULL(scene.ground(0.0f)));
        const Bodies pile = scene.pyramid(0.0f, 4);
        I2D_REQUIRE(all_valid(pile));
        int bad_steps = 0;
        for (int s = 0; s < steps_for(3.0); ++s) {
            I2D_REQUIRE(scene.step());
            const i2d_world_counters c = i2d_world_get_counters(scene.world);
            bad_steps += (c.awake_body_count != 10 || c.sleeping_island_count != 0 || !all_awake(pile)) ? 1 : 0;
        }
        fprintf(stderr, "    world enable_sleep %d: %d of %d steps with a body asleep; %d awake at the end\n", enabled,
                bad_steps, steps_for(3.0), count_awake(pile));
        if (enabled) {
            I2D_CHECK(none_awake(pile));
        } else {
            I2D_CHECK(bad_steps == 0);
        }
    }
}

I2D_TEST(phys_sleep_disabled_on_body) {
    // Body def enable_sleep = false on the bottom box of pile A keeps the whole pile (3)
    // awake for 3 s; pile B beside it, all defaults, falls asleep.
    Scene scene;
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground(0.0f)));
    i2d_body_def sleepless = body_def(I2D_BODY_DYNAMIC, i2d_vec2{-10.0f, 0.5f});
    sleepless.enable_sleep = false;
    const i2d_body_id bottom = scene.box(sleepless, 0.5f, 0.5f);
    const Bodies a = join(Bodies{bottom}, scene.column(-10.0f, 2, 1.0f));
    const Bodies b = scene.column(10.0f, 3);
    I2D_REQUIRE(a.size() == 3 && all_valid(a) && all_valid(b));
    int a_asleep_steps = 0;
    for (int s = 0; s < steps_for(3.0); ++s) {
        I2D_REQUIRE(scene.step());
        a_asleep_steps += all_awake(a) ? 0 : 1;
    }
    const i2d_world_counters c = i2d_world_get_counters(scene.world);
    fprintf(stderr, "    enable_sleep false on one body: its pile had a body asleep in %d steps; the other pile %d/3 "
                    "awake; counters %d awake, %d sleeping islands\n",
            a_asleep_steps, count_awake(b), c.awake_body_count, c.sleeping_island_count);
    I2D_CHECK(a_asleep_steps == 0);
    I2D_CHECK(none_awake(b));
    I2D_CHECK(c.awake_body_count == 3);
    I2D_CHECK(c.sleeping_island_count == 1);
}

I2D_TEST(phys_sleep_set_awake) {
    // i2d_body_set_awake(false) on a box falling in mid-air puts it to sleep at once: it
    // stays where it is, bitwise, for 0.5 s; set_awake(true) wakes it at once and it
    // falls again. On the bottom box of an awake resting pile, set_awake(false) puts the
    // whole pile to sleep at once, and set_awake(true) on its top box wakes all of it.
    // Static bodies are never awake and refuse set_awake(false).
    Scene scene;
    const i2d_body_id ground = scene.ground(0.0f);
    I2D_REQUIRE(!I2D_IS_NULL(ground));
    const i2d_body_id faller = scene.dynamic_box(i2d_vec2{-20, 30}, 0.5f, 0.5f);
    const Bodies pile = scene.column(0.0f, 4);
    I2D_REQUIRE(!I2D_IS_NULL(faller) && all_valid(pile));
    I2D_REQUIRE(scene.step(steps_for(0.2)));
    I2D_REQUIRE(i2d_body_is_awake(faller) && all_awake(pile));

    I2D_CHECK_STATUS(i2d_body_set_awake(faller, false), I2D_OK);
    const bool faller_asleep = !i2d_body_is_awake(faller);
    const Bodies faller_only{faller};
    const Snapshot frozen(faller_only);
    I2D_REQUIRE(scene.step(steps_for(0.5)));
    const int moved_asleep = frozen.differ(Snapshot(faller_only));
    const bool still_asleep = !i2d_body_is_awake(faller);
    I2D_CHECK_STATUS(i2d_body_set_awake(faller, true), I2D_OK);
    const bool faller_awake = i2d_body_is_awake(faller);
    const double y0 = position(faller).y;
    I2D_REQUIRE(scene.step(steps_for(0.2)));
    const double fell = y0 - position(faller).y;

    // The pile: awake at 0.7 s? It may have fallen asleep by itself (it rests from t = 0);
    // wake it first so that set_awake(false) is what puts it to sleep.
    I2D_CHECK_STATUS(i2d_body_set_awake(pile.back(), true), I2D_OK);
    const bool pile_woken = all_awake(pile);
    I2D_CHECK_STATUS(i2d_body_set_awake(pile.front(), false), I2D_OK);
    const int pile_awake_after_sleep = count_awake(pile);
    I2D_REQUIRE(scene.step());
    const int pile_awake_after_step = count_awake(pile);
    I2D_CHECK_STATUS(i2d_body_set_awake(pile.back(), true), I2D_OK);
    const int pile_awake_after_wake = count_awake(pile);

    const bool ground_awake = i2d_body_is_awake(ground);
    const i2d_status refused = i2d_body_set_awake(ground, false);
    fprintf(stderr,
            "    set_awake: faller asleep at once %d, moved while asleep %d, still asleep %d, awake at once %d, then fell "
            "%.4f m in 0.2 s; pile woken %d, %d/4 awake after set_awake(false), %d after a step, %d after "
            "set_awake(true); static awake %d, set_awake(false) on static: %s\n",
            faller_asleep, moved_asleep, still_asleep, faller_awake, fell, pile_woken, pile_awake_after_sleep,
            pile_awake_after_step, pile_awake_after_wake, ground_awake, i2d_status_string(refused));
    I2D_CHECK(faller_asleep);
    I2D_CHECK(moved_asleep == 0);
    I2D_CHECK(still_asleep);
    I2D_CHECK(faller_awake);
    I2D_CHECK(fell > 0.5 * g * 0.2 * 0.2 * 0.9);  // at least free fall from rest
    I2D_CHECK(pile_woken);
    I2D_CHECK(pile_awake_after_sleep == 0);
    I2D_CHECK(pile_awake_after_step == 0);
    I2D_CHECK(pile_awake_after_wake == 4);
    I2D_CHECK(!ground_awake);
    I2D_CHECK(refused == I2D_ERR_INVALID_ARGUMENT);
}

I2D_TEST(phys_sleep_speed_threshold) {
    // Lone bodies without gravity. With the default threshold 0.05 m/s: a box gliding at
    // 1 m/s or spinning at 1 rad/s (rim speed 0.71 m/s) stays awake for 2 s (and keeps
    // moving: 2 m), as does a kinematic box moving at 1 m/s; a box gliding at 0.02 m/s
    // or spinning at 0.02 rad/s (rim 0.014 m/s) is resting: it is still awake at 0.4 s,
    // asleep by 0.5 s + 2 steps. With sleep_speed_threshold = 2 m/s the 1 m/s box sleeps
    // by then too.
    for (float threshold : {0.0f, 2.0f}) {
        i2d_world_def def = Scene::zero_gravity_def();
        if (threshold > 0) {
            def.sleep_speed_threshold = threshold;
        }
        Scene scene(def);
        i2d_body_def spin_fast = body_def(I2D_BODY_DYNAMIC, i2d_vec2{0, 10});
        spin_fast.angular_velocity = 1.0f;
        i2d_body_def spin_slow = body_def(I2D_BODY_DYNAMIC, i2d_vec2{0, 20});
        spin_slow.angular_velocity = 0.02f;
        const i2d_body_id fast = scene.dynamic_box(i2d_vec2{0, 0}, 0.5f, 0.5f, Material{}, i2d_vec2{1, 0});
        const i2d_body_id slow = scene.dynamic_box(i2d_vec2{0, -10}, 0.5f, 0.5f, Material{}, i2d_vec2{0.02f, 0});
        const i2d_body_id spinner = scene.box(spin_fast, 0.5f, 0.5f);
        const i2d_body_id slow_spinner = scene.box(spin_slow, 0.5f, 0.5f);
        const i2d_body_id kin = scene.box(body_def(I2D_BODY_KINEMATIC, i2d_vec2{0, -20}, i2d_vec2{1, 0}), 0.5f, 0.5f);
        I2D_REQUIRE(!I2D_IS_NULL(fast) && !I2D_IS_NULL(slow) && !I2D_IS_NULL(spinner) && !I2D_IS_NULL(slow_spinner) &&
                    !I2D_IS_NULL(kin));
        const Bodies sleepy{slow, slow_spinner};
        I2D_REQUIRE(scene.step(steps_for(0.4)));
        const int sleepy_awake_early = count_awake(sleepy);
        I2D_REQUIRE(scene.step(steps_for(0.1) + 2));
        const int sleepy_awake = count_awake(sleepy);
        const bool fast_awake_mid = i2d_body_is_awake(fast);
        I2D_REQUIRE(scene.step(steps_for(2.0) - steps_for(0.5) - 2));
        const Bodies movers{fast, spinner, kin};
        const int movers_awake = count_awake(movers);
        const double fast_x = position(fast).x, kin_x = position(kin).x;
        const i2d_world_counters c = i2d_world_get_counters(scene.world);
        fprintf(stderr,
                "    sleep threshold %.2f m/s: slow bodies awake %d/2 at 0.4 s, %d/2 at 0.53 s; 1 m/s box awake %d at "
                "0.53 s; at 2 s movers awake %d/3 (box at x %.3f, kinematic at x %.3f); counter %d awake\n",
                double(def.sleep_speed_threshold), sleepy_awake_early, sleepy_awake, fast_awake_mid, movers_awake,
                fast_x, kin_x, c.awake_body_count);
        const int before = i2d_check_failures;
        I2D_CHECK(sleepy_awake_early == 2);
        I2D_CHECK(sleepy_awake == 0);
        // The counter agrees with the bodies.
        const Bodies all{fast, slow, spinner, slow_spinner, kin};
        I2D_CHECK(c.awake_body_count == count_awake(all));
        if (threshold == 0) {
            I2D_CHECK(movers_awake == 3);
            I2D_CHECK_NEAR(fast_x, 2.0, 1e-3);
            I2D_CHECK_NEAR(kin_x, 2.0, 1e-3);
        } else {
            // (Whether a kinematic body moving below this threshold may sleep is not
            // specified; it is not checked here.)
            I2D_CHECK(!fast_awake_mid);
            I2D_CHECK(!i2d_body_is_awake(fast) && !i2d_body_is_awake(spinner));
        }
        report_case(before, threshold > 0 ? "threshold 2 m/s" : "default threshold");
    }
}

I2D_TEST(phys_sleep_kinematic_support_wakes_pile) {
    // Two boxes (friction 1) rest on a kinematic platform (friction 0.25, so the contact
    // below mixes to sqrt(0.25 x 1) = 0.5) that does not move; they fall asleep. Giving
    // the platform a velocity of 1 m/s along x wakes them (by the next step). Friction
    // then drags the stack at mu g = 5 m/s^2 (the top box needs only 5 of the 10 m/s^2
    // its contact allows) until it moves with the platform after 0.2 s: 1 s after the
    // platform starts the boxes have moved 1 - 1 / (2 x 5) = 0.9 m (within 2 cm).
    Scene scene;
    i2d_body_id platform = scene.box(body_def(I2D_BODY_KINEMATIC, i2d_vec2{0, -0.5f}), 10.0f, 0.5f, with_friction(0.25f));
    I2D_REQUIRE(!I2D_IS_NULL(platform));
    const Bodies pile = scene.column(0.0f, 2, 0.0f, with_friction(1.0f));
    I2D_REQUIRE(all_valid(pile));
    const double t = wait_asleep(scene, pile, 3.0);
    const bool platform_awake = i2d_body_is_awake(platform);
    I2D_REQUIRE(t > 0);
    const double x0 = position(pile[0]).x, x1 = position(pile[1]).x;
    I2D_CHECK_STATUS(i2d_body_set_linear_velocity(platform, i2d_vec2{1, 0}), I2D_OK);
    const bool platform_awake_now = i2d_body_is_awake(platform);
    I2D_REQUIRE(scene.step());
    const int awake_after_step = count_awake(pile);
    I2D_REQUIRE(scene.step(steps_for(1.0) - 1));
    const double d0 = position(pile[0]).x - x0, d1 = position(pile[1]).x - x1;
    const double expected = 1.0 - 1.0 / (2 * 0.5 * g);
    fprintf(stderr,
            "    pile on a kinematic platform: asleep at %.3f s (platform awake %d); platform awake after set velocity "
            "%d; pile %d/2 awake after a step; moved %.4f and %.4f m in 1 s (expected %.4f)\n",
            t, platform_awake, platform_awake_now, awake_after_step, d0, d1, expected);
    I2D_CHECK(platform_awake_now);
    I2D_CHECK(awake_after_step == 2);
    I2D_CHECK_NEAR(d0, expected, 0.02);
    I2D_CHECK_NEAR(d1, expected, 0.02);
}

I2D_TEST(phys_sleep_island_splits_when_its_middle_goes) {
    // Three unit boxes side by side on the ground, touching (A | B | C), fall asleep as
    // one island. Destroying B wakes A and C, which no longer touch: they must fall
    // asleep again as two islands (the island is split once it wants to sleep), so that
    // an impulse on A (wake = true) wakes A alone and C stays bitwise still.
    Scene scene;
    I2D_REQUIRE(!I2D_IS_NULL(scene.ground(0.0f)));
    const i2d_body_id a = scene.dynamic_box(i2d_vec2{-1.0f, 0.5f}, 0.5f, 0.5f);
    const i2d_body_id b = scene.dynamic_box(i2d_vec2{0.0f, 0.5f}, 0.5f, 0.5f);
    const i2d_body_id c = scene.dynamic_box(i2d_vec2{1.0f, 0.5f}, 0.5f, 0.5f);
    I2D_REQUIRE(all_valid(Bodies{a, b, c}));
    I2D_REQUIRE(wait_asleep(scene, Bodies{a, b, c}, 3.0) > 0);
    const int islands_together = i2d_world_get_counters(scene.world).sleeping_island_count;
    I2D_CHECK_STATUS(i2d_body_destroy(b), I2D_OK);
    const bool woke = i2d_body_is_awake(a) && i2d_body_is_awake(c);
    const double asleep_after = wait_asleep(scene, Bodies{a, c}, 3.0);
    const int islands_apart = i2d_world_get_counters(scene.world).sleeping_island_count;
    const Snapshot c_before(Bodies{c});
    I2D_CHECK_STATUS(i2d_body_apply_linear_impulse(a, i2d_vec2{0, 1}, i2d_body_get_world_center_of_mass(a), true),
                     I2D_OK);
    I2D_REQUIRE(scene.step(steps_for(0.2)));
    const bool a_awake = i2d_body_is_awake(a), c_awake = i2d_body_is_awake(c);
    const int c_moved = c_before.differ(Snapshot(Bodies{c}), true);
    fprintf(stderr,
            "    A|B|C asleep as %d island(s); B destroyed: A and C woke %d, asleep again after %.3f s as %d "
            "island(s); impulse on A: A awake %d, C awake %d, C moved %d\n",
            islands_together, woke, asleep_after, islands_apart, a_awake, c_awake, c_moved);
    I2D_CHECK(islands_together == 1);
    I2D_CHECK(woke);
    I2D_CHECK(asleep_after > 0);
    I2D_CHECK(islands_apart == 2);
    I2D_CHECK(a_awake);
    I2D_CHECK(!c_awake);
    I2D_CHECK(c_moved == 0);
}
