// SPDX-License-Identifier: MIT
// CPU feature checks through the compiler's cpuid support.
#include "core/cpu_features.hpp"

namespace i2d {

bool cpu_has_avx2() {
#if (defined(__GNUC__) || defined(__clang__)) && (defined(__x86_64__) || defined(__i386__))
    // GCC's and Clang's runtime reports AVX2 only when the OS enabled the YMM state too.
    static const bool has = __builtin_cpu_supports("avx2") != 0;
    return has;
#else
    return false;
#endif
}

bool cpu_has_avx512f() {
#if (defined(__GNUC__) || defined(__clang__)) && (defined(__x86_64__) || defined(__i386__))
    static const bool has = __builtin_cpu_supports("avx512f") != 0;
    return has;
#else
    return false;
#endif
}

}  // namespace i2d
