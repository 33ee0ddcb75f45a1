# SPDX-License-Identifier: MIT
"""Every status code comes back as its exception, carrying the library's message."""

import math

import pytest

import impulse2d
from impulse2d import _native
from impulse2d.errors import error_for


@pytest.mark.parametrize(
    "cls, c_name",
    [
        (impulse2d.InvalidArgument, "I2D_ERR_INVALID_ARGUMENT"),
        (impulse2d.InvalidHandle, "I2D_ERR_INVALID_HANDLE"),
        (impulse2d.WorldLocked, "I2D_ERR_WORLD_LOCKED"),
        (impulse2d.CapacityError, "I2D_ERR_CAPACITY"),
        (impulse2d.OutOfMemory, "I2D_ERR_OUT_OF_MEMORY"),
    ],
)
def test_each_exception_has_the_c_status_code(cls, c_name):
    assert _native.lib.i2d_status_string(cls.status).decode() == c_name
    error = error_for(cls.status, "detail")
    assert type(error) is cls and isinstance(error, impulse2d.Impulse2DError) and str(error) == "detail"


def test_invalid_argument_carries_the_message(world):
    body = world.create_body()
    with pytest.raises(impulse2d.InvalidArgument) as caught:
        body.linear_velocity = (math.nan, 0.0)
    assert str(caught.value) == "i2d_body_set_linear_velocity: velocity.x is NaN"
    assert isinstance(caught.value, ValueError)
    with pytest.raises(impulse2d.InvalidArgument, match="radius"):
        body.create_circle(-1.0)
    with pytest.raises(impulse2d.InvalidArgument, match="collinear"):
        body.create_polygon([(0, 0), (1, 0), (2, 0)])
    with pytest.raises(impulse2d.InvalidArgument, match="time_step"):
        world.step(math.inf)
    assert body.linear_velocity == (0.0, 0.0)  # a refused call changed nothing


def test_invalid_handle_for_destroyed_objects():
    world = impulse2d.World()
    body = world.create_body()
    world.destroy()
    with pytest.raises(impulse2d.InvalidHandle, match="world was destroyed"):
        body.position
    with pytest.raises(impulse2d.InvalidHandle):
        world.step()
    with pytest.raises(impulse2d.InvalidHandle):
        world.create_body()


def test_world_locked_inside_a_query(world):
    body = world.create_body()
    body.create_circle(1.0)
    seen = []

    def change_world(shape):
        seen.append(shape.body.position)  # reads work while locked
        shape.body.linear_velocity = (1.0, 0.0)
        return True

    with pytest.raises(impulse2d.WorldLocked, match="query callback"):
        world.overlap_point((0.0, 0.0), visit=change_world)
    assert seen == [(0.0, 0.0)] and body.linear_velocity == (0.0, 0.0)


def test_capacity_error_past_4096_worlds():
    worlds = []
    try:
        with pytest.raises(impulse2d.CapacityError, match="4096 worlds are alive"):
            for _ in range(4200):
                worlds.append(impulse2d.World())
        assert len(worlds) <= 4096
    finally:
        for w in worlds:
            w.destroy()
    with impulse2d.World() as w:  # the slots came back
        assert w.is_valid
