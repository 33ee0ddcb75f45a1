# SPDX-License-Identifier: MIT
"""impulse2d.gym's rgb_array pictures: the moon under the terrain, the lander's colour
where its hull is, nothing without a render mode."""

import numpy as np
import pytest

from impulse2d.gym import LunarLander, VectorLunarLander
from impulse2d.gym import constants as K
from impulse2d.gym.render import HULL_FILL, MOON, SKY


def pixel(x, y):
    """(row, column) of the pixel holding world point (x, y) m."""
    return K.SCREEN_HEIGHT_PIXELS - 1 - int(y * K.PIXELS_PER_METRE), int(x * K.PIXELS_PER_METRE)


def test_rgb_picture_shows_moon_sky_and_lander():
    env = LunarLander(render_mode="rgb_array")
    env.reset(seed=1)
    for _ in range(30):
        env.step(0)
    image = env.render()
    assert image.shape == (400, 600, 3) and image.dtype == np.uint8
    terrain, hull = env.fleet.terrains[0], env.fleet.landers[0].hull
    x, y = hull.world_center_of_mass
    assert tuple(image[pixel(x, y)]) == HULL_FILL
    assert tuple(image[pixel(x, y - 1.5)]) == SKY  # under the legs, above the moon
    column_x = 2.5
    ground = np.interp(column_x, terrain.xs, terrain.ys)
    assert tuple(image[pixel(column_x, ground - 0.2)]) == MOON
    assert tuple(image[pixel(column_x, ground + 0.2)]) == SKY
    # The picture follows the lander down.
    for _ in range(10):
        env.step(0)
    later = env.render()
    assert not np.array_equal(image, later)


def test_no_render_mode_gives_none_and_bad_modes_are_refused():
    env = LunarLander()
    env.reset(seed=0)
    assert env.render() is None
    with pytest.raises(ValueError):
        LunarLander(render_mode="human")
    with pytest.raises(ValueError):
        VectorLunarLander(2, render_mode="human")


def test_vector_render_gives_one_picture_per_sub_env():
    env = VectorLunarLander(3, render_mode="rgb_array")
    env.reset(seed=0)
    frames = env.render()
    assert len(frames) == 3 and all(f.shape == (400, 600, 3) for f in frames)
    assert not np.array_equal(frames[0], frames[1])  # different terrains
