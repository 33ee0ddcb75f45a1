// SPDX-License-Identifier: MIT
// LanesWasm128: four float lanes in WebAssembly's 128-bit SIMD, bit for bit what Lanes1
// (lanes_scalar.hpp) gives each lane. WebAssembly's f32x4.min and max propagate NaN and
// order -0 below +0, unlike the scalar lanes; its pseudo-minimum pmin(b, a) is
// a < b ? a : b and pmax(b, a) is a > b ? a : b, exactly the scalar definitions.
#pragma once

#include <wasm_simd128.h>

#include <cstdint>

#include "dynamics/solver/body_state.hpp"

namespace i2d {
namespace {

struct LanesWasm128 {
    static constexpr int width = 4;
    struct F {
        v128_t v;
    };
    struct M {
        v128_t v;
    };

    static F load(const float* p) { return {wasm_v128_load(p)}; }
    static void store(float* p, F a) { wasm_v128_store(p, a.v); }
    static F load_unaligned(const float* p) { return {wasm_v128_load(p)}; }
    static void store_unaligned(float* p, F a) { wasm_v128_store(p, a.v); }
    static F splat(float s) { return {wasm_f32x4_splat(s)}; }
    static F sqrt(F a) { return {wasm_f32x4_sqrt(a.v)}; }
    static F min(F a, F b) { return {wasm_f32x4_pmin(b.v, a.v)}; }
    static F max(F a, F b) { return {wasm_f32x4_pmax(b.v, a.v)}; }
    static M gt(F a, F b) { return {wasm_f32x4_gt(a.v, b.v)}; }
    static M ge(F a, F b) { return {wasm_f32x4_ge(a.v, b.v)}; }
    static M lt(F a, F b) { return {wasm_f32x4_lt(a.v, b.v)}; }
    static M eq(F a, F b) { return {wasm_f32x4_eq(a.v, b.v)}; }
    static M both(M a, M b) { return {wasm_v128_and(a.v, b.v)}; }
    static M either(M a, M b) { return {wasm_v128_or(a.v, b.v)}; }
    static M but_not(M a, M b) { return {wasm_v128_andnot(a.v, b.v)}; }
    static F blend(M m, F if_false, F if_true) { return {wasm_v128_bitselect(if_true.v, if_false.v, m.v)}; }
    static bool any(M m) { return wasm_v128_any_true(m.v); }
    static bool all(M m) { return wasm_i32x4_all_true(m.v); }

    // A state is two 4-float halves, [vx vy w moves] and [dpx dpy dqc dqs]: four lanes
    // are two 4x4 transposes.
    static void transpose(v128_t& r0, v128_t& r1, v128_t& r2, v128_t& r3) {
        const v128_t t0 = wasm_i32x4_shuffle(r0, r1, 0, 4, 1, 5);  // a0 b0 a1 b1
        const v128_t t1 = wasm_i32x4_shuffle(r0, r1, 2, 6, 3, 7);  // a2 b2 a3 b3
        const v128_t t2 = wasm_i32x4_shuffle(r2, r3, 0, 4, 1, 5);  // c0 d0 c1 d1
        const v128_t t3 = wasm_i32x4_shuffle(r2, r3, 2, 6, 3, 7);  // c2 d2 c3 d3
        r0 = wasm_i32x4_shuffle(t0, t2, 0, 1, 4, 5);               // a0 b0 c0 d0
        r1 = wasm_i32x4_shuffle(t0, t2, 2, 3, 6, 7);               // a1 b1 c1 d1
        r2 = wasm_i32x4_shuffle(t1, t3, 0, 1, 4, 5);               // a2 b2 c2 d2
        r3 = wasm_i32x4_shuffle(t1, t3, 2, 3, 6, 7);               // a3 b3 c3 d3
    }
    static void gather(const BodyState* states, const int32_t* index, F out[8]) {
        for (int half = 0; half < 2; ++half) {
            v128_t r[4];
            for (int lane = 0; lane < 4; ++lane) {
                r[lane] = wasm_v128_load(reinterpret_cast<const float*>(states + index[lane]) + 4 * half);
            }
            transpose(r[0], r[1], r[2], r[3]);
            for (int k = 0; k < 4; ++k) {
                out[4 * half + k] = {r[k]};
            }
        }
    }
    /// Writes [vx vy w moves] back to the lanes whose state moves (moves is as gathered).
    static void scatter(BodyState* states, const int32_t* index, F vx, F vy, F w, F moves) {
        const uint32_t write = wasm_i32x4_bitmask(wasm_f32x4_ne(moves.v, wasm_f32x4_splat(0.0f)));
        v128_t r0 = vx.v, r1 = vy.v, r2 = w.v, r3 = moves.v;
        transpose(r0, r1, r2, r3);
        const v128_t rows[4] = {r0, r1, r2, r3};
        for (int lane = 0; lane < 4; ++lane) {
            if (write & (1u << lane)) {
                wasm_v128_store(reinterpret_cast<float*>(states + index[lane]), rows[lane]);
            }
        }
    }
};

inline LanesWasm128::F operator+(LanesWasm128::F a, LanesWasm128::F b) { return {wasm_f32x4_add(a.v, b.v)}; }
inline LanesWasm128::F operator-(LanesWasm128::F a, LanesWasm128::F b) { return {wasm_f32x4_sub(a.v, b.v)}; }
inline LanesWasm128::F operator*(LanesWasm128::F a, LanesWasm128::F b) { return {wasm_f32x4_mul(a.v, b.v)}; }
inline LanesWasm128::F operator/(LanesWasm128::F a, LanesWasm128::F b) { return {wasm_f32x4_div(a.v, b.v)}; }
inline LanesWasm128::F operator-(LanesWasm128::F a) { return {wasm_f32x4_neg(a.v)}; }

}  // namespace
}  // namespace i2d
