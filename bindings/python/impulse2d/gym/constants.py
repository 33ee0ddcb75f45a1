# SPDX-License-Identifier: MIT
"""The numbers that define LunarLander-v3, so that a policy trained on Gymnasium's
Box2D version runs on this one. They are facts of that environment (its pixel
geometry, frame rate and engine strengths), given here under names of our own."""

import math

# Gymnasium draws the scene in pixels and divides by this to get metres.
PIXELS_PER_METRE = 30.0
# One environment step is one frame of a 50 Hz game.
FRAMES_PER_SECOND = 50
FRAME_TIME = 1.0 / FRAMES_PER_SECOND

# The screen, in pixels and in metres. Leaving it sideways ends the episode.
SCREEN_WIDTH_PIXELS = 600
SCREEN_HEIGHT_PIXELS = 400
SCREEN_WIDTH = SCREEN_WIDTH_PIXELS / PIXELS_PER_METRE    # 20 m
SCREEN_HEIGHT = SCREEN_HEIGHT_PIXELS / PIXELS_PER_METRE  # 13.33 m

# Terrain: heights drawn at this many points, then smoothed; the middle ones are the pad.
TERRAIN_CHUNKS = 11
TERRAIN_FRICTION = 0.1

# The hull, a hexagon in pixels about the body origin (nose up).
HULL_OUTLINE_PIXELS = ((-14, 17), (-17, 0), (-17, -10), (17, -10), (17, 0), (14, 17))
HULL_DENSITY = 5.0
HULL_FRICTION = 0.1

# Legs: thin boxes hinged at the hull's origin, hanging out and down.
LEG_OFFSET_X_PIXELS = 20      # how far out each leg starts
LEG_DROP_PIXELS = 18          # the hinge sits this far up the leg; also the pad clearance
LEG_HALF_WIDTH_PIXELS = 2
LEG_HALF_HEIGHT_PIXELS = 8
LEG_DENSITY = 1.0
LEG_FRICTION = 0.2            # Box2D 2.3's default fixture friction (Gymnasium sets none)
LEG_MOTOR_TORQUE = 40.0       # the "spring" that keeps the legs splayed
LEG_MOTOR_SPEED = 0.3         # rad/s, slow enough not to kick the lander back up
# Each hinge may travel within a 0.5 rad window ending at 0.9 rad (mirrored per side).
LEG_LIMIT_OUTER = 0.9
LEG_LIMIT_TRAVEL = 0.5
LEG_START_TILT = 0.05         # legs are created turned outwards this much (rad)

# Collision categories: the ground is category 1 (the default); hull and legs touch
# only the ground, never each other.
GROUND_CATEGORY = 0x0001
HULL_CATEGORY = 0x0010
LEG_CATEGORY = 0x0020

# Engines: impulse per frame at full throttle, scaled by the lever arm in metres.
MAIN_ENGINE_POWER = 13.0
SIDE_ENGINE_POWER = 0.6
MAIN_ENGINE_DEPTH_PIXELS = 4       # main nozzle distance below the origin
SIDE_ENGINE_HEIGHT_PIXELS = 14     # side nozzles' height
SIDE_ENGINE_OFFSET_PIXELS = 12     # side nozzles' lever arm
SIDE_ENGINE_REACH_PIXELS = 17      # side impulse point's shift along the body axis

# Fuel cost per frame at full throttle, subtracted from the reward.
MAIN_ENGINE_FUEL_COST = 0.30
SIDE_ENGINE_FUEL_COST = 0.03

# The push on the lander during the first frame, each component uniform in +-this (N).
INITIAL_PUSH = 1000.0

# Rewards at the end of an episode.
LANDED_REWARD = 100.0
CRASHED_REWARD = -100.0

# Wind: a force tanh(sin(2 k t) + sin(pi k t)) * power, with k = 0.01 and t a counter
# started at a random integer in [-9999, 9999).
WIND_FREQUENCY = 0.01
WIND_START_RANGE = 9999

DEFAULT_GRAVITY = -10.0
DEFAULT_WIND_POWER = 15.0
DEFAULT_TURBULENCE_POWER = 1.5
DEFAULT_MAX_EPISODE_STEPS = 1000

# Observation bounds of v3 (x, y, vx, vy, angle, spin, leg, leg).
OBSERVATION_LOW = (-2.5, -2.5, -10.0, -10.0, -2 * math.pi, -10.0, 0.0, 0.0)
OBSERVATION_HIGH = (2.5, 2.5, 10.0, 10.0, 2 * math.pi, 10.0, 1.0, 1.0)
