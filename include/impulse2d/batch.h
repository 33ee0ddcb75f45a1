/* SPDX-License-Identifier: MIT */
/** @file batch.h
 *  Many worlds stepped in one call, as reinforcement learning steps its environments:
 *  hundreds of small worlds, each too small to share among threads on its own, shared
 *  out whole to the calling thread and a pool of workers; and their bodies' state and
 *  their events read and written in one call each. */
#ifndef IMPULSE2D_BATCH_H
#define IMPULSE2D_BATCH_H

#include "base.h"
#include "id.h"
#include "types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** How i2d_worlds_step shares the worlds out. Obtain with i2d_default_batch_def(). */
typedef struct i2d_batch_def {
    /** Threads that step worlds, the calling thread among them; default 1 (the calling
     *  thread alone). Range [1, I2D_MAX_WORKERS]. Without a job system, worker_count > 1
     *  uses a pool of worker_count - 1 threads that the library starts at the first such
     *  call and keeps for later calls with the same count (a pool busy with another
     *  thread's batch is not shared: that batch gets a pool of its own). */
    int32_t worker_count;
    /** Your job system (both or neither), called as a world's are (types.h): the batch
     *  enqueues one task per worker beyond the first and works as worker 0 itself. */
    i2d_enqueue_task_fn* enqueue_task;
    i2d_finish_task_fn* finish_task;
    /** Passed to enqueue_task and finish_task; default NULL. */
    void* user_task_context;
    /** Set by i2d_default_batch_def; a def not made by it is refused. */
    uint32_t internal_cookie;
} i2d_batch_def;

/** worker_count 1, no job system. */
I2D_API i2d_batch_def i2d_default_batch_def(void);

/** Steps count worlds by the same time step and substeps, as i2d_world_step would step
 *  each: each world is stepped whole by one worker (its own worker_count still applies
 *  inside it), so its bits, events and recordings are the same as when stepped alone.
 *  Workers take the next unstepped world as they finish one, so worlds of different
 *  sizes share out evenly.
 *
 *  Refused as a whole, nothing stepped, with a status and a message naming the index:
 *  count outside [0, I2D_MAX_WORLDS], worlds NULL with count > 0, a null, stale or
 *  non-world id, a world listed twice, a locked world (inside a query or draw callback,
 *  or inside a step), and the time step and substeps i2d_world_step refuses; a NULL or
 *  uninitialised def, a worker_count out of range or half a job system. count 0 is a
 *  valid empty batch.
 *
 *  Until the call returns every world in it counts as stepping: contact hooks and job
 *  system callbacks (which run on the workers) get I2D_ERR_WORLD_LOCKED from calls that
 *  name any world of the batch. Out of memory in one world's step: that world stops
 *  there as after a failed i2d_world_step, the others are stepped, and the call answers
 *  I2D_ERR_OUT_OF_MEMORY. */
I2D_API i2d_status i2d_worlds_step(const i2d_world_id* worlds, int32_t count, float time_step,
                                   int32_t substep_count, const i2d_batch_def* def);

/* ---- Bodies and events of many worlds per call ---------------------------------- */
/* What a batch of environments reads and writes every frame, one call for all of them
 * instead of one per world: the bulk state calls of impulse2d.h for bodies of any worlds
 * (each id names its own world), and the worlds' event counts. Every id is checked
 * first: a null, stale or wrong-kind id stops the call with I2D_ERR_INVALID_HANDLE and
 * a message naming its index ("bodies[7]: ..."), a bad value with
 * I2D_ERR_INVALID_ARGUMENT naming the element; a refused call writes nothing, neither
 * the output arrays nor any world. count 0 does nothing (the pointers may then be
 * NULL); a negative count is refused. */

/** Copies the transform, the velocities (linear: m/s of the centre of mass; angular:
 *  rad/s) and whether it is awake of each of bodies[0..count). Any of the four arrays
 *  may be NULL to skip it. */
I2D_API i2d_status i2d_worlds_get_body_states(const i2d_body_id* bodies, int32_t count, i2d_transform* transforms,
                                              i2d_vec2* linear, float* angular, bool* awake);
/** Sets the velocities of bodies[0..count) as i2d_world_set_body_velocities does in each
 *  body's world (finite values only; ignored for static bodies, and the spin for
 *  fixed-rotation ones, but still checked; a non-zero velocity wakes a sleeping body; a
 *  body listed twice gets its last values). Either array may be NULL. Refused, nothing
 *  set, when any of the worlds is locked. */
I2D_API i2d_status i2d_worlds_set_body_velocities(const i2d_body_id* bodies, int32_t count, const i2d_vec2* linear,
                                                  const float* angular);
/** For each of worlds[0..count), how many contact begin and end events its last step
 *  gave (the counts i2d_world_get_contact_events reports), so that only the worlds with
 *  some need their events read. Either array may be NULL. */
I2D_API i2d_status i2d_worlds_get_contact_event_counts(const i2d_world_id* worlds, int32_t count,
                                                        int32_t* begin_counts, int32_t* end_counts);

#ifdef __cplusplus
}
#endif

#endif
