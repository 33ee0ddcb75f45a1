# SPDX-License-Identifier: MIT
"""10,000 worlds created, stepped and destroyed: memory must not grow."""

import os

import numpy as np

import impulse2d


def resident_kib():
    with open("/proc/self/statm") as f:
        pages = int(f.read().split()[1])
    return pages * os.sysconf("SC_PAGE_SIZE") // 1024


def one_world():
    with impulse2d.World() as world:
        ground = world.create_body(impulse2d.STATIC, position=(0.0, -1.0))
        ground.create_box(10.0, 1.0)
        bodies = [world.create_body(position=(i * 1.1, 0.5)) for i in range(4)]
        for body in bodies:
            body.create_circle(0.5)
        world.step()
        world.step()
        world.transforms(bodies)
        world.contact_events()
        world.body_events()


def test_ten_thousand_worlds_do_not_grow_memory():
    for _ in range(1000):  # warm up: allocator pools, ctypes caches
        one_world()
    before = resident_kib()
    for _ in range(10000):
        one_world()
    grown = resident_kib() - before
    print("resident memory grew by %d KiB over 10,000 worlds" % grown)
    # A leak of even one body (about 200 bytes) per world would be 2 MB.
    assert grown < 1024, grown
    assert np is not None
