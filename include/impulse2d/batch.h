/* SPDX-License-Identifier: MIT */
/** @file batch.h
 *  Many worlds stepped in one call, as reinforcement learning steps its environments:
 *  hundreds of small worlds, each too small to share among threads on its own, shared
 *  out whole to the calling thread and a pool of workers. */
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

#ifdef __cplusplus
}
#endif

#endif
