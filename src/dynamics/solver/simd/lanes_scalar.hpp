// SPDX-License-Identifier: MIT
// Lanes1: one float lane in plain C++, the reference every SIMD lane type must match bit
// for bit.
//
// Design note: the contact kernels are written once over a lane type and compiled for
// each instruction set; their results must not depend on it. So each operation here is
// defined as the SIMD instruction behaves, not as the C library would: max(a, b) is
// a > b ? a : b (SSE's maxps: the second operand on a tie, on +0/-0 or on NaN), min the
// same with <, comparisons are ordered (false with NaN), negation flips the sign bit.
// Everything sits in an anonymous namespace so that the kernels built on it have
// internal linkage in each translation unit (see contact_block.hpp).
#pragma once

#include <cmath>
#include <cstdint>

#include "dynamics/solver/body_state.hpp"

namespace i2d {
namespace {

struct Lanes1 {
    static constexpr int width = 1;
    struct F {
        float v;
    };
    struct M {
        bool v;
    };

    static F load(const float* p) { return {*p}; }
    static void store(float* p, F a) { *p = a.v; }
    /// Any float address (load and store ask for the width's alignment).
    static F load_unaligned(const float* p) { return {*p}; }
    static void store_unaligned(float* p, F a) { *p = a.v; }
    static F splat(float s) { return {s}; }
    static F sqrt(F a) { return {std::sqrt(a.v)}; }
    static F min(F a, F b) { return {a.v < b.v ? a.v : b.v}; }
    static F max(F a, F b) { return {a.v > b.v ? a.v : b.v}; }
    static M gt(F a, F b) { return {a.v > b.v}; }
    static M ge(F a, F b) { return {a.v >= b.v}; }
    static M lt(F a, F b) { return {a.v < b.v}; }
    static M eq(F a, F b) { return {a.v == b.v}; }
    static M both(M a, M b) { return {a.v && b.v}; }
    static M either(M a, M b) { return {a.v || b.v}; }
    static M but_not(M a, M b) { return {a.v && !b.v}; }
    /// m ? if_true : if_false, per lane.
    static F blend(M m, F if_false, F if_true) { return m.v ? if_true : if_false; }
    static bool any(M m) { return m.v; }
    static bool all(M m) { return m.v; }

    /// The 8 floats of each lane's body state: vx, vy, w, moves, dpx, dpy, dqc, dqs.
    static void gather(const BodyState* states, const int32_t* index, F out[8]) {
        const BodyState& s = states[index[0]];
        out[0] = {s.linear_velocity.x};
        out[1] = {s.linear_velocity.y};
        out[2] = {s.angular_velocity};
        out[3] = {s.moves};
        out[4] = {s.delta_position.x};
        out[5] = {s.delta_position.y};
        out[6] = {s.delta_rotation.c};
        out[7] = {s.delta_rotation.s};
    }
    /// Writes the velocities back to the lanes whose state moves (moves is as gathered).
    static void scatter(BodyState* states, const int32_t* index, F vx, F vy, F w, F moves) {
        BodyState& s = states[index[0]];
        if (moves.v != 0.0f) {
            s.linear_velocity.x = vx.v;
            s.linear_velocity.y = vy.v;
            s.angular_velocity = w.v;
        }
    }
};

inline Lanes1::F operator+(Lanes1::F a, Lanes1::F b) { return {a.v + b.v}; }
inline Lanes1::F operator-(Lanes1::F a, Lanes1::F b) { return {a.v - b.v}; }
inline Lanes1::F operator*(Lanes1::F a, Lanes1::F b) { return {a.v * b.v}; }
inline Lanes1::F operator/(Lanes1::F a, Lanes1::F b) { return {a.v / b.v}; }
inline Lanes1::F operator-(Lanes1::F a) { return {-a.v}; }

}  // namespace
}  // namespace i2d
