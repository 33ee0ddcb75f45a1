# SPDX-License-Identifier: MIT
"""Bulk state as NumPy arrays, against the per-body calls."""

import math

import numpy as np
import pytest

import impulse2d
from conftest import make_pile


def test_reads_match_per_body_getters(world):
    bodies = make_pile(world, count=30)
    for _ in range(20):
        world.step()
    xf = world.transforms(bodies)
    linear, angular = world.velocities(bodies)
    assert xf.shape == (30, 4) and xf.dtype == np.float32
    assert linear.shape == (30, 2) and angular.shape == (30,)
    for i, body in enumerate(bodies):
        assert (float(xf[i, 0]), float(xf[i, 1])) == body.position
        assert (float(xf[i, 2]), float(xf[i, 3])) == body.rotation
        assert (float(linear[i, 0]), float(linear[i, 1])) == body.linear_velocity
        assert float(angular[i]) == body.angular_velocity
    assert np.any(linear[:, 1] != 0.0)  # the pile is moving: a real comparison


# A world that sleeps restarts rest timers on a write; one that does not skips them.
@pytest.mark.parametrize("enable_sleep", [True, False])
def test_writes_match_per_body_setters(enable_sleep):
    rng = np.random.default_rng(5)
    with impulse2d.World(enable_sleep=enable_sleep) as bulk_world, \
            impulse2d.World(enable_sleep=enable_sleep) as single_world:
        bulk = make_pile(bulk_world)
        single = make_pile(single_world)
        xf = np.zeros((len(bulk), 4), np.float32)
        xf[:, 0] = rng.uniform(-5, 5, len(bulk))
        xf[:, 1] = rng.uniform(2, 20, len(bulk))
        angles = rng.uniform(-3, 3, len(bulk))
        xf[:, 2], xf[:, 3] = np.cos(angles), np.sin(angles)
        linear = rng.uniform(-2, 2, (len(bulk), 2)).astype(np.float32)
        angular = rng.uniform(-2, 2, len(bulk)).astype(np.float32)

        bulk_world.set_transforms(bulk, xf)
        bulk_world.set_velocities(bulk, linear, angular)
        for i, body in enumerate(single):
            body.set_transform(tuple(xf[i, :2]), rotation=tuple(xf[i, 2:]))
            body.linear_velocity = tuple(linear[i])
            body.angular_velocity = float(angular[i])
        assert bulk_world.state_hash == single_world.state_hash
        for _ in range(30):
            bulk_world.step()
            single_world.step()
        assert bulk_world.state_hash == single_world.state_hash
        # round trip: what was written reads back (rotations normalised by the library)
        bulk_world.set_transforms(bulk, xf)
        assert np.allclose(bulk_world.transforms(bulk), xf, atol=1e-6)


def test_id_arrays_out_arrays_and_partial_velocities(world):
    bodies = make_pile(world, count=8)
    ids = world.body_ids(bodies)
    assert ids.dtype == np.uint64 and list(ids) == [b.id for b in bodies]
    out = np.full((8, 4), 7.0, np.float32)
    assert world.transforms(ids, out=out) is out and not np.any(out == 7.0)
    world.set_velocities(ids, angular=np.arange(8, dtype=np.float32))
    linear, angular = world.velocities(ids)
    assert list(angular) == list(range(8)) and not np.any(linear)
    with pytest.raises(ValueError, match="shape"):
        world.set_transforms(ids, np.zeros((7, 4)))
    with pytest.raises(ValueError, match="float32"):
        world.transforms(ids, out=np.zeros((8, 4)))
    with pytest.raises(TypeError, match="uint64"):
        world.transforms(np.zeros(8, np.int64))


def test_a_bad_id_is_named_by_index_and_nothing_is_written(world):
    bodies = make_pile(world, count=10)
    bodies[6].destroy()
    out = np.full((10, 4), 7.0, np.float32)
    with pytest.raises(impulse2d.InvalidHandle, match=r"bodies\[6\] is stale"):
        world.transforms(bodies, out=out)
    assert np.all(out == 7.0)
    before = world.state_hash
    with pytest.raises(impulse2d.InvalidHandle, match=r"bodies\[6\]"):
        world.set_velocities(bodies, np.ones((10, 2)))
    linear = np.ones((9, 2), np.float32)
    linear[4, 1] = math.nan
    alive = bodies[:6] + bodies[7:]
    with pytest.raises(impulse2d.InvalidArgument, match=r"linear\[4\]\.y is NaN"):
        world.set_velocities(alive, linear)
    xf = np.tile(np.array([0, 5, 2, 0], np.float32), (9, 1))
    with pytest.raises(impulse2d.InvalidArgument, match=r"transforms\[0\].*unit rotation"):
        world.set_transforms(alive, xf)
    assert world.state_hash == before
    with impulse2d.World() as other:
        stranger = other.create_body()
        with pytest.raises(impulse2d.InvalidHandle, match=r"bodies\[1\] belongs to another world"):
            world.transforms([alive[0], stranger])
