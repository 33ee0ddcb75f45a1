#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Gymnasium's Box2D environments on whichever `Box2D` module comes first on the path.

Run it once with real pybox2d first on PYTHONPATH and once with bindings/box2d-compat
first, and compare the two outputs: the header names the Box2D module that ran, so the
two files can't be mixed up. Nothing of Gymnasium is copied here: it is imported from
--gymnasium PATH (a source checkout) or from PYTHONPATH, and both heuristics are
Gymnasium's own (`demo_heuristic_lander` and `BipedalWalkerHeuristics`, Gymnasium >= 1.0).

Parts (with none of the flags, the first three run):
  --heuristic      LunarLander-v3 heuristic on seeds 0..19: each total reward, how many
                   exceed 200; BipedalWalker-v3 heuristic for 1,000 steps on a few seeds:
                   hull x distance walked.
  --determinism    the same seed twice gives bit-identical observations (LunarLander:
                   300 heuristic steps; BipedalWalker: 300 steps of fixed random actions;
                   an episode that ends goes on with reset(seed + 1) and so on), in a
                   fresh env and after reset(seed) of the same env.
  --speed          env steps/s with seeded random actions, one env, median of --repeats
                   runs of --seconds each, and the mean time inside world.Step.
  --sync-vector N  steps/s over all N envs of a gymnasium SyncVectorEnv of N LunarLanders.

Usage:
  PYTHONPATH=/path/to/pybox2d-site python3 bench/python/gym_box2d_compare.py \
      --gymnasium /path/to/Gymnasium
"""

import argparse
import contextlib
import hashlib
import io
import os
import platform
import statistics
import sys
import time
import traceback

# Gymnasium's CarRacing imports pygame, which otherwise prints a banner into the output.
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--gymnasium", metavar="PATH",
                   help="Gymnasium source checkout to import (put before sys.path)")
    p.add_argument("--heuristic", action="store_true", help="run the heuristic part")
    p.add_argument("--determinism", action="store_true", help="run the determinism part")
    p.add_argument("--speed", action="store_true", help="run the single-env speed part")
    p.add_argument("--sync-vector", type=int, default=0, metavar="N",
                   help="time a SyncVectorEnv of N LunarLanders")
    p.add_argument("--lander-seeds", type=int, default=20, metavar="K",
                   help="LunarLander heuristic on seeds 0..K-1 (default 20)")
    p.add_argument("--walker-seeds", default="0,1,2,3,4", metavar="LIST",
                   help="BipedalWalker heuristic seeds, comma separated (default 0,1,2,3,4)")
    p.add_argument("--walker-steps", type=int, default=1000,
                   help="BipedalWalker heuristic steps (default 1000)")
    p.add_argument("--det-steps", type=int, default=300,
                   help="steps of each determinism run (default 300)")
    p.add_argument("--det-seed", type=int, default=7, help="seed of the determinism runs")
    p.add_argument("--repeats", type=int, default=5, help="timed repeats (default 5)")
    p.add_argument("--seconds", type=float, default=2.0, help="length of one repeat (default 2 s)")
    p.add_argument("--speed-envs", default="LunarLander-v3,BipedalWalker-v3,CarRacing-v3",
                   help="env ids for --speed, comma separated")
    args = p.parse_args()
    if not (args.heuristic or args.determinism or args.speed or args.sync_vector):
        args.heuristic = args.determinism = args.speed = True
    return args


def digest(array):
    """Short hash of an observation trajectory: equal hashes mean bit-identical runs,
    so two engines' (or two machines') outputs can be compared by eye."""
    return hashlib.sha256(array.tobytes()).hexdigest()[:16]


def print_header(Box2D, gym, np):
    # Say which engine ran: the compat module and pybox2d both import as `Box2D`.
    # A package without __init__.py (a namespace package) has no __file__, only a path.
    where = Box2D.__file__ or ", ".join(getattr(Box2D, "__path__", [])) or "?"
    print(f"Box2D module: {os.path.abspath(where) if os.path.exists(where) else where}")
    print(f"Box2D version: {getattr(Box2D, '__version__', '?')}")
    compat_world = sys.modules.get("Box2D._world")
    if compat_world is not None:  # the compat module: is its ray cast loop compiled?
        print(f"RayCast loop: {'compiled (Box2D._raycast)' if compat_world._ray_cast else 'Python'}")
    print(f"gymnasium: {gym.__version__} at {os.path.dirname(os.path.abspath(gym.__file__))}")
    print(f"python: {platform.python_version()} ({sys.executable}), numpy {np.__version__}")
    print(f"date (UTC): {time.strftime('%Y-%m-%d %H:%M:%S', time.gmtime())}")
    # Load average: timings taken while other work runs are not comparable.
    print(f"cpus: {os.cpu_count()}, load average: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    print()


class StepCounter:
    """Counts env.step calls through a gymnasium wrapper (demo_heuristic_lander does not
    return its step count)."""

    def __init__(self, gym):
        outer = self

        class Counting(gym.Wrapper):
            def step(self, action):
                outer.steps += 1
                return self.env.step(action)

        self.wrapper_class = Counting
        self.steps = 0


def lander_heuristic(gym, seeds):
    from gymnasium.envs.box2d.lunar_lander import demo_heuristic_lander

    counter = StepCounter(gym)
    env = counter.wrapper_class(gym.make("LunarLander-v3"))
    print(f"LunarLander-v3 heuristic (gymnasium's demo_heuristic_lander), seeds 0..{seeds - 1}")
    print(f"{'seed':>4} {'total reward':>13} {'steps':>6}")
    totals = []
    for seed in range(seeds):
        counter.steps = 0
        # The demo prints the observation every 20 steps; keep only the totals.
        with contextlib.redirect_stdout(io.StringIO()):
            total = float(demo_heuristic_lander(env, seed=seed))
        totals.append(total)
        print(f"{seed:>4} {total:>13.2f} {counter.steps:>6}")
    env.close()
    landed = sum(t > 200 for t in totals)
    print(f"above 200: {landed} of {seeds}; mean {statistics.mean(totals):.2f}, "
          f"min {min(totals):.2f}, max {max(totals):.2f}")
    print()


def walker_heuristic(gym, np, seeds, steps):
    try:
        from gymnasium.envs.box2d.bipedal_walker import BipedalWalkerHeuristics
    except ImportError:
        sys.exit("this Gymnasium has no BipedalWalkerHeuristics (added in Gymnasium 1.0.0)")

    print(f"BipedalWalker-v3 heuristic (gymnasium's BipedalWalkerHeuristics), {steps} steps")
    print(f"{'seed':>4} {'distance m':>11} {'total reward':>13} {'steps':>6}  end")
    for seed in seeds:
        env = gym.make("BipedalWalker-v3")
        env.reset(seed=seed)
        x0 = env.unwrapped.hull.position[0]
        # As in bipedal_walker.py's __main__: the first action is zeros, then the
        # heuristic reacts to each new observation.
        action = np.array([0.0, 0.0, 0.0, 0.0])
        heuristics = BipedalWalkerHeuristics()
        total, n, end = 0.0, 0, "ran all steps"
        for n in range(1, steps + 1):
            s, r, terminated, truncated, _ = env.step(action)
            total += r
            action = heuristics.step_heuristic(s)
            if terminated or truncated:
                end = ("fell (hull touched the ground)" if env.unwrapped.game_over
                       else "terminated" if terminated else "truncated")
                break
        distance = env.unwrapped.hull.position[0] - x0
        print(f"{seed:>4} {distance:>11.2f} {total:>13.2f} {n:>6}  {end}")
        env.close()
    print()


def lander_trajectory(np, env, seed, steps):
    from gymnasium.envs.box2d.lunar_lander import heuristic

    return trajectory(np, env, seed, steps, lambda i, s: heuristic(env, s))


def walker_trajectory(np, env, seed, steps):
    # Fixed actions from their own generator, so both runs see exactly the same inputs.
    actions = np.random.default_rng(seed).uniform(-1.0, 1.0, (steps, 4)).astype(np.float32)
    return trajectory(np, env, seed, steps, lambda i, s: actions[i])


def trajectory(np, env, seed, steps, policy):
    """`steps` steps of policy(step index, observation). An episode that ends is followed
    by reset(seed + episodes so far), so every run covers the same number of steps
    (random actions topple the walker in under 100) and resets are compared too.
    Returns the observations stacked, and the number of episodes."""
    s, _ = env.reset(seed=seed)
    observations, episodes = [s], 1
    for i in range(steps):
        s, _, terminated, truncated, _ = env.step(policy(i, s))
        observations.append(s)
        if terminated or truncated:
            s, _ = env.reset(seed=seed + episodes)
            observations.append(s)
            episodes += 1
    return np.array(observations), episodes


def determinism(gym, np, seed, steps):
    print(f"determinism: seed {seed}, {steps} steps (a new episode with the next seed when "
          f"one ends), observations compared bit for bit")
    cases = [("LunarLander-v3", "heuristic", lander_trajectory),
             ("BipedalWalker-v3", "fixed random actions", walker_trajectory)]
    for env_id, inputs, run in cases:
        env_a, env_b = gym.make(env_id), gym.make(env_id)
        first, episodes = run(np, env_a, seed, steps)
        world = env_a.unwrapped.world
        fresh, _ = run(np, env_b, seed, steps)
        # Same env again after reset(seed): catches state kept across resets. The
        # BipedalWalker keeps one b2World for its whole life (LunarLander makes a new one
        # on each reset), so there the world's history can change the contact order.
        again, _ = run(np, env_a, seed, steps)
        world_kept = env_a.unwrapped.world is world
        same_fresh = first.shape == fresh.shape and first.tobytes() == fresh.tobytes()
        same_again = first.shape == again.shape and first.tobytes() == again.tobytes()
        print(f"{env_id} ({inputs}): {episodes} episode(s), "
              f"fresh env identical: {'yes' if same_fresh else 'no'}, "
              f"same env after reset identical: {'yes' if same_again else 'no'} "
              f"({'world kept' if world_kept else 'new world'} across resets), "
              f"digest {digest(first)}")
        env_a.close()
        env_b.close()
    print()


class WorldStepTimer:
    """Times world.Step by wrapping the world's class method (not the instance: the envs
    make a new world on every reset). Restored by close()."""

    def __init__(self, world):
        self.cls = type(world)
        # Keep the class dict's own entry to put back: for SWIG proxies (pybox2d) the
        # value read through the class is an unbound builtin that would not bind `self`
        # if it were stored back.
        self.owner = next(k for k in self.cls.__mro__ if "Step" in vars(k))
        self.raw = vars(self.owner)["Step"]
        self.seconds = 0.0
        self.calls = 0
        original = self.cls.Step  # called with the world as its first argument

        def timed_step(world, *args, **kwargs):
            start = time.perf_counter()
            try:
                return original(world, *args, **kwargs)
            finally:
                self.seconds += time.perf_counter() - start
                self.calls += 1

        self.cls.Step = timed_step  # raises on a class that can't be patched

    def reset(self):
        self.seconds, self.calls = 0.0, 0

    def close(self):
        if self.owner is self.cls:
            self.cls.Step = self.raw
        else:
            del self.cls.Step  # found again on the base class that defines it


def time_one_run(env, timer, seconds):
    """Steps with the env's seeded action sampler for `seconds`; resets (included in the
    time, as in training) when an episode ends. Returns steps/s and mean µs in Step."""
    if timer:
        timer.reset()
    steps = 0
    start = time.perf_counter()
    deadline = start + seconds
    while time.perf_counter() < deadline:
        _, _, terminated, truncated, _ = env.step(env.action_space.sample())
        steps += 1
        if terminated or truncated:
            env.reset()
    elapsed = time.perf_counter() - start
    step_us = timer.seconds / timer.calls * 1e6 if timer and timer.calls else float("nan")
    return steps / elapsed, step_us


def speed(gym, env_ids, repeats, seconds):
    print(f"speed: random actions (action_space.seed(0)), one env, median of {repeats} "
          f"x {seconds:g} s; resets included")
    print(f"{'env':<18} {'steps/s':>9} {'min':>9} {'max':>9} {'Step µs':>9} {'Step share':>10}")
    for env_id in env_ids:
        try:
            env = gym.make(env_id)  # render_mode None; CarRacing still draws its state pixels
            env.reset(seed=0)
        except Exception as error:  # e.g. CarRacing without pygame
            print(f"{env_id:<18} skipped: {type(error).__name__}: {error}")
            continue
        env.action_space.seed(0)
        try:
            timer = WorldStepTimer(env.unwrapped.world)
        except (AttributeError, TypeError) as error:
            print(f"  (world.Step not timed: {error})")
            timer = None
        time_one_run(env, timer, min(0.2, seconds))  # warm-up: first-step checks, caches
        runs = [time_one_run(env, timer, seconds) for _ in range(repeats)]
        if timer:
            timer.close()
        env.close()
        rates = [r[0] for r in runs]
        rate = statistics.median(rates)
        step_us = statistics.median(r[1] for r in runs)
        share = statistics.median(r[1] * 1e-6 * r[0] for r in runs)  # of each run's time
        print(f"{env_id:<18} {rate:>9.0f} {min(rates):>9.0f} {max(rates):>9.0f} "
              f"{step_us:>9.1f} {share:>9.0%}")
    print()


def sync_vector(gym, n, repeats, seconds):
    env = gym.vector.SyncVectorEnv([lambda: gym.make("LunarLander-v3") for _ in range(n)])
    env.reset(seed=0)
    env.action_space.seed(0)
    rates = []
    for repeat in range(repeats + 1):
        steps = 0
        start = time.perf_counter()
        deadline = start + (min(0.2, seconds) if repeat == 0 else seconds)
        while time.perf_counter() < deadline:
            env.step(env.action_space.sample())  # SyncVectorEnv resets finished envs itself
            steps += 1
        if repeat:  # the first run is a warm-up
            rates.append(steps * n / (time.perf_counter() - start))
    env.close()
    print(f"SyncVectorEnv of {n} LunarLander-v3, random actions, median of {repeats} "
          f"x {seconds:g} s: {statistics.median(rates):.0f} env steps/s "
          f"(min {min(rates):.0f}, max {max(rates):.0f})")
    print()


def main():
    args = parse_args()
    if args.gymnasium:
        sys.path.insert(0, os.path.abspath(args.gymnasium))
    import numpy as np
    import Box2D
    import gymnasium as gym

    print_header(Box2D, gym, np)
    walker_seeds = [int(s) for s in args.walker_seeds.split(",") if s]
    parts = []
    if args.heuristic:
        parts.append(("lander heuristic", lambda: lander_heuristic(gym, args.lander_seeds)))
        parts.append(("walker heuristic",
                      lambda: walker_heuristic(gym, np, walker_seeds, args.walker_steps)))
    if args.determinism:
        parts.append(("determinism", lambda: determinism(gym, np, args.det_seed, args.det_steps)))
    if args.speed:
        env_ids = [e for e in args.speed_envs.split(",") if e]
        parts.append(("speed", lambda: speed(gym, env_ids, args.repeats, args.seconds)))
    if args.sync_vector:
        parts.append(("sync vector",
                      lambda: sync_vector(gym, args.sync_vector, args.repeats, args.seconds)))
    # A Box2D stand-in may run some envs and not others: report a failing part and go on
    # to the next, so one run shows everything that works.
    failed = []
    for name, run in parts:
        try:
            run()
        except Exception:
            failed.append(name)
            print(f"\n{name}: FAILED")
            traceback.print_exc(file=sys.stdout)
            print()
    if failed:
        sys.exit(f"failed parts: {', '.join(failed)}")


if __name__ == "__main__":
    main()
