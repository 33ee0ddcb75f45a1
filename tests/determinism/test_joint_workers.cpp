// SPDX-License-Identifier: MIT
// Joints keep the step's determinism: heaps of ragdolls (revolute joints with limits,
// springs and motors, coloured with the contacts), a net of hinges (solved W at a time,
// in chunks the workers cut differently) and bridges hung at both ends (loops solved
// exactly and projected) give the same state hash at every step
// with 1 and 2 workers, and with 2 workers on a job system that runs the tasks shuffled.
#include <impulse2d/impulse2d.h>

#include "det_scenes.hpp"
#include "det_workers.hpp"

using det::check_workers;

I2D_TEST(det_joints_ragdoll_heap_gives_the_same_bits_with_1_and_2_workers) { check_workers(det::ragdoll_heap, 240); }

I2D_TEST(det_joints_hinge_net_gives_the_same_bits_with_1_and_2_workers) { check_workers(det::hinge_net, 240); }

// Loops through the ground, each solved exactly and moved back onto its joints after the
// step, a bridge to a block of work.
I2D_TEST(det_joints_hung_bridges_give_the_same_bits_with_1_and_2_workers) { check_workers(det::hung_bridges, 240); }

// A crowd of 1100 ragdoll bodies: the workers gather the joints to solve in parts, and
// pieces of colours cut between workers end at whole SIMD blocks of hinges.
I2D_TEST(det_joints_ragdoll_crowd_gives_the_same_bits_with_1_2_and_4_workers) {
    check_workers(det::ragdoll_crowd, 240, 4);
}

// Until the heap sleeps: sleeping and waking islands held together by joints, too.
I2D_TEST(det_joints_long_ragdoll_heap_gives_the_same_bits_until_asleep) { check_workers(det::ragdoll_heap, 1200); }
