# SPDX-License-Identifier: MIT
"""Scenes built the way Gymnasium's Box2D environments build theirs (our own scenes,
their API usage): a lander on sprung legs settling on edge terrain and falling asleep,
a walker with hip and knee motors and ten lidar rays, a car whose wheels drive over
sensor tiles."""

import math

import pytest

from box2d_compat_fixture import Box2D, b2, step

FPS = 50.0


class _LegContacts(b2.contactListener):
    """Flags a leg's ground contact and a crash of the body, as a lander game does."""

    def __init__(self, scene):
        b2.contactListener.__init__(self)
        self.scene = scene

    def BeginContact(self, contact):
        bodies = (contact.fixtureA.body, contact.fixtureB.body)
        if self.scene["lander"] in bodies:
            self.scene["crashed"] = True
        for leg in self.scene["legs"]:
            if leg in bodies:
                leg.ground_contact = True

    def EndContact(self, contact):
        for leg in self.scene["legs"]:
            if leg in (contact.fixtureA.body, contact.fixtureB.body):
                leg.ground_contact = False


def _lander_scene():
    world = Box2D.b2World(gravity=(0, -10))
    scene = {"world": world, "crashed": False, "legs": []}
    world.contactListener_keepref = _LegContacts(scene)
    world.contactListener = world.contactListener_keepref
    moon = world.CreateStaticBody(shapes=b2.edgeShape(vertices=[(0, 0), (20, 0)]))
    heights = [3.0, 2.0, 4.0, 4.0, 4.0, 4.0, 2.5, 3.5]  # a flat pad from x = 6 to x = 14
    xs = [0.0, 3.0, 6.0, 8.0, 12.0, 14.0, 17.0, 20.0]
    for i in range(len(xs) - 1):
        moon.CreateEdgeFixture(vertices=[(xs[i], heights[i]), (xs[i + 1], heights[i + 1])], density=0, friction=0.1)
    hull = [(-0.47, 0.57), (-0.57, 0.0), (-0.57, -0.33), (0.57, -0.33), (0.57, 0.0), (0.47, 0.57)]
    lander = world.CreateDynamicBody(position=(10, 8), angle=0.0, fixtures=b2.fixtureDef(
        shape=b2.polygonShape(vertices=hull), density=5.0, friction=0.1, categoryBits=0x0010, maskBits=0x001))
    scene["lander"] = lander
    for i in (-1, 1):
        leg = world.CreateDynamicBody(position=(10 - i * 0.67, 8), angle=i * 0.05, fixtures=b2.fixtureDef(
            shape=b2.polygonShape(box=(0.07, 0.27)), density=1.0, categoryBits=0x0020, maskBits=0x001))
        leg.ground_contact = False
        rjd = b2.revoluteJointDef(bodyA=lander, bodyB=leg, localAnchorA=(0, 0), localAnchorB=(i * 0.67, 0.6),
                                  enableMotor=True, enableLimit=True, maxMotorTorque=40.0, motorSpeed=0.3 * i)
        rjd.lowerAngle, rjd.upperAngle = ((0.4, 0.9) if i == -1 else (-0.9, -0.4))
        leg.joint = world.CreateJoint(rjd)
        scene["legs"].append(leg)
    return scene


def test_lander_settles_on_its_legs_and_falls_asleep():
    scene = _lander_scene()
    world, lander, legs = scene["world"], scene["lander"], scene["legs"]
    # Built at joint angle 0 (the def's referenceAngle came from the bodies) with their
    # anchors 0.6 m apart, outside their limits: the first step's position iterations
    # join them and turn them back within their limits, as Box2D's do.
    world.Step(1.0 / FPS, 6 * 30, 2 * 30)
    for leg, (lower, upper) in zip(legs, ((0.4, 0.9), (-0.9, -0.4))):
        assert lower - 0.05 < leg.joint.angle < upper + 0.05
        assert (leg.joint.anchorA - leg.joint.anchorB).length < 0.01
    particles, asleep_at = [], None
    for i in range(int(10 * FPS)):
        vy = lander.linearVelocity.y
        if vy < -1.0:  # the main engine holds the descent near 1 m/s, spitting particles
            lander.ApplyLinearImpulse((0, 0.5 * lander.mass * (-1.0 - vy)), lander.worldCenter, True)
            p = world.CreateDynamicBody(position=lander.worldCenter - (0, 0.6), fixtures=b2.fixtureDef(
                shape=b2.circleShape(radius=2 / 30.0, pos=(0, 0)), density=1, friction=0.1,
                categoryBits=0x0100, maskBits=0x001, restitution=0.3))
            p.ApplyLinearImpulse((0, -0.05), p.worldCenter, True)
            particles.append(p)
        while len(particles) > 10 or (particles and i >= 200):  # old particles go, as the game's
            world.DestroyBody(particles.pop(0))
        world.Step(1.0 / FPS, 6 * 30, 2 * 30)
        if not lander.awake:
            asleep_at = i / FPS
            break
    assert not scene["crashed"]
    assert all(leg.ground_contact for leg in legs)
    assert asleep_at is not None and asleep_at < 9.0
    assert 4.33 < lander.position.y < 5.0  # on its legs, its hull (0.33 m below its centre) above the pad
    assert lander.linearVelocity.length < 0.01
    # the legs' limits held: every joint angle within its (soft) range
    for leg in legs:
        assert leg.joint.lowerLimit - 0.05 <= leg.joint.angle <= leg.joint.upperLimit + 0.05
    # the renderer's reads: world vertices through the transform
    path = [lander.transform * v * 30 for v in lander.fixtures[0].shape.vertices]
    assert len(path) == 6 and all(len(p) == 2 for p in path)


class _Lidar(b2.rayCastCallback):
    """The closest hit on the ground (category 1), ignoring everything else."""

    def ReportFixture(self, fixture, point, normal, fraction):
        if (fixture.filterData.categoryBits & 1) == 0:
            return -1
        self.p2 = point
        self.fraction = fraction
        return fraction


def _walker_scene():
    world = Box2D.b2World()
    terrain_fd = b2.fixtureDef(shape=b2.polygonShape(vertices=[(0, 0), (1, 0), (1, -1), (0, -1)]), friction=2.5)
    for i in range(40):  # flat ground from tiles of one reused def
        x0 = -10 + i
        terrain_fd.shape.vertices = [(x0, 0), (x0 + 1, 0), (x0 + 1, -1), (x0, -1)]
        world.CreateStaticBody(fixtures=terrain_fd)
    hull = world.CreateDynamicBody(position=(0, 2.0), fixtures=b2.fixtureDef(
        shape=b2.polygonShape(vertices=[(-0.5, 0.3), (0.2, 0.3), (0.5, 0.0), (0.5, -0.3), (-0.5, -0.3)]),
        density=5.0, friction=0.1, categoryBits=0x0020, maskBits=0x001, restitution=0.0))
    joints, legs = [], []
    for side in (-1, 1):
        upper = world.CreateDynamicBody(position=(0, 2.0 - 0.6), angle=side * 0.05, fixtures=b2.fixtureDef(
            shape=b2.polygonShape(box=(0.1, 0.4)), density=1.0, categoryBits=0x0020, maskBits=0x001))
        joints.append(world.CreateJoint(b2.revoluteJointDef(
            bodyA=hull, bodyB=upper, localAnchorA=(0, -0.2), localAnchorB=(0, 0.4), enableMotor=True,
            enableLimit=True, maxMotorTorque=80, motorSpeed=side, lowerAngle=-0.8, upperAngle=1.1)))
        lower = world.CreateDynamicBody(position=(0, 2.0 - 1.4), angle=side * 0.05, fixtures=b2.fixtureDef(
            shape=b2.polygonShape(box=(0.08, 0.4)), density=1.0, categoryBits=0x0020, maskBits=0x001))
        lower.ground_contact = False
        joints.append(world.CreateJoint(b2.revoluteJointDef(
            bodyA=upper, bodyB=lower, localAnchorA=(0, -0.4), localAnchorB=(0, 0.4), enableMotor=True,
            enableLimit=True, maxMotorTorque=80, motorSpeed=1, lowerAngle=-1.6, upperAngle=-0.1)))
        legs += [upper, lower]
    return world, hull, joints, legs


def test_walker_motors_and_ten_lidar_rays():
    world, hull, joints, legs = _walker_scene()
    lidar = [_Lidar() for _ in range(10)]
    for i in range(int(2 * FPS)):
        for j, joint in enumerate(joints):  # alternate the motors as a policy would
            joint.motorSpeed = float((4 if j % 2 == 0 else 6) * (1 if (i // 25 + j) % 2 else -1))
            joint.maxMotorTorque = 80.0
        world.Step(1.0 / FPS, 6 * 30, 2 * 30)
        pos = hull.position
        for k, ray in enumerate(lidar):
            ray.fraction = 1.0
            ray.p1 = pos
            ray.p2 = (pos[0] + math.sin(1.5 * k / 10.0) * 10, pos[1] - math.cos(1.5 * k / 10.0) * 10)
            world.RayCast(ray, ray.p1, ray.p2)
    # flat ground at y = 0: a ray at angle a from the vertical meets it at y0 / (10 cos a)
    for k, ray in enumerate(lidar):
        a = 1.5 * k / 10.0
        expected = hull.position.y / (10 * math.cos(a))
        if expected < 1:
            assert ray.fraction == pytest.approx(expected, abs=2e-4)
            assert ray.p2[1] == pytest.approx(0.0, abs=1e-3)
        else:
            assert ray.fraction == 1.0
    # hull above the ground, the hips' speeds the bodies' relative spin
    assert 0.3 < hull.position.y < 3.0
    assert joints[0].speed == pytest.approx(joints[0].bodyB.angularVelocity - hull.angularVelocity)
    for joint in joints:
        assert joint.lowerLimit - 0.1 <= joint.angle <= joint.upperLimit + 0.1


class _TileDetector(b2.contactListener):
    """A wheel on a tile: the tile joins the wheel's set (and counts once as visited)."""

    def __init__(self):
        b2.contactListener.__init__(self)
        self.visited = 0

    def _tile_and_wheel(self, contact):
        u1, u2 = contact.fixtureA.body.userData, contact.fixtureB.body.userData
        if u1 and "road_friction" in u1.__dict__:
            return u1, u2
        if u2 and "road_friction" in u2.__dict__:
            return u2, u1
        return None, None

    def BeginContact(self, contact):
        tile, wheel = self._tile_and_wheel(contact)
        if tile is None or not wheel or "tiles" not in wheel.__dict__:
            return
        wheel.tiles.add(tile)
        if not tile.road_visited:
            tile.road_visited = True
            self.visited += 1

    def EndContact(self, contact):
        tile, wheel = self._tile_and_wheel(contact)
        if tile is not None and wheel and "tiles" in wheel.__dict__:
            wheel.tiles.remove(tile)


def test_car_wheels_visit_sensor_tiles():
    detector = _TileDetector()
    world = Box2D.b2World((0, 0), contactListener=detector)
    tile_fd = b2.fixtureDef(shape=b2.polygonShape(vertices=[(0, 0), (1, 0), (1, -1), (0, -1)]))
    tiles = []
    for i in range(30):  # a straight road of 30 tiles, 4 m long and 6.7 m wide, from x = -4
        x0 = -4 + 4 * i
        tile_fd.shape.vertices = [(x0, -3.35), (x0 + 4, -3.35), (x0 + 4, 3.35), (x0, 3.35)]
        t = world.CreateStaticBody(fixtures=tile_fd)
        t.userData = t
        t.road_friction = 1.0
        t.road_visited = False
        t.fixtures[0].sensor = True
        tiles.append(t)
    size = 0.02
    hull = world.CreateDynamicBody(position=(0, 0), angle=-math.pi / 2, fixtures=[
        b2.fixtureDef(shape=b2.polygonShape(vertices=[(-60 * size, 130 * size), (60 * size, 130 * size),
                                                      (60 * size, 110 * size), (-60 * size, 110 * size)]),
                      density=1.0),
        b2.fixtureDef(shape=b2.polygonShape(vertices=[(-50 * size, -120 * size), (50 * size, -120 * size),
                                                      (50 * size, 90 * size), (-50 * size, 90 * size)]),
                      density=1.0)])
    wheels = []
    for wx, wy in ((-55, 80), (55, 80), (-55, -82), (55, -82)):
        w = world.CreateDynamicBody(position=hull.GetWorldPoint((wx * size, wy * size)), angle=-math.pi / 2,
                                    fixtures=b2.fixtureDef(shape=b2.polygonShape(box=(14 * size, 27 * size)),
                                                           density=0.1, categoryBits=0x0020, maskBits=0x001,
                                                           restitution=0.0))
        w.tiles = set()
        w.userData = w
        w.joint = world.CreateJoint(b2.revoluteJointDef(
            bodyA=hull, bodyB=w, localAnchorA=(wx * size, wy * size), localAnchorB=(0, 0), enableMotor=True,
            enableLimit=True, maxMotorTorque=180 * 900 * size * size, motorSpeed=0, lowerAngle=-0.4, upperAngle=0.4))
        wheels.append(w)
    step(world, 0.1, FPS)
    # front wheels at x = 1.6 on tile 1 ([0, 4]), rear wheels at x = -1.64 on tile 0
    assert detector.visited == 2
    assert [w.tiles for w in wheels] == [{tiles[1]}, {tiles[1]}, {tiles[0]}, {tiles[0]}]
    for _ in range(int(3 * FPS)):
        for w in wheels:  # push every wheel forward along its own axis
            w.ApplyForceToCenter(w.GetWorldVector((0, 1)) * 20.0, True)
        world.Step(1.0 / FPS, 6 * 30, 2 * 30)
    x = hull.position.x
    assert x > 8  # drove along +x (the hull's nose points along +x at angle -pi/2)
    # every tile the car reached was visited, none beyond the front wheels
    front = max(w.position.x for w in wheels) + 27 * size
    reached = [t for t in tiles if t.fixtures[0].shape.vertices[0][0] < front]
    assert detector.visited == len(reached) == sum(t.road_visited for t in tiles)
    for w in wheels:  # the wheel's set is exactly the tiles its outline overlaps now
        xs = [(w.transform * v)[0] for v in w.fixtures[0].shape.vertices]
        under = {t for t in tiles
                 if min(xs) < t.fixtures[0].shape.vertices[1][0] and max(xs) > t.fixtures[0].shape.vertices[0][0]}
        assert w.tiles == under
