// SPDX-License-Identifier: MIT
// A fixture for the physics validation scenes: a world, a ground, bodies in one line each.
//
// In the spirit of Jolt's PhysicsTestContext: tests build a scene in a few lines and
// step it at the engine's recommended rate, 1/60 s with 4 substeps, then compare with
// closed-form answers computed in the test itself.
#ifndef I2D_TESTS_PHYSICS_FIXTURE_HPP
#define I2D_TESTS_PHYSICS_FIXTURE_HPP

#include <impulse2d/impulse2d.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

#include "check.h"
#include "ragdoll.h"  // bench/: the scenes.md ragdoll, the same one the rain scene drops

namespace phys {

constexpr float time_step = 1.0f / 60.0f;
constexpr int substeps = 4;
constexpr double substep = double(time_step) / substeps;  // h in the integrator
constexpr double pi = 3.14159265358979323846;
/** m/s^2: the default world's downward pull (i2d_default_world_def), which the closed
 *  forms use where a scene keeps it. */
constexpr double g = 10.0;

/** Steps that make up `seconds` at time_step. */
inline int steps_for(double seconds) { return int(std::lround(seconds / time_step)); }

/** An angle given in degrees, in radians. */
constexpr double degrees(double d) { return d * pi / 180.0; }

/** An angle folded into (-pi, pi]. */
inline double wrap_angle(double a) {
    a = std::fmod(a, 2 * pi);
    if (a > pi) {
        a -= 2 * pi;
    } else if (a <= -pi) {
        a += 2 * pi;
    }
    return a;
}

/** The rotation by `angle` (rad), from the double cos and sin: the tests' own, apart from
 *  the engine's i2d_make_rot. */
inline i2d_rot rot(double angle) { return i2d_rot{float(std::cos(angle)), float(std::sin(angle))}; }

/** What a shape is made of. Defaults are the shape def's (density 1, friction 0.6,
 *  restitution 0). */
struct Material {
    float density = 1.0f;
    float restitution = 0.0f;
    float friction = 0.6f;
};

inline Material with_restitution(float e, float density = 1.0f) {
    Material m;
    m.restitution = e;
    m.density = density;
    return m;
}

inline Material with_friction(float mu) {
    Material m;
    m.friction = mu;
    return m;
}

inline Material with_density(float density) {
    Material m;
    m.density = density;
    return m;
}

inline Material material(float friction, float restitution, float density = 1.0f) {
    Material m;
    m.friction = friction;
    m.restitution = restitution;
    m.density = density;
    return m;
}

inline i2d_body_def body_def(i2d_body_type type, i2d_vec2 position, i2d_vec2 velocity = i2d_vec2{0, 0}) {
    i2d_body_def def = i2d_default_body_def();
    def.type = type;
    def.position = position;
    def.linear_velocity = velocity;
    return def;
}

/** A body def turned by `angle` (rad). */
inline i2d_body_def turned_body_def(i2d_body_type type, i2d_vec2 position, double angle,
                                    i2d_vec2 velocity = i2d_vec2{0, 0}) {
    i2d_body_def def = body_def(type, position, velocity);
    def.rotation = rot(angle);
    return def;
}

inline i2d_shape_def shape_def(const Material& m) {
    i2d_shape_def def = i2d_default_shape_def();
    def.density = m.density;
    def.restitution = m.restitution;
    def.friction = m.friction;
    return def;
}

/** A static slope: a box of half length `half_length` and half_thickness, turned by theta
 *  about the origin. Its top face is the line through n half_thickness along t,
 *  t = (cos, sin) uphill, n = (-sin, cos) its outward normal. */
struct Slope {
    double theta;
    double half_length;
    static constexpr double half_thickness = 0.25;
    double tx() const { return std::cos(theta); }
    double ty() const { return std::sin(theta); }
    double nx() const { return -std::sin(theta); }
    double ny() const { return std::cos(theta); }
    /** The point at distance s along the slope (uphill positive) and h above its top face. */
    i2d_vec2 at(double s, double h) const {
        const double up = half_thickness + h;
        return i2d_vec2{float(tx() * s + nx() * up), float(ty() * s + ny() * up)};
    }
    /** A point's distance along the slope from its middle, or a velocity's uphill part. */
    double along(i2d_vec2 v) const { return double(v.x) * tx() + double(v.y) * ty(); }
    /** A point's height above the top face. */
    double above(i2d_vec2 p) const { return double(p.x) * nx() + double(p.y) * ny() - half_thickness; }
};

/** A world that is destroyed with the fixture. Bodies come back null on failure, so
 *  tests I2D_REQUIRE them before use. */
class Scene {
public:
    explicit Scene(const i2d_world_def& def = i2d_default_world_def()) : world(i2d_world_create(&def)) {}
    ~Scene() {
        if (!I2D_IS_NULL(world)) {
            i2d_world_destroy(world);
        }
    }
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    /** The default world without gravity: isolated collisions. */
    static i2d_world_def zero_gravity_def() {
        i2d_world_def def = i2d_default_world_def();
        def.gravity = i2d_vec2{0, 0};
        return def;
    }

    /** `def` (the default world unless given) with sleep off: for scenes measured while
     *  their bodies move slowly or rest, which the world would rightly put to sleep. */
    static i2d_world_def no_sleep_def(i2d_world_def def = i2d_default_world_def()) {
        def.enable_sleep = false;
        return def;
    }

    /** A body with one box of the given half sizes centred on its origin. */
    i2d_body_id box(const i2d_body_def& def, float half_width, float half_height, const Material& m = Material{}) {
        i2d_body_id body = i2d_body_create(world, &def);
        i2d_shape_def sd = shape_def(m);
        if (I2D_IS_NULL(body) || I2D_IS_NULL(i2d_shape_create_box(body, &sd, half_width, half_height))) {
            fprintf(stderr, "    fixture: box creation failed: %s\n", i2d_last_error_message());
            return I2D_NULL_BODY_ID;
        }
        return body;
    }

    /** A body with one circle centred on its origin. */
    i2d_body_id circle(const i2d_body_def& def, float radius, const Material& m = Material{}) {
        i2d_body_id body = i2d_body_create(world, &def);
        i2d_shape_def sd = shape_def(m);
        i2d_circle c{i2d_vec2{0, 0}, radius};
        if (I2D_IS_NULL(body) || I2D_IS_NULL(i2d_shape_create_circle(body, &sd, &c))) {
            fprintf(stderr, "    fixture: circle creation failed: %s\n", i2d_last_error_message());
            return I2D_NULL_BODY_ID;
        }
        return body;
    }

    /** A static ground box, 1 m thick, whose top face is at y = top. */
    i2d_body_id ground(float top = 0.0f, float half_width = 50.0f, const Material& m = Material{}) {
        return box(body_def(I2D_BODY_STATIC, i2d_vec2{0, top - 0.5f}), half_width, 0.5f, m);
    }

    i2d_body_id dynamic_box(i2d_vec2 center, float half_width, float half_height, const Material& m = Material{},
                            i2d_vec2 velocity = i2d_vec2{0, 0}) {
        return box(body_def(I2D_BODY_DYNAMIC, center, velocity), half_width, half_height, m);
    }

    i2d_body_id dynamic_circle(i2d_vec2 center, float radius, const Material& m = Material{},
                               i2d_vec2 velocity = i2d_vec2{0, 0}) {
        return circle(body_def(I2D_BODY_DYNAMIC, center, velocity), radius, m);
    }

    /** A body of `type` turned by `angle` (rad) with one box centred on its origin. */
    i2d_body_id turned_box(i2d_body_type type, i2d_vec2 center, double angle, float half_width, float half_height,
                           const Material& m = Material{}, i2d_vec2 velocity = i2d_vec2{0, 0}) {
        return box(turned_body_def(type, center, angle, velocity), half_width, half_height, m);
    }

    /** The slope `s` as a static body. */
    i2d_body_id slope(const Slope& s, const Material& m = Material{}) {
        const float half_thickness = float(Slope::half_thickness);
        return turned_box(I2D_BODY_STATIC, i2d_vec2{0, 0}, s.theta, float(s.half_length), half_thickness, m);
    }

    /** `count` unit boxes stacked touching on whatever has its top at y = base, centred on
     *  x, bottom first; empty when one could not be made. */
    std::vector<i2d_body_id> column(float x, int count, float base = 0.0f, const Material& m = Material{}) {
        std::vector<i2d_body_id> boxes;
        for (int i = 0; i < count; ++i) {
            const i2d_body_id b = dynamic_box(i2d_vec2{x, base + 0.5f + float(i)}, 0.5f, 0.5f, m);
            if (I2D_IS_NULL(b)) {
                return {};
            }
            boxes.push_back(b);
        }
        return boxes;
    }

    /** A pyramid of unit boxes on whatever has its top at y = base, centred on x: rows of
     *  `rows`, rows - 1, ..., 1 boxes, each touching its neighbours, bottom row first;
     *  empty when one could not be made. */
    std::vector<i2d_body_id> pyramid(float x, int rows, float base = 0.0f) {
        std::vector<i2d_body_id> boxes;
        for (int row = 0; row < rows; ++row) {
            const int n = rows - row;
            for (int k = 0; k < n; ++k) {
                const i2d_vec2 center{x + float(k - 0.5 * (n - 1)), base + 0.5f + float(row)};
                const i2d_body_id b = dynamic_box(center, 0.5f, 0.5f);
                if (I2D_IS_NULL(b)) {
                    return {};
                }
                boxes.push_back(b);
            }
        }
        return boxes;
    }

    /** A static body without shapes: the world end of a joint (a pivot, a wall, a rail). */
    i2d_body_id anchor(i2d_vec2 position = i2d_vec2{0, 0}) {
        const i2d_body_def def = body_def(I2D_BODY_STATIC, position);
        return i2d_body_create(world, &def);
    }

    /** The scenes.md ragdoll (bench/ragdoll.c) standing with its feet 0.275 m above `spawn`;
     *  false (and a message) on failure. */
    bool ragdoll(i2d_vec2 spawn, int32_t group, bench_ragdoll* out) {
        const bench_ragdoll_def def = bench_default_ragdoll_def(spawn, group);
        if (!bench_ragdoll_create(world, &def, out)) {
            fprintf(stderr, "    fixture: ragdoll creation failed: %s\n", i2d_last_error_message());
            return false;
        }
        return true;
    }

    /** The world's downward pull, m/s^2 (10 by default). */
    double gravity() const { return -double(i2d_world_get_gravity(world).y); }

    /** One step of time_step with `substeps` substeps; false (and a message) on failure. */
    bool step() {
        i2d_status s = i2d_world_step(world, time_step, substeps);
        if (s != I2D_OK) {
            fprintf(stderr, "    fixture: step failed: %s (%s)\n", i2d_status_string(s), i2d_last_error_message());
            return false;
        }
        return true;
    }

    bool step(int count) {
        for (int i = 0; i < count; ++i) {
            if (!step()) {
                return false;
            }
        }
        return true;
    }

    i2d_world_id world;
};

inline i2d_vec2 position(i2d_body_id b) { return i2d_body_get_position(b); }
inline i2d_vec2 velocity(i2d_body_id b) { return i2d_body_get_linear_velocity(b); }
inline double speed(i2d_vec2 v) { return std::hypot(double(v.x), double(v.y)); }
inline double distance(i2d_vec2 a, i2d_vec2 b) { return std::hypot(double(a.x) - b.x, double(a.y) - b.y); }
inline bool same_bits(i2d_vec2 a, i2d_vec2 b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/** A body's angle (rad, in (-pi, pi]) by double atan2: apart from the engine's own
 *  i2d_rot_get_angle, which phys_rotmotion_make_rot_and_angle tests. */
inline double angle_of(i2d_body_id b) {
    const i2d_rot q = i2d_body_get_rotation(b);
    return std::atan2(double(q.s), double(q.c));
}

/** The body's only shape; null when it has none or more than one. */
inline i2d_shape_id only_shape(i2d_body_id body) {
    i2d_shape_id shape = I2D_NULL_SHAPE_ID;
    return i2d_body_get_shapes(body, &shape, 1) == 1 ? shape : I2D_NULL_SHAPE_ID;
}

/** How many of `bodies` are awake. */
inline int count_awake(const std::vector<i2d_body_id>& bodies) {
    int n = 0;
    for (const i2d_body_id b : bodies) {
        n += i2d_body_is_awake(b) ? 1 : 0;
    }
    return n;
}

/** A body's pose and velocities, compared bit for bit: a sleeping body and a
 *  deterministic step change nothing, not even by rounding. */
struct BodyState {
    i2d_transform transform;
    i2d_vec2 linear_velocity;
    float angular_velocity;

    static BodyState of(i2d_body_id b) {
        return BodyState{i2d_body_get_transform(b), i2d_body_get_linear_velocity(b), i2d_body_get_angular_velocity(b)};
    }
    bool same_pose(const BodyState& o) const { return std::memcmp(&transform, &o.transform, sizeof transform) == 0; }
    bool same_bits(const BodyState& o) const {
        return same_pose(o) && std::memcmp(&linear_velocity, &o.linear_velocity, sizeof linear_velocity) == 0 &&
               std::memcmp(&angular_velocity, &o.angular_velocity, sizeof angular_velocity) == 0;
    }
};

/** A point in double, for closed forms worked out apart from the engine's floats. */
struct Point {
    double x, y;
};

/** p + R(angle) l: where a body at p turned by `angle` has its local point l. */
inline Point transform_point(double px, double py, double angle, double lx, double ly) {
    return Point{px + std::cos(angle) * lx - std::sin(angle) * ly, py + std::sin(angle) * lx + std::cos(angle) * ly};
}

/** Closed-form masses: density x area. */
inline double box_mass(double half_width, double half_height, double density) {
    return density * 4.0 * half_width * half_height;
}
inline double circle_mass(double radius, double density) { return density * pi * radius * radius; }

/** Fills a joint def's base: bodies a and b joined at a world point (each body's local
 *  anchor is that point in its frame). Works for every kind's def. */
template <class JointDef>
JointDef& join_at(JointDef& def, i2d_body_id a, i2d_body_id b, i2d_vec2 world_point) {
    def.base.body_a = a;
    def.base.body_b = b;
    def.base.local_anchor_a = i2d_body_get_local_point(a, world_point);
    def.base.local_anchor_b = i2d_body_get_local_point(b, world_point);
    return def;
}

/** How far apart a joint's two anchors are in the world, m: 0 for a joint that holds. */
inline double joint_gap(i2d_joint_id joint) {
    const i2d_vec2 a = i2d_body_get_world_point(i2d_joint_get_body_a(joint), i2d_joint_get_local_anchor_a(joint));
    const i2d_vec2 b = i2d_body_get_world_point(i2d_joint_get_body_b(joint), i2d_joint_get_local_anchor_b(joint));
    return distance(a, b);
}

/** Translational plus rotational kinetic energy, J (velocity is that of the centre of mass). */
inline double kinetic_energy(i2d_body_id b) {
    const double v = speed(velocity(b)), w = double(i2d_body_get_angular_velocity(b));
    return 0.5 * double(i2d_body_get_mass(b)) * v * v + 0.5 * double(i2d_body_get_rotational_inertia(b)) * w * w;
}

/** Whether the body's pose and velocities are all finite numbers (a blown-up solver
 *  gives NaN or inf). */
inline bool is_finite(i2d_body_id b) {
    const i2d_transform xf = i2d_body_get_transform(b);
    const i2d_vec2 v = velocity(b);
    return std::isfinite(xf.p.x) && std::isfinite(xf.p.y) && std::isfinite(xf.q.c) && std::isfinite(xf.q.s) &&
           std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(i2d_body_get_angular_velocity(b));
}

/** The deepest penetration of a manifold's points (-inf with none). */
inline double deepest_penetration(const i2d_manifold& m) {
    double deepest = -INFINITY;
    for (int i = 0; i < m.point_count && i < 2; ++i) {
        deepest = std::max(deepest, double(m.points[i].penetration));
    }
    return deepest;
}

/** Running min/max of a value over a time window. */
struct Range {
    double lo = INFINITY, hi = -INFINITY;
    void add(double v) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    double width() const { return hi - lo; }
    double abs_max() const { return std::max(std::fabs(lo), std::fabs(hi)); }
};

/** splitmix64: a fixed seed gives the same numbers on every platform. */
struct SplitMix64 {
    uint64_t state;
    uint64_t next() {
        uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    /** Uniform in [lo, hi) from 53 random bits. */
    double uniform(double lo, double hi) { return lo + (hi - lo) * double(next() >> 11) * (1.0 / 9007199254740992.0); }
    /** Uniform in [lo, hi) from 24 random bits, a float's worth. */
    float uniform_float(float lo, float hi) { return lo + (hi - lo) * float(next() >> 40) / float(1u << 24); }
    int below(int n) { return int(next() % uint64_t(n)); }
};

/** A sampled oscillation x(t) about 0: the times it crosses 0 going up (interpolated
 *  between samples) and its extremes between crossings, for periods and decay. */
class Oscillation {
public:
    void add(double t, double x) {
        if (has_last_ && last_x_ < 0.0 && x >= 0.0) {
            up_crossings.push_back(last_t_ + (t - last_t_) * (-last_x_) / (x - last_x_));
        }
        if (has_last_ && (last_x_ < 0.0) != (x < 0.0)) {
            if (has_extreme_) {
                extremes.push_back(extreme_);
            }
            extreme_ = x;
            has_extreme_ = true;
        } else if (has_extreme_ && std::fabs(x) > std::fabs(extreme_)) {
            extreme_ = x;
        }
        last_t_ = t;
        last_x_ = x;
        has_last_ = true;
    }
    /** Mean period over the whole upward crossings seen; 0 with fewer than two. */
    double period() const {
        const size_t n = up_crossings.size();
        return n < 2 ? 0.0 : (up_crossings[n - 1] - up_crossings[0]) / double(n - 1);
    }
    std::vector<double> up_crossings;
    std::vector<double> extremes;  // one per completed half cycle, signed, in order

private:
    double last_t_ = 0.0, last_x_ = 0.0, extreme_ = 0.0;
    bool has_last_ = false, has_extreme_ = false;
};

/** Prints the scenario when checks failed since `failures_before`, so a failure inside a
 *  loop over cases says which case it was. */
inline void report_case(int failures_before, const char* what) {
    if (i2d_check_failures != failures_before) {
        fprintf(stderr, "    ... in case: %s\n", what);
    }
}

}  // namespace phys

#endif
