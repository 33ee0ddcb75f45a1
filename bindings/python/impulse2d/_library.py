# SPDX-License-Identifier: MIT
"""Finding, loading and checking libimpulse2d, and declaring the C signatures.

Where the library is looked for, first match wins:
1. the file named by the environment variable IMPULSE2D_LIBRARY;
2. next to this package (``pip install`` copies a built library there);
3. the build directories of the source tree this package sits in (build*/capi/);
4. where ``cmake --install`` puts it: the system's library search path and the
   usual prefixes (/usr/local/lib, /usr/lib, ~/.local/lib, ...).

Ids cross the boundary as plain 64-bit integers. An id is a C struct holding one
uint64_t, which every 64-bit ABI the library supports (x86-64 System V and Windows,
AArch64) passes and returns exactly like a uint64_t; ctypes handles integers much
faster than structs. 32-bit platforms return such structs differently, so they are
refused at load.
"""

import ctypes as C
import ctypes.util
import glob
import os
import sys
from typing import Any, Dict, List, Optional, Tuple

from . import _layout, _structs
from .errors import LibraryError

ENVIRONMENT_VARIABLE = "IMPULSE2D_LIBRARY"

_ID = C.c_uint64
_STATUS = C.c_int32
_PTR = C.c_void_p  # arrays passed as addresses (NumPy's arr.ctypes.data)
_OVERLAP_FN = C.CFUNCTYPE(C.c_bool, _ID, C.c_void_p)
_WRITE_FN = C.CFUNCTYPE(None, C.c_void_p, C.c_size_t, C.c_void_p)
# The contact hooks (toolkit.h). The manifold arrives as an address: its class is built
# at load, after these types.
_CUSTOM_FILTER_FN = C.CFUNCTYPE(C.c_bool, _ID, _ID, C.c_void_p)
_PRE_SOLVE_FN = C.CFUNCTYPE(C.c_bool, _ID, _ID, C.c_void_p, C.c_void_p)


def signatures(S: _structs.Structs) -> Dict[str, Tuple[Any, List[Any]]]:
    """restype and argtypes of every function the package calls (but the joints'), with
    the struct classes S of the loaded library."""
    AABB, BodyDef, BodyEvents, Capsule, Circle = S.AABB, S.BodyDef, S.BodyEvents, S.Capsule, S.Circle
    ContactEvents, SensorEvents, Filter = S.ContactEvents, S.SensorEvents, S.Filter
    Polygon, Profile = S.Polygon, S.Profile
    QueryFilter, RayResult, Rot, Segment, ShapeDef = S.QueryFilter, S.RayResult, S.Rot, S.Segment, S.ShapeDef
    Transform, Vec2, WorldCounters, WorldDef = S.Transform, S.Vec2, S.WorldCounters, S.WorldDef
    MassData, SurfaceMaterial, ShapeProxy, DistanceResult = S.MassData, S.SurfaceMaterial, S.ShapeProxy, S.DistanceResult
    ExplosionDef = S.ExplosionDef
    CharacterDef, CharacterResult, PlaneResult, DebugDraw = S.CharacterDef, S.CharacterResult, S.PlaneResult, S.DebugDraw
    return {
        "i2d_version": (C.c_uint32, []),
        "i2d_status_string": (C.c_char_p, [C.c_int32]),
        "i2d_last_status": (_STATUS, []),
        "i2d_last_error_message": (C.c_char_p, []),
        "i2d_default_world_def": (WorldDef, []),
        "i2d_default_world_def_in_units": (WorldDef, [C.c_float]),
        "i2d_default_body_def": (BodyDef, []),
        "i2d_default_shape_def": (ShapeDef, []),
        "i2d_default_query_filter": (QueryFilter, []),
        "i2d_default_filter": (Filter, []),
        "i2d_make_rot": (Rot, [C.c_float]),
        "i2d_rot_get_angle": (C.c_float, [Rot]),
        # pure collision functions (collision.h)
        "i2d_make_polygon": (_STATUS, [C.POINTER(Vec2), C.c_int32, C.c_float, C.POINTER(Polygon)]),
        "i2d_make_proxy": (ShapeProxy, [C.POINTER(Vec2), C.c_int32, C.c_float]),
        "i2d_shape_distance": (DistanceResult, [C.POINTER(ShapeProxy), Transform, C.POINTER(ShapeProxy), Transform]),
        # world
        "i2d_world_create": (_ID, [C.POINTER(WorldDef)]),
        "i2d_world_destroy": (_STATUS, [_ID]),
        "i2d_world_is_valid": (C.c_bool, [_ID]),
        "i2d_world_step": (_STATUS, [_ID, C.c_float, C.c_int32]),
        "i2d_default_batch_def": (S.BatchDef, []),
        "i2d_worlds_step": (_STATUS, [_PTR, C.c_int32, C.c_float, C.c_int32, C.POINTER(S.BatchDef)]),
        "i2d_worlds_get_body_states": (_STATUS, [_PTR, C.c_int32, _PTR, _PTR, _PTR, _PTR]),
        "i2d_worlds_set_body_velocities": (_STATUS, [_PTR, C.c_int32, _PTR, _PTR]),
        "i2d_worlds_get_contact_event_counts": (_STATUS, [_PTR, C.c_int32, _PTR, _PTR]),
        "i2d_world_set_gravity": (_STATUS, [_ID, Vec2]),
        "i2d_world_get_gravity": (Vec2, [_ID]),
        "i2d_world_get_counters": (WorldCounters, [_ID]),
        "i2d_world_get_profile": (Profile, [_ID]),
        "i2d_world_get_state_hash": (C.c_uint64, [_ID]),
        "i2d_world_get_contact_events": (ContactEvents, [_ID]),
        "i2d_world_get_sensor_events": (SensorEvents, [_ID]),
        "i2d_world_get_body_events": (BodyEvents, [_ID]),
        "i2d_world_overlap_aabb_ids": (C.c_int32, [_ID, AABB, QueryFilter, _PTR, C.c_int32]),
        "i2d_world_overlap_point": (_STATUS, [_ID, Vec2, QueryFilter, _OVERLAP_FN, C.c_void_p]),
        "i2d_world_cast_ray_closest": (RayResult, [_ID, Vec2, Vec2, QueryFilter]),
        "i2d_world_get_body_transforms": (_STATUS, [_ID, _PTR, C.c_int32, _PTR]),
        "i2d_world_get_body_velocities": (_STATUS, [_ID, _PTR, C.c_int32, _PTR, _PTR]),
        "i2d_world_set_body_velocities": (_STATUS, [_ID, _PTR, C.c_int32, _PTR, _PTR]),
        "i2d_world_set_body_transforms": (_STATUS, [_ID, _PTR, C.c_int32, _PTR]),
        "i2d_world_get_worker_count": (C.c_int32, [_ID]),
        "i2d_world_get_settings": (WorldDef, [_ID]),
        "i2d_world_enable_sleeping": (_STATUS, [_ID, C.c_bool]),
        "i2d_world_enable_continuous": (_STATUS, [_ID, C.c_bool]),
        "i2d_world_enable_impact_chains": (_STATUS, [_ID, C.c_bool]),
        "i2d_world_set_contact_tuning": (_STATUS, [_ID, C.c_float, C.c_float, C.c_float]),
        "i2d_world_set_joint_tuning": (_STATUS, [_ID, C.c_float, C.c_float]),
        "i2d_world_set_restitution_threshold": (_STATUS, [_ID, C.c_float]),
        "i2d_world_set_hit_event_threshold": (_STATUS, [_ID, C.c_float]),
        "i2d_world_shift_origin": (_STATUS, [_ID, Vec2]),
        "i2d_simd_path_supported": (C.c_bool, [C.c_int32]),
        # contact hooks and explosions (toolkit.h)
        "i2d_world_set_custom_filter_callback": (_STATUS, [_ID, _CUSTOM_FILTER_FN, C.c_void_p]),
        "i2d_world_set_pre_solve_callback": (_STATUS, [_ID, _PRE_SOLVE_FN, C.c_void_p]),
        "i2d_default_explosion_def": (ExplosionDef, []),
        "i2d_world_explode": (_STATUS, [_ID, C.POINTER(ExplosionDef)]),
        # the character mover (toolkit.h); plane arrays passed as addresses
        "i2d_world_cast_mover": (C.c_float, [_ID, C.POINTER(Capsule), Vec2, QueryFilter]),
        "i2d_world_collide_mover": (C.c_int32, [_ID, C.POINTER(Capsule), QueryFilter, _PTR, C.c_int32]),
        "i2d_solve_planes": (PlaneResult, [Vec2, _PTR, C.c_int32]),
        "i2d_clip_vector": (Vec2, [Vec2, _PTR, C.c_int32]),
        "i2d_default_character_def": (CharacterDef, []),
        "i2d_world_move_character": (
            _STATUS, [_ID, C.POINTER(CharacterDef), C.POINTER(Capsule), Vec2, Vec2, C.c_float, C.POINTER(CharacterResult)]
        ),
        # debug drawing (toolkit.h)
        "i2d_default_debug_draw": (DebugDraw, []),
        "i2d_world_draw": (_STATUS, [_ID, C.POINTER(DebugDraw)]),
        # snapshots and rollback states (snapshot.h); buffers passed as addresses or bytes
        "i2d_world_get_snapshot_size": (C.c_size_t, [_ID]),
        "i2d_world_save_snapshot": (_STATUS, [_ID, _PTR, C.c_size_t, C.POINTER(C.c_size_t)]),
        "i2d_world_restore_snapshot": (_STATUS, [_ID, _PTR, C.c_size_t]),
        "i2d_world_create_from_snapshot": (_ID, [_PTR, C.c_size_t, C.POINTER(WorldDef)]),
        "i2d_world_get_state_size": (C.c_size_t, [_ID]),
        "i2d_world_save_state": (_STATUS, [_ID, _PTR, C.c_size_t, C.POINTER(C.c_size_t)]),
        "i2d_world_restore_state": (_STATUS, [_ID, _PTR, C.c_size_t]),
        "i2d_body_in_world": (_ID, [_ID, _ID]),
        # recording and replay (snapshot.h)
        "i2d_world_start_recording": (_STATUS, [_ID, _WRITE_FN, C.c_void_p]),
        "i2d_world_stop_recording": (_STATUS, [_ID]),
        "i2d_replay_open": (_ID, [_PTR, C.c_size_t, C.POINTER(WorldDef)]),
        "i2d_replay_get_world": (_ID, [_ID]),
        "i2d_replay_step": (C.c_int32, [_ID, C.c_int32]),
        "i2d_replay_get_step": (C.c_int32, [_ID]),
        "i2d_replay_get_step_count": (C.c_int32, [_ID]),
        "i2d_replay_get_divergent_step": (C.c_int32, [_ID]),
        "i2d_replay_seek": (_STATUS, [_ID, C.c_int32]),
        "i2d_replay_close": (_STATUS, [_ID]),
        "i2d_shape_in_world": (_ID, [_ID, _ID]),
        # bodies
        "i2d_body_create": (_ID, [_ID, C.POINTER(BodyDef)]),
        "i2d_body_destroy": (_STATUS, [_ID]),
        "i2d_body_is_valid": (C.c_bool, [_ID]),
        "i2d_body_get_world": (_ID, [_ID]),
        "i2d_body_get_type": (C.c_int32, [_ID]),
        "i2d_body_get_position": (Vec2, [_ID]),
        "i2d_body_get_rotation": (Rot, [_ID]),
        "i2d_body_get_transform": (Transform, [_ID]),
        "i2d_body_set_transform": (_STATUS, [_ID, Vec2, Rot]),
        "i2d_body_get_linear_velocity": (Vec2, [_ID]),
        "i2d_body_set_linear_velocity": (_STATUS, [_ID, Vec2]),
        "i2d_body_get_angular_velocity": (C.c_float, [_ID]),
        "i2d_body_set_angular_velocity": (_STATUS, [_ID, C.c_float]),
        "i2d_body_get_mass": (C.c_float, [_ID]),
        "i2d_body_get_rotational_inertia": (C.c_float, [_ID]),
        "i2d_body_get_world_center_of_mass": (Vec2, [_ID]),
        "i2d_body_apply_force": (_STATUS, [_ID, Vec2, Vec2, C.c_bool]),
        "i2d_body_apply_force_to_center": (_STATUS, [_ID, Vec2, C.c_bool]),
        "i2d_body_apply_torque": (_STATUS, [_ID, C.c_float, C.c_bool]),
        "i2d_body_apply_linear_impulse": (_STATUS, [_ID, Vec2, Vec2, C.c_bool]),
        "i2d_body_apply_angular_impulse": (_STATUS, [_ID, C.c_float, C.c_bool]),
        "i2d_body_is_awake": (C.c_bool, [_ID]),
        "i2d_body_is_quarantined": (C.c_bool, [_ID]),
        "i2d_body_set_awake": (_STATUS, [_ID, C.c_bool]),
        "i2d_body_get_shape_count": (C.c_int32, [_ID]),
        "i2d_body_get_shapes": (C.c_int32, [_ID, _PTR, C.c_int32]),
        "i2d_body_get_contact_data": (C.c_int32, [_ID, _PTR, C.c_int32]),
        "i2d_body_get_mass_data": (MassData, [_ID]),
        "i2d_body_set_mass_data": (_STATUS, [_ID, MassData]),
        "i2d_body_apply_mass_from_shapes": (_STATUS, [_ID]),
        "i2d_body_disable": (_STATUS, [_ID]),
        "i2d_body_enable": (_STATUS, [_ID]),
        "i2d_body_is_enabled": (C.c_bool, [_ID]),
        "i2d_body_set_target_transform": (_STATUS, [_ID, Transform, C.c_float]),
        "i2d_body_set_bullet": (_STATUS, [_ID, C.c_bool]),
        "i2d_body_is_bullet": (C.c_bool, [_ID]),
        "i2d_body_enable_sleep": (_STATUS, [_ID, C.c_bool]),
        "i2d_body_is_sleep_enabled": (C.c_bool, [_ID]),
        "i2d_body_set_sleep_threshold": (_STATUS, [_ID, C.c_float]),
        "i2d_body_get_sleep_threshold": (C.c_float, [_ID]),
        "i2d_body_set_gravity_scale": (_STATUS, [_ID, C.c_float]),
        "i2d_body_get_gravity_scale": (C.c_float, [_ID]),
        "i2d_body_set_linear_damping": (_STATUS, [_ID, C.c_float]),
        "i2d_body_get_linear_damping": (C.c_float, [_ID]),
        "i2d_body_set_angular_damping": (_STATUS, [_ID, C.c_float]),
        "i2d_body_get_angular_damping": (C.c_float, [_ID]),
        "i2d_body_set_fixed_rotation": (_STATUS, [_ID, C.c_bool]),
        "i2d_body_is_fixed_rotation": (C.c_bool, [_ID]),
        # shapes
        "i2d_shape_create_circle": (_ID, [_ID, C.POINTER(ShapeDef), C.POINTER(Circle)]),
        "i2d_shape_create_box": (_ID, [_ID, C.POINTER(ShapeDef), C.c_float, C.c_float]),
        "i2d_shape_create_offset_box": (_ID, [_ID, C.POINTER(ShapeDef), C.c_float, C.c_float, Vec2, Rot]),
        "i2d_shape_create_polygon": (_ID, [_ID, C.POINTER(ShapeDef), C.POINTER(Vec2), C.c_int32]),
        "i2d_shape_create_capsule": (_ID, [_ID, C.POINTER(ShapeDef), Vec2, Vec2, C.c_float]),
        "i2d_shape_create_segment": (_ID, [_ID, C.POINTER(ShapeDef), Vec2, Vec2]),
        "i2d_shape_destroy": (_STATUS, [_ID]),
        "i2d_shape_is_valid": (C.c_bool, [_ID]),
        "i2d_shape_get_body": (_ID, [_ID]),
        "i2d_shape_get_type": (C.c_int32, [_ID]),
        "i2d_shape_get_circle": (Circle, [_ID]),
        "i2d_shape_get_polygon": (Polygon, [_ID]),
        "i2d_shape_get_capsule": (Capsule, [_ID]),
        "i2d_shape_get_segment": (Segment, [_ID]),
        "i2d_shape_get_aabb": (AABB, [_ID]),
        "i2d_shape_get_density": (C.c_float, [_ID]),
        "i2d_shape_get_friction": (C.c_float, [_ID]),
        "i2d_shape_set_friction": (_STATUS, [_ID, C.c_float]),
        "i2d_shape_get_restitution": (C.c_float, [_ID]),
        "i2d_shape_set_restitution": (_STATUS, [_ID, C.c_float]),
        "i2d_shape_get_filter": (Filter, [_ID]),
        "i2d_shape_set_filter": (_STATUS, [_ID, Filter]),
        "i2d_shape_is_sensor": (C.c_bool, [_ID]),
        "i2d_shape_get_contact_data": (C.c_int32, [_ID, _PTR, C.c_int32]),
        "i2d_shape_get_sensor_overlaps": (C.c_int32, [_ID, _PTR, C.c_int32]),
        "i2d_shape_get_closest_point": (Vec2, [_ID, Vec2]),
        "i2d_shape_set_circle": (_STATUS, [_ID, C.POINTER(Circle)]),
        "i2d_shape_set_capsule": (_STATUS, [_ID, C.POINTER(Capsule)]),
        "i2d_shape_set_segment": (_STATUS, [_ID, C.POINTER(Segment)]),
        "i2d_shape_set_polygon": (_STATUS, [_ID, C.POINTER(Polygon)]),
        "i2d_shape_set_density": (_STATUS, [_ID, C.c_float, C.c_bool]),
        "i2d_shape_set_material": (_STATUS, [_ID, SurfaceMaterial]),
        "i2d_shape_get_material": (SurfaceMaterial, [_ID]),
        "i2d_shape_enable_sensor_events": (_STATUS, [_ID, C.c_bool]),
        "i2d_shape_are_sensor_events_enabled": (C.c_bool, [_ID]),
        "i2d_shape_enable_contact_events": (_STATUS, [_ID, C.c_bool]),
        "i2d_shape_are_contact_events_enabled": (C.c_bool, [_ID]),
        "i2d_shape_enable_hit_events": (_STATUS, [_ID, C.c_bool]),
        "i2d_shape_are_hit_events_enabled": (C.c_bool, [_ID]),
        "i2d_shape_enable_pre_solve_events": (_STATUS, [_ID, C.c_bool]),
        "i2d_shape_are_pre_solve_events_enabled": (C.c_bool, [_ID]),
    }


_LIBRARY_NAMES = ("libimpulse2d.so", "libimpulse2d.dylib", "impulse2d.dll")


def _package_dir() -> str:
    return os.path.dirname(os.path.abspath(__file__))


def candidate_paths() -> List[str]:
    """Every place the library is looked for, in order (see the module docstring)."""
    paths: List[str] = []
    from_env = os.environ.get(ENVIRONMENT_VARIABLE)
    if from_env:
        return [from_env]
    here = _package_dir()
    paths += [os.path.join(here, name) for name in _LIBRARY_NAMES]
    # bindings/python/impulse2d -> the repository root, when run from a source tree
    root = os.path.dirname(os.path.dirname(os.path.dirname(here)))
    for build in sorted(glob.glob(os.path.join(root, "build*", "capi"))):
        paths += [os.path.join(build, name) for name in _LIBRARY_NAMES]
    found = ctypes.util.find_library("impulse2d")
    if found:
        paths.append(found)
    prefixes = [sys.prefix, "/usr/local", "/usr", os.path.expanduser("~/.local")]
    for prefix in prefixes:
        for libdir in ("lib", "lib64", "lib/x86_64-linux-gnu", "lib/aarch64-linux-gnu"):
            paths += [os.path.join(prefix, libdir, name) for name in _LIBRARY_NAMES]
    return paths


def find_library() -> str:
    """The path of the library to load; LibraryError listing where it looked if none."""
    paths = candidate_paths()
    for path in paths:
        if os.path.sep not in path or os.path.exists(path):
            return path
    raise LibraryError(
        "libimpulse2d was not found. Build it (cmake -S . -B build && cmake --build build), "
        "then either reinstall this package from bindings/python, or set %s to the library's "
        "path. Looked in:\n  %s" % (ENVIRONMENT_VARIABLE, "\n  ".join(paths))
    )


def declare(lib: C.CDLL, S: _structs.Structs) -> C.CDLL:
    """Sets restype and argtypes of every function the package calls."""
    for name, (restype, argtypes) in signatures(S).items():
        fn = getattr(lib, name)
        fn.restype = restype
        fn.argtypes = argtypes
    return lib


def version_string(lib: C.CDLL) -> str:
    lib.i2d_version.restype = C.c_uint32
    v = lib.i2d_version()
    return "%d.%d.%d" % (v >> 16, (v >> 8) & 0xFF, v & 0xFF)


def load(path: Optional[str] = None, description: Optional[_layout.Description] = None) -> C.CDLL:
    """Opens the library, builds the struct classes from its description of its structs
    (description overrides what the library reports, for tests), refuses it unless every
    field the package uses is there as the package uses it (LayoutMismatch), and declares
    its functions. The classes are lib._impulse2d_structs."""
    if C.sizeof(C.c_void_p) != 8:
        raise LibraryError("impulse2d's Python package needs a 64-bit Python")
    path = path or find_library()
    try:
        lib = C.CDLL(path)
    except OSError as error:
        raise LibraryError("cannot load %s: %s" % (path, error)) from error
    if description is None:
        try:
            description = _layout.describe(lib)
        except _layout.LayoutError as error:
            raise LibraryError("%s (impulse2d %s) cannot be used by this package: %s"
                               % (path, version_string(lib), error)) from error
    structs = _structs.build(description, path, version_string(lib))
    lib._impulse2d_path = path
    lib._impulse2d_structs = structs
    return declare(lib, structs)
