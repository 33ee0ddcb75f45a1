# SPDX-License-Identifier: MIT
"""Events as lists of named tuples, queries as lists."""

import pytest

import impulse2d
from conftest import make_ground


def test_contact_and_body_events_of_a_landing(world):
    ground = make_ground(world)
    ball = world.create_body(position=(0.0, 0.6))
    shape = ball.create_circle(0.5)
    begun = []
    moved = 0
    for _ in range(60):
        world.step()
        begin, end = world.contact_events()
        begun += begin
        moved += sum(1 for m in world.body_events() if m.body == ball)
    assert len(begun) == 1
    event = begun[0]
    assert isinstance(event, impulse2d.ContactBegin)
    assert {event.shape_a, event.shape_b} == {shape, ground.shapes[0]}
    assert moved > 0
    # Finite input never needs the non-finite quarantine.
    assert world.quarantine_events() == [] and ball.quarantined is False
    ball.destroy()
    with pytest.raises(impulse2d.InvalidHandle):
        ball.quarantined
    world.step()
    begin, end = world.contact_events()
    assert len(end) == 1 and isinstance(end[0], impulse2d.ContactEnd)


def test_sensor_events_and_body_move_fields(world):
    sensor_body = world.create_body(impulse2d.STATIC)
    sensor = sensor_body.create_box(1.0, 1.0, is_sensor=True)
    ball = world.create_body(position=(0.0, 3.0))
    ball.create_circle(0.25)
    entered = []
    for _ in range(90):
        world.step()
        begin, _end = world.sensor_events()
        entered += begin
        for move in world.body_events():
            assert isinstance(move, impulse2d.BodyMove)
            assert move.position == ball.position and move.rotation == ball.rotation
    assert len(entered) == 1 and entered[0].sensor == sensor


def test_queries_return_lists(world):
    ground = make_ground(world)
    box = world.create_body(impulse2d.STATIC, position=(5.0, 1.0)).create_box(0.5, 0.5)
    found = world.overlap_aabb((4.0, 0.5), (6.0, 1.5))
    assert found == [box]
    assert set(world.overlap_aabb((-60, -3), (60, 3))) == {box, ground.shapes[0]}
    assert world.overlap_point((5.0, 1.0)) == [box]
    assert world.overlap_point((5.0, 3.0)) == []
    hit = world.cast_ray((5.0, 10.0), (0.0, -20.0))
    assert isinstance(hit, impulse2d.RayHit) and hit.shape == box
    assert hit.point == (5.0, 1.5) and hit.normal == (0.0, 1.0)
    assert world.cast_ray((5.0, 10.0), (0.0, 1.0)) is None
    # more hits than the first buffer holds
    for i in range(100):
        world.create_body(impulse2d.STATIC, position=(-20.0 + 0.3 * i, 10.0)).create_circle(0.1)
    assert len(world.overlap_aabb((-21, 9), (20, 11))) == 100
