# SPDX-License-Identifier: MIT
"""Recording and replay from Python: a recorded session replays with every hash as
recorded and seeks back; a replay whose world is nudged names the step it diverges at; a
changed recording is refused; an exception in the writer comes back at stop_recording."""

import pytest

import impulse2d
from conftest import make_pile

STEPS = 60


def record_session():
    """A pile recorded while bodies are pushed and one is added; (recording, hashes)."""
    world = impulse2d.World()
    bodies = make_pile(world, count=12)
    recording = bytearray()
    world.start_recording(recording.extend)
    hashes = []
    for k in range(STEPS):
        if k == 10:
            bodies[3].apply_linear_impulse((1.0, 2.0), bodies[3].position)
        if k == 20:
            extra = world.create_body(position=(0.5, 8.0))
            extra.create_circle(0.3)
        if k == 30:
            world.gravity = (1.0, -9.0)
        world.step(1.0 / 60.0, 4)
        hashes.append(world.state_hash)
    world.stop_recording()
    world.destroy()
    return bytes(recording), hashes


def test_replay_follows_the_recorded_hashes_and_seeks_back():
    recording, hashes = record_session()
    with impulse2d.Replay(recording, worker_count=2) as replay:
        assert replay.step_count == STEPS
        assert replay.step(25) == 25
        assert replay.world.state_hash == hashes[24]
        assert replay.step(1000) == STEPS - 25
        assert replay.divergent_step is None
        replay.seek(10)
        assert replay.current_step == 10
        assert replay.world.state_hash == hashes[9]


def test_replay_names_the_step_a_nudged_world_diverges_at():
    recording, _ = record_session()
    replay = impulse2d.Replay(recording)
    replay.seek(40)
    stray = replay.world.create_body(position=(-30.0, 30.0))
    stray.create_circle(0.2)
    assert replay.step(100) == 1
    assert replay.divergent_step == 41
    replay.close()
    replay.close()  # harmless twice


def test_a_changed_recording_is_refused():
    recording, _ = record_session()
    changed = bytearray(recording)
    changed[len(changed) // 2] ^= 0x40
    with pytest.raises(impulse2d.InvalidSnapshot):
        impulse2d.Replay(bytes(changed))
    with pytest.raises(TypeError):
        impulse2d.Replay(recording, gravity=(0.0, -1.0))


def test_the_replay_world_is_the_replays_to_close():
    recording, _ = record_session()
    with impulse2d.Replay(recording) as replay:
        with pytest.raises(impulse2d.InvalidArgument):
            replay.world.destroy()
        world = replay.world
    assert not world.is_valid


def test_an_exception_in_the_writer_comes_back_at_stop():
    world = impulse2d.World()
    make_pile(world, count=3)

    def broken(_data):
        raise OSError("disk full")

    world.start_recording(broken)
    world.step(1.0 / 60.0, 4)
    with pytest.raises(OSError, match="disk full"):
        world.stop_recording()
    world.destroy()
