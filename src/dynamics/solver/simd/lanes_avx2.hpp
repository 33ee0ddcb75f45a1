// SPDX-License-Identifier: MIT
// LanesAvx2: eight float lanes in AVX (the loads, arithmetic and transposes used here
// need no more than AVX; the translation unit is built with -mavx2 and used only on
// CPUs that report AVX2), bit for bit what Lanes1 (lanes_scalar.hpp) gives each lane.
// Nothing here fuses a multiply and an add: FMA rounds once where the scalar path
// rounds twice.
#pragma once

#include <immintrin.h>

#include <cstdint>

#include "dynamics/solver/body_state.hpp"

namespace i2d {
namespace {

// Eight 32-byte states [vx vy w moves dpx dpy dqc dqs] in, eight lanes of each field out:
// an 8x8 transpose in three rounds (pairs, quads, halves). The AVX-512 lanes use it too.
inline void transpose_states8(const BodyState* states, const int32_t* index, __m256 fields[8]) {
    __m256 r[8], t[8], q[8];
    for (int lane = 0; lane < 8; ++lane) {
        r[lane] = _mm256_load_ps(reinterpret_cast<const float*>(states + index[lane]));
    }
    for (int k = 0; k < 4; ++k) {
        t[2 * k] = _mm256_unpacklo_ps(r[2 * k], r[2 * k + 1]);
        t[2 * k + 1] = _mm256_unpackhi_ps(r[2 * k], r[2 * k + 1]);
    }
    for (int k = 0; k < 2; ++k) {
        const int base = 4 * k;
        q[base + 0] = _mm256_shuffle_ps(t[base + 0], t[base + 2], _MM_SHUFFLE(1, 0, 1, 0));
        q[base + 1] = _mm256_shuffle_ps(t[base + 0], t[base + 2], _MM_SHUFFLE(3, 2, 3, 2));
        q[base + 2] = _mm256_shuffle_ps(t[base + 1], t[base + 3], _MM_SHUFFLE(1, 0, 1, 0));
        q[base + 3] = _mm256_shuffle_ps(t[base + 1], t[base + 3], _MM_SHUFFLE(3, 2, 3, 2));
    }
    for (int k = 0; k < 4; ++k) {
        fields[k] = _mm256_permute2f128_ps(q[k], q[k + 4], 0x20);      // vx vy w moves
        fields[k + 4] = _mm256_permute2f128_ps(q[k], q[k + 4], 0x31);  // dpx dpy dqc dqs
    }
}

struct LanesAvx2 {
    static constexpr int width = 8;
    struct F {
        __m256 v;
    };
    struct M {
        __m256 v;
    };

    static F load(const float* p) { return {_mm256_load_ps(p)}; }
    static void store(float* p, F a) { _mm256_store_ps(p, a.v); }
    static F load_unaligned(const float* p) { return {_mm256_loadu_ps(p)}; }
    static void store_unaligned(float* p, F a) { _mm256_storeu_ps(p, a.v); }
    static F splat(float s) { return {_mm256_set1_ps(s)}; }
    static F sqrt(F a) { return {_mm256_sqrt_ps(a.v)}; }
    static F min(F a, F b) { return {_mm256_min_ps(a.v, b.v)}; }
    static F max(F a, F b) { return {_mm256_max_ps(a.v, b.v)}; }
    static M gt(F a, F b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GT_OQ)}; }
    static M ge(F a, F b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GE_OQ)}; }
    static M lt(F a, F b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_LT_OQ)}; }
    static M eq(F a, F b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_EQ_OQ)}; }
    static M both(M a, M b) { return {_mm256_and_ps(a.v, b.v)}; }
    static M either(M a, M b) { return {_mm256_or_ps(a.v, b.v)}; }
    static M but_not(M a, M b) { return {_mm256_andnot_ps(b.v, a.v)}; }
    static F blend(M m, F if_false, F if_true) { return {_mm256_blendv_ps(if_false.v, if_true.v, m.v)}; }
    static bool any(M m) { return _mm256_movemask_ps(m.v) != 0; }
    static bool all(M m) { return _mm256_movemask_ps(m.v) == 0xFF; }

    static void gather(const BodyState* states, const int32_t* index, F out[8]) {
        __m256 fields[8];
        transpose_states8(states, index, fields);
        for (int k = 0; k < 8; ++k) {
            out[k] = {fields[k]};
        }
    }
    /// Writes [vx vy w moves] back to the lanes whose state moves (moves is as gathered).
    static void scatter(BodyState* states, const int32_t* index, F vx, F vy, F w, F moves) {
        const int write = _mm256_movemask_ps(_mm256_cmp_ps(moves.v, _mm256_setzero_ps(), _CMP_NEQ_OQ));
        const __m256 t0 = _mm256_unpacklo_ps(vx.v, vy.v), t1 = _mm256_unpackhi_ps(vx.v, vy.v);
        const __m256 t2 = _mm256_unpacklo_ps(w.v, moves.v), t3 = _mm256_unpackhi_ps(w.v, moves.v);
        // Row k holds lane k in its low half and lane k + 4 in its high half.
        const __m256 rows[4] = {_mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0)),
                                _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2)),
                                _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0)),
                                _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2))};
        for (int k = 0; k < 4; ++k) {
            if (write & (1 << k)) {
                _mm_store_ps(reinterpret_cast<float*>(states + index[k]), _mm256_castps256_ps128(rows[k]));
            }
            if (write & (1 << (k + 4))) {
                _mm_store_ps(reinterpret_cast<float*>(states + index[k + 4]), _mm256_extractf128_ps(rows[k], 1));
            }
        }
    }
};

inline LanesAvx2::F operator+(LanesAvx2::F a, LanesAvx2::F b) { return {_mm256_add_ps(a.v, b.v)}; }
inline LanesAvx2::F operator-(LanesAvx2::F a, LanesAvx2::F b) { return {_mm256_sub_ps(a.v, b.v)}; }
inline LanesAvx2::F operator*(LanesAvx2::F a, LanesAvx2::F b) { return {_mm256_mul_ps(a.v, b.v)}; }
inline LanesAvx2::F operator/(LanesAvx2::F a, LanesAvx2::F b) { return {_mm256_div_ps(a.v, b.v)}; }
inline LanesAvx2::F operator-(LanesAvx2::F a) { return {_mm256_xor_ps(a.v, _mm256_set1_ps(-0.0f))}; }

}  // namespace
}  // namespace i2d
