# SPDX-License-Identifier: MIT
"""The lander: a hexagonal hull and two legs on motorised, limited hinges, built
into a world at the top middle of the screen."""

from typing import NamedTuple, Tuple

from . import constants as K

# The hull and legs count as resting below this speed (m/s; impulse2d compares it
# with |v| + |w| x the body's largest extent). Box2D 2.3, which Gymnasium uses, asks
# for |v| < 0.01 m/s and |w| < 2 deg/s; for the hull (extent about 0.8 m) the sum of
# those two limits is 0.01 + 0.8 x 0.035 = 0.038 m/s, and both engines wait 0.5 s.
SLEEP_SPEED = 0.038

START_X = K.SCREEN_WIDTH / 2
START_Y = K.SCREEN_HEIGHT


class Lander(NamedTuple):
    hull: object                     # impulse2d.Body
    legs: Tuple[object, object]      # the leg seen in observation[6], then observation[7]
    hull_shape_id: int
    leg_shape_ids: Tuple[int, int]


def _metres(pixels: float) -> float:
    return pixels / K.PIXELS_PER_METRE


def _build_hull(world):
    hull = world.create_body(position=(START_X, START_Y), angle=0.0)
    outline = [(_metres(x), _metres(y)) for x, y in K.HULL_OUTLINE_PIXELS]
    shape = hull.create_polygon(
        outline,
        density=K.HULL_DENSITY,
        friction=K.HULL_FRICTION,
        restitution=0.0,
        filter=(K.HULL_CATEGORY, K.GROUND_CATEGORY),
    )
    hull.sleep_threshold = SLEEP_SPEED
    return hull, shape


def _build_leg(world, hull, side: int):
    """side -1 builds the leg that starts to the right of the hull (Gymnasium's first
    leg), side +1 the one to the left; the signs mirror the hinge's limits and motor."""
    leg = world.create_body(
        position=(START_X - side * _metres(K.LEG_OFFSET_X_PIXELS), START_Y),
        angle=side * K.LEG_START_TILT,
    )
    shape = leg.create_box(
        _metres(K.LEG_HALF_WIDTH_PIXELS),
        _metres(K.LEG_HALF_HEIGHT_PIXELS),
        density=K.LEG_DENSITY,
        friction=K.LEG_FRICTION,
        restitution=0.0,
        filter=(K.LEG_CATEGORY, K.GROUND_CATEGORY),
    )
    leg.sleep_threshold = SLEEP_SPEED
    # The hinge's anchor on the leg is not where the leg was placed: the joint pulls
    # the legs into place during the first frames, as in Gymnasium.
    if side < 0:
        lower, upper = K.LEG_LIMIT_OUTER - K.LEG_LIMIT_TRAVEL, K.LEG_LIMIT_OUTER
    else:
        lower, upper = -K.LEG_LIMIT_OUTER, -K.LEG_LIMIT_OUTER + K.LEG_LIMIT_TRAVEL
    world.create_joint(
        "revolute",
        hull,
        leg,
        local_anchor_a=(0.0, 0.0),
        local_anchor_b=(side * _metres(K.LEG_OFFSET_X_PIXELS), _metres(K.LEG_DROP_PIXELS)),
        enable_limit=True,
        lower_angle=lower,
        upper_angle=upper,
        enable_motor=True,
        max_motor_torque=K.LEG_MOTOR_TORQUE,
        motor_speed=side * K.LEG_MOTOR_SPEED,
    )
    return leg, shape


def build_lander(world) -> Lander:
    hull, hull_shape = _build_hull(world)
    first_leg, first_shape = _build_leg(world, hull, -1)
    second_leg, second_shape = _build_leg(world, hull, +1)
    return Lander(hull, (first_leg, second_leg), hull_shape.id, (first_shape.id, second_shape.id))
