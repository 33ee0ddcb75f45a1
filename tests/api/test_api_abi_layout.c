/* SPDX-License-Identifier: MIT */
/* The ABI binding authors rely on: size and alignment of every public struct, and
 * offset, size, element count and kind of every member, recorded in abi_layout.def for
 * x86-64 (System V, LP64). The record is checked against the library's own description
 * (i2d_get_struct_infos, i2d_get_field_infos), so no struct or field can be left out: one
 * the record lacks fails, printing the exact line to add, and a recorded value that
 * changed fails, printing the old and the new line. Elsewhere the recorded values are not
 * compared (the contract fixes only the ids' size there) but the names still are, and
 * the library's description is checked against this C compiler everywhere. */
#include <impulse2d/impulse2d.h>

#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "check.h"

#if defined(__x86_64__) || defined(_M_X64)
#define RECORDED_PLATFORM 1
#else
#define RECORDED_PLATFORM 0
#endif

/* Alignment without C11's _Alignof: the offset of a member placed after one char, in a
 * probe struct named after the record's line. */
#define ALIGN_PROBE_NAME(line) abi_align_probe_##line
#define ALIGN_PROBE(line) ALIGN_PROBE_NAME(line)
#define DECLARE_PROBE(type) \
    typedef struct {        \
        char c;             \
        type t;             \
    } ALIGN_PROBE(__LINE__);

#define STRUCT(type, size, align) DECLARE_PROBE(type)
#define TYPE(type, size, align) DECLARE_PROBE(type)
#define FIELD(type, field, offset, size, count, kind, type_name)
#include "abi_layout.def"
#undef STRUCT
#undef TYPE
#undef FIELD

typedef struct recorded_type {
    const char* name;
    int32_t size, align; /* as recorded */
    int described;       /* a STRUCT row (in i2d_get_struct_infos), not a TYPE row */
    size_t c_size, c_align; /* as this C compiler lays it out */
    int line;
} recorded_type;

typedef struct recorded_field {
    const char* struct_name;
    const char* field_name;
    int32_t offset, size, count;
    int32_t kind;
    const char* type_name;
    size_t c_offset, c_size;
    int line;
} recorded_field;

static const recorded_type recorded_types[] = {
#define STRUCT(type, size, align) {#type, size, align, 1, sizeof(type), offsetof(ALIGN_PROBE(__LINE__), t), __LINE__},
#define TYPE(type, size, align) {#type, size, align, 0, sizeof(type), offsetof(ALIGN_PROBE(__LINE__), t), __LINE__},
#define FIELD(type, field, offset, size, count, kind, type_name)
#include "abi_layout.def"
#undef STRUCT
#undef TYPE
#undef FIELD
};

static const recorded_field recorded_fields[] = {
#define STRUCT(type, size, align)
#define TYPE(type, size, align)
#define FIELD(type, field, offset, size, count, kind, type_name)                                   \
    {#type, #field, offset, size, count, I2D_FIELD_##kind, #type_name, offsetof(type, field), \
     sizeof(((type*)0)->field), __LINE__},
#include "abi_layout.def"
#undef STRUCT
#undef TYPE
#undef FIELD
};

#define COUNT_OF(array) ((int32_t)(sizeof(array) / sizeof((array)[0])))

static const char* kind_name(int32_t kind) {
    static const char* const names[] = {"?",     "BOOL",   "INT8",   "INT16",   "INT32",    "INT64", "UINT8",
                                        "UINT16", "UINT32", "UINT64", "FLOAT",  "DOUBLE",   "POINTER",
                                        "FUNCTION", "STRUCT"};
    return kind >= I2D_FIELD_BOOL && kind <= I2D_FIELD_STRUCT ? names[kind] : "?";
}

/* The record's line for a library row. */
static void struct_line(char* out, size_t capacity, const i2d_struct_info* s) {
    snprintf(out, capacity, "STRUCT(%s, %d, %d)", s->name, (int)s->size, (int)s->align);
}

static void field_line(char* out, size_t capacity, const i2d_field_info* f) {
    snprintf(out, capacity, "FIELD(%s, %s, %d, %d, %d, %s, %s)", f->struct_name, f->field_name, (int)f->offset,
             (int)f->size, (int)f->count, kind_name(f->kind), f->type_name);
}

static void recorded_field_line(char* out, size_t capacity, const recorded_field* r) {
    snprintf(out, capacity, "FIELD(%s, %s, %d, %d, %d, %s, %s)", r->struct_name, r->field_name, (int)r->offset,
             (int)r->size, (int)r->count, kind_name(r->kind), r->type_name);
}

static void fail(void) { ++i2d_check_failures; }

static const recorded_type* find_type(const char* name) {
    for (int32_t i = 0; i < COUNT_OF(recorded_types); ++i) {
        if (recorded_types[i].described && strcmp(recorded_types[i].name, name) == 0) return &recorded_types[i];
    }
    return NULL;
}

static const recorded_field* find_field(const char* struct_name, const char* field_name) {
    for (int32_t i = 0; i < COUNT_OF(recorded_fields); ++i) {
        const recorded_field* r = &recorded_fields[i];
        if (strcmp(r->struct_name, struct_name) == 0 && strcmp(r->field_name, field_name) == 0) return r;
    }
    return NULL;
}

#define RECORD "tests/api/abi_layout.def"

I2D_TEST(api_abi_struct_layout) {
    const i2d_struct_info* structs = NULL;
    const i2d_field_info* fields = NULL;
    const int32_t struct_count = i2d_get_struct_infos(&structs);
    const int32_t field_count = i2d_get_field_infos(&fields);
    I2D_REQUIRE(structs != NULL && fields != NULL && struct_count > 0 && field_count > 0);
    char line[512], old[512];

    /* The whole layout first, as the record spells it; the problems after it. */
    for (int32_t i = 0; i < struct_count; ++i) {
        struct_line(line, sizeof line, &structs[i]);
        printf("%s\n", line);
    }
    for (int32_t i = 0; i < field_count; ++i) {
        field_line(line, sizeof line, &fields[i]);
        printf("%s\n", line);
    }
    for (int32_t i = 0; i < COUNT_OF(recorded_types); ++i) {
        if (!recorded_types[i].described) {
            printf("TYPE(%s, %zu, %zu)\n", recorded_types[i].name, recorded_types[i].c_size, recorded_types[i].c_align);
        }
    }
    fflush(stdout);

    /* Every struct the library describes is recorded, with its size and alignment; the
     * library agrees with this C compiler. */
    for (int32_t i = 0; i < struct_count; ++i) {
        const i2d_struct_info* s = &structs[i];
        const recorded_type* r = find_type(s->name);
        struct_line(line, sizeof line, s);
        if (r == NULL) {
            fail();
            fprintf(stderr, "%s lacks the struct %s; add the line\n    %s\n", RECORD, s->name, line);
            continue;
        }
        if ((size_t)s->size != r->c_size || (size_t)s->align != r->c_align) {
            fail();
            fprintf(stderr, "%s: the library says size %d, alignment %d; this C compiler %zu, %zu\n", s->name,
                    (int)s->size, (int)s->align, r->c_size, r->c_align);
        }
        if (RECORDED_PLATFORM && (s->size != r->size || s->align != r->align)) {
            fail();
            fprintf(stderr, "%s:%d records STRUCT(%s, %d, %d); the library has\n    %s\n"
                    "(an ABI change: replace the line only if it is deliberate)\n",
                    RECORD, r->line, r->name, (int)r->size, (int)r->align, line);
        }
    }
    /* Every member: recorded with its offset, size, count, kind and type; the library's
     * offset and size agree with this C compiler's. */
    for (int32_t i = 0; i < field_count; ++i) {
        const i2d_field_info* f = &fields[i];
        const recorded_field* r = find_field(f->struct_name, f->field_name);
        field_line(line, sizeof line, f);
        if (r == NULL) {
            fail();
            fprintf(stderr, "%s lacks the field %s.%s; add the line\n    %s\n", RECORD, f->struct_name, f->field_name,
                    line);
            continue;
        }
        if ((size_t)f->offset != r->c_offset || (size_t)f->size != r->c_size) {
            fail();
            fprintf(stderr, "%s.%s: the library says offset %d, size %d; this C compiler %zu, %zu\n", f->struct_name,
                    f->field_name, (int)f->offset, (int)f->size, r->c_offset, r->c_size);
        }
        recorded_field_line(old, sizeof old, r);
        const int names_differ = (int32_t)f->kind != r->kind || strcmp(f->type_name, r->type_name) != 0;
        if (RECORDED_PLATFORM ? strcmp(line, old) != 0 : names_differ) {
            fail();
            fprintf(stderr, "%s:%d records\n    %s\nthe library has\n    %s\n"
                    "(an ABI change: replace the line only if it is deliberate)\n", RECORD, r->line, old, line);
        }
    }
    /* Nothing recorded has gone from the library. */
    for (int32_t i = 0; i < COUNT_OF(recorded_types); ++i) {
        const recorded_type* r = &recorded_types[i];
        int found = !r->described;
        for (int32_t k = 0; k < struct_count && !found; ++k) found = strcmp(structs[k].name, r->name) == 0;
        if (!found) {
            fail();
            fprintf(stderr, "%s:%d records %s, which the library no longer describes\n", RECORD, r->line, r->name);
        }
    }
    for (int32_t i = 0; i < COUNT_OF(recorded_fields); ++i) {
        const recorded_field* r = &recorded_fields[i];
        int found = 0;
        for (int32_t k = 0; k < field_count && !found; ++k) {
            found = strcmp(fields[k].struct_name, r->struct_name) == 0 && strcmp(fields[k].field_name, r->field_name) == 0;
        }
        if (!found) {
            fail();
            fprintf(stderr, "%s:%d records %s.%s, which the library no longer describes\n", RECORD, r->line,
                    r->struct_name, r->field_name);
        }
    }
    /* Types that are not structs (enums cross as 32-bit integers), against this C compiler. */
    for (int32_t i = 0; i < COUNT_OF(recorded_types); ++i) {
        const recorded_type* r = &recorded_types[i];
        if (r->described) continue;
        if (RECORDED_PLATFORM && ((size_t)r->size != r->c_size || (size_t)r->align != r->c_align)) {
            fail();
            fprintf(stderr, "%s:%d records TYPE(%s, %d, %d); this C compiler has size %zu, alignment %zu\n", RECORD,
                    r->line, r->name, (int)r->size, (int)r->align, r->c_size, r->c_align);
        }
    }
    /* Elsewhere only the ids' size is fixed by the contract. */
    I2D_CHECK(sizeof(i2d_world_id) == 8 && sizeof(i2d_body_id) == 8 && sizeof(i2d_shape_id) == 8);
}

static const i2d_struct_info* described_struct(const i2d_struct_info* structs, int32_t count, const char* name) {
    for (int32_t i = 0; i < count; ++i) {
        if (strcmp(structs[i].name, name) == 0) return &structs[i];
    }
    return NULL;
}

/* What a binding may take for granted about the description, on every platform. */
I2D_TEST(api_field_infos_are_consistent) {
    const i2d_struct_info* structs = NULL;
    const i2d_field_info* fields = NULL;
    const int32_t struct_count = i2d_get_struct_infos(&structs);
    const int32_t field_count = i2d_get_field_infos(&fields);
    I2D_REQUIRE(structs != NULL && fields != NULL);
    I2D_CHECK(i2d_get_field_infos(NULL) == field_count && i2d_get_struct_infos(NULL) == struct_count);
    I2D_CHECK(i2d_last_status() == I2D_OK);
    I2D_CHECK(described_struct(structs, struct_count, "i2d_field_info") != NULL);

    /* Rows come struct by struct, in i2d_get_struct_infos order, every struct with at
     * least one member; members do not overlap and fit in their struct. */
    int32_t s = -1, end = 0;
    for (int32_t i = 0; i < field_count; ++i) {
        const i2d_field_info* f = &fields[i];
        if (s < 0 || strcmp(f->struct_name, structs[s].name) != 0) {
            ++s;
            I2D_REQUIRE(s < struct_count);
            if (strcmp(f->struct_name, structs[s].name) != 0) {
                fail();
                fprintf(stderr, "field row %d names %s where %s's rows were expected\n", (int)i, f->struct_name,
                        structs[s].name);
                return;
            }
            end = 0;
        }
        const char* what = f->field_name;
        I2D_CHECK(f->offset >= end);
        I2D_CHECK(f->count >= 1 && f->size > 0 && f->size % f->count == 0);
        I2D_CHECK(f->offset + f->size <= structs[s].size);
        end = f->offset + f->size;
        const int32_t element = f->size / f->count;
        int32_t natural = 0;
        switch (f->kind) {
            case I2D_FIELD_BOOL: case I2D_FIELD_INT8: case I2D_FIELD_UINT8: natural = 1; break;
            case I2D_FIELD_INT16: case I2D_FIELD_UINT16: natural = 2; break;
            case I2D_FIELD_INT32: case I2D_FIELD_UINT32: case I2D_FIELD_FLOAT: natural = 4; break;
            case I2D_FIELD_INT64: case I2D_FIELD_UINT64: case I2D_FIELD_DOUBLE: natural = 8; break;
            case I2D_FIELD_POINTER: natural = (int32_t)sizeof(void*); break;
            case I2D_FIELD_FUNCTION: natural = (int32_t)sizeof(void (*)(void)); break;
            case I2D_FIELD_STRUCT: {
                /* A nested struct is described, and before the struct containing it. */
                const i2d_struct_info* nested = described_struct(structs, s, f->type_name);
                natural = nested != NULL ? nested->size : -1;
                break;
            }
            default: natural = -1; break;
        }
        if (element != natural) {
            fail();
            fprintf(stderr, "%s.%s: kind %s (%s), element size %d, expected %d\n", f->struct_name, what,
                    kind_name(f->kind), f->type_name, (int)element, (int)natural);
        }
        I2D_CHECK(f->type_name != NULL && f->type_name[0] != '\0');
    }
    I2D_CHECK(s == struct_count - 1);
}
