/* SPDX-License-Identifier: MIT */
/** @file snapshot.h
 *  Snapshots: a world saved to bytes and brought back, in place or as a new world.
 *
 *  A snapshot is a portable byte image of one world between steps: every body, shape,
 *  chain, joint, contact (with the impulses it warm starts from), island, sleep timer,
 *  broadphase tree and setting. Restoring it and stepping gives the same bits as never
 *  having saved: in this process or another, on x86-64, AArch64 or WebAssembly, with any
 *  SIMD path and any worker count. The format is little-endian and versioned, with a
 *  magic and a checksum; a newer library reads every older format.
 *
 *  What a snapshot does not hold: the host's wiring (worker_count, task callbacks,
 *  simd_path, enable_profile), which stays the world's own, and the events of the last
 *  step (the arrays are empty after a restore; ends caused between steps before the save
 *  still reach the next step's arrays). User data travels as its 64-bit value: a pointer
 *  means nothing in another process, so bind it again there (i2d_body_set_user_data).
 *
 *  A refused buffer (truncated, corrupted in any byte, not a snapshot, of a newer format,
 *  or describing a world that could not be stepped) answers I2D_ERR_INVALID_SNAPSHOT with
 *  a message saying what is wrong, and the world is exactly as it was: a restore reads
 *  the whole snapshot aside and checks it before the world changes. */
#ifndef IMPULSE2D_SNAPSHOT_H
#define IMPULSE2D_SNAPSHOT_H

#include <stddef.h>

#include "base.h"
#include "id.h"
#include "joint.h"
#include "types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The bytes a snapshot of the world takes now; 0 on a bad id (the status says why). */
I2D_API size_t i2d_world_get_snapshot_size(i2d_world_id world);

/** Saves a snapshot into buffer. `written` (may be NULL) receives its size; when
 *  capacity is less than i2d_world_get_snapshot_size, I2D_ERR_INVALID_ARGUMENT is
 *  returned, `written` receives the size needed and the buffer holds no snapshot (its
 *  header is zeroed; the rest may have been written). Reading
 *  only: allowed inside query callbacks, refused inside a step's job callbacks. */
I2D_API i2d_status i2d_world_save_snapshot(i2d_world_id world, void* buffer, size_t capacity, size_t* written);

/** Replaces the world's state with a snapshot's. The world keeps its id and its host
 *  wiring; ids of bodies, shapes, joints and chains that existed at the save are valid
 *  again (same index and generation), ids made after it are stale. Refused inside
 *  callbacks (I2D_ERR_WORLD_LOCKED); a bad buffer gets I2D_ERR_INVALID_SNAPSHOT and leaves
 *  the world untouched. */
I2D_API i2d_status i2d_world_restore_snapshot(i2d_world_id world, const void* buffer, size_t size);

/** A new world from a snapshot. Its ids keep the snapshot's indices and generations but
 *  name the new world (i2d_body_in_world and the like translate them). `runtime`: the
 *  world def whose host wiring (worker_count, task callbacks, simd_path, enable_profile)
 *  the new world takes; NULL for the defaults; its simulation fields are checked but not
 *  used: the snapshot's settings are. I2D_NULL_WORLD_ID, with the status set, when the
 *  buffer or the def is refused or 256 worlds are alive. */
I2D_API i2d_world_id i2d_world_create_from_snapshot(const void* buffer, size_t size, const i2d_world_def* runtime);

/** Rollback states: what a step changes (poses, velocities, forces, sleep, contacts and
 *  their impulses, joint impulses, islands, the broadphase), for rolling back a few frames
 *  in a netcode or resetting an environment thousands of times. A state belongs to the
 *  world it was saved from, as its structure stood: restoring it into another world, or
 *  after a body, shape, joint or chain was made, destroyed or changed there, or a world
 *  setting (gravity) was changed, is refused with I2D_ERR_INVALID_SNAPSHOT. Stepping after
 *  a restore gives the same bits as stepping from the moment it was saved. A state is not
 *  portable between processes: save a full snapshot for that. */
I2D_API size_t i2d_world_get_state_size(i2d_world_id world);
/** As i2d_world_save_snapshot, for a rollback state. */
I2D_API i2d_status i2d_world_save_state(i2d_world_id world, void* buffer, size_t capacity, size_t* written);
/** Brings the world back to a rollback state saved from it. A refused state (another
 *  world's, saved before a structural change, truncated or corrupted in any byte) answers
 *  I2D_ERR_INVALID_SNAPSHOT with a message, and the world is as it was. A state whose bytes
 *  are not those of one of the world's recent saves is checked as a snapshot is (its
 *  lists and links, and every value against the rule of the call that sets it); one the
 *  world saved restores without those checks. Refused inside callbacks
 *  (I2D_ERR_WORLD_LOCKED). */
I2D_API i2d_status i2d_world_restore_state(i2d_world_id world, const void* buffer, size_t size);

/** The same object in another world made from a snapshot that held it (same index and
 *  generation): a null id, with I2D_OK, when that world has no such object;
 *  I2D_ERR_INVALID_HANDLE for an id of another kind or a dead world. */
I2D_API i2d_body_id i2d_body_in_world(i2d_body_id body, i2d_world_id world);
I2D_API i2d_shape_id i2d_shape_in_world(i2d_shape_id shape, i2d_world_id world);
I2D_API i2d_joint_id i2d_joint_in_world(i2d_joint_id joint, i2d_world_id world);
I2D_API i2d_chain_id i2d_chain_in_world(i2d_chain_id chain, i2d_world_id world);

/* ---- Recording and replay ---------------------------------------------------------- */

/** Receives a recording's bytes as they are made, a whole record at a time; append them
 *  to a file or a buffer. It runs with the world locked: it may not call the library on
 *  that world. */
typedef void i2d_write_fn(const void* bytes, size_t size, void* context);

/** Starts recording the world: `write` receives at once a header and a full snapshot,
 *  then every call that changes the world (creations, destructions, setters, forces,
 *  impulses, bulk writes, restores) and every step with the state hash it produced, as
 *  they happen. The format is little-endian and versioned, each record with a checksum
 *  (docs/snapshots.md). A world that already records starts again with the new writer.
 *  Refused inside callbacks (I2D_ERR_WORLD_LOCKED); `write` NULL: I2D_ERR_INVALID_ARGUMENT.
 *  Recording costs a state hash per step and a few bytes per call. */
I2D_API i2d_status i2d_world_start_recording(i2d_world_id world, i2d_write_fn* write, void* context);
/** Stops recording; I2D_OK if it was not recording. */
I2D_API i2d_status i2d_world_stop_recording(i2d_world_id world);

/** A recording being replayed. */
typedef struct i2d_replay_id {
    uint64_t bits;
} i2d_replay_id;

/** Opens a recording (its bytes are copied) and makes its world from the snapshot it
 *  starts with: step 0. `runtime`: the host wiring, as for i2d_world_create_from_snapshot.
 *  A refused recording (not a recording, a newer format, a record whose checksum does not
 *  match, a first snapshot refused) gives a null id and I2D_ERR_INVALID_SNAPSHOT; a last
 *  record cut short (a program that stopped mid-write) is left out. At most 64 replays are
 *  open at once (I2D_ERR_CAPACITY). */
I2D_API i2d_replay_id i2d_replay_open(const void* recording, size_t size, const i2d_world_def* runtime);
/** The replay's world, to read (or draw) as the replay goes; it belongs to the replay. */
I2D_API i2d_world_id i2d_replay_get_world(i2d_replay_id replay);
/** Replays up to step_count more steps, each with the calls recorded before it, checking
 *  the hash after each. Returns the steps run: fewer at the recording's end, or when a
 *  step's hash differs from the recorded one (that step is then the divergent step; the
 *  next call goes on from there). A call the replay world refuses (a recording changed
 *  behind its checksums) stops the replay with I2D_ERR_INVALID_SNAPSHOT. */
I2D_API int32_t i2d_replay_step(i2d_replay_id replay, int32_t step_count);
/** Steps replayed so far: the world is as it was after that many recorded steps. */
I2D_API int32_t i2d_replay_get_step(i2d_replay_id replay);
/** Steps in the recording. */
I2D_API int32_t i2d_replay_get_step_count(i2d_replay_id replay);
/** The first step whose hash differed from the recording's (1 for the first step), or -1. */
I2D_API int32_t i2d_replay_get_divergent_step(i2d_replay_id replay);
/** Brings the replay to step `step` (0 to the step count), backwards too (from the first
 *  snapshot again). Step k is the state after k recorded steps, before the calls recorded
 *  after it. Divergences met on the way are noted, not stopped at. */
I2D_API i2d_status i2d_replay_seek(i2d_replay_id replay, int32_t step);
/** Closes the replay and destroys its world. */
I2D_API i2d_status i2d_replay_close(i2d_replay_id replay);

#ifdef __cplusplus
}
#endif

#endif /* IMPULSE2D_SNAPSHOT_H */
