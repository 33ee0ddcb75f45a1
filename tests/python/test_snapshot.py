# SPDX-License-Identifier: MIT
"""Snapshots, rollback states, pickle and deepcopy: a world brought back from bytes steps
on to the same bits as a reference world that was never saved; refused bytes change
nothing."""

import copy
import multiprocessing
import pickle

import pytest

import impulse2d
from conftest import make_pile

BEFORE = 40  # steps before the save: the pile is falling and landing
AFTER = 30  # steps after it


def make_scene(**settings):
    """A falling pile and a pendulum on a revolute joint; (world, bodies, joint)."""
    world = impulse2d.World(**settings)
    bodies = make_pile(world, count=16)
    pivot = world.create_body(impulse2d.STATIC, position=(6.0, 6.0))
    bob = world.create_body(position=(8.0, 6.0))
    bob.create_box(0.3, 0.3)
    joint = world.create_joint("revolute", pivot, bob, local_anchor_b=(-2.0, 0.0))
    bodies.append(bob)
    return world, bodies, joint


def step(world, steps):
    """Steps the world; its state hash after each step."""
    hashes = []
    for _ in range(steps):
        world.step(1.0 / 60.0, 4)
        hashes.append(world.state_hash)
    return hashes


@pytest.fixture(scope="module")
def reference():
    """The scene at the save (its snapshot and hash), and the hashes of the AFTER steps it
    takes from there without ever being saved or restored (a world of its own)."""
    world, bodies, _ = make_scene()
    step(world, BEFORE)
    at_save = world.state_hash
    positions = [b.position for b in bodies]
    after = step(world, AFTER)
    world.destroy()
    saver, _, _ = make_scene()
    step(saver, BEFORE)
    snapshot = saver.save_snapshot()
    saver.destroy()
    # The scene moves: a world that stood still would pass every comparison below.
    assert len(set(after)) == AFTER and after[0] != at_save
    return {"hash": at_save, "positions": positions, "after": after, "snapshot": snapshot}


def test_restored_in_place_goes_on_as_the_world_never_saved(reference):
    world, bodies, joint = make_scene()
    step(world, BEFORE)
    snapshot = world.save_snapshot()
    assert isinstance(snapshot, bytes) and snapshot == reference["snapshot"]
    step(world, 25)  # somewhere else
    late = world.create_body(position=(0.0, 20.0))  # made after the save: stale after the restore
    assert world.state_hash != reference["hash"]
    world.restore_snapshot(bytearray(snapshot))
    assert world.state_hash == reference["hash"]
    assert world.save_snapshot() == snapshot
    assert all(b.is_valid for b in bodies) and joint.is_valid and not late.is_valid
    assert step(world, AFTER) == reference["after"]
    world.destroy()


def test_a_world_from_a_snapshot_goes_on_as_the_world_never_saved(reference):
    world, bodies, joint = make_scene()
    step(world, BEFORE)
    for workers in (1, 2):
        copy_ = impulse2d.World.from_snapshot(world.save_snapshot(), worker_count=workers)
        assert copy_.id != world.id and copy_.state_hash == reference["hash"]
        # The bodies of the saved world, found again by their ids.
        found = [copy_.body(b.id) for b in bodies]
        assert [b.position for b in found] == reference["positions"]
        assert copy_.body(bodies[0]) == found[0] and found[0].world is copy_
        assert copy_.joint(joint).body_b == found[-1]
        assert copy_.shape(bodies[0].shapes[0]) == found[0].shapes[0]
        assert step(copy_, AFTER) == reference["after"]
        copy_.destroy()
    assert world.state_hash == reference["hash"]  # saving changed nothing
    world.destroy()


def test_from_snapshot_takes_the_hosts_wiring_only(reference):
    with pytest.raises(TypeError, match="host's wiring only .*not gravity"):
        impulse2d.World.from_snapshot(reference["snapshot"], gravity=(0.0, 10.0))
    with pytest.raises(impulse2d.InvalidArgument, match="worker_count"):
        impulse2d.World.from_snapshot(reference["snapshot"], worker_count=0)
    with pytest.raises(TypeError, match="takes bytes"):
        impulse2d.World.from_snapshot("not bytes")


def test_pickle_round_trip_goes_on_as_the_world_never_saved(reference):
    world, bodies, joint = make_scene(worker_count=2)
    step(world, BEFORE)
    bodies[0].user_data = {"name": "first", "itself": bodies[0]}
    bob = bodies.pop()
    data = pickle.dumps((world, bodies, joint, bob), protocol=pickle.HIGHEST_PROTOCOL)
    world2, bodies2, joint2, bob2 = pickle.loads(data)
    assert world2 is not world and world2.id != world.id
    assert all(b.world is world2 for b in bodies2) and joint2.body_b == bob2 != bob
    assert [b.position for b in bodies2] == [b.position for b in bodies]
    assert bodies2[0].user_data["name"] == "first" and bodies2[0].user_data["itself"] == bodies2[0]
    assert world2._runtime_of()["worker_count"] == 2
    assert step(world2, AFTER) == reference["after"]
    assert world.state_hash == reference["hash"]
    world.destroy()
    world2.destroy()


def test_a_destroyed_body_comes_back_from_a_pickle_invalid():
    with impulse2d.World() as world:
        body = world.create_body()
        body.destroy()
        world2, body2 = pickle.loads(pickle.dumps((world, body)))
        assert not body2.is_valid and body2.id == 0
        world2.destroy()


def test_deepcopy_is_a_world_of_its_own(reference):
    world, bodies, _ = make_scene()
    step(world, BEFORE)
    copied, copied_bodies = copy.deepcopy((world, bodies))
    assert copied is not world and copied_bodies[3].world is copied
    assert copy.copy(bodies[3]) is bodies[3]  # a handle copied is the same handle
    assert step(copied, AFTER) == reference["after"]
    assert world.state_hash == reference["hash"]  # stepping the copy left the original alone
    assert step(world, AFTER) == reference["after"]
    world.destroy()
    copied.destroy()


def _step_in_child(world, body, steps):
    """Runs in a spawned process: steps an unpickled world, says where it got."""
    hashes = step(world, steps)
    return hashes[-1], body.position, world.id


def test_a_spawned_process_steps_an_unpickled_world_to_the_same_bits(reference):
    world, bodies, _ = make_scene()
    step(world, BEFORE)
    context = multiprocessing.get_context("spawn")
    with context.Pool(1) as pool:
        child_hash, child_position, child_world = pool.apply(_step_in_child, (world, bodies[5], AFTER))
    assert child_hash == reference["after"][-1]
    step(world, AFTER)
    assert child_position == bodies[5].position
    world.destroy()


def test_rollback_eight_frames_and_simulate_again():
    world, bodies, _ = make_scene()
    ring = [b""] * 8
    hashes = {}
    for frame in range(20):
        ring[frame % 8] = world.save_state()
        hashes[frame] = world.state_hash
        world.step(1.0 / 60.0, 4)
    hashes[20] = world.state_hash
    # A late input for frame 12: roll back to it, apply the input, simulate the 8 frames again.
    world.restore_state(ring[12 % 8])
    assert world.state_hash == hashes[12]
    bodies[0].apply_linear_impulse((5.0, 0.0))
    step(world, 8)
    assert world.state_hash != hashes[20]
    # And without the input: back to the frame-20 state exactly.
    world.restore_state(ring[12 % 8])
    assert step(world, 8)[-1] == hashes[20]
    reference, _, _ = make_scene()
    assert step(reference, 20)[-1] == hashes[20]
    reference.destroy()
    world.destroy()


def refused(world, call, data, match):
    before = world.state_hash
    with pytest.raises(impulse2d.InvalidSnapshot, match=match) as error:
        call(data)
    assert error.value.status == 7 and isinstance(error.value, impulse2d.Impulse2DError)
    assert world.state_hash == before


def test_truncated_and_corrupted_bytes_are_refused_and_change_nothing(reference):
    world, _, _ = make_scene()
    step(world, BEFORE + 10)
    snapshot, state = world.save_snapshot(), world.save_state()
    step(world, 5)
    for name, data in (("snapshot", snapshot), ("state", state)):
        call = world.restore_snapshot if name == "snapshot" else world.restore_state
        prefix = "i2d_world_restore_%s: %s refused: " % (name, "snapshot" if name == "snapshot" else "rollback state")
        refused(world, call, b"", prefix)
        refused(world, call, data[:-1], prefix)
        refused(world, call, data[: len(data) // 2], prefix)
        for at in (0, 9, len(data) // 3, len(data) - 1):
            corrupted = bytearray(data)
            corrupted[at] ^= 0x10
            refused(world, call, bytes(corrupted), prefix)
    with pytest.raises(impulse2d.InvalidSnapshot, match="i2d_world_create_from_snapshot: snapshot refused"):
        impulse2d.World.from_snapshot(reference["snapshot"][:-8])
    with pytest.raises(impulse2d.InvalidSnapshot):
        impulse2d.World.from_snapshot(state)  # a state is not a snapshot
    # The refusals left the world as it was: it goes on as one never refused.
    twin, _, _ = make_scene()
    step(twin, BEFORE + 15)
    assert step(world, 10) == step(twin, 10)
    world.destroy()
    twin.destroy()


def test_a_state_of_another_world_or_an_older_structure_is_refused():
    world, _, _ = make_scene()
    other, _, _ = make_scene()
    step(world, 10)
    step(other, 10)
    state = world.save_state()
    assert other.state_hash == world.state_hash  # the same scene, but not the same world
    refused(other, other.restore_state, state, "rollback state refused")
    world.create_body(position=(0.0, 30.0))
    refused(world, world.restore_state, state, "rollback state refused")
    world.destroy()
    other.destroy()
