// SPDX-License-Identifier: MIT
// i2d_get_struct_infos and i2d_get_field_infos: the size and alignment of every public
// struct and the offset, size and kind of every member, so that a binding can lay its
// structs out from the library it loaded (or check its own against it).
//
// Both tables come from struct_fields.inc, generated from the public headers by
// gen_struct_fields.py (CTest's tools.struct_fields_current fails when it is stale): the
// script gives the names, kinds and C types, the compiler the offsets and sizes, and
// the static_asserts below check every kind and type the script wrote against the
// member's real type, so a row the script misread does not compile.
#include <cstddef>
#include <type_traits>

#include "boundary.hpp"

namespace {

// The kind a binding reads an element of type T as; 0 for a type no kind describes.
template <typename T>
constexpr int kind_of() {
    if constexpr (std::is_same_v<T, bool>) {
        return I2D_FIELD_BOOL;
    } else if constexpr (std::is_floating_point_v<T>) {
        return sizeof(T) == 4 ? I2D_FIELD_FLOAT : sizeof(T) == 8 ? I2D_FIELD_DOUBLE : 0;
    } else if constexpr (std::is_integral_v<T>) {
        constexpr bool is_signed = std::is_signed_v<T>;
        switch (sizeof(T)) {
            case 1: return is_signed ? I2D_FIELD_INT8 : I2D_FIELD_UINT8;
            case 2: return is_signed ? I2D_FIELD_INT16 : I2D_FIELD_UINT16;
            case 4: return is_signed ? I2D_FIELD_INT32 : I2D_FIELD_UINT32;
            case 8: return is_signed ? I2D_FIELD_INT64 : I2D_FIELD_UINT64;
            default: return 0;
        }
    } else if constexpr (std::is_enum_v<T>) {
        // C enums cross every binding as 32-bit integers (the ABI record fixes it).
        return sizeof(T) == 4 ? I2D_FIELD_INT32 : 0;
    } else if constexpr (std::is_pointer_v<T>) {
        return std::is_function_v<std::remove_pointer_t<T>> ? I2D_FIELD_FUNCTION : I2D_FIELD_POINTER;
    } else if constexpr (std::is_class_v<T>) {
        return I2D_FIELD_STRUCT;
    } else {
        return 0;
    }
}

// The type a row names: a pointer's pointee, otherwise the element type itself.
template <typename T>
using named_type_t = std::conditional_t<std::is_pointer_v<T>, std::remove_cv_t<std::remove_pointer_t<T>>, T>;

template <typename Member>
using element_t = std::remove_cv_t<std::remove_all_extents_t<Member>>;

#define I2D_MEMBER_TYPE(type, field) decltype(type::field)

// Every row checked against the member's real type.
#define I2D_STRUCT(type) \
    static_assert(std::is_standard_layout_v<type> && std::is_trivially_copyable_v<type>, #type " is not plain data");
#define I2D_FIELD(type, field, kind, ctype)                                                                    \
    static_assert(std::rank_v<I2D_MEMBER_TYPE(type, field)> <= 1, #type "." #field ": arrays of arrays");     \
    static_assert(kind_of<element_t<I2D_MEMBER_TYPE(type, field)>>() == I2D_FIELD_##kind,                     \
                  "struct_fields.inc: " #type "." #field " is not of kind " #kind                              \
                  ": regenerate it (python3 capi/gen_struct_fields.py)");                                      \
    static_assert(std::is_same_v<named_type_t<element_t<I2D_MEMBER_TYPE(type, field)>>, ctype>,              \
                  "struct_fields.inc: " #type "." #field " is not of type " #ctype                             \
                  ": regenerate it (python3 capi/gen_struct_fields.py)");
#include "struct_fields.inc"
#undef I2D_STRUCT
#undef I2D_FIELD

// Every typedef struct of include/impulse2d/*.h, in include order.
const i2d_struct_info struct_infos[] = {
#define I2D_STRUCT(type) \
    i2d_struct_info{#type, static_cast<int32_t>(sizeof(type)), static_cast<int32_t>(alignof(type))},
#define I2D_FIELD(type, field, kind, ctype)
#include "struct_fields.inc"
#undef I2D_STRUCT
#undef I2D_FIELD
};

template <typename Member>
constexpr int32_t element_count() {
    return std::is_array_v<Member> ? static_cast<int32_t>(std::extent_v<Member>) : 1;
}

// Every member of those structs, struct by struct, in declaration order.
const i2d_field_info field_infos[] = {
#define I2D_STRUCT(type)
#define I2D_FIELD(type, field, kind, ctype)                                                       \
    i2d_field_info{#type,                                                                         \
                   #field,                                                                        \
                   #ctype,                                                                        \
                   static_cast<int32_t>(offsetof(type, field)),                                   \
                   static_cast<int32_t>(sizeof(I2D_MEMBER_TYPE(type, field))),                    \
                   element_count<I2D_MEMBER_TYPE(type, field)>(),                                 \
                   I2D_FIELD_##kind},
#include "struct_fields.inc"
#undef I2D_STRUCT
#undef I2D_FIELD
};

#undef I2D_MEMBER_TYPE

}  // namespace

I2D_API int32_t i2d_get_struct_infos(const i2d_struct_info** out) {
    i2d::capi::set_ok();
    if (out != nullptr) {
        *out = struct_infos;
    }
    return static_cast<int32_t>(sizeof struct_infos / sizeof struct_infos[0]);
}

I2D_API int32_t i2d_get_field_infos(const i2d_field_info** out) {
    i2d::capi::set_ok();
    if (out != nullptr) {
        *out = field_infos;
    }
    return static_cast<int32_t>(sizeof field_infos / sizeof field_infos[0]);
}
