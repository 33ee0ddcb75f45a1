/* SPDX-License-Identifier: MIT */
/* The scene benchmark app: milliseconds per step of each scene, with its sanity figure beside it.
 *
 * Method (docs: shared/design/scenes.md, as Box2D v3's benchmark does): a new world per run; the
 * first step (hook + world step) untimed; steps 1..N-1 timed together with a monotonic clock,
 * hooks included; ms per step = total / (N - 1). Each scene runs R times; the median and the
 * minimum over the runs are reported. Times are never asserted on: the exit status says only
 * whether every scene ran and stayed sane (and gave the same final state in every run). */

/* clock_gettime and CLOCK_MONOTONIC are POSIX, not C99. */
#define _POSIX_C_SOURCE 199309L

#include "scenes.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define TIME_STEP (1.0f / 60.0f)
#define SUBSTEPS 4
#define MAX_REPEATS 1000

enum { EXIT_SANE = 0, EXIT_INSANE = 1, EXIT_USAGE = 2, EXIT_API_ERROR = 3 };

/* ---- Build description: what the numbers were measured on --------------------------------- */

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

typedef struct build_info {
    char library_version[32];
    char date[32];
} build_info;

static build_info describe_build(void) {
    build_info info;
    uint32_t v = i2d_version();
    time_t now = time(NULL);
    struct tm* utc = gmtime(&now);
    snprintf(info.library_version, sizeof info.library_version, "%u.%u.%u", (unsigned)(v >> 16),
             (unsigned)((v >> 8) & 0xffu), (unsigned)(v & 0xffu));
    if (!utc || !strftime(info.date, sizeof info.date, "%Y-%m-%d %H:%M:%S UTC", utc)) {
        snprintf(info.date, sizeof info.date, "unknown");
    }
    return info;
}

/* ---- Options ------------------------------------------------------------------------------ */

typedef enum output_format { FORMAT_TABLE, FORMAT_CSV, FORMAT_JSON } output_format;

typedef struct options {
    int32_t steps;       /* 0: each scene's own count */
    int32_t repeats;
    const char* scene;   /* NULL: every scene */
    output_format format;
    bool list;
} options;

static void usage(FILE* f) {
    fprintf(f, "usage: impulse2d_bench [--scene NAME] [--steps N] [--repeat R] [--csv | --json] [--list]\n"
               "  --scene NAME  run one scene (see --list); default: all\n"
               "  --steps N     steps per run, N >= 2 (the first is untimed); default: the scene's own\n"
               "  --repeat R    runs per scene, each in a new world; default 3\n"
               "  --csv, --json machine-readable output instead of the table\n"
               "  --list        list the scenes and exit\n"
               "exit status: 0 every scene sane, 1 a sanity check failed, 2 bad usage, 3 an i2d call failed\n");
}

/* Parses a whole decimal argument in [lo, hi]. */
static bool parse_int(const char* text, int32_t lo, int32_t hi, int32_t* out) {
    char* end;
    long value;
    if (!text) {
        return false;
    }
    value = strtol(text, &end, 10);
    if (end == text || *end != '\0' || value < lo || value > hi) {
        return false;
    }
    *out = (int32_t)value;
    return true;
}

static const bench_scene* find_scene(const char* name) {
    int32_t i;
    for (i = 0; i < bench_scene_count; ++i) {
        if (strcmp(bench_scenes[i].name, name) == 0) {
            return &bench_scenes[i];
        }
    }
    return NULL;
}

static bool parse_options(int argc, char** argv, options* opt) {
    int i;
    memset(opt, 0, sizeof *opt);
    opt->repeats = 3;
    for (i = 1; i < argc; ++i) {
        const char* arg = argv[i];
        const char* value = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(arg, "--steps") == 0 && parse_int(value, 2, 1000000, &opt->steps)) {
            ++i;
        } else if (strcmp(arg, "--repeat") == 0 && parse_int(value, 1, MAX_REPEATS, &opt->repeats)) {
            ++i;
        } else if (strcmp(arg, "--scene") == 0 && value) {
            if (!find_scene(value)) {
                fprintf(stderr, "impulse2d_bench: no scene '%s' (--list shows them)\n", value);
                return false;
            }
            opt->scene = value;
            ++i;
        } else if (strcmp(arg, "--csv") == 0) {
            opt->format = FORMAT_CSV;
        } else if (strcmp(arg, "--json") == 0) {
            opt->format = FORMAT_JSON;
        } else if (strcmp(arg, "--list") == 0) {
            opt->list = true;
        } else if (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0) {
            usage(stdout);
            exit(EXIT_SANE);
        } else {
            fprintf(stderr, "impulse2d_bench: bad argument '%s'%s%s\n", arg, value ? " " : "", value ? value : "");
            usage(stderr);
            return false;
        }
    }
    return true;
}

/* ---- Running a scene ------------------------------------------------------------------------ */

typedef struct scene_result {
    const bench_scene* scene;
    int32_t steps, repeats;
    int32_t bodies, contacts;    /* counters after the last step of the last run */
    double ms[MAX_REPEATS];      /* ms per timed step, one per run */
    double median_ms, min_ms;
    double figure;               /* the sanity figure of the last run */
    bool sane;                   /* every run sane */
    uint64_t hash;               /* final state of the first run */
    bool deterministic;          /* every run ended in that state */
} scene_result;

static double seconds_now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void report_failure(const bench_scene* scene, const bench_state* state, const char* what) {
    /* Read the status and copy the message before another i2d_ call replaces them. */
    i2d_status status = i2d_last_status();
    char message[256];
    snprintf(message, sizeof message, "%s", state->error ? state->error : i2d_last_error_message());
    fprintf(stderr, "impulse2d_bench: scene %s: %s failed: %s: %s\n", scene->name, what,
            state->error ? "error" : i2d_status_string(status), message);
}

static bool step_once(const bench_scene* scene, bench_state* state, int32_t step) {
    if (scene->step_hook && !scene->step_hook(state, step)) {
        return false;
    }
    return i2d_world_step(state->world, TIME_STEP, SUBSTEPS) == I2D_OK;
}

/* One run in a new world. Fills the run's time, the counters, the sanity figure and the hash. */
static bool run_once(const bench_scene* scene, int32_t steps, scene_result* r, int32_t run) {
    bench_state state;
    i2d_world_counters counters;
    double start, figure = 0.0;
    bool sane = false;
    uint64_t hash = 0;
    int32_t step;

    memset(&state, 0, sizeof state);
    if (!scene->create(&state)) {
        report_failure(scene, &state, "create");
        bench_state_destroy(&state);
        return false;
    }
    /* The first step is not timed: it pairs every shape for the first time. */
    if (!step_once(scene, &state, 0)) {
        report_failure(scene, &state, "step 0");
        bench_state_destroy(&state);
        return false;
    }
    start = seconds_now();
    for (step = 1; step < steps; ++step) {
        if (!step_once(scene, &state, step)) {
            report_failure(scene, &state, "step");
            bench_state_destroy(&state);
            return false;
        }
    }
    r->ms[run] = 1000.0 * (seconds_now() - start) / (double)(steps - 1);

    counters = i2d_world_get_counters(state.world);
    if (i2d_last_status() != I2D_OK || !scene->sanity(&state, steps, &figure, &sane) ||
        !bench_state_hash(&state, &hash)) {
        report_failure(scene, &state, "reading the final state");
        bench_state_destroy(&state);
        return false;
    }
    r->bodies = counters.body_count;
    r->contacts = counters.contact_count;
    r->figure = figure;
    r->sane = r->sane && sane;
    if (run == 0) {
        r->hash = hash;
    }
    r->deterministic = r->deterministic && hash == r->hash;
    if (!bench_state_destroy(&state)) {
        report_failure(scene, &state, "i2d_world_destroy");
        return false;
    }
    return true;
}

static int compare_doubles(const void* a, const void* b) {
    double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

static void summarise_times(scene_result* r) {
    double sorted[MAX_REPEATS];
    int32_t n = r->repeats;
    memcpy(sorted, r->ms, (size_t)n * sizeof sorted[0]);
    qsort(sorted, (size_t)n, sizeof sorted[0], compare_doubles);
    r->min_ms = sorted[0];
    r->median_ms = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
}

static bool run_scene(const bench_scene* scene, const options* opt, scene_result* r) {
    int32_t run;
    memset(r, 0, sizeof *r);
    r->scene = scene;
    r->steps = opt->steps > 0 ? opt->steps : scene->steps;
    r->repeats = opt->repeats;
    r->sane = true;
    r->deterministic = true;
    for (run = 0; run < r->repeats; ++run) {
        if (!run_once(scene, r->steps, r, run)) {
            return false;
        }
    }
    summarise_times(r);
    return true;
}

/* ---- Output ----------------------------------------------------------------------------------- */

static const char* verdict(const scene_result* r) {
    if (!r->sane) {
        return "FAIL";
    }
    return r->deterministic ? "ok" : "NONDETERMINISTIC";
}

/* Writes s as a JSON string body (without quotes). */
static void json_string(const char* s) {
    for (; *s; ++s) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') {
            printf("\\%c", c);
        } else if (c < 0x20) {
            printf("\\u%04x", c);
        } else {
            putchar(c);
        }
    }
}

static void print_build(output_format format, const build_info* b) {
    if (format == FORMAT_JSON) {
        printf("{\"build\": {\"library\": \"%s\", \"compiler\": \"", b->library_version);
        json_string(BENCH_COMPILER);
        printf("\", \"library_compiler\": \"");
        json_string(I2D_BENCH_CXX_COMPILER);
        printf("\", \"build_type\": \"");
        json_string(I2D_BENCH_BUILD_TYPE);
        printf("\", \"c_flags\": \"");
        json_string(I2D_BENCH_C_FLAGS);
        printf("\", \"cxx_flags\": \"");
        json_string(I2D_BENCH_CXX_FLAGS);
        printf("\", \"library_options\": \"");
        json_string(I2D_BENCH_LIBRARY);
        printf("\", \"simd\": \"%s\", \"commit\": \"", simd_macros());
        json_string(I2D_BENCH_COMMIT);
        printf("\", \"date\": \"%s\", \"time_step\": %.6f, \"substeps\": %d},\n \"scenes\": [", b->date,
               (double)TIME_STEP, SUBSTEPS);
        return;
    }
    printf("# impulse2d %s bench | %s | library: %s, %s | %s | C flags: %s | C++ flags: %s | SIMD: %s"
           " | commit %s | %s\n",
           b->library_version, BENCH_COMPILER, I2D_BENCH_CXX_COMPILER, I2D_BENCH_LIBRARY, I2D_BENCH_BUILD_TYPE,
           I2D_BENCH_C_FLAGS, I2D_BENCH_CXX_FLAGS, simd_macros(), I2D_BENCH_COMMIT, b->date);
    if (format == FORMAT_CSV) {
        printf("scene,bodies,contacts,steps,repeats,median_ms,min_ms,sanity_name,sanity,verdict,hash\n");
    } else {
        printf("# dt 1/60 s, %d substeps; ms per step over steps 1..N-1, median and min of the runs\n", SUBSTEPS);
        printf("%-10s %7s %9s %6s %4s %11s %11s  %-20s %10s  %-7s %s\n", "scene", "bodies", "contacts", "steps",
               "runs", "median ms", "min ms", "sanity", "figure", "verdict", "final-state hash");
    }
}

static void print_result(output_format format, const scene_result* r, bool first) {
    const bench_scene* s = r->scene;
    if (format == FORMAT_JSON) {
        printf("%s\n  {\"scene\": \"%s\", \"bodies\": %d, \"contacts\": %d, \"steps\": %d, \"repeats\": %d, "
               "\"median_ms\": %.6f, \"min_ms\": %.6f, \"ms\": [",
               first ? "" : ",", s->name, (int)r->bodies, (int)r->contacts, (int)r->steps, (int)r->repeats,
               r->median_ms, r->min_ms);
        {
            int32_t i;
            for (i = 0; i < r->repeats; ++i) {
                printf("%s%.6f", i ? ", " : "", r->ms[i]);
            }
        }
        printf("], \"sanity_name\": \"%s\", \"sanity\": %.6g, \"sane\": %s, \"deterministic\": %s, "
               "\"hash\": \"%016llx\"}",
               s->sanity_name, r->figure, r->sane ? "true" : "false", r->deterministic ? "true" : "false",
               (unsigned long long)r->hash);
    } else if (format == FORMAT_CSV) {
        printf("%s,%d,%d,%d,%d,%.6f,%.6f,%s,%.6g,%s,%016llx\n", s->name, (int)r->bodies, (int)r->contacts,
               (int)r->steps, (int)r->repeats, r->median_ms, r->min_ms, s->sanity_name, r->figure, verdict(r),
               (unsigned long long)r->hash);
    } else {
        printf("%-10s %7d %9d %6d %4d %11.4f %11.4f  %-20s %10.4f  %-7s %016llx\n", s->name, (int)r->bodies,
               (int)r->contacts, (int)r->steps, (int)r->repeats, r->median_ms, r->min_ms, s->sanity_name, r->figure,
               verdict(r), (unsigned long long)r->hash);
    }
    fflush(stdout);
}

static void list_scenes(void) {
    int32_t i;
    for (i = 0; i < bench_scene_count; ++i) {
        printf("%-10s %5d steps  %s\n", bench_scenes[i].name, (int)bench_scenes[i].steps, bench_scenes[i].description);
    }
}

int main(int argc, char** argv) {
    static scene_result result; /* holds MAX_REPEATS times: static rather than on the stack */
    options opt;
    build_info build;
    int exit_code = EXIT_SANE;
    bool first = true;
    int32_t i;

    if (!parse_options(argc, argv, &opt)) {
        return EXIT_USAGE;
    }
    if (opt.list) {
        list_scenes();
        return EXIT_SANE;
    }
    if (i2d_version() != (uint32_t)I2D_VERSION) {
        fprintf(stderr, "impulse2d_bench: built against impulse2d %d.%d.%d but loaded another version\n",
                I2D_VERSION_MAJOR, I2D_VERSION_MINOR, I2D_VERSION_PATCH);
        return EXIT_API_ERROR;
    }
    build = describe_build();
    print_build(opt.format, &build);
    for (i = 0; i < bench_scene_count; ++i) {
        const bench_scene* scene = &bench_scenes[i];
        if (opt.scene && strcmp(opt.scene, scene->name) != 0) {
            continue;
        }
        if (!run_scene(scene, &opt, &result)) {
            exit_code = EXIT_API_ERROR;
            break;
        }
        print_result(opt.format, &result, first);
        first = false;
        if (!result.sane || !result.deterministic) {
            fprintf(stderr, "impulse2d_bench: scene %s: %s (%s = %g)\n", scene->name, verdict(&result),
                    scene->sanity_name, result.figure);
            exit_code = EXIT_INSANE;
        }
    }
    if (opt.format == FORMAT_JSON) {
        printf("\n]}\n");
    }
    return exit_code;
}
