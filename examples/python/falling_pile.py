#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""A falling pile: 40 boxes, circles and capsules dropped into a walled box.

Prints what happened (when the pile landed, how it settled, what fell asleep) and
writes an SVG of where every body ended up and the paths of a few of them.

Usage: python3 falling_pile.py [output.svg]     (default: falling_pile.svg)
Run it from a source tree after building (it finds build/capi/libimpulse2d.so), after
`pip install bindings/python`, or with IMPULSE2D_LIBRARY set.
"""

import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "bindings", "python"))

import numpy as np  # noqa: E402

import impulse2d  # noqa: E402

STEPS = 360  # 6 s at 60 Hz
TRACKED = 4  # bodies whose paths are drawn


def build(world):
    """The container and the pile; returns the dynamic bodies."""
    walls = world.create_body(impulse2d.STATIC)
    walls.create_box(6.0, 0.5, center=(0.0, -0.5))
    walls.create_box(0.5, 5.0, center=(-6.5, 4.0))
    walls.create_box(0.5, 5.0, center=(6.5, 4.0))
    bodies = []
    for i in range(40):
        x = -4.5 + (i % 8) * 1.25 + 0.1 * (i // 8)
        y = 2.0 + (i // 8) * 1.4
        body = world.create_body(position=(x, y), angle=0.3 * i)
        kind = i % 3
        if kind == 0:
            body.create_box(0.45, 0.35, friction=0.6)
        elif kind == 1:
            body.create_circle(0.4, restitution=0.2)
        else:
            body.create_capsule((-0.35, 0.0), (0.35, 0.0), 0.22)
        body.user_data = ("box", "circle", "capsule")[kind]
        bodies.append(body)
    return walls, bodies


def svg(path, world, walls, bodies, paths):
    """Draws the walls and every body's shapes where they ended, and tracked paths."""
    scale, width, height = 40.0, 560, 480

    def px(p):
        return (width / 2 + p[0] * scale, height - 20 - p[1] * scale)

    def polygon(points, fill):
        return '<polygon points="%s" fill="%s" stroke="#333" stroke-width="1"/>' % (
            " ".join("%.1f,%.1f" % px(p) for p in points),
            fill,
        )

    def world_point(body, local):
        (x, y), (c, s) = body.position, body.rotation
        return (x + c * local[0] - s * local[1], y + s * local[0] + c * local[1])

    items = []
    colours = {"box": "#e8a33d", "circle": "#4c9be8", "capsule": "#5cb85c"}
    for body in [walls] + bodies:
        fill = colours.get(body.user_data, "#999")
        for shape in body.shapes:
            g = shape.geometry()
            if shape.type == impulse2d.ShapeType.CIRCLE:
                cx, cy = px(world_point(body, g[0]))
                items.append('<circle cx="%.1f" cy="%.1f" r="%.1f" fill="%s" stroke="#333"/>' % (cx, cy, g[1] * scale, fill))
            elif shape.type == impulse2d.ShapeType.CAPSULE:
                (x1, y1), (x2, y2) = px(world_point(body, g[0])), px(world_point(body, g[1]))
                items.append(
                    '<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="%s" stroke-width="%.1f" '
                    'stroke-linecap="round"/>' % (x1, y1, x2, y2, fill, 2 * g[2] * scale)
                )
            else:
                items.append(polygon([world_point(body, p) for p in g], fill))
    for track in paths:
        items.append(
            '<polyline points="%s" fill="none" stroke="#c0392b" stroke-width="1.5" stroke-dasharray="4 2"/>'
            % " ".join("%.1f,%.1f" % px(p) for p in track)
        )
    with open(path, "w") as f:
        f.write('<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d">\n' % (width, height))
        f.write('<rect width="100%" height="100%" fill="white"/>\n')
        f.write("\n".join(items))
        f.write("\n</svg>\n")


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "falling_pile.svg"
    with impulse2d.World(gravity=(0.0, -10.0)) as world:
        walls, bodies = build(world)
        ids = world.body_ids(bodies)
        paths = [[] for _ in range(TRACKED)]
        first_contact_step = None
        contacts_begun = 0
        asleep_at = None
        for step in range(STEPS):
            world.step(1.0 / 60.0, 4)
            begin, _end = world.contact_events()
            contacts_begun += len(begin)
            if begin and first_contact_step is None:
                first_contact_step = step
            xf = world.transforms(ids)  # every body's [x, y, c, s] in one call
            for k in range(TRACKED):
                paths[k].append((float(xf[k * 9, 0]), float(xf[k * 9, 1])))
            if asleep_at is None and world.counters.awake_body_count == 0:
                asleep_at = step
        xf = world.transforms(ids)
        linear, _angular = world.velocities(ids)
        top = float(xf[:, 1].max())
        print("impulse2d %s from %s" % (impulse2d.library_version, impulse2d.library_path))
        print("%d bodies dropped into a 12 m wide box" % len(bodies))
        print("first contact at step %s (%.2f s); %d contacts began in all" % (
            first_contact_step, (first_contact_step or 0) / 60.0, contacts_begun))
        print("after %.1f s: highest body at %.2f m, lowest at %.2f m, fastest moving at %.3f m/s" % (
            STEPS / 60.0, top, float(xf[:, 1].min()), float(np.hypot(linear[:, 0], linear[:, 1]).max())))
        inside = int(np.sum((np.abs(xf[:, 0]) < 6.0) & (xf[:, 1] > -0.01)))
        print("%d of %d bodies inside the box" % (inside, len(bodies)))
        if asleep_at is None:
            print("not every body is asleep yet")
        else:
            print("every body asleep at step %d (%.2f s)" % (asleep_at, asleep_at / 60.0))
        svg(out, world, walls, bodies, paths)
        print("wrote %s" % out)
        return 0 if inside == len(bodies) else 1


if __name__ == "__main__":
    sys.exit(main())
