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
 *  differs, instead of corrupting memory; i2d_get_field_infos below describes every
 *  member, so that a binding need not declare the structs at all. Always succeeds
 *  (I2D_OK); the table lives as long as the library; out may be NULL to ask only for
 *  the count. The structs come in include order, each after the structs it contains. */
I2D_API int32_t i2d_get_struct_infos(const i2d_struct_info** out);

/** How a binding reads a field described by i2d_field_info: its element type. The values
 *  are fixed; new kinds are only ever added at the end. */
typedef enum i2d_field_kind {
    I2D_FIELD_BOOL = 1, /**< C bool: one byte, 0 or 1 */
    I2D_FIELD_INT8,
    I2D_FIELD_INT16,
    I2D_FIELD_INT32,    /**< also every enum (type_name names it, e.g. "i2d_body_type") */
    I2D_FIELD_INT64,
    I2D_FIELD_UINT8,
    I2D_FIELD_UINT16,
    I2D_FIELD_UINT32,
    I2D_FIELD_UINT64,
    I2D_FIELD_FLOAT,    /**< IEEE 754 binary32 */
    I2D_FIELD_DOUBLE,   /**< IEEE 754 binary64 */
    I2D_FIELD_POINTER,  /**< a data pointer (void*, const char*, const i2d_vec2*, ...) */
    I2D_FIELD_FUNCTION, /**< a function pointer (type_name: its typedef, e.g. "i2d_task_fn") */
    I2D_FIELD_STRUCT    /**< a nested struct, described by its own rows (type_name) */
} i2d_field_kind;

/** One member of a public struct as the library was compiled: where it is and how to
 *  read it. An array member `T name[N]` is one row with count N. */
typedef struct i2d_field_info {
    const char* struct_name; /**< the struct's C name, as in i2d_struct_info.name */
    const char* field_name;  /**< the member's name, e.g. "gravity" */
    /** The member's C type as the header spells it, without const, pointer or array: a
     *  nested struct's name ("i2d_vec2"), a pointer's pointee ("void", "char",
     *  "i2d_contact_begin_event"), a function pointer's typedef ("i2d_enqueue_task_fn"),
     *  an enum's name ("i2d_body_type") or a scalar's ("float", "uint64_t"). */
    const char* type_name;
    int32_t offset;          /**< offsetof, in bytes */
    int32_t size;            /**< sizeof the member, in bytes: count elements of size / count bytes */
    int32_t count;           /**< 1, or N for an array member */
    i2d_field_kind kind;     /**< how to read one element */
} i2d_field_info;

/** Self-description for bindings, field by field: points *out at a static table with one
 *  row per member of every public struct and returns how many rows it has; out may be
 *  NULL to ask only for the count. Always succeeds (I2D_OK); the table and its strings
 *  live as long as the library.
 *
 *  The rows come struct by struct in i2d_get_struct_infos order, members in declaration
 *  order; a struct comes after every struct it contains, so a binding can build its
 *  struct types in one pass (ctypes Structures, typed views over wasm memory, ...) from
 *  the library it loaded rather than from declarations of its own, and a field added in a
 *  new version reaches it with no edit. A binding should still check, at load, that every
 *  field it reads or writes is there with the kind it expects. The table is generated
 *  from these headers (capi/gen_struct_fields.py); offsets and sizes are the compiler's. */
I2D_API int32_t i2d_get_field_infos(const i2d_field_info** out);

/** What a call did. Calls that act return it; every call also records it per thread. */
typedef enum i2d_status {
    I2D_OK = 0,
    I2D_ERR_INVALID_ARGUMENT, /**< NaN/inf, negative or zero size, uninitialised def, ... */
    I2D_ERR_INVALID_HANDLE,   /**< null, stale or foreign id */
    I2D_ERR_WORLD_LOCKED,     /**< called from inside a callback during a step or query */
    I2D_ERR_CAPACITY,         /**< a documented limit would be exceeded */
    I2D_ERR_OUT_OF_MEMORY,
    I2D_ERR_INTERNAL,         /**< a defect inside the library (an unexpected exception); please report it */
    I2D_ERR_INVALID_SNAPSHOT  /**< a snapshot or rollback state that is truncated, corrupted, foreign, of a
                                   newer format, or of a world whose structure changed (snapshot.h) */
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
