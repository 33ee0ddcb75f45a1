# SPDX-License-Identifier: MIT
"""The load-time check that this package and the native library agree on every struct."""

import ctypes as C
from typing import Dict, Iterable, List, Mapping, Tuple

from ._structs import DECLARED, StructInfo
from .errors import LayoutMismatch

# name -> (size, alignment) in bytes
Layouts = Dict[str, Tuple[int, int]]


def read_struct_infos(lib: C.CDLL) -> Layouts:
    """What the library says about its structs (i2d_get_struct_infos)."""
    fn = lib.i2d_get_struct_infos
    fn.restype = C.c_int32
    fn.argtypes = [C.POINTER(C.POINTER(StructInfo))]
    table = C.POINTER(StructInfo)()
    count = fn(C.byref(table))
    return {table[i].name.decode(): (table[i].size, table[i].align) for i in range(count)}


def declared_layouts(declared: Mapping[str, type] = DECLARED) -> Layouts:
    """What this package's ctypes declarations say."""
    return {name: (C.sizeof(cls), C.alignment(cls)) for name, cls in declared.items()}


def layout_problems(library: Layouts, package: Layouts) -> List[str]:
    """One line per struct the package declares that the library lays out differently
    or does not list at all."""
    problems = []
    for name in sorted(package):
        if name not in library:
            problems.append("%s: not described by the library" % name)
            continue
        (lib_size, lib_align), (our_size, our_align) = library[name], package[name]
        if (lib_size, lib_align) != (our_size, our_align):
            problems.append(
                "%s: library has size %d, alignment %d; this package expects size %d, alignment %d"
                % (name, lib_size, lib_align, our_size, our_align)
            )
    return problems


def check_layouts(library: Layouts, path: str, version: str, package: Layouts = None) -> None:
    """Raises LayoutMismatch, naming every differing struct, unless the layouts agree."""
    problems = layout_problems(library, declared_layouts() if package is None else package)
    if problems:
        raise LayoutMismatch(
            "refusing to use %s (impulse2d %s): its structs do not match this Python package, "
            "so calls would corrupt memory. Install the package and the library from the "
            "same version.\n  %s" % (path, version, "\n  ".join(problems))
        )


def missing_from(names: Iterable[str], library: Layouts) -> List[str]:
    return [name for name in names if name not in library]
