/* SPDX-License-Identifier: MIT */
/* Export macro, version and status codes: what every other public header needs. */
#ifndef IMPULSE2D_BASE_H
#define IMPULSE2D_BASE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
#define I2D_EXTERN_C extern "C"
#else
#define I2D_EXTERN_C extern
#endif

#if defined(I2D_STATIC_LIBRARY)
#define I2D_EXPORT
#elif defined(_WIN32)
#if defined(impulse2d_EXPORTS)
#define I2D_EXPORT __declspec(dllexport)
#else
#define I2D_EXPORT __declspec(dllimport)
#endif
#else
#define I2D_EXPORT __attribute__((visibility("default")))
#endif

/** Marks every function the library exports. */
#define I2D_API I2D_EXTERN_C I2D_EXPORT

#define I2D_VERSION_MAJOR 0
#define I2D_VERSION_MINOR 2
#define I2D_VERSION_PATCH 0
/** Packed as (major << 16) | (minor << 8) | patch, the same packing as i2d_version(). */
#define I2D_VERSION ((I2D_VERSION_MAJOR << 16) | (I2D_VERSION_MINOR << 8) | I2D_VERSION_PATCH)

/** The version of the library actually loaded; compare with I2D_VERSION at start-up. */
I2D_API uint32_t i2d_version(void);

/** The size and alignment, in bytes, of one public struct as the library was compiled. */
typedef struct i2d_struct_info {
    const char* name; /**< the struct's C name, e.g. "i2d_body_def" */
    int32_t size;     /**< sizeof */
    int32_t align;    /**< alignof */
} i2d_struct_info;

/** Self-description for bindings: points *out at a static table describing every public
 *  struct (i2d_vec2 ... i2d_struct_info itself) and returns how many rows it has. A
 *  binding that declares the structs itself (ctypes, cffi, P/Invoke, ...) compares its
 *  own sizes and alignments with this table at load time and refuses a library that
 *  differs, instead of corrupting memory. The table lives as long as the library; out
 *  may be NULL to ask only for the count. */
I2D_API int32_t i2d_get_struct_infos(const i2d_struct_info** out);

/** What a call did. Calls that act return it; every call also records it per thread. */
typedef enum i2d_status {
    I2D_OK = 0,
    I2D_ERR_INVALID_ARGUMENT, /**< NaN/inf, negative or zero size, uninitialised def, ... */
    I2D_ERR_INVALID_HANDLE,   /**< null, stale or foreign id */
    I2D_ERR_WORLD_LOCKED,     /**< called from inside a callback during a step or query */
    I2D_ERR_CAPACITY,         /**< a documented limit would be exceeded */
    I2D_ERR_OUT_OF_MEMORY,
    I2D_ERR_INTERNAL          /**< a defect inside the library (an unexpected exception); please report it */
} i2d_status;

/** A fixed English name for a status, e.g. "I2D_ERR_INVALID_HANDLE". Never NULL: a value
 *  outside the enumeration (any int a caller passes) gives "I2D_UNKNOWN_STATUS". */
I2D_API const char* i2d_status_string(i2d_status status);
/** The status of the last i2d_ call made on this thread. */
I2D_API i2d_status i2d_last_status(void);
/** Detail for the last status on this thread, e.g. "body def: position.x is NaN".
 *  Empty after a successful call. Valid until the next i2d_ call on this thread. */
I2D_API const char* i2d_last_error_message(void);

#endif
