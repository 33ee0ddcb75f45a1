# SPDX-License-Identifier: MIT
"""N lunar landers, each alone in its own impulse2d world, advanced a frame at a time
together: the engines of all are computed with NumPy, the worlds are stepped in one
library call (impulse2d.WorldBatch over i2d_worlds_step, GIL released, on worker
threads), and the state each policy sees is read with one bulk call for all the worlds
(i2d_worlds_get_body_states), the engines' kicks written with another.

This is the simulation shared by VectorLunarLander and LunarLander; episodes,
autoreset and time limits are theirs."""

from typing import List, Optional, Tuple

import numpy as np

from .. import World
from .._native import check, lib, structs
from ..batch import WorldBatch
from . import constants as K
from .engines import Throttles, fuel_cost, velocity_change
from .lander import Lander, build_lander
from .observation import state_of, unwrap_angle
from .reward import episode_end, frame_reward, shaping
from .streams import LanderStreams
from .terrain import Terrain, build_moon, random_terrain, shape_moon
from .wind import gust, random_start

# impulse2d's solver takes substeps within each frame instead of Box2D 2.3's iterations
# (Gymnasium asks for 180 velocity and 60 position iterations per frame): 4, as its
# worlds take by default, with the legs' hinges softened to suit them (leg_joint_hertz).
DEFAULT_SUBSTEPS = 4

# The legs' hinges are soft rows as stiff as the world's joint_hertz (60 Hz), which a
# world caps at a quarter of the substep rate: at 4 substeps of 5 ms, 50 Hz. There a
# landed lander sways on its legs at about 5 Hz and 0.04 m/s for good, never sleeps, and
# so a landing never ends: the tests' PD pilot landed 1 of seeds 0-19. With the hinges
# at 45 Hz (and the world's damping ratio, 2) it landed 12; at 40, 35 and 30 Hz 20, 18
# and 19; at 25 Hz 10 (the legs give and the hull touches down). At a sixth of the
# substep rate (33 Hz at 4 substeps, the world's 60 Hz from 8 on) the lander took longer
# to come to rest than with 8 substeps (from the first leg's touchdown to sleep, median
# 2.39 s against 1.67); damped ten times critically, 1.98 s (at most 2.56), and the
# pilot lands 19 of 20 and the continuous pilot 20, as 8 substeps at 60 Hz did (18 and
# 20), with half the substeps.
LEG_JOINT_RATE_SHARE = 1.0 / 6.0
LEG_JOINT_DAMPING_RATIO = 10.0


def leg_joint_hertz(substeps: int) -> float:
    """The joint_hertz of a lander's world stepped in substeps per frame, Hz."""
    world_hertz = lib.i2d_default_world_def().joint_hertz
    return min(world_hertz, LEG_JOINT_RATE_SHARE * K.FRAMES_PER_SECOND * substeps)


class FrameResult:
    """What one frame gives every lander: observations (n, 8) float32, rewards (n,)
    float64 and terminated (n,) bool."""

    __slots__ = ("observations", "rewards", "terminated")

    def __init__(self, observations: np.ndarray, rewards: np.ndarray, terminated: np.ndarray) -> None:
        self.observations, self.rewards, self.terminated = observations, rewards, terminated


class LanderFleet:
    def __init__(self, count: int, gravity: float = K.DEFAULT_GRAVITY, enable_wind: bool = False,
                 wind_power: float = K.DEFAULT_WIND_POWER, turbulence_power: float = K.DEFAULT_TURBULENCE_POWER,
                 substeps: int = DEFAULT_SUBSTEPS, workers: int = 1) -> None:
        if count < 1:
            raise ValueError("a fleet needs at least one lander; got %d" % count)
        if not -12.0 < gravity < 0.0:
            raise ValueError("gravity must be within (-12, 0), as in LunarLander-v3; got %r" % gravity)
        self.count = count
        self.gravity, self.enable_wind = float(gravity), bool(enable_wind)
        self.wind_power, self.turbulence_power = float(wind_power), float(turbulence_power)
        self.substeps, self.workers = int(substeps), int(workers)
        self.streams = LanderStreams(count)
        self.worlds: List[Optional[World]] = [None] * count
        self.landers: List[Optional[Lander]] = [None] * count
        self.terrains: List[Optional[Terrain]] = [None] * count
        self._batch: Optional[WorldBatch] = None
        # The new episode every reset restores, and the ids in it (those of the world it
        # was saved from) of the moon's surface segments, the hull and the legs.
        self._new_episode: Optional[bytes] = None
        self._template_surface: List[int] = []
        self._template_lander: Tuple[int, List[int]] = (0, [])
        self._surfaces: List[Optional[List[object]]] = [None] * count  # each world's moon segments
        self._allocate_state()

    def _allocate_state(self) -> None:
        n = self.count
        # Filled by the library through the addresses below; never reallocated.
        self.hull_ids = np.zeros(n, dtype=np.uint64)
        self.transforms = np.zeros((n, 4), dtype=np.float32)
        self.linear = np.zeros((n, 2), dtype=np.float32)
        self.angular = np.zeros(n, dtype=np.float32)
        self._new_linear = np.zeros((n, 2), dtype=np.float32)
        self._new_angular = np.zeros(n, dtype=np.float32)
        self._addresses = [a.ctypes.data for a in (self.hull_ids, self.transforms, self.linear, self.angular)]
        self._kick_addresses = [a.ctypes.data for a in (self.hull_ids, self._new_linear, self._new_angular)]
        self._world_ids = np.zeros(n, dtype=np.uint64)
        self._awake = np.zeros(n, dtype=np.bool_)
        self._begin_counts = np.zeros(n, dtype=np.int32)
        self._end_counts = np.zeros(n, dtype=np.int32)
        # Read once: an array's .ctypes.data costs about as much as the call it feeds.
        self._event_addresses = [a.ctypes.data for a in (self._world_ids, self._awake, self._begin_counts,
                                                         self._end_counts)]
        self.angle = np.zeros(n, dtype=np.float64)
        self.leg_touches = np.zeros((n, 2), dtype=np.int32)
        self.crashed = np.zeros(n, dtype=bool)
        self.at_rest = np.zeros(n, dtype=bool)
        self.previous_potential = np.full(n, np.nan)
        self.pad_height = np.zeros(n, dtype=np.float64)
        self.wind_counter = np.zeros(n, dtype=np.int64)
        self.turbulence_counter = np.zeros(n, dtype=np.int64)
        self._hull_mass: Optional[tuple] = None

    # ---- Episodes -----------------------------------------------------------------------

    def seed(self, index: int, seed: Optional[int]) -> None:
        """A new random stream for lander index (NumPy's default generator, PCG64, as
        Gymnasium's np_random; None draws fresh entropy)."""
        self.streams.seed(index, seed)

    def rebuild(self, index: int) -> None:
        """Starts lander index's episode: its world brought back to the fleet's new
        episode (the moon, laid flat, and the lander; the same bytes for every lander and
        episode, so an episode depends on its seed alone), then the terrain, initial push
        and wind counters drawn from its random stream in Gymnasium's order. The world
        keeps its id, so the batch that steps it stands. The episode's first frame is the
        caller's (a frame with no engines, as Gymnasium's reset takes)."""
        rng = self.streams.for_episode(index)
        world = self.worlds[index]
        if world is None:
            world = self._new_world(index)
        world.restore_snapshot(self._new_episode)
        lander = self.landers[index]
        terrain = random_terrain(rng)
        shape_moon(self._surfaces[index], terrain)
        push = (rng.uniform(-K.INITIAL_PUSH, K.INITIAL_PUSH), rng.uniform(-K.INITIAL_PUSH, K.INITIAL_PUSH))
        lander.hull.apply_force(push)  # acts during the first frame only
        if self.enable_wind:
            self.wind_counter[index] = random_start(rng)
            self.turbulence_counter[index] = random_start(rng)
        self.terrains[index] = terrain
        self.pad_height[index] = terrain.pad_height
        self.angle[index] = 0.0
        self.leg_touches[index] = 0
        self.crashed[index] = self.at_rest[index] = False
        self.previous_potential[index] = np.nan
        self._read_motion(index)

    def _new_world(self, index: int) -> World:
        """Lander index's world, made once: the first builds the new episode's world and
        saves it for every reset; the others are made from those bytes."""
        if self._new_episode is None:
            world = World(gravity=(0.0, self.gravity), joint_hertz=leg_joint_hertz(self.substeps),
                          joint_damping_ratio=LEG_JOINT_DAMPING_RATIO)
            self._template_surface = [shape.id for shape in build_moon(world)]
            lander = build_lander(world)
            self._template_lander = (lander.hull.id, [leg.id for leg in lander.legs])
            mass_data = lander.hull.mass_data
            self._hull_mass = (mass_data.mass, mass_data.rotational_inertia, mass_data.center)
            self._new_episode = world.save_snapshot()
        else:
            world = World.from_snapshot(self._new_episode)
        hull_id, leg_ids = self._template_lander
        hull, legs = world.body(hull_id), tuple(world.body(leg) for leg in leg_ids)
        hull_shape, leg_shapes = hull.shapes[0], tuple(leg.shapes[0] for leg in legs)
        self.landers[index] = Lander(hull, legs, hull_shape.id, tuple(shape.id for shape in leg_shapes))
        self._surfaces[index] = [world.shape(shape) for shape in self._template_surface]
        self.worlds[index] = world
        self.hull_ids[index] = hull.id
        self._world_ids[index] = world.id
        self._batch = None  # its id list lacks the new world
        return world

    def close(self) -> None:
        for world in self.worlds:
            if world is not None:
                world.destroy()
        self.worlds = [None] * self.count
        self._batch = None

    # ---- One frame ----------------------------------------------------------------------

    def frame(self, throttles: Throttles) -> FrameResult:
        """Fires the engines as throttles say, advances every world by 1/50 s and reads
        what the landers see."""
        dispersion = self.streams.dispersion()
        if self.enable_wind:
            self._blow()
        self._fire_engines(throttles, dispersion)
        if self._batch is None:
            self._batch = WorldBatch(self.worlds, self.workers)
        self._batch.step(K.FRAME_TIME, self.substeps)
        self._read_all()
        return self._score(throttles)

    def _blow(self) -> None:
        """Wind and turbulence push a lander in flight (Gymnasium stops them, and their
        counters, while a leg touches the ground)."""
        airborne = ~np.any(self.leg_touches > 0, axis=1)
        for index in np.flatnonzero(airborne):
            hull_id = int(self.hull_ids[index])
            force = gust(int(self.wind_counter[index])) * self.wind_power
            torque = gust(int(self.turbulence_counter[index])) * self.turbulence_power
            check(lib.i2d_body_apply_force_to_center(hull_id, structs.Vec2(force, 0.0), True))
            check(lib.i2d_body_apply_torque(hull_id, torque, True))
        self.wind_counter += airborne
        self.turbulence_counter += airborne

    def _fire_engines(self, throttles: Throttles, dispersion: np.ndarray) -> None:
        mass, inertia, center = self._hull_mass
        dv, dw = velocity_change(throttles, self.transforms, dispersion, mass, inertia, center)
        self._new_linear[:] = self.linear + dv
        self._new_angular[:] = self.angular + dw
        firing = (throttles.main > 0.0) | (throttles.side > 0.0)
        count = int(np.count_nonzero(firing))
        if count == 0:
            return
        # One library call for all the firing landers: every row, or copies of theirs.
        if count == self.count:
            addresses = self._kick_addresses
        else:
            rows = (self.hull_ids[firing], self._new_linear[firing], self._new_angular[firing])
            addresses = [a.ctypes.data for a in rows]
        ids, linear, angular = addresses
        check(lib.i2d_worlds_set_body_velocities(ids, count, linear, angular))

    def _read_all(self) -> None:
        """Every hull's motion and sleep after a frame in one library call for all the
        worlds, their contact event counts in another, and the events of the few worlds
        that have some."""
        ids, transforms, linear, angular = self._addresses
        worlds, awake, begins, ends = self._event_addresses
        n = self.count
        check(lib.i2d_worlds_get_body_states(ids, n, transforms, linear, angular, awake))
        np.logical_not(self._awake, out=self.at_rest)
        check(lib.i2d_worlds_get_contact_event_counts(worlds, n, begins, ends))
        get_events = lib.i2d_world_get_contact_events
        for index in np.flatnonzero(self._begin_counts | self._end_counts).tolist():  # counts are >= 0
            self._count_contacts(index, get_events(int(self._world_ids[index])))

    def _read_motion(self, index: int) -> None:
        ids, transforms, linear, angular = self._addresses
        world_id = int(self._world_ids[index])
        check(lib.i2d_world_get_body_transforms(world_id, ids + 8 * index, 1, transforms + 16 * index))
        check(lib.i2d_world_get_body_velocities(world_id, ids + 8 * index, 1, linear + 8 * index, angular + 4 * index))

    def _count_contacts(self, index: int, events) -> None:
        """Crash and leg contacts from the frame's contact begin and end events. A leg is
        down while it has at least one contact (Gymnasium keeps one flag per leg, which
        the end of one of two contacts clears; counting avoids that)."""
        lander = self.landers[index]
        hull, legs = lander.hull_shape_id, lander.leg_shape_ids
        for k in range(events.begin_count):
            event = events.begin_events[k]
            pair = (event.shape_a, event.shape_b)
            if hull in pair:
                self.crashed[index] = True
            for leg in (0, 1):
                if legs[leg] in pair:
                    self.leg_touches[index, leg] += 1
        for k in range(events.end_count):
            event = events.end_events[k]
            pair = (event.shape_a, event.shape_b)
            for leg in (0, 1):
                if legs[leg] in pair:
                    self.leg_touches[index, leg] -= 1

    def _score(self, throttles: Throttles) -> FrameResult:
        self.angle = unwrap_angle(self.angle, self.transforms[:, 2], self.transforms[:, 3])
        state = state_of(self.transforms[:, :2].astype(np.float64), self.linear.astype(np.float64), self.angle,
                         self.angular.astype(np.float64), self.leg_touches > 0, self.pad_height)
        potential = shaping(state)
        rewards = frame_reward(potential, self.previous_potential, fuel_cost(throttles))
        self.previous_potential = potential
        off_screen = np.abs(state[:, 0]) >= 1.0
        rewards, terminated = episode_end(rewards, self.crashed.copy(), off_screen, self.at_rest.copy())
        return FrameResult(state.astype(np.float32), rewards, terminated)
