# SPDX-License-Identifier: MIT
"""impulse2d.gym's LunarLander-v3: spaces, seeding, physics outcomes, a PD pilot's
landings, vector/single agreement, NEXT_STEP autoreset and truncation."""

import numpy as np
import pytest

from impulse2d.gym import LunarLander, VectorLunarLander
from impulse2d.gym.streams import BLOCK_FRAMES, LanderStreams


def pd_commands(obs):
    """A PD pilot's turn and lift on the observation: lean so the main engine pushes
    toward the pad, hold a height that falls as the lander nears it, cushion the
    touchdown."""
    x, y, vx, vy, angle, spin, left_down, right_down = obs
    lean = np.clip(0.5 * x + 1.0 * vx, -0.4, 0.4)
    turn = 0.5 * (lean - angle) - 1.0 * spin
    lift = 0.5 * (0.5 * abs(x) - y) - 0.5 * vy
    if left_down or right_down:
        turn, lift = 0.0, -0.5 * vy
    return turn, lift


def pilot(obs):
    """The PD pilot's commands as discrete actions: the stronger one fires."""
    turn, lift = pd_commands(obs)
    if lift > abs(turn) and lift > 0.05:
        return 2
    if turn < -0.05:
        return 3
    if turn > 0.05:
        return 1
    return 0


def run_episode(env, seed, policy, limit=1000):
    obs, _ = env.reset(seed=seed)
    observations, total = [obs], 0.0
    for _ in range(limit):
        obs, reward, terminated, truncated, _ = env.step(policy(obs))
        observations.append(obs)
        total += reward
        if terminated or truncated:
            break
    return np.array(observations), total, reward, terminated, truncated


def test_single_env_spaces_and_dtypes():
    env = LunarLander()
    obs, info = env.reset(seed=3)
    assert obs.shape == (8,) and obs.dtype == np.float32 and info == {}
    assert env.observation_space.shape == (8,) and env.action_space.n == 4
    obs, reward, terminated, truncated, info = env.step(0)
    assert obs.dtype == np.float32 and isinstance(reward, float)
    assert terminated is False and truncated is False and info == {}
    # The lander starts at the top middle: x near 0, y near 1.4 half-screens above the pad.
    assert abs(obs[0]) < 0.05 and 1.3 < obs[1] < 1.5 and obs[6] == obs[7] == 0.0
    env.close()


def test_vector_env_spaces_and_dtypes():
    env = VectorLunarLander(5)
    obs, infos = env.reset(seed=0)
    assert obs.shape == (5, 8) and obs.dtype == np.float32 and infos == {}
    obs, rewards, terminations, truncations, infos = env.step(np.zeros(5, dtype=np.int64))
    assert rewards.shape == (5,) and rewards.dtype == np.float64
    assert terminations.dtype == bool and truncations.dtype == bool
    assert env.single_observation_space.shape == (8,) and env.observation_space.shape == (5, 8)
    assert env.action_space.shape == (5,) and env.metadata["autoreset_mode"] in ("NextStep",) or \
        getattr(env.metadata["autoreset_mode"], "value", None) == "NextStep"
    env.close()


def test_continuous_spaces():
    env = VectorLunarLander(3, continuous=True)
    assert env.single_action_space.shape == (2,) and env.action_space.shape == (3, 2)
    obs, _ = env.reset(seed=0)
    obs, rewards, _, _, _ = env.step(np.zeros((3, 2), dtype=np.float32))
    assert obs.shape == (3, 8)
    with pytest.raises(ValueError):
        env.step(np.zeros(3))
    env.close()


def test_bad_actions_and_gravity_are_refused():
    env = VectorLunarLander(2)
    env.reset(seed=0)
    with pytest.raises(ValueError):
        env.step([0, 4])
    with pytest.raises(ValueError):
        env.step([0, 1, 2])
    single = LunarLander()
    single.reset(seed=0)
    with pytest.raises(ValueError):
        single.step(7)
    with pytest.raises(ValueError):
        LunarLander(gravity=-13.0)
    with pytest.raises(ValueError):
        VectorLunarLander(2, gravity=1.0)


def test_same_seed_same_episode_bitwise():
    env = LunarLander()
    actions = np.random.default_rng(7).integers(0, 4, size=150)
    runs = []
    for _ in range(2):
        obs, _ = env.reset(seed=42)
        trace = [obs]
        for a in actions:
            obs, reward, terminated, truncated, _ = env.step(int(a))
            trace.append(obs)
            if terminated:
                break
        runs.append(np.array(trace))
    assert runs[0].shape == runs[1].shape
    assert runs[0].tobytes() == runs[1].tobytes()


def test_different_seeds_give_different_terrain_and_start():
    env = LunarLander()
    env.reset(seed=1)
    first = env.fleet.terrains[0]
    obs_1 = env.step(0)[0]
    env.reset(seed=2)
    second = env.fleet.terrains[0]
    obs_2 = env.step(0)[0]
    assert not np.array_equal(first.ys, second.ys)
    assert not np.array_equal(obs_1, obs_2)
    # The pad is flat in both, between the same x, at the same height.
    middle = len(first.ys) // 2
    for terrain in (first, second):
        assert terrain.pad_left < terrain.pad_right
        np.testing.assert_allclose(terrain.ys[middle - 1 : middle + 2], 0.99 * terrain.pad_height)


def test_left_alone_the_lander_falls_and_the_episode_ends_by_physics():
    env = LunarLander()
    for seed in range(5):
        observations, total, last_reward, terminated, truncated = run_episode(env, seed, lambda obs: 0)
        assert terminated and not truncated
        assert observations[-1][1] < observations[0][1] - 1.0  # fell more than half a screen
        fleet = env.fleet
        if fleet.crashed[0] or abs(observations[-1][0]) >= 1.0:
            assert last_reward == -100.0
        else:
            assert fleet.at_rest[0] and last_reward == 100.0


def test_pd_pilot_lands_most_seeds_with_more_than_200():
    env = LunarLander()
    scores, landed = [], 0
    for seed in range(10):
        _, total, last_reward, terminated, _ = run_episode(env, seed, pilot)
        scores.append(total)
        landed += bool(terminated and last_reward == 100.0)
    assert sum(s > 200 for s in scores) >= 8, scores
    assert landed >= 8, scores


def test_vector_sub_envs_match_single_envs_bitwise_through_autoreset():
    n, seed, steps = 4, 10, 800
    rng = np.random.default_rng(3)
    # A pilot with a random twist, so that episodes end at different times.
    noise = rng.random((steps, n)) < 0.15
    random_actions = rng.integers(0, 4, size=(steps, n))
    vector = VectorLunarLander(n)
    obs, _ = vector.reset(seed=seed)
    vector_trace = [obs]
    vector_events = []
    for t in range(steps):
        actions = np.array([random_actions[t, i] if noise[t, i] else pilot(obs[i]) for i in range(n)])
        obs, rewards, terminations, truncations, _ = vector.step(actions)
        vector_trace.append(obs)
        vector_events.append((rewards, terminations))
    vector_trace = np.array(vector_trace)
    resets = 0
    for i in range(n):
        single = LunarLander()
        obs, _ = single.reset(seed=seed + i)
        assert obs.tobytes() == vector_trace[0, i].tobytes()
        finished = False
        for t in range(steps):
            if finished:
                obs, _ = single.reset()
                reward, terminated = 0.0, False
                resets += 1
            else:
                action = random_actions[t, i] if noise[t, i] else pilot(obs)
                obs, reward, terminated, truncated, _ = single.step(action)
            assert obs.tobytes() == vector_trace[t + 1, i].tobytes(), (i, t)
            assert reward == vector_events[t][0][i] and terminated == vector_events[t][1][i]
            finished = terminated
        single.close()
    assert resets >= 2  # the comparison went through autoresets


def test_next_step_autoreset():
    env = VectorLunarLander(2)
    obs, _ = env.reset(seed=5)
    ended_at = None
    for t in range(600):
        obs, rewards, terminations, truncations, _ = env.step(np.zeros(2, dtype=np.int64))
        if terminations[0]:
            ended_at = t
            assert rewards[0] in (-100.0, 100.0)
            break
    assert ended_at is not None
    # The next step resets sub-env 0 whatever its action: a fresh lander at the top,
    # reward 0, not terminated; sub-env 1 goes on.
    obs, rewards, terminations, truncations, _ = env.step(np.array([2, 0]))
    assert rewards[0] == 0.0 and not terminations[0] and not truncations[0]
    assert 1.3 < obs[0, 1] < 1.5 and obs[0, 6] == obs[0, 7] == 0.0
    # Its first reset obs is what its random stream gives a new episode: a new terrain.
    obs, rewards, terminations, truncations, _ = env.step(np.array([0, 0]))
    assert rewards[0] != 0.0 and not terminations[0]


def test_truncation_at_max_episode_steps_then_autoreset():
    env = VectorLunarLander(3, max_episode_steps=5)
    env.reset(seed=0)
    for t in range(1, 6):
        _, _, terminations, truncations, _ = env.step(np.zeros(3, dtype=np.int64))
        assert not terminations.any()
        assert truncations.all() == (t == 5) and truncations.any() == (t == 5)
    obs, rewards, terminations, truncations, _ = env.step(np.zeros(3, dtype=np.int64))
    assert not truncations.any() and (rewards == 0.0).all() and (obs[:, 1] > 1.3).all()
    # The counters started again: 5 more steps truncate once more.
    for t in range(1, 6):
        _, _, _, truncations, _ = env.step(np.zeros(3, dtype=np.int64))
    assert truncations.all()
    single = LunarLander(max_episode_steps=3)
    single.reset(seed=0)
    assert [single.step(0)[3] for _ in range(3)] == [False, False, True]


def test_default_time_limit_is_1000():
    assert VectorLunarLander(1).max_episode_steps == 1000
    assert LunarLander().max_episode_steps == 1000


def test_continuous_actions_fire_the_same_engines_as_discrete_ones():
    # Full throttle in the continuous space is the discrete engine exactly, and
    # inputs below the engines' thresholds are no action at all.
    pairs = [([-1.0, 0.0], 0), ([0.0, 0.3], 0), ([1.0, 0.0], 2), ([0.0, -1.0], 1), ([0.0, 1.0], 3)]
    for continuous_action, discrete_action in pairs:
        traces = []
        for continuous, action in ((True, continuous_action), (False, discrete_action)):
            env = LunarLander(continuous=continuous)
            obs, _ = env.reset(seed=8)
            trace = [obs] + [env.step(np.array(action) if continuous else action)[0] for _ in range(20)]
            traces.append(np.array(trace))
        assert traces[0].tobytes() == traces[1].tobytes(), (continuous_action, discrete_action)


def test_engines_push_and_turn_the_lander():
    def after(action, steps=15):
        env = LunarLander()
        env.reset(seed=4)
        for _ in range(steps):
            obs = env.step(action)[0]
        return obs

    idle, main, left, right = after(0), after(2), after(1), after(3)
    assert main[3] > idle[3] + 0.5           # the main engine slows the fall
    assert right[5] < idle[5] < left[5]      # the left nozzle turns it counter-clockwise
    assert np.sign(left[4] - idle[4]) == -np.sign(right[4] - idle[4])


def test_wind_and_gravity_options_change_the_flight():
    def trajectory(**options):
        env = LunarLander(**options)
        env.reset(seed=6)
        return np.array([env.step(0)[0] for _ in range(30)])

    calm, windy = trajectory(), trajectory(enable_wind=True, wind_power=20.0, turbulence_power=2.0)
    assert np.abs(calm[:, 2] - windy[:, 2]).max() > 0.01  # wind changes the sideways speed
    light = trajectory(gravity=-2.0)
    assert light[-1, 3] > calm[-1, 3] + 0.5              # lower gravity, slower fall
    repeat = trajectory(enable_wind=True, wind_power=20.0, turbulence_power=2.0)
    assert repeat.tobytes() == windy.tobytes()           # wind is seeded too


def test_dispersion_drawn_ahead_leaves_each_stream_as_gymnasium_draws_it():
    # Frames across a block's end, a reset's draws, more frames: the same numbers, in the
    # same order, as one generator drawing two per frame and the reset's in between.
    first, then, reset_draws = BLOCK_FRAMES + 6, 5, 13
    streams = LanderStreams(2)
    streams.seed(0, 40)
    streams.seed(1, 41)
    taken = [streams.dispersion() for _ in range(first)]
    lander_0_reset = streams.for_episode(0).uniform(0.0, 1.0, size=reset_draws)
    taken += [streams.dispersion() for _ in range(then)]
    lander_1_reset = streams.for_episode(1).uniform(0.0, 1.0, size=reset_draws)
    gymnasium_0, gymnasium_1 = np.random.default_rng(40), np.random.default_rng(41)
    expected_0 = [gymnasium_0.uniform(-1.0, 1.0, size=(first, 2)), gymnasium_0.uniform(0.0, 1.0, size=reset_draws),
                  gymnasium_0.uniform(-1.0, 1.0, size=(then, 2))]
    expected_1 = [gymnasium_1.uniform(-1.0, 1.0, size=(first + then, 2)), gymnasium_1.uniform(0.0, 1.0, size=reset_draws)]
    taken = np.array(taken)
    assert taken[:first, 0].tobytes() == expected_0[0].tobytes()
    assert lander_0_reset.tobytes() == expected_0[1].tobytes()
    assert taken[first:, 0].tobytes() == expected_0[2].tobytes()
    assert taken[:, 1].tobytes() == expected_1[0].tobytes()
    assert lander_1_reset.tobytes() == expected_1[1].tobytes()


def test_many_sub_envs_keep_independent_streams():
    env = VectorLunarLander(8)
    obs, _ = env.reset(seed=100)
    assert len({row.tobytes() for row in obs}) == 8
    again, _ = env.reset(seed=[100 + i for i in range(8)])
    assert again.tobytes() == obs.tobytes()


def continuous_pilot(obs):
    """The PD pilot's lift and turn as throttles: main engine from -1 (off) to 1, the
    lateral input's sign choosing the nozzle."""
    turn, lift = pd_commands(obs)
    return np.clip([20.0 * lift - 1.0, -20.0 * turn], -1.0, 1.0).astype(np.float32)


def test_continuous_pd_pilot_lands_most_seeds_with_more_than_200():
    env = LunarLander(continuous=True)
    results = [run_episode(env, seed, continuous_pilot) for seed in range(10)]
    assert sum(total > 200 and last == 100.0 for _, total, last, _, _ in results) >= 8, \
        [round(r[1]) for r in results]
