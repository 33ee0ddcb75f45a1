# SPDX-License-Identifier: MIT
"""The impulse2d package's loaded library and the few functions it does not declare.

The compat layer calls the library through the package's handle (impulse2d._native)
rather than through impulse2d.Body and friends on the per-step paths: one ctypes call
per Box2D getter, no wrapper object, no tuple conversion."""

import ctypes as C

from impulse2d._native import check, check_last, lib, structs

Vec2, Rot, Transform = structs.Vec2, structs.Rot, structs.Transform
_ID = C.c_uint64

# Functions the package leaves undeclared; declared here once, by their C prototypes.
for _name, _restype, _argtypes in (
    ("i2d_body_get_local_center_of_mass", Vec2, [_ID]),
    ("i2d_world_cast_ray_all", C.c_int32, [_ID, Vec2, Vec2, structs.QueryFilter, C.c_void_p, C.c_int32]),
    ("i2d_body_set_type", C.c_int32, [_ID, C.c_int32]),
    ("i2d_revolute_joint_get_angle", C.c_float, [_ID]),
    ("i2d_revolute_joint_get_motor_torque", C.c_float, [_ID]),
    ("i2d_prismatic_joint_get_translation", C.c_float, [_ID]),
    ("i2d_prismatic_joint_get_speed", C.c_float, [_ID]),
    ("i2d_wheel_joint_get_translation", C.c_float, [_ID]),
    ("i2d_revolute_joint_set_limits", C.c_int32, [_ID, C.c_float, C.c_float]),
    ("i2d_body_get_world_point_velocity", Vec2, [_ID, Vec2]),
):
    _fn = getattr(lib, _name)
    _fn.restype, _fn.argtypes = _restype, _argtypes

__all__ = ["C", "check", "check_last", "lib", "structs", "Vec2", "Rot", "Transform"]
