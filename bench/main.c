/* SPDX-License-Identifier: MIT */
/* The scene benchmark app: milliseconds per step of each scene, with its sanity figures beside it,
 * where the step's time went (the engine's own profile), and how the cost grows with body count.
 *
 * Method (shared/design/scenes.md, as Box2D v3's benchmark does): a new world per run; the first
 * step (hook + world step) untimed; then steps 1..N-1, each hook + world step timed with a
 * monotonic clock; ms per step = their total / (N - 1). A scene whose table row says
 * BENCH_SLEEP_FIRST (sleeping_pile) is first stepped, untimed, until no body is awake (at most
 * BENCH_SLEEP_LIMIT_S simulated), and its N steps are timed after that. The other scenes either
 * disable sleep (the solver scenes: they must never time a sleeping world) or run with it on,
 * as a game does, and the output says how many bodies were awake at the end. Each scene runs R
 * times; the median and the minimum over the runs are reported, and the 90th percentile of
 * single steps. The engine's profile (i2d_world_get_profile) is read after every timed step,
 * outside the clock. Times are never asserted on: the exit status says only whether every scene
 * ran and stayed sane (and gave the same final state in every run). */

#include "arguments.h"
#include "build_info.h"
#include "timing.h"
#include "scenes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_REPEATS 100
/* Single-step times kept for the p90; past this many the p90 is not computed. */
#define MAX_STEP_SAMPLES (16 * 1024 * 1024)

enum { EXIT_SANE = 0, EXIT_INSANE = 1, EXIT_USAGE = 2, EXIT_API_ERROR = 3 };

/* Where a step's time went: the engine's stages, its whole step, and the rest of the wall time
 * (the C API boundary and the scene's hook). */
typedef enum stage {
    STAGE_PAIRS,
    STAGE_COLLIDE,
    STAGE_SOLVE,
    STAGE_BOUNDS,
    STAGE_SLEEP,
    STAGE_EVENTS,
    STAGE_CONTINUOUS,
    STAGE_STEP,    /* the profile's whole step */
    STAGE_OUTSIDE, /* wall time of hook + i2d_world_step minus the profile's step */
    STAGE_COUNT
} stage;

static const char* const stage_names[STAGE_COUNT] = {"pairs", "collide", "solve",      "update_bounds", "sleep",
                                                     "events", "continuous", "step", "outside"};
#define ENGINE_STAGES 7 /* the first seven add up to the profile's step (within timer reads) */

#define STRINGIFY_(x) #x
#define STRINGIFY(x) STRINGIFY_(x)

/* By bench_sleep: its name in the output, and what it means for the figures. */
static const char* const sleep_names[] = {"off", "on", "first"};
static const char* const sleep_notes[] = {
    "sleep disabled for the solver scenes, so that none times a sleeping world",
    "sleep enabled, as a game runs; the awake column gives the bodies still awake after the last step",
    "stepped, untimed, until every body sleeps (at most " STRINGIFY(BENCH_SLEEP_LIMIT_S) " s simulated), then "
    "timed: the cost of a sleeping world",
};

/* ---- Options ------------------------------------------------------------------------------ */

typedef enum output_format { FORMAT_TABLE, FORMAT_CSV, FORMAT_JSON } output_format;

typedef enum selection { SELECT_DEFAULT, SELECT_SWEEP, SELECT_ALL } selection;

typedef struct options {
    int32_t steps;       /* 0: each scene's own count */
    int32_t repeats;
    int32_t workers;
    bool chosen[64];     /* by --scene; none chosen: by selection */
    bool any_chosen;
    selection select;
    output_format format;
    bool list;
} options;

static void usage(FILE* f) {
    fprintf(f,
            "usage: impulse2d_bench [--scene NAME[,NAME...]] [--sweep | --all] [--steps N] [--repeat R]\n"
            "                       [--workers W] [--simd PATH] [--no-recycling] [--idle-hooks] [--csv | --json]\n"
            "                       [--list]\n"
            "  (default)      the scenes of scenes.md the engine can run, then the extras\n"
            "  --scene NAMES  only these scenes (see --list); may be given more than once\n"
            "  --sweep        the scaling sweep: rain_circles and pyramid_field at 1k, 4k, 16k, 64k bodies\n"
            "  --all          every scene: scenes.md, extras and the sweep\n"
            "  --steps N      steps per run, N >= 2 (the first is untimed); default: each scene's own\n"
            "  --repeat R     runs per scene, each in a new world, 1..%d; default 3\n"
            "  --workers W    worker threads of each world, 1..64 (the built-in pool); default 1\n"
            "  --simd PATH    contact kernels: automatic (default), scalar, sse2, avx2, avx512, neon or wasm128\n"
            "  --no-recycling make every manifold afresh at every step (enable_contact_recycling off)\n"
            "  --idle-hooks   set both contact hooks on every world, no shape opting in (their idle cost)\n"
            "  --csv, --json  machine-readable output instead of the table\n"
            "  --list         list the scenes and exit\n"
            "exit status: 0 every scene sane, 1 a sanity check failed or a run differed, 2 bad usage,\n"
            "             3 an i2d call failed or a scene could not be set up (e.g. never fell asleep)\n",
            MAX_REPEATS);
}

/* Marks each scene of a comma-separated list. */
static bool choose_scenes(const char* list, options* opt) {
    char name[128];
    const char* p = list;
    while (*p) {
        const char* comma = strchr(p, ',');
        size_t n = comma ? (size_t)(comma - p) : strlen(p);
        const bench_scene* scene;
        if (n == 0 || n >= sizeof name) {
            fprintf(stderr, "impulse2d_bench: bad scene list '%s'\n", list);
            return false;
        }
        memcpy(name, p, n);
        name[n] = '\0';
        scene = bench_find_scene(name);
        if (!scene) {
            fprintf(stderr, "impulse2d_bench: no scene '%s' (--list shows them)\n", name);
            return false;
        }
        opt->chosen[scene - bench_scenes] = true;
        opt->any_chosen = true;
        p += n;
        if (*p == ',') {
            ++p;
        }
    }
    return true;
}

/* Sets bench_simd_path from its name; false (with a message) for an unknown or unsupported one. */
static bool parse_simd_path(const char* name) {
    static const char* const names[] = {"automatic", "scalar", "sse2", "avx2", "avx512", "neon", "wasm128"};
    int k;
    for (k = 0; k < 6; ++k) {
        if (strcmp(name, names[k]) == 0) {
            if (!i2d_simd_path_supported((i2d_simd_path)k)) {
                fprintf(stderr, "impulse2d_bench: --simd %s: not supported by this build or CPU\n", name);
                return false;
            }
            bench_simd_path = (i2d_simd_path)k;
            return true;
        }
    }
    fprintf(stderr, "impulse2d_bench: --simd %s: expected automatic, scalar, sse2, avx2, avx512, neon or wasm128\n", name);
    return false;
}

static bool parse_options(int argc, char** argv, options* opt) {
    int i;
    memset(opt, 0, sizeof *opt);
    opt->repeats = 3;
    opt->workers = 1;
    if (bench_scene_count > (int32_t)(sizeof opt->chosen / sizeof opt->chosen[0])) {
        fprintf(stderr, "impulse2d_bench: too many scenes for the option table\n");
        return false;
    }
    for (i = 1; i < argc; ++i) {
        const char* arg = argv[i];
        const char* value = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(arg, "--steps") == 0 && bench_parse_int(value, 2, 1000000, &opt->steps)) {
            ++i;
        } else if (strcmp(arg, "--repeat") == 0 && bench_parse_int(value, 1, MAX_REPEATS, &opt->repeats)) {
            ++i;
        } else if (strcmp(arg, "--workers") == 0 && bench_parse_int(value, 1, I2D_MAX_WORKERS, &opt->workers)) {
            bench_worker_count = opt->workers;
            ++i;
        } else if (strcmp(arg, "--simd") == 0 && value) {
            if (!parse_simd_path(value)) {
                return false;
            }
            ++i;
        } else if (strcmp(arg, "--no-recycling") == 0) {
            bench_contact_recycling = false;
        } else if (strcmp(arg, "--idle-hooks") == 0) {
            bench_idle_hooks = true;
        } else if (strcmp(arg, "--scene") == 0 && value) {
            if (!choose_scenes(value, opt)) {
                return false;
            }
            ++i;
        } else if (strcmp(arg, "--sweep") == 0) {
            opt->select = SELECT_SWEEP;
        } else if (strcmp(arg, "--all") == 0) {
            opt->select = SELECT_ALL;
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

static bool is_selected(const options* opt, int32_t index) {
    bench_group group = bench_scenes[index].group;
    if (opt->any_chosen) {
        return opt->chosen[index];
    }
    switch (opt->select) {
    case SELECT_SWEEP:
        return group == BENCH_GROUP_SWEEP;
    case SELECT_ALL:
        return true;
    default:
        return group != BENCH_GROUP_SWEEP;
    }
}

/* ---- Running a scene ------------------------------------------------------------------------ */

typedef struct scene_result {
    const bench_scene* scene;
    int32_t steps, repeats;
    int32_t dynamic_bodies;      /* the scene's dynamic bodies */
    int32_t bodies, contacts, pairs; /* the world's counters after the last step of the last run */
    int32_t awake, sleeping_islands; /* awake dynamic bodies and sleeping islands, likewise */
    int32_t warm_steps;          /* untimed steps before the timed ones, in the last run */
    double ms[MAX_REPEATS];      /* ms per timed step, one per run */
    double stage_ms[MAX_REPEATS][STAGE_COUNT]; /* per run: mean ms per timed step of each stage */
    double median_ms, min_ms, p90_ms;
    double stage_median[STAGE_COUNT];
    bench_sanity sanity;         /* the figures of the last run */
    bool sane;                   /* every run sane */
    uint64_t hash;               /* final state of the first run */
    bool deterministic;          /* every run ended in that state */
} scene_result;

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
    return i2d_world_step(state->world, BENCH_TIME_STEP, BENCH_SUBSTEPS) == I2D_OK;
}

/* The world must have the sleep setting that the scene's table row states. */
static bool check_sleep_setting(const bench_scene* scene, bench_state* state) {
    if (state->sleep_enabled != (scene->sleep != BENCH_SLEEP_OFF)) {
        state->error = "the world's enable_sleep differs from the scene table's sleep setting";
        return false;
    }
    return true;
}

/* Untimed: steps until no body is awake, counting the steps in state->warm_steps. Gives up after
 * BENCH_SLEEP_LIMIT_S simulated seconds. */
static bool wait_for_sleep(const bench_scene* scene, bench_state* state) {
    static char message[160];
    const int32_t limit = (int32_t)((float)BENCH_SLEEP_LIMIT_S / BENCH_TIME_STEP + 0.5f);
    for (;;) {
        i2d_world_counters counters = i2d_world_get_counters(state->world);
        if (i2d_last_status() != I2D_OK) {
            return false;
        }
        if (counters.awake_body_count == 0) {
            return true;
        }
        if (state->warm_steps >= limit) {
            snprintf(message, sizeof message, "%d bodies still awake after %.0f s simulated (%d steps); giving up",
                     (int)counters.awake_body_count, (double)BENCH_SLEEP_LIMIT_S, (int)state->warm_steps);
            state->error = message;
            return false;
        }
        if (!step_once(scene, state, state->warm_steps)) {
            return false;
        }
        state->warm_steps++;
    }
}

/* Creates the scene and runs its untimed steps: the first one (it pairs every shape for the first
 * time) and, in a BENCH_SLEEP_FIRST scene, every one until no body is awake. */
static bool start_run(const bench_scene* scene, bench_state* state) {
    if (!scene->create(state) || !check_sleep_setting(scene, state)) {
        report_failure(scene, state, "create");
        return false;
    }
    if (!step_once(scene, state, 0)) {
        report_failure(scene, state, "step 0");
        return false;
    }
    state->warm_steps = 1;
    if (scene->sleep == BENCH_SLEEP_FIRST && !wait_for_sleep(scene, state)) {
        report_failure(scene, state, "waiting for every body to sleep");
        return false;
    }
    return true;
}

/* Adds a timed step's profile to the stage sums; ms is the step's wall time. */
static void add_profile(const i2d_profile* p, double ms, double* stages) {
    stages[STAGE_PAIRS] += p->pairs;
    stages[STAGE_COLLIDE] += p->collide;
    stages[STAGE_SOLVE] += p->solve;
    stages[STAGE_BOUNDS] += p->update_bounds;
    stages[STAGE_SLEEP] += p->sleep;
    stages[STAGE_EVENTS] += p->events;
    stages[STAGE_CONTINUOUS] += p->continuous;
    stages[STAGE_STEP] += p->step;
    stages[STAGE_OUTSIDE] += ms - (double)p->step;
}

/* After the run's last step: the counters, the awake bodies, the sanity figures and the hash. */
static bool read_final_state(const bench_scene* scene, const bench_state* state, int32_t steps, scene_result* r,
                             int32_t run) {
    bench_sanity sanity;
    i2d_world_counters counters = i2d_world_get_counters(state->world);
    uint64_t hash = 0;
    int32_t awake = 0;
    memset(&sanity, 0, sizeof sanity);
    if (i2d_last_status() != I2D_OK || !scene->sanity(state, state->warm_steps - 1 + steps, &sanity) ||
        !bench_state_hash(state, &hash) || !bench_count_awake(state, &awake)) {
        report_failure(scene, state, "reading the final state");
        return false;
    }
    r->dynamic_bodies = state->body_count;
    r->bodies = counters.body_count;
    r->contacts = counters.contact_count;
    r->pairs = counters.pair_count;
    r->awake = awake;
    r->sleeping_islands = counters.sleeping_island_count;
    r->warm_steps = state->warm_steps;
    r->sanity = sanity;
    r->sane = r->sane && sanity.sane;
    if (run == 0) {
        r->hash = hash;
    }
    r->deterministic = r->deterministic && hash == r->hash;
    return true;
}

/* One run in a new world. Fills the run's time and stage times, the counters, the sanity figures
 * and the hash; appends each timed step's ms to samples (when not NULL). */
static bool run_once(const bench_scene* scene, int32_t steps, scene_result* r, int32_t run, double* samples) {
    bench_state state;
    double total = 0.0, stages[STAGE_COUNT];
    int32_t step, k;

    memset(&state, 0, sizeof state);
    memset(stages, 0, sizeof stages);
    if (!start_run(scene, &state)) {
        bench_state_destroy(&state);
        return false;
    }
    for (step = 1; step < steps; ++step) {
        double start = bench_seconds_now(), ms;
        i2d_profile p;
        if (!step_once(scene, &state, state.warm_steps - 1 + step)) {
            report_failure(scene, &state, "step");
            bench_state_destroy(&state);
            return false;
        }
        ms = 1000.0 * (bench_seconds_now() - start);
        total += ms;
        if (samples) {
            samples[step - 1] = ms;
        }
        p = i2d_world_get_profile(state.world);
        add_profile(&p, ms, stages);
    }
    r->ms[run] = total / (double)(steps - 1);
    for (k = 0; k < STAGE_COUNT; ++k) {
        r->stage_ms[run][k] = stages[k] / (double)(steps - 1);
    }
    if (!read_final_state(scene, &state, steps, r, run)) {
        bench_state_destroy(&state);
        return false;
    }
    if (!bench_state_destroy(&state)) {
        report_failure(scene, &state, "i2d_world_destroy");
        return false;
    }
    return true;
}

static void summarise(scene_result* r, double* samples, int32_t sample_count) {
    double sorted[MAX_REPEATS];
    int32_t n = r->repeats, k, i;
    memcpy(sorted, r->ms, (size_t)n * sizeof sorted[0]);
    r->median_ms = bench_sort_median(sorted, n);
    r->min_ms = sorted[0];
    for (k = 0; k < STAGE_COUNT; ++k) {
        for (i = 0; i < n; ++i) {
            sorted[i] = r->stage_ms[i][k];
        }
        r->stage_median[k] = bench_sort_median(sorted, n);
    }
    if (samples && sample_count > 0) {
        /* Nearest rank. */
        int32_t rank = (int32_t)ceil(0.9 * (double)sample_count);
        qsort(samples, (size_t)sample_count, sizeof samples[0], bench_compare_doubles);
        r->p90_ms = samples[(rank > 0 ? rank : 1) - 1];
    } else {
        r->p90_ms = NAN;
    }
}

static bool run_scene(const bench_scene* scene, const options* opt, scene_result* r) {
    double* samples = NULL;
    int32_t run, per_run;
    bool ok = true;
    memset(r, 0, sizeof *r);
    r->scene = scene;
    r->steps = opt->steps > 0 ? opt->steps : scene->steps;
    r->repeats = opt->repeats;
    r->sane = true;
    r->deterministic = true;
    per_run = r->steps - 1;
    if ((double)per_run * (double)r->repeats <= (double)MAX_STEP_SAMPLES) {
        samples = (double*)malloc((size_t)per_run * (size_t)r->repeats * sizeof *samples);
    }
    for (run = 0; run < r->repeats && ok; ++run) {
        ok = run_once(scene, r->steps, r, run, samples ? samples + (size_t)run * (size_t)per_run : NULL);
    }
    if (ok) {
        summarise(r, samples, samples ? per_run * r->repeats : 0);
    }
    free(samples);
    return ok;
}

/* ---- Derived figures -------------------------------------------------------------------------- */

/* The engine stage that took the most time, and its share of the profile's step. */
static int32_t dominant_stage(const scene_result* r, double* share) {
    int32_t k, best = 0;
    for (k = 1; k < ENGINE_STAGES; ++k) {
        if (r->stage_median[k] > r->stage_median[best]) {
            best = k;
        }
    }
    *share = r->stage_median[STAGE_STEP] > 0.0 ? r->stage_median[best] / r->stage_median[STAGE_STEP] : 0.0;
    return best;
}

/* ns of the solve stage per touching contact per substep (the last run's final contact count). */
static double solve_ns_per_contact(const scene_result* r) {
    return r->contacts > 0 ? 1e6 * r->stage_median[STAGE_SOLVE] / ((double)r->contacts * BENCH_SUBSTEPS) : NAN;
}

/* ns of the collide stage per pair (fat bounds overlapping) per step: it runs once a step. */
static double collide_ns_per_pair(const scene_result* r) {
    return r->pairs > 0 ? 1e6 * r->stage_median[STAGE_COLLIDE] / (double)r->pairs /* once per step */ : NAN;
}

/* Simulated seconds a BENCH_SLEEP_FIRST scene took to fall asleep (its untimed steps); NaN for
 * the other scenes. */
static double asleep_after_s(const scene_result* r) {
    return r->scene->sleep == BENCH_SLEEP_FIRST ? (double)r->warm_steps * (double)BENCH_TIME_STEP : NAN;
}

static const char* verdict(const scene_result* r) {
    if (!r->sane) {
        return "FAIL";
    }
    return r->deterministic ? "ok" : "NONDETERMINISTIC";
}

static const char* group_name(bench_group group) {
    switch (group) {
    case BENCH_GROUP_SCENES_MD:
        return "scenes.md";
    case BENCH_GROUP_EXTRA:
        return "extra";
    default:
        return "sweep";
    }
}

/* ---- Output ----------------------------------------------------------------------------------- */

/* A JSON number, or null for NaN and infinities (which JSON cannot hold). */
static void json_number(double value) {
    if (isfinite(value)) {
        printf("%.9g", value);
    } else {
        printf("null");
    }
}

/* Counts as integers, measures with 4 significant digits. */
static void print_sanity_text(const bench_sanity* s, const char* separator) {
    int32_t i;
    for (i = 0; i < s->figure_count; ++i) {
        double v = s->figures[i].value;
        if (v == floor(v) && fabs(v) < 1e9) {
            printf("%s%s=%.0f", i ? separator : "", s->figures[i].name, v);
        } else {
            printf("%s%s=%.4g", i ? separator : "", s->figures[i].name, v);
        }
    }
}

/* Notes that belong beside the figures: substitutions in the scenes run, and scenes.md scenes
 * that cannot run yet (when the run covers scenes.md). */
static void print_notes(const options* opt) {
    int32_t i;
    bool scenes_md = false, first = true;
    for (i = 0; i < bench_scene_count; ++i) {
        const bench_scene* s = &bench_scenes[i];
        if (!is_selected(opt, i)) {
            continue;
        }
        scenes_md = scenes_md || s->group == BENCH_GROUP_SCENES_MD;
        if (!s->substitution) {
            continue;
        }
        if (opt->format == FORMAT_JSON) {
            printf("%s{\"scene\": \"%s\", \"substitution\": \"", first ? "" : ", ", s->name);
            bench_json_string(stdout, s->substitution);
            printf("\"}");
            first = false;
        } else {
            printf("# SUBSTITUTION in %s: %s\n", s->name, s->substitution);
        }
    }
    if (opt->format == FORMAT_JSON) {
        printf("],\n \"not_run\": [");
    }
    first = true;
    for (i = 0; scenes_md && i < bench_missing_scene_count; ++i) {
        const bench_missing_scene* m = &bench_missing_scenes[i];
        if (opt->format == FORMAT_JSON) {
            printf("%s{\"scene\": \"%s\", \"reason\": \"", first ? "" : ", ", m->name);
            bench_json_string(stdout, m->reason);
            printf("\"}");
            first = false;
        } else {
            printf("# NOT RUN: %s (scenes.md): %s\n", m->name, m->reason);
        }
    }
}

/* The selected scenes of one sleep setting, as a JSON array or a comma-separated list; false when
 * there are none. */
static bool print_sleep_scenes(const options* opt, bench_sleep mode, bool json) {
    int32_t i;
    bool any = false;
    for (i = 0; i < bench_scene_count; ++i) {
        if (!is_selected(opt, i) || bench_scenes[i].sleep != mode) {
            continue;
        }
        printf(json ? "%s\"%s\"" : "%s%s", any ? ", " : "", bench_scenes[i].name);
        any = true;
    }
    return any;
}

/* Which scenes run with sleep off, on, or until asleep first: a line each (text and CSV), or the
 * members of the header's "sleep" object (JSON). */
static void print_sleep_notes(const options* opt) {
    int32_t mode;
    bool first = true;
    for (mode = BENCH_SLEEP_OFF; mode <= BENCH_SLEEP_FIRST; ++mode) {
        if (opt->format == FORMAT_JSON) {
            printf("%s\"%s\": {\"note\": \"%s\", \"scenes\": [", first ? "" : ", ", sleep_names[mode],
                   sleep_notes[mode]);
            print_sleep_scenes(opt, (bench_sleep)mode, true);
            printf("]}");
            first = false;
        } else {
            printf("# SLEEP %s (%s): ", sleep_names[mode], sleep_notes[mode]);
            if (!print_sleep_scenes(opt, (bench_sleep)mode, false)) {
                printf("no scene selected");
            }
            printf("\n");
        }
    }
}

/* The name of the contact kernels the scenes' worlds use (bench_simd_path, automatic resolved). */
static const char* simd_path_in_use(void) {
    static const char* const names[] = {"automatic", "scalar", "sse2", "avx2", "avx512", "neon", "wasm128"};
    i2d_world_def def = i2d_default_world_def();
    i2d_world_id world;
    i2d_simd_path path;
    def.simd_path = bench_simd_path;
    world = i2d_world_create(&def);
    path = i2d_world_get_simd_path(world);
    i2d_world_destroy(world);
    return (int)path >= 0 && (int)path < 6 ? names[path] : "unknown";
}

static void print_header(const options* opt) {
    if (opt->format == FORMAT_JSON) {
        printf("{\"build\": {");
        bench_print_build_json(stdout);
        printf(", \"time_step\": %.9g, \"substeps\": %d, \"workers\": %d},\n"
               " \"notes\": [",
               (double)BENCH_TIME_STEP, BENCH_SUBSTEPS, (int)opt->workers);
        print_notes(opt);
        printf("],\n \"sleep\": {");
        print_sleep_notes(opt);
        printf("},\n \"scenes\": [");
        return;
    }
    bench_print_build_line(stdout, "bench");
    printf("# dt 1/60 s, %d substeps (a solve and a relax pass each), %d worker%s, contact kernels %s, "
           "contact recycling %s, contact hooks %s\n",
           BENCH_SUBSTEPS, (int)opt->workers, opt->workers == 1 ? "" : "s", simd_path_in_use(),
           bench_contact_recycling ? "on" : "off", bench_idle_hooks ? "set, idle" : "unset");
    print_notes(opt);
    print_sleep_notes(opt);
    if (opt->format == FORMAT_CSV) {
        printf("scene,group,workers,dynamic_bodies,bodies,contacts,pairs,steps,repeats,median_ms,min_ms,p90_ms");
        printf(",profile_step_ms,pairs_ms,collide_ms,solve_ms,update_bounds_ms,sleep_ms,events_ms,continuous_ms,"
               "outside_ms");
        printf(",solve_ns_per_contact_substep,collide_ns_per_pair_step,sanity,verdict,hash");
        printf(",sleep,awake_bodies,sleeping_islands,asleep_after_s\n");
    } else {
        printf("# ms per step = time of steps 1..N-1 (hook + i2d_world_step) / (N - 1); median and min over the "
               "runs, each in a new world; p90 of single steps; bodies = dynamic bodies; contacts = touching "
               "pairs after the last step; awake = dynamic bodies awake after the last step\n");
        printf("%-17s %6s %6s %8s %5s %4s %10s %10s %10s  %-7s %-16s  %s\n", "scene", "bodies", "awake", "contacts",
               "steps", "runs", "median ms", "min ms", "p90 ms", "verdict", "final-state hash", "sanity");
    }
}

/* Text format: decimals of a row's ms figures, from its step's scale: 3, or 5 below 0.01 ms (a
 * sleeping world) so that its figures do not all read 0.000. */
static int ms_decimals(double ms) {
    return ms < 0.01 ? 5 : 3;
}

/* Text format: a note under a scene that timed bodies asleep without being meant to. */
static void print_sleep_warning(const scene_result* r) {
    if (r->scene->sleep == BENCH_SLEEP_FIRST || r->awake == r->dynamic_bodies) {
        return;
    }
    printf("# NOTE: %s: %d of %d bodies asleep after the last step (%d sleeping islands): its time is partly "
           "that of a sleeping world\n",
           r->scene->name, (int)(r->dynamic_bodies - r->awake), (int)r->dynamic_bodies, (int)r->sleeping_islands);
}

static void print_result(output_format format, int32_t workers, const scene_result* r, bool first) {
    const bench_scene* s = r->scene;
    int32_t i;
    if (format == FORMAT_JSON) {
        printf("%s\n  {\"scene\": \"%s\", \"group\": \"%s\", \"workers\": %d, \"dynamic_bodies\": %d, "
               "\"bodies\": %d, \"contacts\": %d, \"pairs\": %d, \"steps\": %d, \"repeats\": %d, "
               "\"median_ms\": %.6f, \"min_ms\": %.6f, \"p90_ms\": ",
               first ? "" : ",", s->name, group_name(s->group), (int)workers, (int)r->dynamic_bodies,
               (int)r->bodies, (int)r->contacts, (int)r->pairs, (int)r->steps, (int)r->repeats, r->median_ms,
               r->min_ms);
        json_number(r->p90_ms);
        printf(", \"ms\": [");
        for (i = 0; i < r->repeats; ++i) {
            printf("%s%.6f", i ? ", " : "", r->ms[i]);
        }
        printf("],\n   \"profile_median_ms\": {");
        for (i = 0; i < STAGE_COUNT; ++i) {
            printf("%s\"%s\": %.6f", i ? ", " : "", stage_names[i], r->stage_median[i]);
        }
        printf("}, \"solve_ns_per_contact_substep\": ");
        json_number(solve_ns_per_contact(r));
        printf(", \"collide_ns_per_pair_step\": ");
        json_number(collide_ns_per_pair(r));
        printf(",\n   \"sanity\": {");
        for (i = 0; i < r->sanity.figure_count; ++i) {
            printf("%s\"%s\": ", i ? ", " : "", r->sanity.figures[i].name);
            json_number(r->sanity.figures[i].value);
        }
        printf("}, \"sane\": %s, \"deterministic\": %s, \"hash\": \"%016llx\",\n   \"sleep\": \"%s\", "
               "\"awake_bodies\": %d, \"sleeping_islands\": %d, \"warm_up_steps\": %d, \"asleep_after_s\": ",
               r->sane ? "true" : "false", r->deterministic ? "true" : "false", (unsigned long long)r->hash,
               sleep_names[s->sleep], (int)r->awake, (int)r->sleeping_islands, (int)r->warm_steps);
        json_number(asleep_after_s(r));
        printf("}");
    } else if (format == FORMAT_CSV) {
        printf("%s,%s,%d,%d,%d,%d,%d,%d,%d,%.6f,%.6f,%.6f", s->name, group_name(s->group), (int)workers,
               (int)r->dynamic_bodies, (int)r->bodies, (int)r->contacts, (int)r->pairs, (int)r->steps,
               (int)r->repeats, r->median_ms, r->min_ms, r->p90_ms);
        printf(",%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f", r->stage_median[STAGE_STEP],
               r->stage_median[STAGE_PAIRS], r->stage_median[STAGE_COLLIDE], r->stage_median[STAGE_SOLVE],
               r->stage_median[STAGE_BOUNDS], r->stage_median[STAGE_SLEEP], r->stage_median[STAGE_EVENTS],
               r->stage_median[STAGE_CONTINUOUS], r->stage_median[STAGE_OUTSIDE]);
        printf(",%.3f,%.3f,\"", solve_ns_per_contact(r), collide_ns_per_pair(r));
        print_sanity_text(&r->sanity, ";");
        printf("\",%s,%016llx", verdict(r), (unsigned long long)r->hash);
        printf(",%s,%d,%d,%.4f\n", sleep_names[s->sleep], (int)r->awake, (int)r->sleeping_islands,
               asleep_after_s(r));
    } else {
        int d = ms_decimals(r->median_ms);
        printf("%-17s %6d %6d %8d %5d %4d %10.*f %10.*f %10.*f  %-7s %016llx  ", s->name, (int)r->dynamic_bodies,
               (int)r->awake, (int)r->contacts, (int)r->steps, (int)r->repeats, d, r->median_ms, d, r->min_ms, d,
               r->p90_ms, verdict(r), (unsigned long long)r->hash);
        print_sanity_text(&r->sanity, ", ");
        printf("\n");
        print_sleep_warning(r);
    }
    fflush(stdout);
}

/* Table format: where each scene's step went. */
static void print_profile_table(const scene_result* results, int32_t count) {
    int32_t i, k;
    printf("\n# engine profile (i2d_world_get_profile after each timed step): ms per step, median over the runs;\n"
           "# outside = wall time minus the profile's step (C API boundary, hook); per contact/pair figures use\n"
           "# the final counts and the %d substeps\n",
           BENCH_SUBSTEPS);
    printf("%-17s %8s %8s %8s %8s %8s %8s %8s %8s %8s  %-13s %14s %14s %6s\n", "scene", "step", "pairs", "collide",
           "solve", "bounds", "sleep", "events", "ccd", "outside", "dominant", "solve ns/c/ss", "collide ns/p/st",
           "ccd %");
    for (i = 0; i < count; ++i) {
        const scene_result* r = &results[i];
        double share;
        int32_t top = dominant_stage(r, &share);
        int d = ms_decimals(r->stage_median[STAGE_STEP]);
        char dominant[32];
        printf("%-17s %8.*f", r->scene->name, d, r->stage_median[STAGE_STEP]);
        for (k = 0; k < ENGINE_STAGES; ++k) {
            printf(" %8.*f", d, r->stage_median[k]);
        }
        snprintf(dominant, sizeof dominant, "%s %.0f%%", stage_names[top], 100.0 * share);
        /* The continuous collision stage's share of the profile's step. */
        printf(" %8.*f  %-13s %14.1f %14.1f %5.2f%%\n", d, r->stage_median[STAGE_OUTSIDE], dominant,
               solve_ns_per_contact(r), collide_ns_per_pair(r),
               r->stage_median[STAGE_STEP] > 0.0 ? 100.0 * r->stage_median[STAGE_CONTINUOUS] / r->stage_median[STAGE_STEP]
                                                 : 0.0);
    }
}

/* How the cost grows with body count, per sweep family, in the order the scenes ran. */
static void print_scaling(output_format format, const scene_result* results, int32_t count) {
    int32_t i, j;
    bool any = false, first = true;
    for (i = 0; i < count; ++i) {
        any = any || results[i].scene->family != NULL;
    }
    if (format == FORMAT_JSON) {
        printf("\n ],\n \"scaling\": [");
    } else if (format == FORMAT_TABLE && any) {
        printf("\n# scaling sweep: each size is ~4x the one before, so linear growth reads x4.0 per row\n");
        printf("%-14s %7s %10s %8s %14s %14s\n", "family", "bodies", "median ms", "x prev", "us/body/step",
               "contacts/body");
    }
    if (format == FORMAT_CSV) {
        return;
    }
    for (i = 0; i < count; ++i) {
        const scene_result* r = &results[i];
        const scene_result* prev = NULL;
        double growth, per_body;
        if (!r->scene->family) {
            continue;
        }
        for (j = i - 1; j >= 0; --j) {
            if (results[j].scene->family && strcmp(results[j].scene->family, r->scene->family) == 0) {
                prev = &results[j];
                break;
            }
        }
        growth = prev ? r->median_ms / prev->median_ms : NAN;
        per_body = 1000.0 * r->median_ms / (double)r->dynamic_bodies;
        if (format == FORMAT_JSON) {
            printf("%s\n  {\"family\": \"%s\", \"scene\": \"%s\", \"dynamic_bodies\": %d, \"median_ms\": %.6f, "
                   "\"growth\": ",
                   first ? "" : ",", r->scene->family, r->scene->name, (int)r->dynamic_bodies, r->median_ms);
            json_number(growth);
            printf(", \"us_per_body_step\": %.5f}", per_body);
            first = false;
        } else {
            char growth_text[16] = "-";
            if (prev) {
                snprintf(growth_text, sizeof growth_text, "x%.2f", growth);
            }
            printf("%-14s %7d %10.3f %8s %14.3f %14.2f\n", r->scene->family, (int)r->dynamic_bodies, r->median_ms,
                   growth_text, per_body, (double)r->contacts / (double)r->dynamic_bodies);
        }
    }
    if (format == FORMAT_JSON) {
        printf("\n ]}\n");
    }
}

static void list_scenes(void) {
    int32_t i;
    for (i = 0; i < bench_scene_count; ++i) {
        const bench_scene* s = &bench_scenes[i];
        printf("%-17s %-9s sleep %-5s %5d steps  %s\n", s->name, group_name(s->group), sleep_names[s->sleep],
               (int)s->steps, s->description);
        if (s->substitution) {
            printf("%-17s %-9s %11s %5s        substitution: %s\n", "", "", "", "", s->substitution);
        }
    }
    for (i = 0; i < bench_missing_scene_count; ++i) {
        printf("%-17s %-9s %11s %5s        not run: %s\n", bench_missing_scenes[i].name, "scenes.md", "", "",
               bench_missing_scenes[i].reason);
    }
}

int main(int argc, char** argv) {
    /* Up to one result per scene; static rather than on the stack (each holds MAX_REPEATS rows). */
    static scene_result results[64];
    options opt;
    int exit_code = EXIT_SANE;
    int32_t i, done = 0;

    if (!parse_options(argc, argv, &opt)) {
        return EXIT_USAGE;
    }
    if (opt.list) {
        list_scenes();
        return EXIT_SANE;
    }
    if (!bench_check_library_version("impulse2d_bench")) {
        return EXIT_API_ERROR;
    }
    print_header(&opt);
    for (i = 0; i < bench_scene_count; ++i) {
        const bench_scene* scene = &bench_scenes[i];
        scene_result* r = &results[done];
        if (!is_selected(&opt, i)) {
            continue;
        }
        if (!run_scene(scene, &opt, r)) {
            exit_code = EXIT_API_ERROR;
            break;
        }
        print_result(opt.format, opt.workers, r, done == 0);
        ++done;
        if (!r->sane || !r->deterministic) {
            fprintf(stderr, "impulse2d_bench: scene %s: %s (", scene->name, verdict(r));
            {
                int32_t k;
                for (k = 0; k < r->sanity.figure_count; ++k) {
                    fprintf(stderr, "%s%s = %g", k ? ", " : "", r->sanity.figures[k].name, r->sanity.figures[k].value);
                }
            }
            fprintf(stderr, ")\n");
            exit_code = EXIT_INSANE;
        }
    }
    if (opt.format == FORMAT_TABLE && done > 0) {
        print_profile_table(results, done);
    }
    print_scaling(opt.format, results, done);
    return exit_code;
}
