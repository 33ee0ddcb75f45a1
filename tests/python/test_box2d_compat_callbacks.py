# SPDX-License-Identifier: MIT
"""Box2D contact listener, sensors as contacts, DestroyBody's EndContact, ray casts
(ignore / clip / terminate; the compiled loop and the Python one) and QueryAABB."""

import os

import impulse2d
import pytest

from box2d_compat_fixture import Box2D, Recorder, b2, ground, step


def _box(world, name, position, half=0.5, **fixture):
    fixture.setdefault("density", 1.0)
    return world.CreateDynamicBody(position=position, userData=name,
                                   fixtures=b2.fixtureDef(shape=b2.polygonShape(box=(half, half)), **fixture))


def test_begin_and_end_contact_with_the_created_bodies():
    world = Box2D.b2World()
    recorder = Recorder()
    world.contactListener = recorder
    floor = ground(world)
    floor.userData = "floor"
    box = _box(world, "box", (0, 2))
    seen = []

    class Check(b2.contactListener):
        def BeginContact(self, contact):
            bodies = {contact.fixtureA.body, contact.fixtureB.body}
            seen.append(bodies == {floor, box} and box in bodies and contact.touching)

    step(world, 1.0)
    assert recorder.calls == [("begin", "box", "floor", False)]
    box.linearVelocity = (0, 8)  # jumps off: the pair ends
    step(world, 0.5)
    assert recorder.calls[-1] == ("end", "box", "floor", False)
    world.contactListener = Check()
    step(world, 2.0)
    assert seen == [True]
    world.contactListener = None  # allowed, as pybox2d
    box.linearVelocity = (0, 8)
    step(world, 0.2)


def test_filters_decide_which_pairs_are_reported():
    world = Box2D.b2World()
    recorder = Recorder()
    world.contactListener = recorder
    floor = world.CreateStaticBody(userData="floor")
    floor.CreateEdgeFixture(vertices=[(-10, 0), (10, 0)], categoryBits=0x0001)
    _box(world, "lander", (0, 1), categoryBits=0x0010, maskBits=0x0001)
    _box(world, "ghost", (3, 1), categoryBits=0x0010, maskBits=0x0000)  # collides with nothing
    step(world, 1.0)
    assert recorder.calls == [("begin", "floor", "lander", False)]


def test_sensor_overlaps_are_reported_as_contacts():
    world = Box2D.b2World(gravity=(0, 0))
    recorder = Recorder()
    world.contactListener = recorder
    tile = world.CreateStaticBody(userData="tile", fixtures=b2.fixtureDef(shape=b2.polygonShape(box=(2, 2))))
    tile.fixtures[0].sensor = True  # set after creation, as CarRacing does
    assert tile.fixtures[0].sensor
    car = _box(world, "car", (-5, 0), half=0.25)
    car.linearVelocity = (6, 0)
    touched_at = None
    for i in range(120):
        world.Step(1 / 60.0, 6, 2)
        if recorder.calls and touched_at is None:
            touched_at = (i + 1) / 60.0
    assert recorder.calls == [("begin", "car", "tile", True), ("end", "car", "tile", True)]
    # the car's front edge reaches the tile's at x = -2: t = (5 - 2 - 0.25) / 6
    assert touched_at == pytest.approx(2.75 / 6, abs=1.5 / 60)
    # a static sensor does not report static shapes, as in Box2D
    world.CreateStaticBody(position=(0.5, 0), userData="rock", shapes=b2.polygonShape(box=(0.2, 0.2)))
    step(world, 0.1)
    assert len(recorder.calls) == 2


def test_destroy_body_ends_its_contacts_at_once():
    world = Box2D.b2World()
    recorder = Recorder()
    world.contactListener = recorder
    ground(world).userData = "floor"
    box = _box(world, "box", (0, 0.5))
    lone = _box(world, "lone", (5, 20))
    step(world, 0.2)
    assert recorder.calls == [("begin", "box", "floor", False)]
    world.DestroyBody(box)
    assert recorder.calls[-1] == ("end", "box", "floor", False)
    world.DestroyBody(lone)  # no contact: no call
    step(world, 0.2)
    assert len(recorder.calls) == 2
    assert world.contacts == []


class _Collect(b2.rayCastCallback):
    """Records each report and answers with the given policy."""

    def __init__(self, policy):
        b2.rayCastCallback.__init__(self)
        self.policy, self.hits = policy, []

    def ReportFixture(self, fixture, point, normal, fraction):
        self.hits.append((fixture.body.userData, tuple(point), tuple(normal), fraction))
        return self.policy(fraction)


def _wall_row(world):
    for i, x in enumerate((2.0, 4.0, 6.0)):
        world.CreateStaticBody(position=(x, 0), userData="wall%d" % i, shapes=b2.polygonShape(box=(0.5, 1)))


def test_ray_cast_fractions_follow_the_closed_form():
    world = Box2D.b2World()
    _wall_row(world)
    ignore = _Collect(lambda f: -1)
    world.RayCast(ignore, (0, 0), (10, 0))
    # faces at x = 1.5, 3.5, 5.5 on a 10 m ray from the origin
    assert [h[0] for h in ignore.hits] == ["wall0", "wall1", "wall2"]
    assert [h[3] for h in ignore.hits] == pytest.approx([0.15, 0.35, 0.55])
    assert ignore.hits[0][1] == pytest.approx((1.5, 0)) and ignore.hits[0][2] == pytest.approx((-1, 0))
    clip = _Collect(lambda f: f)  # the closest hit, as BipedalWalker's lidar
    world.RayCast(clip, (0, 0), (10, 0))
    assert [h[0] for h in clip.hits] == ["wall0"]
    stop = _Collect(lambda f: 0)
    world.RayCast(stop, (0, 0), (10, 0))
    assert len(stop.hits) == 1
    go_on = _Collect(lambda f: 1)
    world.RayCast(go_on, (0, 0), (10, 0))
    assert len(go_on.hits) == 3
    missed = _Collect(lambda f: 1)
    world.RayCast(missed, (0, 5), (10, 5))
    assert missed.hits == []


def test_ray_cast_runs_the_loop_this_test_run_asks_for():
    # CTest runs this file with the compiled loop (IMPULSE2D_COMPAT_RAYCAST, where Python's
    # headers were found) and again with IMPULSE2D_COMPAT_PURE: a loader that fell back to
    # Python silently would leave the compiled loop untested.
    import Box2D._world as world_module

    compiled = bool(os.environ.get("IMPULSE2D_COMPAT_RAYCAST")) and not os.environ.get("IMPULSE2D_COMPAT_PURE")
    assert (world_module._ray_cast is not None) == compiled


def test_ray_cast_reports_every_one_of_many_hits_nearest_first():
    # 100 walls: more results than a cast keeps on the stack.
    world = Box2D.b2World()
    for i in range(100):
        world.CreateStaticBody(position=(2.0 + i, 0), userData=i, shapes=b2.polygonShape(box=(0.25, 1)))
    every = _Collect(lambda f: 1)
    world.RayCast(every, (0, 0), (110, 0))
    assert [h[0] for h in every.hits] == list(range(100))
    assert [h[3] for h in every.hits] == pytest.approx([(1.75 + i) / 110 for i in range(100)])


def test_ray_cast_callback_may_cast_again_and_destroy_bodies():
    world = Box2D.b2World()
    _wall_row(world)
    inner = _Collect(lambda f: 1)
    seen = []

    class CastsAgain(b2.rayCastCallback):
        def ReportFixture(self, fixture, point, normal, fraction):
            seen.append(fixture.body.userData)
            if fixture.body.userData == "wall0":
                # From the other side: had it overwritten this cast's results, this loop
                # would go on with wall1 and then the destroyed wall0.
                world.RayCast(inner, (10, 0.5), (0, 0.5))
                world.DestroyBody(fixture.body)
            return 1

    world.RayCast(CastsAgain(), (0, 0), (10, 0))
    assert seen == ["wall0", "wall1", "wall2"]
    assert [h[0] for h in inner.hits] == ["wall2", "wall1", "wall0"]
    assert world.bodyCount == 2


def test_ray_cast_callback_errors_reach_the_caller():
    world = Box2D.b2World()
    _wall_row(world)

    class Fails(b2.rayCastCallback):
        def ReportFixture(self, fixture, point, normal, fraction):
            raise KeyError("from the callback")

    with pytest.raises(KeyError, match="from the callback"):
        world.RayCast(Fails(), (0, 0), (10, 0))

    class NoNumber(b2.rayCastCallback):
        def ReportFixture(self, fixture, point, normal, fraction):
            return None

    with pytest.raises(TypeError):
        world.RayCast(NoNumber(), (0, 0), (10, 0))
    with pytest.raises(impulse2d.InvalidArgument) as error:
        world.RayCast(_Collect(lambda f: 1), (0, 0), (float("nan"), 0))
    assert "i2d_world_cast_ray_all" in str(error.value)


def test_query_aabb_reports_fixtures_until_false():
    world = Box2D.b2World()
    _wall_row(world)
    found = []

    class Query(b2.queryCallback):
        def ReportFixture(self, fixture):
            found.append(fixture.body.userData)
            return True

    world.QueryAABB(Query(), b2.AABB(lowerBound=(1, -0.1), upperBound=(4, 0.1)))
    assert sorted(found) == ["wall0", "wall1"]
    found.clear()

    class First(b2.queryCallback):
        def ReportFixture(self, fixture):
            found.append(fixture)
            return False

    world.QueryAABB(First(), b2.AABB(lowerBound=(0, -2), upperBound=(10, 2)))
    assert len(found) == 1


def test_ends_come_before_begins_within_a_step():
    # A body leaving one tile and entering the next in a single step: a listener keeping
    # one "on a tile" flag per body, as the environments do, ends with it set.
    world = Box2D.b2World(gravity=(0, 0))
    order = []

    class Flag(b2.contactListener):
        def BeginContact(self, contact):
            order.append(("begin", contact.fixtureA.body.userData))
            car.on_tile = True

        def EndContact(self, contact):
            order.append(("end", contact.fixtureA.body.userData))
            car.on_tile = False

    world.contactListener = Flag()
    for name, x in (("a", 0.5), ("b", 1.5)):
        world.CreateStaticBody(position=(x, 0), userData=name,
                               fixtures=b2.fixtureDef(shape=b2.polygonShape(box=(0.5, 0.5)), isSensor=True))
    car = _box(world, "car", (0.9, 0), half=0.05)
    car.on_tile = False
    world.Step(1 / 60.0, 6, 2)
    assert order == [("begin", "a")] and car.on_tile
    car.linearVelocity = (12, 0)  # 0.2 m in the next step: from 0.85..0.95 to 1.05..1.15
    world.Step(1 / 60.0, 6, 2)
    assert order == [("begin", "a"), ("end", "a"), ("begin", "b")] and car.on_tile
