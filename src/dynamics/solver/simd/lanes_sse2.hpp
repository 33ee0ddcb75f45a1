// SPDX-License-Identifier: MIT
// LanesSse2: four float lanes in SSE2, bit for bit what Lanes1 (lanes_scalar.hpp) gives
// each lane. SSE2 is part of every x86-64 CPU.
#pragma once

#include <emmintrin.h>

#include <cstdint>

#include "dynamics/solver/body_state.hpp"

namespace i2d {
namespace {

struct LanesSse2 {
    static constexpr int width = 4;
    struct F {
        __m128 v;
    };
    struct M {
        __m128 v;
    };

    static F load(const float* p) { return {_mm_load_ps(p)}; }
    static void store(float* p, F a) { _mm_store_ps(p, a.v); }
    static F load_unaligned(const float* p) { return {_mm_loadu_ps(p)}; }
    static void store_unaligned(float* p, F a) { _mm_storeu_ps(p, a.v); }
    static F splat(float s) { return {_mm_set1_ps(s)}; }
    static F sqrt(F a) { return {_mm_sqrt_ps(a.v)}; }
    static F min(F a, F b) { return {_mm_min_ps(a.v, b.v)}; }
    static F max(F a, F b) { return {_mm_max_ps(a.v, b.v)}; }
    static M gt(F a, F b) { return {_mm_cmpgt_ps(a.v, b.v)}; }
    static M ge(F a, F b) { return {_mm_cmpge_ps(a.v, b.v)}; }
    static M lt(F a, F b) { return {_mm_cmplt_ps(a.v, b.v)}; }
    static M eq(F a, F b) { return {_mm_cmpeq_ps(a.v, b.v)}; }
    static M both(M a, M b) { return {_mm_and_ps(a.v, b.v)}; }
    static M either(M a, M b) { return {_mm_or_ps(a.v, b.v)}; }
    static M but_not(M a, M b) { return {_mm_andnot_ps(b.v, a.v)}; }
    static F blend(M m, F if_false, F if_true) {
        return {_mm_or_ps(_mm_and_ps(m.v, if_true.v), _mm_andnot_ps(m.v, if_false.v))};
    }
    static bool any(M m) { return _mm_movemask_ps(m.v) != 0; }
    static bool all(M m) { return _mm_movemask_ps(m.v) == 0xF; }

    // A state is two 4-float halves, [vx vy w moves] and [dpx dpy dqc dqs]: four lanes
    // are two 4x4 transposes.
    static void transpose(__m128& r0, __m128& r1, __m128& r2, __m128& r3) {
        const __m128 t0 = _mm_unpacklo_ps(r0, r1), t1 = _mm_unpackhi_ps(r0, r1);
        const __m128 t2 = _mm_unpacklo_ps(r2, r3), t3 = _mm_unpackhi_ps(r2, r3);
        r0 = _mm_movelh_ps(t0, t2);
        r1 = _mm_movehl_ps(t2, t0);
        r2 = _mm_movelh_ps(t1, t3);
        r3 = _mm_movehl_ps(t3, t1);
    }
    static void gather(const BodyState* states, const int32_t* index, F out[8]) {
        for (int half = 0; half < 2; ++half) {
            __m128 r[4];
            for (int lane = 0; lane < 4; ++lane) {
                r[lane] = _mm_load_ps(reinterpret_cast<const float*>(states + index[lane]) + 4 * half);
            }
            transpose(r[0], r[1], r[2], r[3]);
            for (int k = 0; k < 4; ++k) {
                out[4 * half + k] = {r[k]};
            }
        }
    }
    /// Writes [vx vy w moves] back to the lanes whose state moves (moves is as gathered).
    static void scatter(BodyState* states, const int32_t* index, F vx, F vy, F w, F moves) {
        const int write = _mm_movemask_ps(_mm_cmpneq_ps(moves.v, _mm_setzero_ps()));
        __m128 r0 = vx.v, r1 = vy.v, r2 = w.v, r3 = moves.v;
        transpose(r0, r1, r2, r3);
        const __m128 rows[4] = {r0, r1, r2, r3};
        for (int lane = 0; lane < 4; ++lane) {
            if (write & (1 << lane)) {
                _mm_store_ps(reinterpret_cast<float*>(states + index[lane]), rows[lane]);
            }
        }
    }
};

inline LanesSse2::F operator+(LanesSse2::F a, LanesSse2::F b) { return {_mm_add_ps(a.v, b.v)}; }
inline LanesSse2::F operator-(LanesSse2::F a, LanesSse2::F b) { return {_mm_sub_ps(a.v, b.v)}; }
inline LanesSse2::F operator*(LanesSse2::F a, LanesSse2::F b) { return {_mm_mul_ps(a.v, b.v)}; }
inline LanesSse2::F operator/(LanesSse2::F a, LanesSse2::F b) { return {_mm_div_ps(a.v, b.v)}; }
inline LanesSse2::F operator-(LanesSse2::F a) { return {_mm_xor_ps(a.v, _mm_set1_ps(-0.0f))}; }

}  // namespace
}  // namespace i2d
