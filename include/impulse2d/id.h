/* SPDX-License-Identifier: MIT */
/* Handles: small value-type ids for the world and everything in it. */
#ifndef IMPULSE2D_ID_H
#define IMPULSE2D_ID_H

#include <stdint.h>

/* An id is 8 bytes, copied by value. bits == 0 is the null id. The encoding is private:
 * it names the object's kind, its world and a generation, so that every call detects a
 * destroyed object, a destroyed world (even when its slot was reused) and an id of the
 * wrong kind, and answers I2D_ERR_INVALID_HANDLE instead of touching memory. */
typedef struct i2d_world_id { uint64_t bits; } i2d_world_id;
typedef struct i2d_body_id { uint64_t bits; } i2d_body_id;
typedef struct i2d_shape_id { uint64_t bits; } i2d_shape_id;
typedef struct i2d_chain_id { uint64_t bits; } i2d_chain_id;

#ifdef __cplusplus
#define I2D_NULL_WORLD_ID (i2d_world_id{0})
#define I2D_NULL_BODY_ID (i2d_body_id{0})
#define I2D_NULL_SHAPE_ID (i2d_shape_id{0})
#define I2D_NULL_CHAIN_ID (i2d_chain_id{0})
#else
#define I2D_NULL_WORLD_ID ((i2d_world_id){0})
#define I2D_NULL_BODY_ID ((i2d_body_id){0})
#define I2D_NULL_SHAPE_ID ((i2d_shape_id){0})
#define I2D_NULL_CHAIN_ID ((i2d_chain_id){0})
#endif

#define I2D_IS_NULL(id) ((id).bits == 0)
#define I2D_ID_EQUALS(a, b) ((a).bits == (b).bits)

#endif
