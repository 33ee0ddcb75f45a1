// SPDX-License-Identifier: MIT
// i2d_world_cast_mover, i2d_world_collide_mover, i2d_solve_planes, i2d_clip_vector,
// i2d_default_character_def and i2d_world_move_character: the character mover, checked at
// the boundary (toolkit.h).
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <vector>

#include <impulse2d/toolkit.h>

#include "boundary.hpp"
#include "collision/mover_planes.hpp"
#include "convert.hpp"
#include "dynamics/mover/character_mover.hpp"
#include "limits.hpp"
#include "math/math.hpp"

using namespace i2d;
using namespace i2d::capi;

namespace {

/// A plane's normal must have a length within this of 1 (as a rotation's must): looser
/// input is more likely a bug than rounding. It is used as given.
constexpr float plane_normal_tolerance = 1.0e-3f;

/// Planes the plane calls convert on the stack; more go to the heap.
constexpr int32_t stack_planes = 32;

// A mover in world space: centres within the coordinate range, a radius a shape could have.
bool valid_mover(Call& call, const i2d_capsule* mover, const char* what) {
    return call.not_null(mover, what) && call.coordinate(mover->center1, what) &&
           call.coordinate(mover->center2, what) && call.extent(mover->radius, what);
}

// The character's capsule in its own frame: centres as a shape's in its body's frame.
bool valid_local_capsule(Call& call, const i2d_capsule* capsule) {
    return call.not_null(capsule, "capsule") && call.local_point(capsule->center1, "capsule center1") &&
           call.local_point(capsule->center2, "capsule center2") && call.extent(capsule->radius, "capsule radius");
}

bool valid_plane(Call& call, const i2d_collision_plane& p, int32_t index) {
    char what[48], normal[64], offset[64], push_limit[64];
    std::snprintf(what, sizeof what, "planes[%d]", static_cast<int>(index));
    std::snprintf(normal, sizeof normal, "%s.plane.normal", what);
    std::snprintf(offset, sizeof offset, "%s.plane.offset", what);
    std::snprintf(push_limit, sizeof push_limit, "%s.push_limit", what);
    if (!call.finite(p.plane.normal, normal) ||
        !call.in_range(p.plane.offset, -max_coordinate, max_coordinate, offset) ||
        !call.in_range(p.push_limit, 0.0f, FLT_MAX, push_limit)) {
        return false;
    }
    const float length_sq = p.plane.normal.x * p.plane.normal.x + p.plane.normal.y * p.plane.normal.y;
    if (!(std::fabs(length_sq - 1.0f) <= plane_normal_tolerance)) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "%s normal (%g, %g) is not unit length", what,
                         static_cast<double>(p.plane.normal.x), static_cast<double>(p.plane.normal.y));
    }
    return true;
}

bool valid_planes(Call& call, const i2d_collision_plane* planes, int32_t count) {
    if (count < 0 || (count > 0 && planes == nullptr)) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "planes is NULL or count (%d) is negative", static_cast<int>(count));
    }
    for (int32_t i = 0; i < count; ++i) {
        if (!valid_plane(call, planes[i], i)) {
            return false;
        }
    }
    return true;
}

// The caller's planes as the core's, on the stack when they are few.
class CorePlanes {
public:
    CorePlanes(const i2d_collision_plane* planes, int32_t count) : count_(count) {
        if (count > stack_planes) {
            heap_.resize(static_cast<std::size_t>(count));
        }
        CollisionPlane* out = data();
        for (int32_t i = 0; i < count; ++i) {
            out[i].plane = Plane{to_core(planes[i].plane.normal), planes[i].plane.offset};
            out[i].push_limit = planes[i].push_limit;
            out[i].push = planes[i].push;
            out[i].clip_velocity = planes[i].clip_velocity;
        }
    }
    CollisionPlane* data() { return count_ > stack_planes ? heap_.data() : stack_; }

private:
    int32_t count_;
    CollisionPlane stack_[stack_planes];
    std::vector<CollisionPlane> heap_;
};

bool valid_character_def(Call& call, const i2d_character_def* def) {
    if (!call.not_null(def, "def") || !call.cookie(def->internal_cookie, "character_def")) {
        return false;
    }
    if (!(def->max_slope_angle >= 0.0f && def->max_slope_angle < 0.5f * pi)) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%g", static_cast<double>(def->max_slope_angle));
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "def max_slope_angle is %s; it must be in [0, pi/2) rad", buffer);
    }
    if (!call.in_range(def->step_height, 0.0f, max_shape_extent, "def step_height") ||
        !call.in_range(def->snap_distance, 0.0f, max_shape_extent, "def snap_distance") ||
        !call.in_range(def->push_mass, 0.0f, max_mass, "def push_mass")) {
        return false;
    }
    if (!(def->skin > 0.0f && def->skin <= max_shape_extent)) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "def skin is %g; it must be in (0, %g]", static_cast<double>(def->skin),
                         static_cast<double>(max_shape_extent));
    }
    if (def->max_iterations < 1 || def->max_iterations > 64) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "def max_iterations is %d; it must be in [1, 64]",
                         static_cast<int>(def->max_iterations));
    }
    return true;
}

CharacterDef to_core(const i2d_character_def& def) {
    CharacterDef core;
    core.max_slope_angle = def.max_slope_angle;
    core.step_height = def.step_height;
    core.snap_distance = def.snap_distance;
    core.skin = def.skin;
    core.max_iterations = def.max_iterations;
    core.push_mass = def.push_mass;
    core.filter = capi::to_core(def.filter);
    return core;
}

// The move: a finite velocity that a time step within range takes no farther than a cast goes.
bool valid_move(Call& call, i2d_vec2 velocity, float time_step) {
    if (!call.finite(velocity, "velocity") || !call.in_range(time_step, 0.0f, max_time_step, "time_step")) {
        return false;
    }
    const double reach = std::hypot(double(velocity.x), double(velocity.y)) * double(time_step);
    if (reach > double(max_cast_length)) {
        return call.fail(I2D_ERR_INVALID_ARGUMENT, "velocity * time_step is %g long; a move goes at most %g", reach,
                         static_cast<double>(max_cast_length));
    }
    return true;
}

}  // namespace

I2D_API float i2d_world_cast_mover(i2d_world_id world, const i2d_capsule* mover, i2d_vec2 translation,
                                   i2d_query_filter filter) {
    return guarded("i2d_world_cast_mover", 0.0f, [&](Call& call) {
        WorldRef w;
        if (!call.world(world, w) || !valid_mover(call, mover, "mover") ||
            !call.cast_translation(translation, "translation")) {
            return 0.0f;
        }
        return w.world->cast_mover(capi::to_core(*mover), to_core(translation), capi::to_core(filter));
    });
}

I2D_API int32_t i2d_world_collide_mover(i2d_world_id world, const i2d_capsule* mover, i2d_query_filter filter,
                                        i2d_collision_plane* out, int32_t capacity) {
    return guarded("i2d_world_collide_mover", int32_t(0), [&](Call& call) -> int32_t {
        WorldRef w;
        if (!call.world(world, w) || !valid_mover(call, mover, "mover")) {
            return 0;
        }
        if (capacity < 0 || (capacity > 0 && out == nullptr)) {
            call.fail(I2D_ERR_INVALID_ARGUMENT, "out is NULL or capacity (%d) is negative", static_cast<int>(capacity));
            return 0;
        }
        int32_t total = 0;
        w.world->collide_mover(capi::to_core(*mover), capi::to_core(filter), [&](int32_t, const MoverContact& c) {
            if (total < capacity) {
                out[total] = i2d_collision_plane{i2d_plane{to_public(c.normal), c.separation}, FLT_MAX, 0.0f, true};
            }
            ++total;
        });
        return total;
    });
}

I2D_API i2d_plane_result i2d_solve_planes(i2d_vec2 target_delta, i2d_collision_plane* planes, int32_t count) {
    return guarded("i2d_solve_planes", i2d_plane_result{}, [&](Call& call) {
        if (!call.cast_translation(target_delta, "target_delta") || !valid_planes(call, planes, count)) {
            return i2d_plane_result{};
        }
        CorePlanes core(planes, count);
        const PlaneSolution solution = solve_planes(to_core(target_delta), core.data(), count);
        for (int32_t i = 0; i < count; ++i) {
            planes[i].push = core.data()[i].push;
        }
        return i2d_plane_result{to_public(solution.translation), solution.iteration_count};
    });
}

I2D_API i2d_vec2 i2d_clip_vector(i2d_vec2 vector, const i2d_collision_plane* planes, int32_t count) {
    return guarded("i2d_clip_vector", i2d_vec2{0.0f, 0.0f}, [&](Call& call) {
        if (!call.cast_translation(vector, "vector") || !valid_planes(call, planes, count)) {
            return i2d_vec2{0.0f, 0.0f};
        }
        CorePlanes core(planes, count);
        return to_public(clip_vector(to_core(vector), core.data(), count));
    });
}

// Here rather than in defaults.cpp: the character def belongs to the mover, whose rules
// (valid_character_def) sit beside it.
I2D_API i2d_character_def i2d_default_character_def(void) {
    set_ok();
    const CharacterDef core;
    i2d_character_def def{};
    def.max_slope_angle = core.max_slope_angle;
    def.step_height = core.step_height;
    def.snap_distance = core.snap_distance;
    def.skin = core.skin;
    def.max_iterations = core.max_iterations;
    def.push_mass = core.push_mass;
    def.filter = i2d_query_filter{core.filter.category_bits, core.filter.mask_bits};
    def.internal_cookie = def_cookie;
    return def;
}

I2D_API i2d_status i2d_world_move_character(i2d_world_id world, const i2d_character_def* def,
                                            const i2d_capsule* capsule, i2d_vec2 position, i2d_vec2 velocity,
                                            float time_step, i2d_character_result* out) {
    if (out != nullptr) {
        *out = i2d_character_result{};
    }
    return guarded("i2d_world_move_character", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!call.world(world, w) || !call.not_null(out, "out") || !valid_character_def(call, def)) {
            return last_status();
        }
        // Pushing changes the world, which a query callback must not; a move that pushes
        // nothing is a query.
        if ((def->push_mass > 0.0f && !call.unlocked(*w.world)) || !valid_local_capsule(call, capsule) ||
            !call.coordinate(position, "position") || !valid_move(call, velocity, time_step)) {
            return last_status();
        }
        const CharacterResult r = move_character(*w.world, to_core(*def), capi::to_core(*capsule), to_core(position),
                                                 to_core(velocity), time_step);
        out->position = to_public(r.position);
        out->velocity = to_public(r.velocity);
        out->on_ground = r.on_ground;
        out->ground_normal = to_public(r.ground_normal);
        if (r.ground_shape != null_index) {
            out->ground_shape = make_shape_id(w.id, r.ground_shape, w.world->shapes().generation(r.ground_shape));
        }
        out->ground_velocity = to_public(r.ground_velocity);
        out->hit_count = r.hit_count;
        return I2D_OK;
    });
}
