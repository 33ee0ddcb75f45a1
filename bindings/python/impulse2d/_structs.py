# SPDX-License-Identifier: MIT
"""The public C structs as ctypes classes, built at load from the library's own
description (i2d_get_field_infos, see _layout.py), and the fields this package relies on.

Nothing here lays a struct out: a field added to a C header appears in these classes with
no edit. The classes carry the package's names (i2d_world_def -> WorldDef, i2d_aabb ->
AABB) and are reached as attributes of this module once the library is loaded
(``from ._structs import Vec2``). Ids are plain 64-bit integers here, members included
(see _library.py).

USES lists every field the package reads or writes, with the kind it reads it as; a
library that lacks one or describes it otherwise is refused at load (LayoutMismatch,
naming every problem) instead of being misread. A field the package starts to use is
added to USES, nothing else.
"""

from typing import Any, Dict, List, Optional

from . import _layout
from .errors import LayoutMismatch

# Python names that are not simply the C name in CamelCase.
NAMES = {"i2d_aabb": "AABB"}

# Joint kinds in i2d_joint_type order: the C enum's value is the index.
JOINT_KINDS = ("distance", "filter", "motor", "mouse", "prismatic", "revolute", "weld", "wheel")

# i2d_debug_draw's callbacks (each the name of the drawer's method it calls) and its
# flags, in the header's order.
DRAW_CALLBACKS = (
    "draw_polygon", "draw_solid_polygon", "draw_circle", "draw_solid_circle", "draw_solid_capsule", "draw_segment",
    "draw_transform", "draw_point", "draw_string",
)
DRAW_FLAGS = (
    "draw_shapes", "draw_joints", "draw_joint_extras", "draw_bounds", "draw_mass", "draw_contacts",
    "draw_contact_normals", "draw_contact_impulses", "draw_friction_impulses", "draw_graph_colors", "draw_islands",
)

_VEC2 = "i2d_vec2"
_ID = "i2d_shape_id"
USES: Dict[str, Dict[str, str]] = {
    # Built positionally (Vec2(x, y), Rot(c, s)): see _POSITIONAL.
    "i2d_vec2": {"x": "float", "y": "float"},
    "i2d_rot": {"c": "float", "s": "float"},
    "i2d_transform": {"p": _VEC2, "q": "i2d_rot"},
    "i2d_aabb": {"min": _VEC2, "max": _VEC2},
    "i2d_filter": {"category_bits": "uint64", "mask_bits": "uint64", "group_index": "int32"},
    "i2d_query_filter": {"category_bits": "uint64", "mask_bits": "uint64"},
    "i2d_circle": {"center": _VEC2, "radius": "float"},
    "i2d_capsule": {"center1": _VEC2, "center2": _VEC2, "radius": "float"},
    "i2d_segment": {"point1": _VEC2, "point2": _VEC2},
    "i2d_polygon": {"vertices": _VEC2 + "[]", "count": "int32", "radius": "float"},
    # Defs: what the wrappers set by name; other settings pass through by their C name.
    "i2d_world_def": {"gravity": _VEC2},
    "i2d_batch_def": {"worker_count": "int32"},
    "i2d_body_def": {"type": "int32", "position": _VEC2, "rotation": "i2d_rot"},
    "i2d_shape_def": {"filter": "i2d_filter"},
    "i2d_joint_base": {
        "body_a": "i2d_body_id", "body_b": "i2d_body_id", "local_anchor_a": _VEC2, "local_anchor_b": _VEC2,
        "collide_connected": "bool", "force_threshold": "float", "torque_threshold": "float",
    },
    "i2d_world_counters": {name: "int32" for name in (
        "body_count", "shape_count", "contact_count", "pair_count", "static_tree_height", "kinematic_tree_height",
        "dynamic_tree_height", "awake_body_count", "sleeping_island_count")},
    # Events and results.
    "i2d_contact_events": {
        "begin_events": "i2d_contact_begin_event*", "begin_count": "int32",
        "end_events": "i2d_contact_end_event*", "end_count": "int32",
    },
    "i2d_contact_begin_event": {"shape_a": _ID, "shape_b": _ID},
    "i2d_contact_end_event": {"shape_a": _ID, "shape_b": _ID},
    "i2d_sensor_events": {
        "begin_events": "i2d_sensor_begin_event*", "begin_count": "int32",
        "end_events": "i2d_sensor_end_event*", "end_count": "int32",
    },
    "i2d_sensor_begin_event": {"sensor_shape": _ID, "visitor_shape": _ID},
    "i2d_sensor_end_event": {"sensor_shape": _ID, "visitor_shape": _ID},
    "i2d_body_events": {
        "move_events": "i2d_body_move_event*", "move_count": "int32",
        "quarantine_events": "i2d_body_quarantine_event*", "quarantine_count": "int32",
    },
    "i2d_body_move_event": {"transform": "i2d_transform", "body": "i2d_body_id", "fell_asleep": "bool"},
    "i2d_body_quarantine_event": {"transform": "i2d_transform", "body": "i2d_body_id", "former_type": "int32"},
    "i2d_ray_result": {"shape": _ID, "point": _VEC2, "normal": _VEC2, "fraction": "float", "hit": "bool"},
    "i2d_joint_events": {"events": "i2d_joint_event*", "count": "int32"},
    "i2d_mass_data": {"mass": "float", "center": _VEC2, "rotational_inertia": "float"},
    "i2d_surface_material": {name: "float" for name in (
        "friction", "restitution", "rolling_resistance", "tangent_speed")},
    "i2d_manifold_point": {"point": _VEC2, "penetration": "float", "id": "uint32"},
    "i2d_manifold": {"normal": _VEC2, "point_count": "int32", "points": "i2d_manifold_point[]"},
    "i2d_contact_data": {
        "shape_a": _ID, "shape_b": _ID, "manifold": "i2d_manifold",
        "normal_impulses": "float[]", "tangent_impulses": "float[]",
    },
    "i2d_shape_proxy": {"points": _VEC2 + "[]", "count": "int32", "radius": "float"},
    "i2d_distance_result": {"point_a": _VEC2, "point_b": _VEC2, "normal": _VEC2, "distance": "float"},
    "i2d_joint_event": {"joint": "i2d_joint_id"},
    "i2d_explosion_def": {
        "mask_bits": "uint64", "position": _VEC2, "radius": "float", "falloff": "float", "impulse_per_length": "float",
    },
    # The character mover (toolkit.h).
    "i2d_plane": {"normal": _VEC2, "offset": "float"},
    "i2d_collision_plane": {"plane": "i2d_plane", "push_limit": "float", "push": "float", "clip_velocity": "bool"},
    "i2d_plane_result": {"translation": _VEC2, "iteration_count": "int32"},
    "i2d_character_def": {
        "max_slope_angle": "float", "step_height": "float", "snap_distance": "float", "skin": "float",
        "max_iterations": "int32", "push_mass": "float", "filter": "i2d_query_filter",
    },
    "i2d_character_result": {
        "position": _VEC2, "velocity": _VEC2, "on_ground": "bool", "ground_normal": _VEC2, "ground_shape": _ID,
        "ground_velocity": _VEC2, "hit_count": "int32",
    },
    # Debug drawing (toolkit.h): the callbacks, the culling box and the flags.
    "i2d_debug_draw": dict(
        {name: "function" for name in DRAW_CALLBACKS},
        drawing_bounds="i2d_aabb", **{name: "bool" for name in ("use_drawing_bounds",) + DRAW_FLAGS},
    ),
}
# Every joint def: its base (its own settings pass through by name, as with the other defs).
USES.update({"i2d_%s_joint_def" % kind: {"base": "i2d_joint_base"} for kind in JOINT_KINDS})
# Structs the package builds positionally: their first members must be USES' fields, in order.
_POSITIONAL = ("i2d_vec2", "i2d_rot")


class Structs:
    """The classes of one loaded library: an attribute per struct under its Python name,
    plus by_c_name, JOINT_DEFS (kind -> def class, in i2d_joint_type order) and
    MAX_POLYGON_VERTICES."""

    def __init__(self, classes: Dict[str, type], description: _layout.Description) -> None:
        self.by_c_name = classes
        self.description = description
        for cls in classes.values():
            setattr(self, cls.__name__, cls)
        self.JOINT_DEFS = {kind: classes["i2d_%s_joint_def" % kind] for kind in JOINT_KINDS}
        self.MAX_POLYGON_VERTICES = next(f.count for f in description["i2d_polygon"].fields if f.name == "vertices")

    def __getattr__(self, name: str) -> Any:  # only for names not set above
        raise AttributeError("the library describes no struct the package calls %s" % name)


def python_name(c_name: str) -> str:
    return NAMES.get(c_name) or _layout.camel_case(c_name)


def problems(description: _layout.Description) -> List[str]:
    """Everything in the description this package cannot work with."""
    found = _layout.usage_problems(description, USES)
    for c_name in _POSITIONAL:
        struct = description.get(c_name)
        order = [f.name for f in struct.fields[: len(USES[c_name])]] if struct else []
        if struct and order != list(USES[c_name]):
            found.append("%s: the package builds it as (%s); the library's members begin (%s)"
                         % (c_name, ", ".join(USES[c_name]), ", ".join(order)))
    return found


def build(description: _layout.Description, path: str, version: str) -> Structs:
    """The classes for a library's description; LayoutMismatch naming every problem if
    the package cannot use it."""
    found = problems(description)
    classes, unbuilt = _layout.build_structs(description, python_name, ids_as_integers=True, module=__name__)
    found += unbuilt
    if found:
        raise LayoutMismatch(
            "refusing to use %s (impulse2d %s): its structs do not match this Python package, "
            "so calls would misread or corrupt memory. Install the package and the library from the "
            "same version.\n  %s" % (path, version, "\n  ".join(found))
        )
    return Structs(classes, description)


_loaded: Optional[Structs] = None


def __getattr__(name: str) -> Any:
    """Vec2, WorldDef, JOINT_DEFS, ...: the loaded library's classes (loading it first)."""
    global _loaded
    if name.startswith("__"):
        raise AttributeError(name)
    if _loaded is None:
        from ._native import structs  # loads the library

        _loaded = structs
    value = getattr(_loaded, name)
    globals()[name] = value
    return value

