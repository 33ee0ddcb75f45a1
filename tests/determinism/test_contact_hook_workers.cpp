// SPDX-License-Identifier: MIT
// The contact hooks run on the step's workers (toolkit.h): hooks that answer from their
// arguments alone give the same state hash at every step with 1, 2 and 4 workers and with
// 2 on a job system that runs the tasks shuffled. ThreadSanitizer runs this suite in CI.
#include "det_scenes.hpp"
#include "det_workers.hpp"

I2D_TEST(det_contact_hooks_give_the_same_bits_with_1_2_and_4_workers) { det::check_workers(det::hooked_bin, 300, 4); }
