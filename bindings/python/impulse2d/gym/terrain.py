# SPDX-License-Identifier: MIT
"""The moon's surface: random heights smoothed into a chain of segments, with a flat
landing pad in the middle at a quarter of the screen's height."""

from typing import List, NamedTuple, Sequence

import numpy as np

from .. import BodyType
from . import constants as K


class Terrain(NamedTuple):
    xs: np.ndarray        # (TERRAIN_CHUNKS,) x of each surface point, m
    ys: np.ndarray        # (TERRAIN_CHUNKS,) y of each surface point, m
    pad_left: float       # the pad spans [pad_left, pad_right] ...
    pad_right: float
    pad_height: float     # ... at this nominal height (observations measure from it)


def _surface_xs() -> List[float]:
    """The x of each surface point, evenly across the screen, m."""
    return [K.SCREEN_WIDTH / (K.TERRAIN_CHUNKS - 1) * i for i in range(K.TERRAIN_CHUNKS)]


def random_terrain(rng: np.random.Generator) -> Terrain:
    """Draws a terrain. It takes TERRAIN_CHUNKS + 1 uniform draws from rng in one call,
    the first draws of an episode, as Gymnasium does, so one seed gives one moon here
    and there."""
    chunks = K.TERRAIN_CHUNKS
    heights = rng.uniform(0, K.SCREEN_HEIGHT / 2, size=(chunks + 1,))
    xs = np.array(_surface_xs())
    middle = chunks // 2
    pad_height = K.SCREEN_HEIGHT / 4
    # Five heights around the middle are the pad, so that smoothing keeps it flat.
    heights[middle - 2 : middle + 3] = pad_height
    # Each point is the (slightly under-weighted: 0.33, not 1/3) sum of its neighbours;
    # the first point's left neighbour is the extra last draw, wrapping around.
    ys = np.array([0.33 * (heights[i - 1] + heights[i] + heights[i + 1]) for i in range(chunks)])
    return Terrain(xs, ys, float(xs[middle - 1]), float(xs[middle + 1]), pad_height)


def build_moon(world) -> List[object]:
    """Adds the moon to world as one static body: a floor along y = 0 under the whole
    screen and the surface's segments above it, laid flat at the pad's height until
    shape_moon gives them a terrain. Returns the surface segments, left to right."""
    moon = world.create_body(BodyType.STATIC)
    surface = dict(friction=K.TERRAIN_FRICTION, density=0.0)
    moon.create_segment((0.0, 0.0), (K.SCREEN_WIDTH, 0.0), **surface)
    xs = _surface_xs()
    flat = K.SCREEN_HEIGHT / 4
    return [moon.create_segment((x0, flat), (x1, flat), **surface) for x0, x1 in zip(xs[:-1], xs[1:])]


def shape_moon(surface: Sequence[object], terrain: Terrain) -> None:
    """Lays the surface segments build_moon made along the terrain's points."""
    points = list(zip(terrain.xs.tolist(), terrain.ys.tolist()))
    for segment, start, end in zip(surface, points[:-1], points[1:]):
        segment.set_segment(start, end)
