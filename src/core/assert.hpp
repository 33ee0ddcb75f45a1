// SPDX-License-Identifier: MIT
// I2D_ASSERT: internal invariants only, never user input (the C boundary refuses that
// with a status). Active when the build defines I2D_VALIDATE (Debug and CI by default).
#pragma once

#if defined(I2D_VALIDATE)
#include <cstdio>
#include <cstdlib>
#define I2D_ASSERT(cond)                                                                        \
    do {                                                                                        \
        if (!(cond)) {                                                                          \
            std::fprintf(stderr, "impulse2d internal check failed: %s (%s:%d)\n", #cond, __FILE__, \
                         __LINE__);                                                             \
            std::abort();                                                                       \
        }                                                                                       \
    } while (0)
#else
#define I2D_ASSERT(cond) ((void)0)
#endif
