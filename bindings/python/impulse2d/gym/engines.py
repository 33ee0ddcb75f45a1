# SPDX-License-Identifier: MIT
"""The engines: actions become throttles, throttles become impulses on the hull.

Gymnasium applies each engine's impulse at a nozzle point jittered by a random
"dispersion", so the push also turns the lander a little. Here the impulses of a whole
batch are computed at once with NumPy and turned into the velocity change they cause
(dv = J / m, dw = (p - c) x J / I, which is what applying an impulse at a point does),
so that each world needs one velocity write instead of one call per engine."""

from typing import NamedTuple

import numpy as np

from . import constants as K

NOOP_DISCRETE = 0
MAIN_ENGINE_ACTION = 2
LEFT_ENGINE_ACTION = 1    # the left nozzle: turns the lander counter-clockwise ...
RIGHT_ENGINE_ACTION = 3   # ... and the right one clockwise


class Throttles(NamedTuple):
    main: np.ndarray        # (n,) 0 (off) or 0.5..1
    side: np.ndarray        # (n,) 0 (off) or 0.5..1
    direction: np.ndarray   # (n,) -1 left nozzle, +1 right nozzle, 0 neither


def discrete_throttles(actions: np.ndarray) -> Throttles:
    """Actions 0..3: nothing, left nozzle, main engine, right nozzle, each at full power."""
    actions = np.asarray(actions)
    if actions.dtype.kind not in "iu" or np.any((actions < 0) | (actions > 3)):
        raise ValueError("discrete LunarLander actions are integers 0, 1, 2 or 3; got %r" % (actions,))
    main = (actions == MAIN_ENGINE_ACTION).astype(np.float64)
    sideways = (actions == LEFT_ENGINE_ACTION) | (actions == RIGHT_ENGINE_ACTION)
    direction = np.where(sideways, actions - 2, 0).astype(np.float64)
    return Throttles(main, sideways.astype(np.float64), direction)


def continuous_throttles(actions: np.ndarray) -> Throttles:
    """Rows [main, lateral] in [-1, 1] (clipped). The main engine is off below 0 and
    runs at 50..100% over [0, 1]; the side nozzles are off within (-0.5, 0.5) and run
    at 50..100% beyond, the sign choosing the nozzle."""
    actions = np.clip(np.asarray(actions, dtype=np.float64), -1.0, 1.0)
    if actions.ndim != 2 or actions.shape[1] != 2:
        raise ValueError("continuous LunarLander actions are rows [main, lateral]; got shape %s" % (actions.shape,))
    main_input, lateral = actions[:, 0], actions[:, 1]
    main = np.where(main_input > 0.0, (np.clip(main_input, 0.0, 1.0) + 1.0) * 0.5, 0.0)
    firing = np.abs(lateral) > 0.5
    side = np.where(firing, np.clip(np.abs(lateral), 0.5, 1.0), 0.0)
    direction = np.where(firing, np.sign(lateral), 0.0)
    return Throttles(main, side, direction)


def _cross(r: np.ndarray, j: np.ndarray) -> np.ndarray:
    return r[:, 0] * j[:, 1] - r[:, 1] * j[:, 0]


def velocity_change(throttles: Throttles, transforms: np.ndarray, dispersion: np.ndarray,
                    mass: float, inertia: float, local_center) -> tuple:
    """(dv (n, 2), dw (n,)) that the engines' impulses give hulls at transforms (rows
    [x, y, cos, sin]), with dispersion (n, 2) the frame's two jitters in [-1, 1)."""
    x, y, cos, sin = (transforms[:, k].astype(np.float64) for k in range(4))
    jitter_along, jitter_across = dispersion[:, 0] / K.PIXELS_PER_METRE, dispersion[:, 1] / K.PIXELS_PER_METRE
    # tip: the body's up axis; side: the axis across it (pointing left when upright).
    tip_x, tip_y = sin, cos
    side_x, side_y = -cos, sin
    origin = np.stack([x, y], axis=1)

    # Main engine: nozzle under the hull, pushing along the body's up axis.
    depth = K.MAIN_ENGINE_DEPTH_PIXELS / K.PIXELS_PER_METRE + 2 * jitter_along
    main_offset = np.stack([tip_x * depth + side_x * jitter_across, -tip_y * depth - side_y * jitter_across], axis=1)
    main_point = origin + main_offset
    main_impulse = -main_offset * (K.MAIN_ENGINE_POWER * throttles.main)[:, None]

    # Side nozzles: high on the hull, pushing sideways; the point's shift along the body
    # axis is as Gymnasium has it (it makes the torque depend on the tilt, a known quirk).
    lever = 3 * jitter_across + throttles.direction * K.SIDE_ENGINE_OFFSET_PIXELS / K.PIXELS_PER_METRE
    side_offset = np.stack([tip_x * jitter_along + side_x * lever, -tip_y * jitter_along - side_y * lever], axis=1)
    side_point = origin + side_offset + np.stack(
        [-tip_x * K.SIDE_ENGINE_REACH_PIXELS, tip_y * K.SIDE_ENGINE_HEIGHT_PIXELS], axis=1) / K.PIXELS_PER_METRE
    side_impulse = -side_offset * (K.SIDE_ENGINE_POWER * throttles.side)[:, None]

    cx, cy = local_center
    center = origin + np.stack([cos * cx - sin * cy, sin * cx + cos * cy], axis=1)
    dv = (main_impulse + side_impulse) / mass
    dw = (_cross(main_point - center, main_impulse) + _cross(side_point - center, side_impulse)) / inertia
    return dv, dw


def fuel_cost(throttles: Throttles) -> np.ndarray:
    return throttles.main * K.MAIN_ENGINE_FUEL_COST + throttles.side * K.SIDE_ENGINE_FUEL_COST
