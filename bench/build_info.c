/* SPDX-License-Identifier: MIT */
#include "build_info.h"

#include <impulse2d/impulse2d.h>
#include <time.h>

/* Defined by bench/CMakeLists.txt; the fallbacks let the file build by hand. */
#ifndef I2D_BENCH_BUILD_TYPE
#define I2D_BENCH_BUILD_TYPE "unknown"
#endif
#ifndef I2D_BENCH_C_FLAGS
#define I2D_BENCH_C_FLAGS "unknown"
#endif
#ifndef I2D_BENCH_CXX_COMPILER
#define I2D_BENCH_CXX_COMPILER "unknown"
#endif
#ifndef I2D_BENCH_CXX_FLAGS
#define I2D_BENCH_CXX_FLAGS "unknown"
#endif
#ifndef I2D_BENCH_LIBRARY
#define I2D_BENCH_LIBRARY "unknown"
#endif
#ifndef I2D_BENCH_COMMIT
#define I2D_BENCH_COMMIT "unknown"
#endif

#define BENCH_STR2(x) #x
#define BENCH_STR(x) BENCH_STR2(x)
#if defined(__clang__)
#define BENCH_COMPILER "clang " __clang_version__
#elif defined(__GNUC__)
#define BENCH_COMPILER "gcc " __VERSION__
#elif defined(_MSC_VER)
#define BENCH_COMPILER "msvc " BENCH_STR(_MSC_FULL_VER)
#else
#define BENCH_COMPILER "unknown"
#endif

/* Instruction sets this file was compiled for; the library is built with the same flags. */
static const char* simd_macros(void) {
    static const char list[] = ""
#if defined(__AVX512F__)
                               " AVX512F"
#endif
#if defined(__AVX2__)
                               " AVX2"
#endif
#if defined(__FMA__)
                               " FMA"
#endif
#if defined(__AVX__)
                               " AVX"
#endif
#if defined(__SSE4_2__)
                               " SSE4.2"
#endif
#if defined(__SSE4_1__)
                               " SSE4.1"
#endif
#if defined(__SSE2__)
                               " SSE2"
#endif
#if defined(__ARM_NEON)
                               " NEON"
#endif
        ;
    return list[0] ? list + 1 : "none";
}

static void library_version(char* out, size_t size) {
    uint32_t v = i2d_version();
    snprintf(out, size, "%u.%u.%u", (unsigned)(v >> 16), (unsigned)((v >> 8) & 0xffu), (unsigned)(v & 0xffu));
}

static void utc_date(char* out, size_t size) {
    time_t now = time(NULL);
    struct tm* utc = gmtime(&now);
    if (!utc || !strftime(out, size, "%Y-%m-%d %H:%M:%S UTC", utc)) {
        snprintf(out, size, "unknown");
    }
}

void bench_print_build_line(FILE* out, const char* app) {
    char version[32], date[32];
    library_version(version, sizeof version);
    utc_date(date, sizeof date);
    fprintf(out,
            "# impulse2d %s %s | %s | library: %s, %s | %s | C flags: %s | C++ flags: %s | SIMD: %s"
            " | commit %s | %s\n",
            version, app, BENCH_COMPILER, I2D_BENCH_CXX_COMPILER, I2D_BENCH_LIBRARY, I2D_BENCH_BUILD_TYPE,
            I2D_BENCH_C_FLAGS, I2D_BENCH_CXX_FLAGS, simd_macros(), I2D_BENCH_COMMIT, date);
}

void bench_json_string(FILE* out, const char* s) {
    for (; *s; ++s) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') {
            fprintf(out, "\\%c", c);
        } else if (c < 0x20) {
            fprintf(out, "\\u%04x", c);
        } else {
            fputc(c, out);
        }
    }
}

static void json_member(FILE* out, const char* name, const char* value, int last) {
    fprintf(out, "\"%s\": \"", name);
    bench_json_string(out, value);
    fprintf(out, "\"%s", last ? "" : ", ");
}

void bench_print_build_json(FILE* out) {
    char version[32], date[32];
    library_version(version, sizeof version);
    utc_date(date, sizeof date);
    json_member(out, "library", version, 0);
    json_member(out, "compiler", BENCH_COMPILER, 0);
    json_member(out, "library_compiler", I2D_BENCH_CXX_COMPILER, 0);
    json_member(out, "build_type", I2D_BENCH_BUILD_TYPE, 0);
    json_member(out, "c_flags", I2D_BENCH_C_FLAGS, 0);
    json_member(out, "cxx_flags", I2D_BENCH_CXX_FLAGS, 0);
    json_member(out, "library_options", I2D_BENCH_LIBRARY, 0);
    json_member(out, "simd", simd_macros(), 0);
    json_member(out, "commit", I2D_BENCH_COMMIT, 0);
    json_member(out, "date", date, 1);
}

bool bench_check_library_version(const char* app) {
    if (i2d_version() != (uint32_t)I2D_VERSION) {
        fprintf(stderr, "%s: built against impulse2d %d.%d.%d but loaded another version\n", app,
                I2D_VERSION_MAJOR, I2D_VERSION_MINOR, I2D_VERSION_PATCH);
        return false;
    }
    return true;
}
