// SPDX-License-Identifier: MIT
// ContactHooks: game code's say over contacts, set by the host: which pairs may ever touch
// (the custom filter) and which touching contacts take part in this step (pre-solve).
//
// Design note: the hooks are the host's wiring, like the task callbacks: a snapshot does
// not hold them and a recording does not record them. The core calls them with the
// public 64-bit shape ids (the event recorder's encoder) through a trampoline the C
// boundary sets, so that the core never sees the C API's function types. They run on the
// step's workers (pair finding, the narrowphase, continuous sweeps). A pair reaches them
// only when one of its shapes opted in, so a world whose shapes opt in to nothing pays a
// flag test per new pair and nothing per contact.
#pragma once

#include <cstdint>

#include "collision/shapes.hpp"
#include "core/pool.hpp"
#include "dynamics/body/shape.hpp"
#include "dynamics/world/events.hpp"

namespace i2d {

struct ContactHooks {
    /// The host's function, of a type only the host knows: the trampoline casts it back.
    using HostFn = void (*)();

    struct CustomFilter {
        bool (*call)(HostFn fn, void* context, uint64_t shape_a, uint64_t shape_b) = nullptr;
        HostFn fn = nullptr;
        void* context = nullptr;
    };
    struct PreSolve {
        bool (*call)(HostFn fn, void* context, uint64_t shape_a, uint64_t shape_b, const Manifold& manifold) = nullptr;
        HostFn fn = nullptr;
        void* context = nullptr;
    };

    CustomFilter custom_filter;
    PreSolve pre_solve;

    /// Whether the custom filter lets shapes a and b touch; true when it is not set or
    /// neither shape opted in.
    bool allows_pair(const IdEncoder& ids, const Pool<Shape>& shapes, int32_t a, int32_t b) const {
        if (custom_filter.call == nullptr ||
            !(shapes[a].enable_custom_filtering || shapes[b].enable_custom_filtering)) {
            return true;
        }
        return custom_filter.call(custom_filter.fn, custom_filter.context, ids.shape_id(a, shapes.generation(a)),
                                  ids.shape_id(b, shapes.generation(b)));
    }

    /// Whether the pre-solve hook is to be asked about contacts between a and b.
    bool asks_pre_solve(const Shape& a, const Shape& b) const {
        return pre_solve.call != nullptr && (a.enable_pre_solve_events || b.enable_pre_solve_events);
    }

    /// The pre-solve hook's answer for a touching pair (it must be set: asks_pre_solve).
    bool allows_contact(const IdEncoder& ids, const Pool<Shape>& shapes, int32_t a, int32_t b,
                        const Manifold& manifold) const {
        return pre_solve.call(pre_solve.fn, pre_solve.context, ids.shape_id(a, shapes.generation(a)),
                              ids.shape_id(b, shapes.generation(b)), manifold);
    }
};

}  // namespace i2d
