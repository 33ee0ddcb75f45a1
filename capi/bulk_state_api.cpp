// SPDX-License-Identifier: MIT
// i2d_world_get/set_body_*: the state of many bodies per call, for bindings that would
// otherwise cross the boundary once per body per frame.
//
// Every call checks all of its input before it writes anything (ids first, then values),
// so a refused call leaves both the caller's arrays and the world as they were. The
// writes then go through the same World setters as the per-body calls, so waking and
// the rules for static and fixed-rotation bodies are the same.
#include <cmath>
#include <cstdio>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "boundary.hpp"
#include "bulk_checks.hpp"
#include "convert.hpp"
#include "limits.hpp"
#include "geometry_checks.hpp"
#include "registry.hpp"

using namespace i2d;
using namespace i2d::capi;

namespace {

// Names a refused id by its place in the caller's array.
bool explain_bad_body(Call& call, const WorldRef& w, i2d_body_id id, int32_t position) {
    if (id.bits == 0) {
        return call.fail(I2D_ERR_INVALID_HANDLE, "bodies[%d] is the null id", position);
    }
    const IdFields f = decode_id(id.bits);
    if (f.kind != IdKind::body) {
        return call.fail(I2D_ERR_INVALID_HANDLE, "bodies[%d] (0x%016llx) is not a body id", position,
                         static_cast<unsigned long long>(id.bits));
    }
    if (f.world_slot != w.id.world_slot || f.world_generation != w.id.world_generation) {
        return find_world(f.world_slot, f.world_generation) == nullptr
                   ? call.fail(I2D_ERR_INVALID_HANDLE, "bodies[%d]: the body's world was destroyed", position)
                   : call.fail(I2D_ERR_INVALID_HANDLE, "bodies[%d] belongs to another world", position);
    }
    return call.fail(I2D_ERR_INVALID_HANDLE, "bodies[%d] is stale: the body was destroyed", position);
}

// The body's slot when the id names a live body of this world (the fast path every id
// of a good call takes: no registry lookup).
inline int32_t body_slot(const WorldRef& w, i2d_body_id id) {
    const IdFields f = decode_id(id.bits);
    const bool ours = id.bits != 0 && f.kind == IdKind::body && f.world_slot == w.id.world_slot &&
                      f.world_generation == w.id.world_generation && w.world->bodies().is_live(f.index, f.generation);
    return ours ? f.index : -1;
}

// The slot of an id that valid_bodies accepted: its index field, without checking again.
inline int32_t checked_slot(i2d_body_id id) { return decode_id(id.bits).index; }

// The world, a sane count and array, and every id live in that world.
bool valid_bodies(Call& call, i2d_world_id world_id, const i2d_body_id* bodies, int32_t count, WorldRef& w) {
    if (!call.world(world_id, w) || !valid_count(call, count, bodies, "bodies")) {
        return false;
    }
    for (int32_t i = 0; i < count; ++i) {
        if (body_slot(w, bodies[i]) < 0) {
            return explain_bad_body(call, w, bodies[i], i);
        }
    }
    return true;
}

// The per-body rules of i2d_body_set_transform, without formatting anything for a good
// element: a finite position within range and a rotation close enough to unit length.
bool plausible_transform(const i2d_transform& xf) {
    const float length_sq = xf.q.c * xf.q.c + xf.q.s * xf.q.s;
    return std::isfinite(xf.p.x) && std::isfinite(xf.p.y) && std::fabs(xf.p.x) <= max_coordinate &&
           std::fabs(xf.p.y) <= max_coordinate && std::isfinite(xf.q.c) && std::isfinite(xf.q.s) &&
           std::fabs(length_sq - 1.0f) <= rotation_normalization_tolerance;
}

bool valid_transforms(Call& call, int32_t count, const i2d_transform* in) {
    for (int32_t i = 0; i < count; ++i) {
        Rot unused;
        if (!plausible_transform(in[i]) && (!call.coordinate(in[i].p, ElementName("transforms", i).text) ||
                                            !normalized_rotation(call, in[i].q, ElementName("transforms", i).text, unused))) {
            return false;
        }
    }
    return true;
}

// The transforms of a write that valid_transforms accepted, rotations normalised as
// normalize() does it: c / len and s / len with len = sqrt(c * c + s * s), never 0 here.
// The square root and the two divisions were most of the write's own cost; SSE2 does
// them four bodies at a time, correctly rounded like the scalar instructions, so the
// bits are the same.
void normalized_transforms(const i2d_transform* in, int32_t n, Transform* out) {
    static_assert(sizeof(i2d_transform) == 4 * sizeof(float) && sizeof(Transform) == 4 * sizeof(float),
                  "a transform is one row of four floats: x, y, c, s");
    int32_t i = 0;
#if defined(__SSE2__)
    for (; i + 4 <= n; i += 4) {
        const float* rows = reinterpret_cast<const float*>(in + i);
        __m128 x = _mm_loadu_ps(rows), y = _mm_loadu_ps(rows + 4), c = _mm_loadu_ps(rows + 8),
               s = _mm_loadu_ps(rows + 12);
        _MM_TRANSPOSE4_PS(x, y, c, s);  // now lanes of bodies: all x, all y, all c, all s
        const __m128 length = _mm_sqrt_ps(_mm_add_ps(_mm_mul_ps(c, c), _mm_mul_ps(s, s)));
        c = _mm_div_ps(c, length);
        s = _mm_div_ps(s, length);
        _MM_TRANSPOSE4_PS(x, y, c, s);
        float* out_rows = reinterpret_cast<float*>(out + i);
        _mm_storeu_ps(out_rows, x);
        _mm_storeu_ps(out_rows + 4, y);
        _mm_storeu_ps(out_rows + 8, c);
        _mm_storeu_ps(out_rows + 12, s);
    }
#endif
    for (; i < n; ++i) {
        out[i] = Transform{capi::to_core(in[i].p), normalize(capi::to_core(in[i].q))};
    }
}

}  // namespace

I2D_API i2d_status i2d_world_get_body_transforms(i2d_world_id world_id, const i2d_body_id* bodies, int32_t count,
                                                 i2d_transform* out) {
    return guarded("i2d_world_get_body_transforms", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!valid_bodies(call, world_id, bodies, count, w) || (count > 0 && !call.not_null(out, "out"))) {
            return last_status();
        }
        for (int32_t i = 0; i < count; ++i) {
            out[i] = to_public(w.world->bodies()[checked_slot(bodies[i])].transform);
        }
        return I2D_OK;
    });
}

I2D_API i2d_status i2d_world_get_body_velocities(i2d_world_id world_id, const i2d_body_id* bodies, int32_t count,
                                                 i2d_vec2* linear, float* angular) {
    return guarded("i2d_world_get_body_velocities", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!valid_bodies(call, world_id, bodies, count, w)) {
            return last_status();
        }
        for (int32_t i = 0; i < count; ++i) {
            const Body& body = w.world->bodies()[checked_slot(bodies[i])];
            if (linear != nullptr) {
                linear[i] = to_public(body.linear_velocity);
            }
            if (angular != nullptr) {
                angular[i] = body.angular_velocity;
            }
        }
        return I2D_OK;
    });
}

I2D_API i2d_status i2d_world_set_body_velocities(i2d_world_id world_id, const i2d_body_id* bodies, int32_t count,
                                                 const i2d_vec2* linear, const float* angular) {
    return guarded("i2d_world_set_body_velocities", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!valid_bodies(call, world_id, bodies, count, w) || !call.unlocked(*w.world) ||
            !valid_velocities(call, count, linear, angular)) {
            return last_status();
        }
        for (int32_t i = 0; i < count; ++i) {
            const int32_t slot = checked_slot(bodies[i]);
            if (linear != nullptr) {
                w.world->set_linear_velocity(slot, capi::to_core(linear[i]));
            }
            if (angular != nullptr) {
                w.world->set_angular_velocity(slot, angular[i]);
            }
        }
        return I2D_OK;
    });
}

I2D_API i2d_status i2d_world_set_body_transforms(i2d_world_id world_id, const i2d_body_id* bodies, int32_t count,
                                                 const i2d_transform* in) {
    return guarded("i2d_world_set_body_transforms", I2D_ERR_OUT_OF_MEMORY, [&](Call& call) {
        WorldRef w;
        if (!valid_bodies(call, world_id, bodies, count, w) || !call.unlocked(*w.world) ||
            (count > 0 && !call.not_null(in, "transforms")) || !valid_transforms(call, count, in)) {
            return last_status();
        }
        // In chunks on the stack: no allocation.
        constexpr int32_t chunk = 256;
        int32_t slots[chunk];
        Transform transforms[chunk];
        for (int32_t first = 0; first < count; first += chunk) {
            const int32_t n = count - first < chunk ? count - first : chunk;
            for (int32_t i = 0; i < n; ++i) {
                slots[i] = checked_slot(bodies[first + i]);
            }
            // What normalized_rotation() would give, without checking each element twice.
            normalized_transforms(in + first, n, transforms);
            w.world->set_transforms(slots, transforms, n);
        }
        return I2D_OK;
    });
}
