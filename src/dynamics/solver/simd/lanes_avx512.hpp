// SPDX-License-Identifier: MIT
// LanesAvx512: sixteen float lanes in AVX-512F, bit for bit what Lanes1
// (lanes_scalar.hpp) gives each lane. Masks are the mask registers; the 32 vector
// registers keep the kernels' working set out of memory. No fused multiply-add. Bodies
// are gathered as two halves with the AVX2 transpose (AVX-512F implies AVX2).
#pragma once

#include <immintrin.h>

#include <cstdint>

#include "dynamics/solver/body_state.hpp"
#include "dynamics/solver/simd/lanes_avx2.hpp"

namespace i2d {
namespace {

struct LanesAvx512 {
    static constexpr int width = 16;
    struct F {
        __m512 v;
    };
    struct M {
        __mmask16 v;
    };

    static F load(const float* p) { return {_mm512_load_ps(p)}; }
    static void store(float* p, F a) { _mm512_store_ps(p, a.v); }
    static F load_unaligned(const float* p) { return {_mm512_loadu_ps(p)}; }
    static void store_unaligned(float* p, F a) { _mm512_storeu_ps(p, a.v); }
    static F splat(float s) { return {_mm512_set1_ps(s)}; }
    static F sqrt(F a) { return {_mm512_sqrt_ps(a.v)}; }
    static F min(F a, F b) { return {_mm512_min_ps(a.v, b.v)}; }
    static F max(F a, F b) { return {_mm512_max_ps(a.v, b.v)}; }
    static M gt(F a, F b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_GT_OQ)}; }
    static M ge(F a, F b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_GE_OQ)}; }
    static M lt(F a, F b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_LT_OQ)}; }
    static M eq(F a, F b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_EQ_OQ)}; }
    static M both(M a, M b) { return {__mmask16(a.v & b.v)}; }
    static M either(M a, M b) { return {__mmask16(a.v | b.v)}; }
    static M but_not(M a, M b) { return {__mmask16(a.v & ~b.v)}; }
    static F blend(M m, F if_false, F if_true) { return {_mm512_mask_blend_ps(m.v, if_false.v, if_true.v)}; }
    static bool any(M m) { return m.v != 0; }
    static bool all(M m) { return m.v == 0xFFFF; }

    // Two 8x8 transposes (lanes 0-7 and 8-15) in 256-bit halves, joined.
    static __m512 join(__m256 lo, __m256 hi) {
        return _mm512_castpd_ps(_mm512_insertf64x4(_mm512_castpd256_pd512(_mm256_castps_pd(lo)), _mm256_castps_pd(hi), 1));
    }
    static void gather(const BodyState* states, const int32_t* index, F out[8]) {
        __m256 lo[8], hi[8];
        transpose_states8(states, index, lo);
        transpose_states8(states, index + 8, hi);
        for (int k = 0; k < 8; ++k) {
            out[k] = {join(lo[k], hi[k])};
        }
    }
    /// Writes [vx vy w moves] back to the lanes whose state moves (moves is as gathered).
    static void scatter(BodyState* states, const int32_t* index, F vx, F vy, F w, F moves) {
        const __mmask16 write = _mm512_cmp_ps_mask(moves.v, _mm512_setzero_ps(), _CMP_NEQ_OQ);
        // Rows [vx vy w moves] per lane: lane k of each 128-bit quarter q is lane 4q + k.
        const __m512 t0 = _mm512_unpacklo_ps(vx.v, vy.v), t1 = _mm512_unpackhi_ps(vx.v, vy.v);
        const __m512 t2 = _mm512_unpacklo_ps(w.v, moves.v), t3 = _mm512_unpackhi_ps(w.v, moves.v);
        const __m512 rows[4] = {_mm512_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0)),
                                _mm512_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2)),
                                _mm512_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0)),
                                _mm512_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2))};
        alignas(64) float quarters[4][16];
        for (int k = 0; k < 4; ++k) {
            _mm512_store_ps(quarters[k], rows[k]);
        }
        for (int lane = 0; lane < 16; ++lane) {
            if (write & (1u << lane)) {
                // Lane 4q + k sits in quarter q of row k.
                const float* row = quarters[lane & 3] + 4 * (lane >> 2);
                _mm_store_ps(reinterpret_cast<float*>(states + index[lane]), _mm_load_ps(row));
            }
        }
    }
};

inline LanesAvx512::F operator+(LanesAvx512::F a, LanesAvx512::F b) { return {_mm512_add_ps(a.v, b.v)}; }
inline LanesAvx512::F operator-(LanesAvx512::F a, LanesAvx512::F b) { return {_mm512_sub_ps(a.v, b.v)}; }
inline LanesAvx512::F operator*(LanesAvx512::F a, LanesAvx512::F b) { return {_mm512_mul_ps(a.v, b.v)}; }
inline LanesAvx512::F operator/(LanesAvx512::F a, LanesAvx512::F b) { return {_mm512_div_ps(a.v, b.v)}; }
inline LanesAvx512::F operator-(LanesAvx512::F a) {
    return {_mm512_castsi512_ps(_mm512_xor_si512(_mm512_castps_si512(a.v), _mm512_set1_epi32(int(0x80000000u))))};
}

}  // namespace
}  // namespace i2d
