#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""BipedalWalker's heuristic handed over from one Box2D module to another mid-episode.

Run once with real pybox2d first on the path and --save: it walks Gymnasium's heuristic
--after steps and writes the state it reached (every body's pose and velocity, the legs'
contact flags, the heuristic's own state) to --state. Run again with the compat module
first on the path and --load: it resets the same seed (same terrain), puts the walker in
that state and walks on. Both then print the hull's distance every 100 steps, so the
gait can be compared from the same start whatever the first steps did. Nothing of
Gymnasium is copied: it comes from --gymnasium PATH.

  PYTHONPATH=/path/to/pybox2d-site python3 walker_handoff.py --gymnasium G --save
  PYTHONPATH=bindings/box2d-compat:bindings/python python3 walker_handoff.py --gymnasium G --load
"""

import argparse
import json
import sys

INITIAL_X = 14 / 30.0 * 20 / 2  # BipedalWalker's init_x: TERRAIN_STEP * TERRAIN_STARTPAD / 2


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--gymnasium", metavar="PATH", help="Gymnasium source checkout to import")
    mode = p.add_mutually_exclusive_group(required=True)
    mode.add_argument("--save", action="store_true", help="walk --after steps, save the state, walk on")
    mode.add_argument("--load", action="store_true", help="load the saved state and walk on from it")
    p.add_argument("--after", type=int, default=10, help="steps before the handover (default 10)")
    p.add_argument("--steps", type=int, default=1000, help="steps of the whole episode (default 1000)")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--state", default="walker_state.json", help="file the state goes through")
    return p.parse_args()


def save_state(env, heuristic, observation, path):
    bodies = [env.hull] + env.legs
    state = {
        "bodies": [[b.position[0], b.position[1], b.angle, b.linearVelocity[0], b.linearVelocity[1],
                    b.angularVelocity] for b in bodies],
        "ground_contact": [bool(env.legs[1].ground_contact), bool(env.legs[3].ground_contact)],
        "observation": [float(x) for x in observation],
        "heuristic": {"state": heuristic.state, "moving_leg": heuristic.moving_leg,
                      "supporting_leg": heuristic.supporting_leg,
                      "supporting_knee_angle": heuristic.supporting_knee_angle,
                      "a": [float(x) for x in heuristic.a]},
        "prev_shaping": env.prev_shaping,
    }
    with open(path, "w") as f:
        json.dump(state, f)


def load_state(env, heuristic, path, np):
    with open(path) as f:
        state = json.load(f)
    for body, (x, y, angle, vx, vy, w) in zip([env.hull] + env.legs, state["bodies"]):
        body.transform = ((x, y), angle)
        body.linearVelocity = (vx, vy)
        body.angularVelocity = w
    env.legs[1].ground_contact, env.legs[3].ground_contact = state["ground_contact"]
    for key, value in state["heuristic"].items():
        setattr(heuristic, key, np.array(value) if key == "a" else value)
    env.prev_shaping = state["prev_shaping"]
    return np.array(state["observation"], dtype=np.float32)


def main():
    args = parse_args()
    if args.gymnasium:
        sys.path.insert(0, args.gymnasium)
    import Box2D
    import gymnasium as gym
    import numpy as np
    from gymnasium.envs.box2d.bipedal_walker import BipedalWalkerHeuristics

    print(f"Box2D module: {Box2D.__file__}; seed {args.seed}; handover after {args.after} steps")
    env = gym.make("BipedalWalker-v3").unwrapped
    observation, _ = env.reset(seed=args.seed)
    heuristic = BipedalWalkerHeuristics()
    if args.save:
        for _ in range(args.after):
            observation, _, terminated, _, _ = env.step(heuristic.step_heuristic(observation))
        save_state(env, heuristic, observation, args.state)
    else:
        observation = load_state(env, heuristic, args.state, np)
    for step in range(args.after + 1, args.steps + 1):
        observation, _, terminated, _, _ = env.step(heuristic.step_heuristic(observation))
        if step % 100 == 0 or terminated:
            end = " fell (hull touched the ground)" if terminated else ""
            print(f"step {step:4d}: hull {env.hull.position[0] - INITIAL_X:6.2f} m from the start{end}")
        if terminated:
            break
    env.close()


if __name__ == "__main__":
    main()
