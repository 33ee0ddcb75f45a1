# SPDX-License-Identifier: MIT
"""RGB pictures of a lander's world, 600 x 400 like Gymnasium's, without pygame: the
moon is filled from the episode's terrain, the lander's shapes come from impulse2d's
debug draw (World.draw) and are filled by a small NumPy rasteriser. The pad's flags
are drawn too. Engine flames are not (the particles are not simulated)."""

import numpy as np

from .. import COLOR_ASLEEP
from . import constants as K

SKY = (0, 0, 0)
MOON = (255, 255, 255)
HULL_FILL = (128, 102, 230)
SLEEPING_FILL = (77, 77, 128)
FLAG_POLE = (255, 255, 255)
FLAG = (204, 204, 0)

# Pixel centres in metres, shared by every picture.
_COLUMNS = (np.arange(K.SCREEN_WIDTH_PIXELS) + 0.5) / K.PIXELS_PER_METRE
_ROWS_UP = (np.arange(K.SCREEN_HEIGHT_PIXELS)[::-1] + 0.5) / K.PIXELS_PER_METRE  # row 0 is the top


def _fill_convex(image: np.ndarray, corners, colour) -> None:
    """Paints the pixels whose centres lie inside a convex polygon (world metres)."""
    corners = np.asarray(corners, dtype=np.float64)
    left, bottom = np.floor(corners.min(axis=0) * K.PIXELS_PER_METRE).astype(int)
    right, top = np.ceil(corners.max(axis=0) * K.PIXELS_PER_METRE).astype(int)
    columns = slice(max(left, 0), min(right, K.SCREEN_WIDTH_PIXELS))
    rows = slice(max(K.SCREEN_HEIGHT_PIXELS - top, 0), min(K.SCREEN_HEIGHT_PIXELS - bottom, K.SCREEN_HEIGHT_PIXELS))
    xs, ys = np.meshgrid(_COLUMNS[columns], _ROWS_UP[rows])
    inside_left = np.ones(xs.shape, dtype=bool)
    inside_right = np.ones(xs.shape, dtype=bool)
    for start, end in zip(corners, np.roll(corners, -1, axis=0)):
        side = (end[0] - start[0]) * (ys - start[1]) - (end[1] - start[1]) * (xs - start[0])
        inside_left &= side >= 0
        inside_right &= side <= 0
    image[rows, columns][inside_left | inside_right] = colour


class _ShapeFiller:
    """A World.draw drawer that fills the dynamic bodies' polygons."""

    def __init__(self, image: np.ndarray) -> None:
        self.image = image

    def draw_solid_polygon(self, transform, vertices, radius, color) -> None:
        fill = SLEEPING_FILL if color == COLOR_ASLEEP else HULL_FILL
        _fill_convex(self.image, [transform.apply(v) for v in vertices], fill)


def _draw_moon(image: np.ndarray, terrain) -> None:
    surface = np.interp(_COLUMNS, terrain.xs, terrain.ys)
    image[_ROWS_UP[:, None] <= surface[None, :]] = MOON


def _draw_flags(image: np.ndarray, terrain) -> None:
    for x in (terrain.pad_left, terrain.pad_right):
        base = terrain.pad_height
        _fill_convex(image, [(x - 0.02, base), (x + 0.02, base), (x + 0.02, base + 50 / K.PIXELS_PER_METRE),
                             (x - 0.02, base + 50 / K.PIXELS_PER_METRE)], FLAG_POLE)
        top = base + 50 / K.PIXELS_PER_METRE
        _fill_convex(image, [(x, top), (x, top - 10 / K.PIXELS_PER_METRE), (x + 25 / K.PIXELS_PER_METRE,
                                                                            top - 5 / K.PIXELS_PER_METRE)], FLAG)


def render_rgb(world, terrain) -> np.ndarray:
    """A (400, 600, 3) uint8 picture of one lander's world."""
    image = np.empty((K.SCREEN_HEIGHT_PIXELS, K.SCREEN_WIDTH_PIXELS, 3), dtype=np.uint8)
    image[:] = SKY
    _draw_moon(image, terrain)
    _draw_flags(image, terrain)
    world.draw(_ShapeFiller(image), joints=False)
    return image
