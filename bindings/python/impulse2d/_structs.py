# SPDX-License-Identifier: MIT
"""ctypes declarations of the public C structs (include/impulse2d/*.h).

Every struct declared here is checked against the loaded library's own size and
alignment (i2d_get_struct_infos) before any call is made: see _layout.py.
Ids are passed as plain 64-bit integers (see _library.py), so the id structs are
declared only to check their layout.
"""

import ctypes as C


class Vec2(C.Structure):
    _fields_ = [("x", C.c_float), ("y", C.c_float)]


class Rot(C.Structure):
    _fields_ = [("c", C.c_float), ("s", C.c_float)]


class Transform(C.Structure):
    _fields_ = [("p", Vec2), ("q", Rot)]


class AABB(C.Structure):
    _fields_ = [("min", Vec2), ("max", Vec2)]


class IdStruct(C.Structure):
    _fields_ = [("bits", C.c_uint64)]


class Filter(C.Structure):
    _fields_ = [("category_bits", C.c_uint64), ("mask_bits", C.c_uint64), ("group_index", C.c_int32)]


class QueryFilter(C.Structure):
    _fields_ = [("category_bits", C.c_uint64), ("mask_bits", C.c_uint64)]


class WorldDef(C.Structure):
    _fields_ = [
        ("gravity", Vec2),
        ("contact_slop", C.c_float),
        ("contact_hertz", C.c_float),
        ("contact_damping_ratio", C.c_float),
        ("contact_push_max_speed", C.c_float),
        ("restitution_threshold", C.c_float),
        ("maximum_linear_speed", C.c_float),
        ("friction_mixing", C.c_int32),
        ("restitution_mixing", C.c_int32),
        ("enable_sleep", C.c_bool),
        ("sleep_speed_threshold", C.c_float),
        ("time_to_sleep", C.c_float),
        ("simd_path", C.c_int32),
        ("enable_contact_recycling", C.c_bool),
        ("enable_profile", C.c_bool),
        ("worker_count", C.c_int32),
        ("enqueue_task", C.c_void_p),
        ("finish_task", C.c_void_p),
        ("user_task_context", C.c_void_p),
        ("joint_hertz", C.c_float),
        ("joint_damping_ratio", C.c_float),
        ("enable_continuous", C.c_bool),
        ("hit_event_threshold", C.c_float),
        ("internal_cookie", C.c_uint32),
    ]


class BodyDef(C.Structure):
    _fields_ = [
        ("type", C.c_int32),
        ("position", Vec2),
        ("rotation", Rot),
        ("linear_velocity", Vec2),
        ("angular_velocity", C.c_float),
        ("linear_damping", C.c_float),
        ("angular_damping", C.c_float),
        ("gravity_scale", C.c_float),
        ("fixed_rotation", C.c_bool),
        ("enable_sleep", C.c_bool),
        ("is_bullet", C.c_bool),
        ("user_data", C.c_void_p),
        ("internal_cookie", C.c_uint32),
    ]


class ShapeDef(C.Structure):
    _fields_ = [
        ("density", C.c_float),
        ("friction", C.c_float),
        ("restitution", C.c_float),
        ("rolling_resistance", C.c_float),
        ("tangent_speed", C.c_float),
        ("is_sensor", C.c_bool),
        ("enable_contact_events", C.c_bool),
        ("enable_sensor_events", C.c_bool),
        ("enable_hit_events", C.c_bool),
        ("filter", Filter),
        ("user_data", C.c_void_p),
        ("internal_cookie", C.c_uint32),
    ]


class WorldCounters(C.Structure):
    _fields_ = [
        (name, C.c_int32)
        for name in (
            "body_count",
            "shape_count",
            "contact_count",
            "pair_count",
            "static_tree_height",
            "kinematic_tree_height",
            "dynamic_tree_height",
            "awake_body_count",
            "sleeping_island_count",
        )
    ]


class Profile(C.Structure):
    _fields_ = [
        (name, C.c_float) for name in ("step", "pairs", "collide", "solve", "update_bounds", "sleep", "events", "continuous")
    ]


class ShapePair(C.Structure):
    """i2d_contact_begin_event, i2d_contact_end_event and the sensor events: two ids."""

    _fields_ = [("a", C.c_uint64), ("b", C.c_uint64)]


class ManifoldPoint(C.Structure):
    _fields_ = [("point", Vec2), ("penetration", C.c_float), ("id", C.c_uint32)]


class Manifold(C.Structure):
    _fields_ = [("normal", Vec2), ("point_count", C.c_int32), ("points", ManifoldPoint * 2)]


class ContactBeginEvent(C.Structure):
    """i2d_contact_begin_event: the two ids and the contact's manifold."""

    _fields_ = [("a", C.c_uint64), ("b", C.c_uint64), ("manifold", Manifold)]


class ContactHitEvent(C.Structure):
    _fields_ = [
        ("a", C.c_uint64),
        ("b", C.c_uint64),
        ("point", Vec2),
        ("normal", Vec2),
        ("approach_speed", C.c_float),
    ]


class SensorEvents(C.Structure):
    _fields_ = [
        ("begin_events", C.POINTER(ShapePair)),
        ("begin_count", C.c_int32),
        ("end_events", C.POINTER(ShapePair)),
        ("end_count", C.c_int32),
    ]


class ContactEvents(C.Structure):
    _fields_ = [
        ("begin_events", C.POINTER(ContactBeginEvent)),
        ("begin_count", C.c_int32),
        ("end_events", C.POINTER(ShapePair)),
        ("end_count", C.c_int32),
        ("hit_events", C.POINTER(ContactHitEvent)),
        ("hit_count", C.c_int32),
    ]


class BodyMoveEvent(C.Structure):
    _fields_ = [("transform", Transform), ("body", C.c_uint64), ("user_data", C.c_void_p), ("fell_asleep", C.c_bool)]


class BodyQuarantineEvent(C.Structure):
    _fields_ = [("transform", Transform), ("body", C.c_uint64), ("user_data", C.c_void_p), ("former_type", C.c_int)]


class BodyEvents(C.Structure):
    _fields_ = [
        ("move_events", C.POINTER(BodyMoveEvent)),
        ("move_count", C.c_int32),
        ("quarantine_events", C.POINTER(BodyQuarantineEvent)),
        ("quarantine_count", C.c_int32),
    ]


class RayResult(C.Structure):
    _fields_ = [
        ("shape", C.c_uint64),
        ("point", Vec2),
        ("normal", Vec2),
        ("fraction", C.c_float),
        ("hit", C.c_bool),
    ]


class Circle(C.Structure):
    _fields_ = [("center", Vec2), ("radius", C.c_float)]


MAX_POLYGON_VERTICES = 8


class Polygon(C.Structure):
    _fields_ = [
        ("vertices", Vec2 * MAX_POLYGON_VERTICES),
        ("normals", Vec2 * MAX_POLYGON_VERTICES),
        ("centroid", Vec2),
        ("radius", C.c_float),
        ("count", C.c_int32),
    ]


class Capsule(C.Structure):
    _fields_ = [("center1", Vec2), ("center2", Vec2), ("radius", C.c_float)]


class Segment(C.Structure):
    _fields_ = [("point1", Vec2), ("point2", Vec2)]


class JointBase(C.Structure):
    """The first member of every joint def (i2d_joint_base); ids as plain integers."""

    _fields_ = [
        ("body_a", C.c_uint64),
        ("body_b", C.c_uint64),
        ("local_anchor_a", Vec2),
        ("local_anchor_b", Vec2),
        ("collide_connected", C.c_bool),
        ("force_threshold", C.c_float),
        ("torque_threshold", C.c_float),
        ("user_data", C.c_void_p),
    ]


def _joint_def(name, fields):
    """A joint def: the base, the kind's fields (C.c_float unless given), the cookie."""
    spelled = [(f, C.c_float) if isinstance(f, str) else f for f in fields]
    return type(name, (C.Structure,), {"_fields_": [("base", JointBase)] + spelled + [("internal_cookie", C.c_uint32)]})


_flag = C.c_bool

RevoluteJointDef = _joint_def(
    "RevoluteJointDef",
    ["reference_angle", ("enable_limit", _flag), "lower_angle", "upper_angle", ("enable_motor", _flag),
     "motor_speed", "max_motor_torque", ("enable_spring", _flag), "hertz", "damping_ratio", "target_angle"],
)
PrismaticJointDef = _joint_def(
    "PrismaticJointDef",
    [("local_axis_a", Vec2), "reference_angle", ("enable_limit", _flag), "lower_translation", "upper_translation",
     ("enable_motor", _flag), "motor_speed", "max_motor_force", ("enable_spring", _flag), "hertz", "damping_ratio",
     "target_translation"],
)
DistanceJointDef = _joint_def(
    "DistanceJointDef",
    ["length", ("enable_limit", _flag), "min_length", "max_length", ("enable_spring", _flag), "hertz",
     "damping_ratio", ("enable_motor", _flag), "motor_speed", "max_motor_force"],
)
WeldJointDef = _joint_def(
    "WeldJointDef", ["reference_angle", "linear_hertz", "angular_hertz", "linear_damping_ratio", "angular_damping_ratio"]
)
WheelJointDef = _joint_def(
    "WheelJointDef",
    [("local_axis_a", Vec2), ("enable_spring", _flag), "hertz", "damping_ratio", ("enable_limit", _flag),
     "lower_translation", "upper_translation", ("enable_motor", _flag), "motor_speed", "max_motor_torque"],
)
MotorJointDef = _joint_def(
    "MotorJointDef", [("linear_offset", Vec2), "angular_offset", "max_force", "max_torque", "correction_factor"]
)
MouseJointDef = _joint_def("MouseJointDef", [("target", Vec2), "hertz", "damping_ratio", "max_force"])
FilterJointDef = _joint_def("FilterJointDef", [])


class JointEvent(C.Structure):
    _fields_ = [("joint", C.c_uint64), ("user_data", C.c_void_p)]


class JointEvents(C.Structure):
    _fields_ = [("events", C.POINTER(JointEvent)), ("count", C.c_int32)]


# Joint kind name -> its def struct, in i2d_joint_type order.
JOINT_DEFS = {
    "distance": DistanceJointDef,
    "filter": FilterJointDef,
    "motor": MotorJointDef,
    "mouse": MouseJointDef,
    "prismatic": PrismaticJointDef,
    "revolute": RevoluteJointDef,
    "weld": WeldJointDef,
    "wheel": WheelJointDef,
}


class StructInfo(C.Structure):
    _fields_ = [("name", C.c_char_p), ("size", C.c_int32), ("align", C.c_int32)]


# The C name of every struct above, for the layout check. A C struct the binding does
# not use need not be listed; every one listed must match the library.
DECLARED = {
    "i2d_struct_info": StructInfo,
    "i2d_world_id": IdStruct,
    "i2d_body_id": IdStruct,
    "i2d_shape_id": IdStruct,
    "i2d_vec2": Vec2,
    "i2d_rot": Rot,
    "i2d_transform": Transform,
    "i2d_aabb": AABB,
    "i2d_filter": Filter,
    "i2d_query_filter": QueryFilter,
    "i2d_world_def": WorldDef,
    "i2d_body_def": BodyDef,
    "i2d_shape_def": ShapeDef,
    "i2d_world_counters": WorldCounters,
    "i2d_profile": Profile,
    "i2d_contact_begin_event": ContactBeginEvent,
    "i2d_manifold": Manifold,
    "i2d_manifold_point": ManifoldPoint,
    "i2d_contact_end_event": ShapePair,
    "i2d_contact_events": ContactEvents,
    "i2d_sensor_begin_event": ShapePair,
    "i2d_sensor_end_event": ShapePair,
    "i2d_sensor_events": SensorEvents,
    "i2d_contact_hit_event": ContactHitEvent,
    "i2d_body_move_event": BodyMoveEvent,
    "i2d_body_quarantine_event": BodyQuarantineEvent,
    "i2d_body_events": BodyEvents,
    "i2d_ray_result": RayResult,
    "i2d_circle": Circle,
    "i2d_polygon": Polygon,
    "i2d_capsule": Capsule,
    "i2d_segment": Segment,
    "i2d_joint_id": IdStruct,
    "i2d_joint_base": JointBase,
    "i2d_joint_event": JointEvent,
    "i2d_joint_events": JointEvents,
}
DECLARED.update({"i2d_%s_joint_def" % kind: cls for kind, cls in JOINT_DEFS.items()})
