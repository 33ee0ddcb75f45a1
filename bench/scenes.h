/* SPDX-License-Identifier: MIT */
/* Benchmark scenes, built through the public C API so that the benchmark measures what users get.
 *
 * A scene is a row of a table: a name, a builder, an optional per-step hook (game logic that is
 * timed with the step, as Box2D's benchmark times its spawning), a default step count and a
 * sanity check whose figures are printed beside the time, so that a fast but broken run shows.
 * The scenes of shared/design/scenes.md are rebuilt exactly (geometry, masses, materials); the
 * others are extras, said to be so. */
#ifndef IMPULSE2D_BENCH_SCENES_H
#define IMPULSE2D_BENCH_SCENES_H

#include <impulse2d/impulse2d.h>

/* Every scene steps at 1/60 s with 4 substeps (scenes.md). */
#define BENCH_TIME_STEP (1.0f / 60.0f)
#define BENCH_SUBSTEPS 4

/* The SIMD path every scene's world uses (the bench's --simd); automatic by default. */
extern i2d_simd_path bench_simd_path;
/* Whether the scenes' worlds recycle contact manifolds (the bench's --no-recycling turns it off). */
extern bool bench_contact_recycling;
/* Worker threads of every scene's world (the built-in pool when above 1). */
extern int32_t bench_worker_count;
/* Whether every scene's world has both contact hooks set, no shape opting in (--idle-hooks). */
extern bool bench_idle_hooks;

/* The world of one run and what its hook and sanity check need to find in it. */
typedef struct bench_state {
    i2d_world_id world;
    i2d_body_id* bodies;     /* the dynamic bodies, in creation order */
    float* start_x;          /* each dynamic body's starting position, m */
    float* start_y;
    int32_t body_count;
    int32_t body_capacity;
    int32_t* marks;          /* indices into bodies of the bodies the sanity check follows */
    int32_t mark_count;      /* (the top box of each pyramid) */
    i2d_aabb region;         /* where every dynamic body must stay (the sanity check) */
    i2d_body_id mover;       /* a driven body (the small scene's kinematic platform, the tumbler's
                                drum, the spinner's blade); null when none */
    i2d_vec2 mover_start;
    i2d_joint_id* joints;    /* joints the sanity check measures (joint_grid, rain); may be NULL */
    int32_t joint_count;
    int32_t joint_capacity;
    void* scene_data;        /* what a scene's hook keeps between steps (rain's columns); freed with
                                the state */
    bool sleep_enabled;      /* the world's enable_sleep, as create set it */
    /* Untimed steps before the timed ones: 1 (the first step), or, in a scene that waits for
     * sleep, every step until no body was awake. Set by the runner. */
    int32_t warm_steps;
    /* Set when a failure did not come from an i2d_ call (then read i2d_last_error_message()). */
    const char* error;
} bench_state;

#define BENCH_MAX_FIGURES 4

/* One number of a sanity check, with its name (unit included). */
typedef struct bench_figure {
    const char* name;
    double value;
} bench_figure;

typedef struct bench_sanity {
    bench_figure figures[BENCH_MAX_FIGURES];
    int32_t figure_count;
    bool sane;
} bench_sanity;

typedef enum bench_group {
    BENCH_GROUP_SCENES_MD, /* a scene of scenes.md, rebuilt exactly (or with a stated substitution) */
    BENCH_GROUP_EXTRA,     /* not from scenes.md: a small game scene, a resting grid */
    BENCH_GROUP_SWEEP      /* the scaling sweep: one family at 1k, 4k, 16k and 64k bodies */
} bench_group;

/* What a scene's world does with resting bodies. */
typedef enum bench_sleep {
    BENCH_SLEEP_OFF,   /* sleep disabled: the scene times the solver, never a sleeping world */
    BENCH_SLEEP_ON,    /* sleep enabled, as a game runs: bodies may fall asleep during the run */
    BENCH_SLEEP_FIRST  /* sleep enabled, and the runner steps (untimed) until every body sleeps */
} bench_sleep;

/* The longest a BENCH_SLEEP_FIRST scene may take to fall asleep, whole simulated seconds. */
#define BENCH_SLEEP_LIMIT_S 20

typedef struct bench_scene {
    const char* name;
    bench_group group;
    const char* family;      /* sweep scenes: the family's name; NULL otherwise */
    int32_t nominal_bodies;  /* sweep scenes: 1000, 4000, ...; 0 otherwise */
    const char* description;
    /* A departure from scenes.md that the output must state beside the figures; NULL when none. */
    const char* substitution;
    bench_sleep sleep;       /* must match the enable_sleep that create gives the world */
    int32_t steps;           /* default step count */
    /* Creates the world and the scene in state (zeroed by the caller). False on failure. */
    bool (*create)(bench_state* state);
    /* Runs before world step number `step` (0-based); NULL when the scene has none. */
    bool (*step_hook)(bench_state* state, int32_t step);
    /* After `steps_run` steps: the scene's figures and whether it is sane. False on failure. */
    bool (*sanity)(const bench_state* state, int32_t steps_run, bench_sanity* out);
} bench_scene;

extern const bench_scene bench_scenes[];
extern const int32_t bench_scene_count;

/* The scenes of scenes.md that are not built yet, and why (none since joints came; the table keeps
 * the place for the next scene that cannot run). */
typedef struct bench_missing_scene {
    const char* name;
    const char* reason;
} bench_missing_scene;

extern const bench_missing_scene bench_missing_scenes[];
extern const int32_t bench_missing_scene_count;

const bench_scene* bench_find_scene(const char* name);

/* Destroys the world (if any) and frees the arrays; leaves state zeroed. False if the destroy failed. */
bool bench_state_destroy(bench_state* state);

/* FNV-1a over the bits of every dynamic body's position, rotation and velocities, in creation
 * order: equal inputs on the same binary must give equal hashes. False on failure. */
bool bench_state_hash(const bench_state* state, uint64_t* hash);

/* How many of the dynamic bodies are awake. False on failure. */
bool bench_count_awake(const bench_state* state, int32_t* awake);

#endif
