// SPDX-License-Identifier: MIT
// Soak: a churning scene stepped for a long time through the public API. Bodies and
// shapes of every kind are created and destroyed, filters and materials changed, impulses
// applied, queries run and events read, every step, from a fixed seed. Every live body
// must stay finite, the world's counters must match what the test holds, and the
// process's memory must stop growing once the population has reached its largest size.
#include <impulse2d/impulse2d.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <vector>

#include "check.h"
#include "physics_fixture.hpp"

namespace {

using Rng = phys::SplitMix64;

// Memory the process holds, in KiB, or -1 where it cannot be read (or a sanitizer's
// allocator makes it meaningless). With glibc, what malloc has handed out and not had
// back: the library's and the test's own allocations, which is what a leak grows, and not
// what the kernel or an emulator adds (under qemu, resident memory also counts the
// emulator's cache of translated code, which grew by 2 MiB when new code first ran late in
// the soak). Elsewhere on Linux, resident memory.
long resident_kib() {
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33)) && \
    !defined(__SANITIZE_ADDRESS__)
    const struct mallinfo2 m = mallinfo2();
    return long((m.uordblks + m.hblkhd) / 1024);
#elif defined(__linux__) && !defined(__SANITIZE_ADDRESS__)
    std::FILE* f = std::fopen("/proc/self/statm", "r");
    if (f == nullptr) {
        return -1;
    }
    long pages = 0, resident = 0;
    const int read = std::fscanf(f, "%ld %ld", &pages, &resident);
    std::fclose(f);
    return read == 2 ? resident * 4 : -1;
#else
    return -1;
#endif
}

constexpr int max_population = 90;

class ChurningScene {
public:
    explicit ChurningScene(uint64_t seed) : rng_{seed} {
        i2d_world_def def = i2d_default_world_def();
        world_ = i2d_world_create(&def);
        i2d_body_def ground_def = i2d_default_body_def();
        const i2d_body_id ground = i2d_body_create(world_, &ground_def);
        i2d_shape_def shape = i2d_default_shape_def();
        i2d_shape_create_box(ground, &shape, 30.0f, 0.5f);
        // Walls keep the pile in the box so that it stays busy.
        i2d_shape_create_offset_box(ground, &shape, 0.5f, 20.0f, i2d_vec2{-30.0f, 20.0f}, i2d_rot{1.0f, 0.0f});
        i2d_shape_create_offset_box(ground, &shape, 0.5f, 20.0f, i2d_vec2{30.0f, 20.0f}, i2d_rot{1.0f, 0.0f});
        sensor_body_ = i2d_body_create(world_, &ground_def);
        i2d_shape_def sensor = i2d_default_shape_def();
        sensor.is_sensor = true;
        sensor.enable_sensor_events = true;
        i2d_shape_create_box(sensor_body_, &sensor, 5.0f, 3.0f);
    }
    ~ChurningScene() { i2d_world_destroy(world_); }

    bool valid() const { return i2d_world_is_valid(world_); }

    // One step: a few random changes, the step, then queries and events.
    void step() {
        const int changes = 1 + rng_.below(4);
        for (int k = 0; k < changes; ++k) {
            change();
        }
        if (i2d_world_step(world_, phys::time_step, phys::substeps) != I2D_OK) {
            ++i2d_check_failures;
            std::fprintf(stderr, "step failed: %s\n", i2d_last_error_message());
        }
        query();
        read_events();
    }

    // Every held body finite and the world's counts what the test holds.
    int check(const char* when) {
        int bad = 0;
        for (const i2d_body_id b : bodies_) {
            bad += phys::is_finite(b) ? 0 : 1;
        }
        const i2d_world_counters counters = i2d_world_get_counters(world_);
        if (bad > 0 || counters.body_count != int32_t(bodies_.size()) + 2) {
            ++i2d_check_failures;
            std::fprintf(stderr, "%s: %d non-finite bodies; world counts %d bodies, the test holds %zu + 2\n", when,
                         bad, int(counters.body_count), bodies_.size());
        }
        return bad;
    }

    int population() const { return int(bodies_.size()); }

private:
    void change() {
        const int action = rng_.below(10);
        if (bodies_.size() < 20 || (action < 3 && bodies_.size() < size_t(max_population))) {
            create_body();
        } else if (action < 5) {
            destroy_body();
        } else if (action == 5) {
            add_or_remove_shape();
        } else if (action == 6) {
            change_filter();
        } else if (action == 7) {
            const i2d_body_id b = pick();
            i2d_body_apply_linear_impulse(b, i2d_vec2{rng_.uniform_float(-5, 5), rng_.uniform_float(0, 10)},
                                          i2d_body_get_world_center_of_mass(b), true);
        } else if (action == 8) {
            i2d_shape_id shapes[4];
            const int32_t n = i2d_body_get_shapes(pick(), shapes, 4);
            if (n > 0) {
                i2d_shape_set_friction(shapes[0], rng_.uniform_float(0, 1));
                i2d_shape_set_restitution(shapes[0], rng_.uniform_float(0, 0.5f));
            }
        } else {
            const i2d_body_id b = pick();
            i2d_body_set_awake(b, rng_.below(2) == 0);
        }
    }

    i2d_body_id pick() { return bodies_[size_t(rng_.below(int(bodies_.size())))]; }

    void create_body() {
        i2d_body_def def = i2d_default_body_def();
        def.type = rng_.below(12) == 0 ? I2D_BODY_KINEMATIC : I2D_BODY_DYNAMIC;
        def.position = i2d_vec2{rng_.uniform_float(-25, 25), rng_.uniform_float(2, 30)};
        def.rotation = i2d_make_rot(rng_.uniform_float(-3.1f, 3.1f));
        def.angular_velocity = def.type == I2D_BODY_KINEMATIC ? rng_.uniform_float(-1, 1) : 0.0f;
        const i2d_body_id b = i2d_body_create(world_, &def);
        if (I2D_IS_NULL(b)) {
            ++i2d_check_failures;
            return;
        }
        add_shape(b);
        bodies_.push_back(b);
    }

    void add_shape(i2d_body_id b) {
        i2d_shape_def def = i2d_default_shape_def();
        def.density = rng_.uniform_float(0.5f, 3.0f);
        def.restitution = rng_.uniform_float(0, 0.3f);
        const float size = rng_.uniform_float(0.2f, 0.8f);
        const i2d_vec2 offset{rng_.uniform_float(-0.3f, 0.3f), rng_.uniform_float(-0.3f, 0.3f)};
        switch (rng_.below(5)) {
            case 0: {
                const i2d_circle c{offset, size};
                i2d_shape_create_circle(b, &def, &c);
                break;
            }
            case 1: i2d_shape_create_box(b, &def, size, size * rng_.uniform_float(0.3f, 1.0f)); break;
            case 2: i2d_shape_create_capsule(b, &def, i2d_vec2{-size, 0}, i2d_vec2{size, 0}, size * 0.4f); break;
            case 3: {
                i2d_vec2 points[6];
                for (int i = 0; i < 6; ++i) {
                    const i2d_rot q = i2d_make_rot(float(i) * 1.047f + rng_.uniform_float(-0.3f, 0.3f));
                    points[i] = i2d_vec2{offset.x + size * q.c, offset.y + size * q.s};
                }
                i2d_shape_create_polygon(b, &def, points, 6);
                break;
            }
            default:
                i2d_shape_create_offset_box(b, &def, size, size * 0.5f, offset, i2d_make_rot(rng_.uniform_float(0, 3)));
                break;
        }
    }

    void destroy_body() {
        const size_t k = size_t(rng_.below(int(bodies_.size())));
        i2d_body_destroy(bodies_[k]);
        bodies_[k] = bodies_.back();
        bodies_.pop_back();
    }

    void add_or_remove_shape() {
        const i2d_body_id b = pick();
        i2d_shape_id shapes[4];
        const int32_t n = i2d_body_get_shapes(b, shapes, 4);
        if (n > 1 && rng_.below(2) == 0) {
            i2d_shape_destroy(shapes[rng_.below(n < 4 ? n : 4)]);
        } else if (n < 4) {
            add_shape(b);
        }
    }

    // Groups and masks that exclude some pairs, then include them again.
    void change_filter() {
        i2d_shape_id shapes[4];
        const int32_t n = i2d_body_get_shapes(pick(), shapes, 4);
        if (n == 0) {
            return;
        }
        i2d_filter f = i2d_default_filter();
        f.category_bits = uint64_t(1) << rng_.below(4);
        f.mask_bits = rng_.below(3) == 0 ? ~uint64_t(2) : ~uint64_t(0);
        f.group_index = rng_.below(4) - 1;
        i2d_shape_set_filter(shapes[0], f);
    }

    static bool count_overlap(i2d_shape_id, void* context) {
        ++*static_cast<int*>(context);
        return true;
    }

    void query() {
        const i2d_vec2 c{rng_.uniform_float(-25, 25), rng_.uniform_float(0, 20)};
        i2d_shape_id found[32];
        i2d_world_overlap_aabb_ids(world_, i2d_aabb{{c.x - 3, c.y - 3}, {c.x + 3, c.y + 3}},
                                   i2d_default_query_filter(), found, 32);
        int touched = 0;
        i2d_world_overlap_point(world_, c, i2d_default_query_filter(), count_overlap, &touched);
        const i2d_ray_result hit =
            i2d_world_cast_ray_closest(world_, i2d_vec2{c.x, 40}, i2d_vec2{0, -45}, i2d_default_query_filter());
        if (hit.hit && !(std::isfinite(hit.point.x) && std::isfinite(hit.point.y))) {
            ++i2d_check_failures;
        }
    }

    void read_events() {
        const i2d_contact_events contacts = i2d_world_get_contact_events(world_);
        for (int32_t i = 0; i < contacts.begin_count; ++i) {
            events_seen_ += i2d_shape_is_valid(contacts.begin_events[i].shape_a) ? 1 : 0;
        }
        const i2d_sensor_events sensors = i2d_world_get_sensor_events(world_);
        events_seen_ += sensors.begin_count + sensors.end_count;
        const i2d_body_events moves = i2d_world_get_body_events(world_);
        for (int32_t i = 0; i < moves.move_count; ++i) {
            if (!std::isfinite(moves.move_events[i].transform.p.x)) {
                ++i2d_check_failures;
            }
        }
    }

    Rng rng_;
    i2d_world_id world_{};
    i2d_body_id sensor_body_{};
    std::vector<i2d_body_id> bodies_;
    long events_seen_ = 0;
};

// Runs `steps` steps; memory is sampled once the population has been at its largest for
// a while (a tenth of the run) and at the end: growth beyond 1 MiB is a leak.
void run_soak(int steps, uint64_t seed) {
    ChurningScene scene(seed);
    I2D_REQUIRE(scene.valid());
    const int settle = steps / 10;
    long resident_after_settle = -1;
    for (int s = 0; s < steps; ++s) {
        scene.step();
        if (s % 500 == 499 && scene.check("soak") > 0) {
            return;
        }
        if (s == settle) {
            resident_after_settle = resident_kib();
        }
    }
    scene.check("end of soak");
    const long resident_at_end = resident_kib();
    std::printf("soak: %d steps, %d bodies at the end, memory held %ld KiB after %d steps, %ld KiB at the end\n",
                steps, scene.population(), resident_after_settle, settle, resident_at_end);
    if (resident_after_settle > 0 && resident_at_end > 0) {
        I2D_CHECK(resident_at_end - resident_after_settle <= 1024);
    }
}

}  // namespace

I2D_TEST(phys_soak_churn) { run_soak(3000, 18); }

I2D_TEST(phys_soak_churn_long_100k) { run_soak(100000, 1018); }
