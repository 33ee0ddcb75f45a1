// SPDX-License-Identifier: MIT
// LanesNeon: four float lanes in AArch64 NEON, bit for bit what Lanes1 (lanes_scalar.hpp)
// gives each lane. NEON's own min and max differ from SSE's on signed zeros and NaN, so
// they are a compare and a select here, as the scalar lanes define them.
#pragma once

#include <arm_neon.h>

#include <cstdint>

#include "dynamics/solver/body_state.hpp"

namespace i2d {
namespace {

struct LanesNeon {
    static constexpr int width = 4;
    struct F {
        float32x4_t v;
    };
    struct M {
        uint32x4_t v;
    };

    static F load(const float* p) { return {vld1q_f32(p)}; }
    static void store(float* p, F a) { vst1q_f32(p, a.v); }
    static F load_unaligned(const float* p) { return {vld1q_f32(p)}; }
    static void store_unaligned(float* p, F a) { vst1q_f32(p, a.v); }
    static F splat(float s) { return {vdupq_n_f32(s)}; }
    static F sqrt(F a) { return {vsqrtq_f32(a.v)}; }
    static F min(F a, F b) { return {vbslq_f32(vcltq_f32(a.v, b.v), a.v, b.v)}; }
    static F max(F a, F b) { return {vbslq_f32(vcgtq_f32(a.v, b.v), a.v, b.v)}; }
    static M gt(F a, F b) { return {vcgtq_f32(a.v, b.v)}; }
    static M ge(F a, F b) { return {vcgeq_f32(a.v, b.v)}; }
    static M lt(F a, F b) { return {vcltq_f32(a.v, b.v)}; }
    static M eq(F a, F b) { return {vceqq_f32(a.v, b.v)}; }
    static M both(M a, M b) { return {vandq_u32(a.v, b.v)}; }
    static M either(M a, M b) { return {vorrq_u32(a.v, b.v)}; }
    static M but_not(M a, M b) { return {vbicq_u32(a.v, b.v)}; }
    static F blend(M m, F if_false, F if_true) { return {vbslq_f32(m.v, if_true.v, if_false.v)}; }
    static bool any(M m) { return vmaxvq_u32(m.v) != 0; }
    static bool all(M m) { return vminvq_u32(m.v) != 0; }

    // A state is two 4-float halves, [vx vy w moves] and [dpx dpy dqc dqs]: four lanes
    // are two 4x4 transposes.
    static void transpose(float32x4_t& r0, float32x4_t& r1, float32x4_t& r2, float32x4_t& r3) {
        const float32x4_t t0 = vzip1q_f32(r0, r2), t1 = vzip2q_f32(r0, r2);  // a0 c0 a1 c1 | a2 c2 a3 c3
        const float32x4_t t2 = vzip1q_f32(r1, r3), t3 = vzip2q_f32(r1, r3);  // b0 d0 b1 d1 | b2 d2 b3 d3
        r0 = vzip1q_f32(t0, t2);  // a0 b0 c0 d0
        r1 = vzip2q_f32(t0, t2);  // a1 b1 c1 d1
        r2 = vzip1q_f32(t1, t3);  // a2 b2 c2 d2
        r3 = vzip2q_f32(t1, t3);  // a3 b3 c3 d3
    }
    static void gather(const BodyState* states, const int32_t* index, F out[8]) {
        for (int half = 0; half < 2; ++half) {
            float32x4_t r[4];
            for (int lane = 0; lane < 4; ++lane) {
                r[lane] = vld1q_f32(reinterpret_cast<const float*>(states + index[lane]) + 4 * half);
            }
            transpose(r[0], r[1], r[2], r[3]);
            for (int k = 0; k < 4; ++k) {
                out[4 * half + k] = {r[k]};
            }
        }
    }
    /// Writes [vx vy w moves] back to the lanes whose state moves (moves is as gathered).
    static void scatter(BodyState* states, const int32_t* index, F vx, F vy, F w, F moves) {
        float32x4_t r0 = vx.v, r1 = vy.v, r2 = w.v, r3 = moves.v;
        transpose(r0, r1, r2, r3);
        const float32x4_t rows[4] = {r0, r1, r2, r3};
        for (int lane = 0; lane < 4; ++lane) {
            if (vgetq_lane_f32(rows[lane], 3) != 0.0f) {
                vst1q_f32(reinterpret_cast<float*>(states + index[lane]), rows[lane]);
            }
        }
    }
};

inline LanesNeon::F operator+(LanesNeon::F a, LanesNeon::F b) { return {vaddq_f32(a.v, b.v)}; }
inline LanesNeon::F operator-(LanesNeon::F a, LanesNeon::F b) { return {vsubq_f32(a.v, b.v)}; }
inline LanesNeon::F operator*(LanesNeon::F a, LanesNeon::F b) { return {vmulq_f32(a.v, b.v)}; }
inline LanesNeon::F operator/(LanesNeon::F a, LanesNeon::F b) { return {vdivq_f32(a.v, b.v)}; }
inline LanesNeon::F operator-(LanesNeon::F a) { return {vnegq_f32(a.v)}; }

}  // namespace
}  // namespace i2d
