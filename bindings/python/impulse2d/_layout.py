# SPDX-License-Identifier: MIT
"""ctypes Structures made from the loaded library's own description of its structs.

The library lists every public struct (i2d_get_struct_infos: size and alignment) and
every member (i2d_get_field_infos: offset, size, element count, kind and C type name);
build_structs turns that into ctypes classes, nested structs and arrays included, and
checks that ctypes lays each one out exactly as the library says. usage_problems checks
that the fields a binding reads or writes are there with the kind it expects. Nothing
here declares a struct of the API, so a field added to a header reaches the bindings
with no edit.

Standard library only, and no imports from the package: tests/ffi/test_ctypes.py loads
this file by path to build its structs the same way without the package's wrappers.
"""

import ctypes as C
import re
from typing import Callable, Dict, List, Mapping, NamedTuple, Optional, Tuple

# i2d_field_kind's values (include/impulse2d/base.h) by name.
KINDS = {
    1: "bool", 2: "int8", 3: "int16", 4: "int32", 5: "int64", 6: "uint8", 7: "uint16", 8: "uint32",
    9: "uint64", 10: "float", 11: "double", 12: "pointer", 13: "function", 14: "struct",
}
SCALARS = {
    "bool": C.c_bool, "int8": C.c_int8, "int16": C.c_int16, "int32": C.c_int32, "int64": C.c_int64,
    "uint8": C.c_uint8, "uint16": C.c_uint16, "uint32": C.c_uint32, "uint64": C.c_uint64,
    "float": C.c_float, "double": C.c_double,
}
# Scalar C type names a pointer may point to, as type_name spells them.
_POINTEES = {
    "bool": C.c_bool, "int8_t": C.c_int8, "int16_t": C.c_int16, "int32_t": C.c_int32, "int64_t": C.c_int64,
    "uint8_t": C.c_uint8, "uint16_t": C.c_uint16, "uint32_t": C.c_uint32, "uint64_t": C.c_uint64,
    "float": C.c_float, "double": C.c_double,
}


# The two structs that describe the others: the only ones declared by hand, and checked
# against the library's description of themselves before anything is built.
class StructInfo(C.Structure):
    _fields_ = [("name", C.c_char_p), ("size", C.c_int32), ("align", C.c_int32)]


class FieldInfo(C.Structure):
    _fields_ = [
        ("struct_name", C.c_char_p),
        ("field_name", C.c_char_p),
        ("type_name", C.c_char_p),
        ("offset", C.c_int32),
        ("size", C.c_int32),
        ("count", C.c_int32),
        ("kind", C.c_int32),
    ]


_SELF = {"i2d_struct_info": StructInfo, "i2d_field_info": FieldInfo}


class Field(NamedTuple):
    name: str
    kind: str  # a KINDS name, or "kind <n>" for a kind newer than this module
    type_name: str
    offset: int
    size: int  # of the whole member: count elements
    count: int


class Struct(NamedTuple):
    name: str
    size: int
    align: int
    fields: Tuple[Field, ...]


# C struct name -> Struct, in the library's order (a struct after those it contains).
Description = Dict[str, Struct]


class LayoutError(Exception):
    """The library's description cannot be read or built: the message lists why."""


def describe(lib: C.CDLL) -> Description:
    """What the library says about its structs (i2d_get_struct_infos and
    i2d_get_field_infos). LayoutError if it lacks them or describes them oddly."""
    for name in ("i2d_get_struct_infos", "i2d_get_field_infos"):
        if not hasattr(lib, name):
            raise LayoutError("the library does not describe its structs (%s is missing)" % name)
    get_structs, get_fields = lib.i2d_get_struct_infos, lib.i2d_get_field_infos
    get_structs.restype = get_fields.restype = C.c_int32
    get_structs.argtypes = [C.POINTER(C.POINTER(StructInfo))]
    get_fields.argtypes = [C.POINTER(C.POINTER(FieldInfo))]
    structs = C.POINTER(StructInfo)()
    struct_count = get_structs(C.byref(structs))
    fields = C.POINTER(FieldInfo)()
    field_count = get_fields(C.byref(fields))
    members: Dict[str, List[Field]] = {}
    for i in range(field_count):
        row = fields[i]
        kind = KINDS.get(row.kind, "kind %d" % row.kind)
        field = Field(row.field_name.decode(), kind, row.type_name.decode(), row.offset, row.size, row.count)
        members.setdefault(row.struct_name.decode(), []).append(field)
    description: Description = {}
    for i in range(struct_count):
        row = structs[i]
        name = row.name.decode()
        description[name] = Struct(name, row.size, row.align, tuple(members.get(name, ())))
    problems = layout_problems(description, _SELF)
    if problems:
        raise LayoutError("the library describes its own description differently:\n  " + "\n  ".join(problems))
    return description


def camel_case(c_name: str) -> str:
    """i2d_world_def -> WorldDef."""
    return "".join(part.capitalize() for part in c_name[len("i2d_"):].split("_"))


def is_id(struct: Struct) -> bool:
    """An id struct: one uint64_t named bits (i2d_body_id, i2d_shape_id, ...)."""
    return len(struct.fields) == 1 and struct.fields[0].name == "bits" and struct.fields[0].kind == "uint64"


def build_structs(
    description: Description,
    name_of: Callable[[str], str] = camel_case,
    ids_as_integers: bool = False,
    module: str = __name__,
) -> Tuple[Dict[str, type], List[str]]:
    """(classes, problems): a ctypes Structure per described struct, by C name, named
    name_of(c_name). Nested structs are those classes, arrays ctypes arrays, pointers to
    a struct POINTER(class) (c_char_p for char, c_void_p for void), function pointers
    c_void_p. ids_as_integers makes id members plain c_uint64 (same layout), as a binding
    passing ids as integers wants. A struct ctypes would lay out differently from the
    library (or holding a kind this module does not know) is left out and named in
    problems."""
    classes: Dict[str, type] = {}
    problems: List[str] = []
    for struct in description.values():
        if struct.name in _SELF:
            classes[struct.name] = _SELF[struct.name]
            continue
        members = []
        unknown = [f.name for f in struct.fields if _element(f, description, classes, ids_as_integers) is None]
        if unknown:
            problems.append("%s: cannot build the members %s (unknown kind or nested type)" % (struct.name, ", ".join(unknown)))
            continue
        for f in struct.fields:
            element = _element(f, description, classes, ids_as_integers)
            members.append((f.name, element * f.count if f.count != 1 else element))
        cls = type(name_of(struct.name), (C.Structure,), {"_fields_": members, "__module__": module,
                                                          "__doc__": "ctypes layout of %s, from the library" % struct.name})
        found = layout_problems({struct.name: struct}, {struct.name: cls})
        if found:
            problems.extend(found)
            continue
        classes[struct.name] = cls
    return classes, problems


def _element(f: Field, description: Description, classes: Mapping[str, type], ids_as_integers: bool) -> Optional[type]:
    if f.kind in SCALARS:
        return SCALARS[f.kind]
    if f.kind == "struct":
        nested = description.get(f.type_name)
        if ids_as_integers and nested is not None and is_id(nested):
            return C.c_uint64
        return classes.get(f.type_name)
    if f.kind == "pointer":
        if f.type_name == "char":
            return C.c_char_p
        if f.type_name in classes:
            return C.POINTER(classes[f.type_name])
        if f.type_name in _POINTEES:
            return C.POINTER(_POINTEES[f.type_name])
        return C.c_void_p
    if f.kind == "function":
        return C.c_void_p
    return None


def layout_problems(description: Description, classes: Mapping[str, type]) -> List[str]:
    """One line per class whose size, alignment or member offsets and sizes differ from
    the library's description of the struct of that C name."""
    problems = []
    for name, cls in classes.items():
        struct = description.get(name)
        if struct is None:
            problems.append("%s: not described by the library" % name)
            continue
        ours = (C.sizeof(cls), C.alignment(cls))
        if ours != (struct.size, struct.align):
            problems.append("%s: the library has size %d, alignment %d; ctypes lays it out with size %d, alignment %d"
                            % (name, struct.size, struct.align, ours[0], ours[1]))
        declared = {member[0] for member in cls._fields_}
        for f in struct.fields:
            member = getattr(cls, f.name, None) if f.name in declared else None
            if member is None:
                problems.append("%s.%s: not declared here" % (name, f.name))
            elif (member.offset, member.size) != (f.offset, f.size):
                problems.append("%s.%s: the library has offset %d, size %d; here offset %d, size %d"
                                % (name, f.name, f.offset, f.size, member.offset, member.size))
    return problems


_SPEC = re.compile(r"^(\w+)(\*?)(\[(\d*)\])?$")


def usage_problems(description: Description, uses: Mapping[str, Mapping[str, str]]) -> List[str]:
    """One line per field a binding uses that the library lacks or describes with
    another kind. uses maps a C struct name to {field: spec}, spec naming what the
    binding reads or writes: a kind ("float", "int32", "bool", "uint64", "function"; an
    enum is "int32") or a struct's C name ("i2d_vec2"), either with [N] for an array of N
    or [] for an array of any length; or a pointer to a type ("i2d_contact_begin_event*",
    "void*", "char*")."""
    problems = []
    for struct_name, used in uses.items():
        struct = description.get(struct_name)
        if struct is None:
            problems.append("%s: not described by the library" % struct_name)
            continue
        members = {f.name: f for f in struct.fields}
        for name, spec in used.items():
            f = members.get(name)
            if f is None:
                problems.append("%s.%s: the library has no such field; this package uses it as %s"
                                % (struct_name, name, spec))
                continue
            m = _SPEC.match(spec)
            if not m:
                raise ValueError("bad field spec %r for %s.%s" % (spec, struct_name, name))
            base, pointer = m.group(1), m.group(2)
            count = None if m.group(3) == "[]" else int(m.group(4) or 1)  # None: any length
            if pointer:
                expected = ("pointer", base)
            elif base in SCALARS or base == "function":
                expected = (base, None)
            else:
                expected = ("struct", base)
            actual = (f.kind, f.type_name if expected[1] is not None else None)
            if actual != expected or (count is not None and f.count != count):
                had = f.kind + ("" if f.kind in SCALARS or f.kind == "function" else " " + f.type_name)
                problems.append("%s.%s: the library has %s%s; this package uses it as %s"
                                % (struct_name, name, had, "[%d]" % f.count if f.count != 1 else "", spec))
    return problems
