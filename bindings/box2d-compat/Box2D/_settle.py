# SPDX-License-Identifier: MIT
"""Box2D 2.3's position iterations over revolute joints, run once before the step that
follows a joint's creation.

Box2D closes a joint created with its anchors apart (Gymnasium's walker is built with
its hips 0.53 m apart, its lander with the legs' hinges 0.6 m apart) in the position
iterations of its next step: each iteration moves and turns both bodies of each joint,
in proportion to their inverse masses, so that the anchors meet and the angle comes
back within the limits, and gives them no velocity. impulse2d's soft joints close such
a gap with velocity (that walker would leave the ground at 8 m/s), so the compat world
does what Box2D does, here, on the bodies' poses: the same point and limit corrections
(b2RevoluteJoint's SolvePositionConstraints), its 8 degree cap per iteration and its
early stop. Box2D leaves a gap within its slops (5 mm, 2 degrees) for its next steps to
hold; impulse2d's joints and limits have no slop and would close what is left with
velocity, so here the corrections aim at no gap and stop once within GAP_LEFT and
TURN_LEFT. Box2D corrects contacts in the same iterations; so do these, for what a
built scene needs (Gymnasium's walker is built with its feet in the ground): a
dynamic polygon's corners against the static edges they have sunk into, with Box2D's
Baumgarte share, its 0.2 m cap and its 5 mm slop. Other shapes and joint kinds take
no part."""

import math

from ._native import lib

GAP_LEFT = 1e-4  # m: an anchors' gap taken as closed (Box2D's b2_linearSlop is 5 mm)
TURN_LEFT = 1e-4  # rad: an angle taken as back within its limits (b2_angularSlop: 2 degrees)
ANGULAR_SLOP = 2.0 / 180.0 * math.pi  # rad: b2_angularSlop, the range below which limits are equal
MAX_ANGULAR_CORRECTION = 8.0 / 180.0 * math.pi  # rad per iteration: b2_maxAngularCorrection
LINEAR_SLOP = 0.005  # m: b2_linearSlop, the overlap a contact keeps
BAUMGARTE = 0.2  # share of a contact's overlap removed per iteration: b2_baumgarte
MAX_LINEAR_CORRECTION = 0.2  # m per iteration: b2_maxLinearCorrection
SEPARATION_LEFT = -3.0 * LINEAR_SLOP  # m: the deepest overlap Box2D's early stop accepts
REACH = 0.5  # m: how far apart a corner and an edge may start and still be tried
INACTIVE, AT_LOWER, AT_UPPER, EQUAL = range(4)


class _Pose:
    """A body's centre of mass, angle and inverse masses, as Box2D's position solver
    holds them; static and kinematic bodies do not move (inverse masses 0)."""

    __slots__ = ("body", "cx", "cy", "angle", "inv_mass", "inv_inertia", "local_center", "moved")

    def __init__(self, body, dynamic):
        self.body = body
        data = lib.i2d_body_get_mass_data(body._id)
        self.local_center = (data.center.x, data.center.y)
        center = lib.i2d_body_get_world_center_of_mass(body._id)
        self.cx, self.cy = center.x, center.y
        self.angle = body.angle
        self.inv_mass = 1.0 / data.mass if dynamic and data.mass > 0.0 else 0.0
        self.inv_inertia = 1.0 / data.rotational_inertia if dynamic and data.rotational_inertia > 0.0 else 0.0
        self.moved = False

    def arm(self, local_anchor):
        """The anchor relative to the centre of mass, in world axes."""
        x, y = local_anchor[0] - self.local_center[0], local_anchor[1] - self.local_center[1]
        c, s = math.cos(self.angle), math.sin(self.angle)
        return c * x - s * y, s * x + c * y

    def to_world(self, local_point):
        x, y = self.arm(local_point)
        return self.cx + x, self.cy + y

    def write_back(self):
        """The body's origin and angle from the corrected centre and angle."""
        x, y = self.local_center
        c, s = math.cos(self.angle), math.sin(self.angle)
        self.body.transform = ((self.cx - (c * x - s * y), self.cy - (s * x + c * y)), self.angle)


class RevoluteSpec:
    """What the position iterations read of a revolute joint."""

    __slots__ = ("body_a", "body_b", "anchor_a", "anchor_b", "reference", "limited", "lower", "upper")

    def __init__(self, defn):
        self.body_a, self.body_b = defn.bodyA, defn.bodyB
        self.anchor_a = tuple(defn.localAnchorA)
        self.anchor_b = tuple(defn.localAnchorB)
        self.reference = defn.referenceAngle
        self.limited = bool(defn.enableLimit)
        self.lower, self.upper = defn.lowerAngle, defn.upperAngle


def _limit_state(spec, pa, pb):
    if not spec.limited or pa.inv_inertia + pb.inv_inertia == 0.0:
        return INACTIVE
    angle = pb.angle - pa.angle - spec.reference
    if abs(spec.upper - spec.lower) < 2.0 * ANGULAR_SLOP:
        return EQUAL
    if angle <= spec.lower:
        return AT_LOWER
    if angle >= spec.upper:
        return AT_UPPER
    return INACTIVE


def _correct_limit(spec, state, pa, pb):
    """Turns the bodies toward the limit, at most MAX_ANGULAR_CORRECTION; the error left."""
    angle = pb.angle - pa.angle - spec.reference
    if state == EQUAL:
        error = min(max(angle - spec.lower, -MAX_ANGULAR_CORRECTION), MAX_ANGULAR_CORRECTION)
        left = abs(error)
    elif state == AT_LOWER:
        left = spec.lower - angle
        error = min(max(angle - spec.lower, -MAX_ANGULAR_CORRECTION), 0.0)
    else:
        left = angle - spec.upper
        error = min(max(angle - spec.upper, 0.0), MAX_ANGULAR_CORRECTION)
    impulse = -error / (pa.inv_inertia + pb.inv_inertia)
    pa.angle -= pa.inv_inertia * impulse
    pb.angle += pb.inv_inertia * impulse
    return left


def _correct_point(spec, pa, pb):
    """Moves and turns the bodies so that the anchors meet; the gap before."""
    rax, ray = pa.arm(spec.anchor_a)
    rbx, rby = pb.arm(spec.anchor_b)
    cx = pb.cx + rbx - pa.cx - rax
    cy = pb.cy + rby - pa.cy - ray
    ma, mb, ia, ib = pa.inv_mass, pb.inv_mass, pa.inv_inertia, pb.inv_inertia
    k11 = ma + mb + ia * ray * ray + ib * rby * rby
    k12 = -ia * rax * ray - ib * rbx * rby
    k22 = ma + mb + ia * rax * rax + ib * rbx * rbx
    det = k11 * k22 - k12 * k12
    if det == 0.0:
        return 0.0
    px = -(k22 * cx - k12 * cy) / det
    py = -(k11 * cy - k12 * cx) / det
    pa.cx -= ma * px
    pa.cy -= ma * py
    pa.angle -= ia * (rax * py - ray * px)
    pb.cx += mb * px
    pb.cy += mb * py
    pb.angle += ib * (rbx * py - rby * px)
    return math.hypot(cx, cy)


class CornerContact:
    """A dynamic polygon's corner (local point) and a static edge (world end points)."""

    __slots__ = ("corner", "e1", "e2")

    def __init__(self, corner, e1, e2):
        self.corner, self.e1, self.e2 = corner, e1, e2


def corner_contacts(pose, polygon_points, edges_near):
    """The corners of a polygon (body frame) each paired with the edges near the
    polygon: edges_near(low_x, low_y, high_x, high_y) lists the static edges (world end
    point pairs) within the polygon's box grown by REACH, then its corners are sifted
    by theirs."""
    corners = [(corner, pose.to_world(corner)) for corner in polygon_points]
    xs = [p[0] for _, p in corners]
    ys = [p[1] for _, p in corners]
    near = edges_near(min(xs) - REACH, min(ys) - REACH, max(xs) + REACH, max(ys) + REACH)
    found = []
    for corner, (px, py) in corners:
        for e1, e2 in near:
            if (min(e1[0], e2[0]) - REACH <= px <= max(e1[0], e2[0]) + REACH and
                    min(e1[1], e2[1]) - REACH <= py <= max(e1[1], e2[1]) + REACH):
                found.append(CornerContact(corner, e1, e2))
    return found


def _correct_contact(contact, pose):
    """Pushes a corner sunk below an edge back out along the edge's normal (toward the
    body's centre), by Box2D's share; the separation before (negative: overlap)."""
    (ax, ay), (bx, by) = contact.e1, contact.e2
    length = math.hypot(bx - ax, by - ay)
    if length == 0.0:
        return 0.0
    dx, dy = (bx - ax) / length, (by - ay) / length
    px, py = pose.to_world(contact.corner)
    along = (px - ax) * dx + (py - ay) * dy
    if along < 0.0 or along > length:
        return 0.0
    nx, ny = -dy, dx
    if (pose.cx - ax) * nx + (pose.cy - ay) * ny < 0.0:
        nx, ny = -nx, -ny
    separation = (px - ax) * nx + (py - ay) * ny
    if separation >= 0.0:
        return 0.0
    error = min(max(BAUMGARTE * (separation + LINEAR_SLOP), -MAX_LINEAR_CORRECTION), 0.0)
    rx, ry = px - pose.cx, py - pose.cy
    arm = rx * ny - ry * nx
    mass = pose.inv_mass + pose.inv_inertia * arm * arm
    if mass == 0.0:
        return separation
    impulse = -error / mass
    pose.cx += pose.inv_mass * impulse * nx
    pose.cy += pose.inv_mass * impulse * ny
    pose.angle += pose.inv_inertia * impulse * arm
    pose.moved = True
    return separation


def settle(specs, iterations, is_dynamic, polygons_of, edges_near):
    """Runs up to iterations rounds of the corrections over specs, then the corner
    contacts, in order, as Box2D does; stops once every gap is closed and no corner is
    deeper than Box2D accepts. polygons_of(body) lists a body's polygons (body frame
    points) that touch static edges; edges_near lists the static edges in a box (see
    corner_contacts). Writes back the bodies moved."""
    poses = {}

    def pose(body):
        found = poses.get(body._id)
        if found is None:
            found = poses[body._id] = _Pose(body, is_dynamic(body))
        return found

    joints = [(spec, pose(spec.body_a), pose(spec.body_b)) for spec in specs]
    states = [_limit_state(spec, pa, pb) for spec, pa, pb in joints]
    contacts = [(contact, p) for p in list(poses.values()) if p.inv_mass > 0.0
                for points in polygons_of(p.body) for contact in corner_contacts(p, points, edges_near)]
    for _ in range(iterations):
        worst_gap = worst_turn = deepest = 0.0
        for (spec, pa, pb), state in zip(joints, states):
            if state != INACTIVE:
                worst_turn = max(worst_turn, _correct_limit(spec, state, pa, pb))
            worst_gap = max(worst_gap, _correct_point(spec, pa, pb))
            pa.moved = pa.moved or pa.inv_mass > 0.0
            pb.moved = pb.moved or pb.inv_mass > 0.0
        for contact, p in contacts:
            deepest = min(deepest, _correct_contact(contact, p))
        if worst_gap <= GAP_LEFT and worst_turn <= TURN_LEFT and deepest >= SEPARATION_LEFT:
            break
    for p in poses.values():
        if p.moved:
            p.write_back()
