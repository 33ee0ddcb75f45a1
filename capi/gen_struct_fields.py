#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes capi/struct_fields.inc, the list of every public struct and its fields, from
the public headers (include/impulse2d/*.h).

    python3 capi/gen_struct_fields.py            rewrite capi/struct_fields.inc
    python3 capi/gen_struct_fields.py --check    exit 1, showing the difference, if it is stale

The file is committed, so building the library needs no Python (the WebAssembly and
cross builds run no script); CTest's tools.struct_fields_current runs --check.
capi/struct_info_api.cpp turns its rows into the tables of i2d_get_struct_infos and
i2d_get_field_infos: the names, kinds and C types come from here, the offsets and sizes
from the compiler, which also checks every row's kind and type (a row this script got
wrong does not compile).

The public structs are plain data and this reads only what they use: `typedef struct
name { ... } name;` whose members are bool, float, double, the <stdint.h> fixed-width
integers, enums declared `typedef enum name { ... } name;`, structs declared before,
pointers to any of these or to void or char, function typedefs used through a pointer
(`i2d_task_fn* task`), and one-dimensional arrays (`i2d_vec2 vertices[8]`). Anything else
(unions, bitfields, nested or anonymous structs, `int` or `char` members, pointers to
pointers, inline function pointer declarators) stops it with the header and struct
named, rather than describing a layout it does not understand.
"""

import argparse
import difflib
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
DEFAULT_INCLUDE = os.path.join(ROOT, "include", "impulse2d")
DEFAULT_OUTPUT = os.path.join(HERE, "struct_fields.inc")
# The header every other is reached from: files are read in its include order, so that a
# struct always comes after the structs it contains.
TOP_HEADER = "impulse2d.h"

SCALARS = {
    "bool": "BOOL",
    "int8_t": "INT8",
    "int16_t": "INT16",
    "int32_t": "INT32",
    "int64_t": "INT64",
    "uint8_t": "UINT8",
    "uint16_t": "UINT16",
    "uint32_t": "UINT32",
    "uint64_t": "UINT64",
    "float": "FLOAT",
    "double": "DOUBLE",
}
# Types a pointer may point to beyond the scalars, enums and structs.
POINTEES = {"void", "char"}
QUALIFIERS = {"const", "volatile", "struct", "enum"}


class HeaderError(Exception):
    pass


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.DOTALL)
    return re.sub(r"//[^\n]*", " ", text)


def without_preprocessor(text):
    """Drops preprocessor lines (with their continuations): macros are not members."""
    out, continued = [], False
    for line in text.split("\n"):
        if continued or line.lstrip().startswith("#"):
            continued = line.rstrip().endswith("\\")
            continue
        out.append(line)
    return "\n".join(out)


def header_order(include_dir):
    """The headers, depth first along their #include lines from TOP_HEADER, then any the
    top header does not reach, by name."""
    names = sorted(n for n in os.listdir(include_dir) if n.endswith(".h"))
    order = []

    def visit(name):
        if name in order or name not in names:
            return
        order.append(name)  # marks it, so an include cycle ends
        with open(os.path.join(include_dir, name), encoding="utf-8") as f:
            includes = re.findall(r'^\s*#\s*include\s+"([^"]+)"', f.read(), re.MULTILINE)
        order.remove(name)
        for included in includes:
            visit(included)
        order.append(name)

    visit(TOP_HEADER)
    return order + [n for n in names if n not in order]


def parse_members(header, struct, body, known):
    """[(field, kind, type_name)] for a struct body; known holds the types seen so far."""
    if re.search(r"[{}()]", body):
        raise HeaderError("%s: %s: nested braces or parentheses (a nested struct, union or an inline "
                          "function pointer) are not supported; use a typedef" % (header, struct))
    if ":" in body:
        raise HeaderError("%s: %s: bitfields are not supported" % (header, struct))
    fields = []
    for declaration in body.split(";"):
        tokens = re.findall(r"\w+|\S", declaration)
        if not tokens:
            continue
        words = [t for t in tokens if t not in QUALIFIERS]
        if len(words) < 2 or not re.match(r"[A-Za-z_]\w*$", words[0]):
            raise HeaderError("%s: %s: cannot read member %r" % (header, struct, declaration.strip()))
        base = words[0]
        declarators, current = [], []
        for token in words[1:]:
            if token == ",":
                declarators.append(current)
                current = []
            else:
                current.append(token)
        declarators.append(current)
        for declarator in declarators:
            text = " ".join(declarator)
            m = re.match(r"^(\**)\s*(\w+)\s*(\[\s*\w+\s*\])?$", text)
            if not m:
                raise HeaderError("%s: %s: cannot read declarator %r of type %s" % (header, struct, text, base))
            stars, name = len(m.group(1)), m.group(2)
            fields.append((name,) + classify(header, struct, name, base, stars, known))
    if not fields:
        raise HeaderError("%s: %s has no members" % (header, struct))
    return fields


def classify(header, struct, name, base, stars, known):
    """(kind, type_name) of a member of type base with `stars` pointer levels."""
    where = "%s: %s.%s" % (header, struct, name)
    if stars > 1:
        raise HeaderError("%s: pointers to pointers are not supported" % where)
    what = known.get(base)
    if stars == 1:
        if what == "function":
            return "FUNCTION", base
        if what == "function pointer":
            raise HeaderError("%s: a pointer to a function pointer is not supported" % where)
        if base in SCALARS or base in POINTEES or what in ("enum", "struct"):
            return "POINTER", base
        raise HeaderError("%s: pointer to unknown type %s" % (where, base))
    if base in SCALARS:
        return SCALARS[base], base
    if what == "enum":
        return "INT32", base  # the compiler checks that the enum is 4 bytes
    if what == "struct":
        return "STRUCT", base
    if what == "function pointer":
        return "FUNCTION", base
    if what == "function":
        raise HeaderError("%s: a function type must be a pointer member (%s* %s)" % (where, base, name))
    raise HeaderError("%s: unsupported type %s (use bool, float, double, a <stdint.h> fixed-width "
                      "integer, an enum, a struct declared before it, or a pointer)" % (where, base))


def parse_headers(include_dir):
    """[(struct, [(field, kind, type_name)])] in header and declaration order."""
    known = {}
    structs = []
    for header in header_order(include_dir):
        with open(os.path.join(include_dir, header), encoding="utf-8") as f:
            text = without_preprocessor(strip_comments(f.read()))
        if re.search(r"\bunion\b", text):
            raise HeaderError("%s: unions are not supported" % header)
        # Every declaration in the order written, so that a member's type is known
        # exactly when C knows it.
        pattern = re.compile(
            r"typedef\s+(struct|enum)\s+(\w*)\s*\{([^{}]*)\}\s*(\w+)\s*;"  # struct or enum
            r"|typedef\s+([^;{}]*?)\(\s*\*\s*(\w+)\s*\)\s*\([^;{}]*\)\s*;"  # function pointer type
            r"|typedef\s+([^;{}]*?)\b(\w+)\s*\([^;{}]*\)\s*;"  # function type
            r"|\b(struct|enum)\s+(\w+)\s*\{",  # anything else with a body
            re.DOTALL,
        )
        for m in pattern.finditer(text):
            if m.group(1):
                keyword, tag, body, name = m.group(1), m.group(2), m.group(3), m.group(4)
                if tag and tag != name:
                    raise HeaderError("%s: typedef %s %s { ... } %s: the tag and the name differ" % (header, keyword, tag, name))
                if keyword == "enum":
                    known[name] = "enum"
                else:
                    structs.append((name, parse_members(header, name, body, known)))
                    known[name] = "struct"
            elif m.group(6):
                known[m.group(6)] = "function pointer"
            elif m.group(8):
                known[m.group(8)] = "function"
            else:
                raise HeaderError("%s: %s %s { ... } outside `typedef %s name { ... } name;` is not "
                                  "supported" % (header, m.group(9), m.group(10), m.group(9)))
    if not structs:
        raise HeaderError("no typedef struct found in %s" % include_dir)
    return structs


def render(structs):
    lines = [
        "/* SPDX-License-Identifier: MIT */",
        "/* Generated by capi/gen_struct_fields.py from the headers in include/impulse2d: do not edit.",
        " * After changing a public struct, run: python3 capi/gen_struct_fields.py",
        " *",
        " * Every public struct, in include order (a struct after the structs it contains), and",
        " * its members in declaration order, as X-macro rows for capi/struct_info_api.cpp:",
        " *   I2D_STRUCT(struct)",
        " *   I2D_FIELD(struct, field, kind, type)   kind: I2D_FIELD_<kind>; type: the member's C",
        " *       type without const, pointer or array (a pointer's pointee, a function",
        " *       pointer's function typedef). */",
    ]
    for name, fields in structs:
        lines.append("I2D_STRUCT(%s)" % name)
        for field, kind, type_name in fields:
            lines.append("I2D_FIELD(%s, %s, %s, %s)" % (name, field, kind, type_name))
    return "\n".join(lines) + "\n"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--check", action="store_true", help="fail if the output file is not current; write nothing")
    parser.add_argument("--include-dir", default=DEFAULT_INCLUDE, help="the public headers (default: %(default)s)")
    parser.add_argument("--output", default=DEFAULT_OUTPUT, help="the file to write or check (default: %(default)s)")
    args = parser.parse_args(argv)
    try:
        text = render(parse_headers(args.include_dir))
    except HeaderError as error:
        print("gen_struct_fields.py: %s" % error, file=sys.stderr)
        return 2
    try:
        with open(args.output, encoding="utf-8") as f:
            current = f.read()
    except FileNotFoundError:
        current = None
    if args.check:
        if current == text:
            print("%s is current" % args.output)
            return 0
        diff = difflib.unified_diff((current or "").splitlines(True), text.splitlines(True),
                                    args.output + " (committed)", args.output + " (from the headers)")
        sys.stdout.writelines(diff)
        print("\n%s is out of date with the public headers. Regenerate it and commit the result:\n"
              "    python3 %s" % (args.output, os.path.abspath(__file__)))
        return 1
    if current != text:
        with open(args.output, "w", encoding="utf-8", newline="\n") as f:
            f.write(text)
        print("wrote %s" % args.output)
    else:
        print("%s is already current" % args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
