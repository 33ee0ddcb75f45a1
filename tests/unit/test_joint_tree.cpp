// SPDX-License-Identifier: MIT
// JointTrees' choice of joints: the rigid rows of groups hung from a body that does not
// move, trees or closing a few loops, are solved exactly; free groups and groups closing
// more loops than the cuts allow (a grid) are left to the sweep, and so are kinds without
// rigid rows and angle rows that no body can turn. The solving itself is checked against
// closed forms by the physics suite (test_joints_chain.cpp, test_joints_weld.cpp,
// test_joints_loops.cpp).
#include <vector>

#include "check.h"
#include "dynamics/joint/joint_tree.hpp"

using namespace i2d;

namespace {

// Bodies and joints as the solver sees them at a step's start: dynamic awake bodies take
// the next state, static, kinematic and sleeping ones none.
struct Layout {
    Pool<Body> bodies;
    Pool<Joint> joints;
    std::vector<JointConstraint> constraints;
    int32_t states = 0;

    int32_t body(BodyType type, bool awake = true, bool turns = true) {
        const int32_t b = bodies.allocate();
        bodies[b].type = type;
        bodies[b].inv_mass = type == BodyType::dynamic ? 1.0f : 0.0f;
        bodies[b].inv_inertia = type == BodyType::dynamic && turns ? 1.0f : 0.0f;
        bodies[b].awake_index = type != BodyType::static_body && awake ? states++ : null_index;
        return b;
    }
    int32_t joint(JointType type, int32_t a, int32_t b, float weld_linear_hertz = 0.0f) {
        const int32_t j = joints.allocate();
        joints[j].def.type = type;
        joints[j].def.body_a = a;
        joints[j].def.body_b = b;
        joints[j].def.weld.linear_hertz = weld_linear_hertz;
        JointConstraint c;
        c.joint = j;
        constraints.push_back(c);
        return int32_t(constraints.size()) - 1;
    }
    int32_t dynamic() { return body(BodyType::dynamic); }
};

// Joints from a to b, b to c, ... along the bodies given; returns the first's constraint.
int32_t chain(Layout& l, const std::vector<int32_t>& bodies) {
    const int32_t first = int32_t(l.constraints.size());
    for (std::size_t i = 0; i + 1 < bodies.size(); ++i) {
        l.joint(JointType::revolute, bodies[i], bodies[i + 1]);
    }
    return first;
}

bool all_exact(const Layout& l, int32_t first, int32_t count, uint8_t rows = exact_point_rows) {
    bool ok = true;
    for (int32_t k = first; k < first + count; ++k) {
        ok = ok && l.constraints[std::size_t(k)].exact_rows == rows;
    }
    return ok;
}

}  // namespace

I2D_TEST(unit_joint_trees_take_hung_trees_and_few_loops_and_leave_the_rest_to_the_sweep) {
    Layout l;
    const int32_t ceiling = l.body(BodyType::static_body);
    // A chain hung from the ceiling, with a branch: one tree.
    const int32_t c0 = l.dynamic(), c1 = l.dynamic(), c2 = l.dynamic(), branch = l.dynamic();
    const int32_t hung = chain(l, {ceiling, c0, c1, c2});
    l.joint(JointType::revolute, c1, branch);
    // A ragdoll-like free tree: no joint to anything fixed.
    const int32_t f0 = l.dynamic(), f1 = l.dynamic(), f2 = l.dynamic();
    const int32_t free_tree = chain(l, {f0, f1, f2});
    // A bridge hung at both ends: a tree and one cut (its second hold).
    const int32_t b0 = l.dynamic(), b1 = l.dynamic();
    const int32_t bridge = chain(l, {ceiling, b0, b1, ceiling});
    // A hung loop: ceiling - l0, then l0 - l1 - l2 - l0: one cut.
    const int32_t l0 = l.dynamic(), l1 = l.dynamic(), l2 = l.dynamic();
    const int32_t loop = chain(l, {ceiling, l0, l1, l2, l0});
    // A 4 x 4 grid of bodies hung by a corner: 24 joints among 16 bodies close 9 loops,
    // more than the cuts allow.
    int32_t grid[4][4];
    for (auto& row : grid) {
        for (int32_t& body : row) {
            body = l.dynamic();
        }
    }
    const int32_t grid_first = int32_t(l.constraints.size());
    l.joint(JointType::revolute, ceiling, grid[0][0]);
    for (int32_t i = 0; i < 4; ++i) {
        for (int32_t j = 0; j < 4; ++j) {
            if (j + 1 < 4) {
                l.joint(JointType::revolute, grid[i][j], grid[i][j + 1]);
            }
            if (i + 1 < 4) {
                l.joint(JointType::revolute, grid[i][j], grid[i + 1][j]);
            }
        }
    }
    const int32_t grid_joints = int32_t(l.constraints.size()) - grid_first;
    // Hung from a kinematic body, and from a sleeping one: both count as fixed.
    const int32_t crane = l.body(BodyType::kinematic, false), k0 = l.dynamic();
    const int32_t from_kinematic = chain(l, {crane, k0});
    const int32_t sleeper = l.body(BodyType::dynamic, false), s0 = l.dynamic();
    const int32_t from_sleeper = chain(l, {sleeper, s0});
    // A weld with a soft point row gives only its angle; a distance joint gives nothing,
    // and a mouse joint on the hung chain leaves the chain a tree.
    const int32_t w0 = l.dynamic();
    const int32_t weld = l.joint(JointType::weld, ceiling, w0, 5.0f);
    const int32_t distance = l.joint(JointType::distance, ceiling, l.dynamic());
    const int32_t mouse = l.joint(JointType::mouse, ceiling, c2);
    // A rigid weld to a body that cannot turn gives its point only.
    const int32_t slider = l.body(BodyType::dynamic, true, false);
    const int32_t fixed_turn_weld = l.joint(JointType::weld, ceiling, slider);

    JointTrees trees;
    trees.build(l.constraints, l.joints, l.bodies, l.states, true);
    I2D_CHECK(all_exact(l, hung, 4));
    I2D_CHECK(all_exact(l, free_tree, 2, 0));
    I2D_CHECK(all_exact(l, bridge, 3));
    I2D_CHECK(all_exact(l, loop, 4));
    I2D_CHECK(all_exact(l, grid_first, grid_joints, 0));
    I2D_CHECK(all_exact(l, from_kinematic, 1));
    I2D_CHECK(all_exact(l, from_sleeper, 1));
    I2D_CHECK(l.constraints[std::size_t(weld)].exact_rows == exact_angle_row);
    I2D_CHECK(l.constraints[std::size_t(distance)].exact_rows == 0);
    I2D_CHECK(l.constraints[std::size_t(mouse)].exact_rows == 0);
    I2D_CHECK(l.constraints[std::size_t(fixed_turn_weld)].exact_rows == exact_point_rows);
    // The hung chain with its branch, the bridge, the hung loop, the two single hangers
    // and the two welds: seven trees, two of them with a cut.
    I2D_CHECK(trees.tree_count() == 7);
    I2D_CHECK(trees.cut_count() == 2);

    // The same layout again keeps the marks; the bridge's far end let go leaves it a
    // tree without a cut.
    trees.build(l.constraints, l.joints, l.bodies, l.states, true);
    I2D_CHECK(trees.tree_count() == 7 && trees.cut_count() == 2 && all_exact(l, hung, 4));
    l.joints[l.constraints[std::size_t(bridge + 2)].joint].def.type = JointType::filter;
    trees.build(l.constraints, l.joints, l.bodies, l.states, true);
    I2D_CHECK(all_exact(l, bridge, 2));
    I2D_CHECK(l.constraints[std::size_t(bridge + 2)].exact_rows == 0);
    I2D_CHECK(trees.tree_count() == 7 && trees.cut_count() == 1);
}

// Without a hold nothing is exact, whether the trees find that in their grouping (free
// groups only) or are told so (may_hold false), and the marks a build with trees left are
// cleared. Told so, the trees read nothing, so the next build with a hold does not take
// the key it last built for as still standing: the marks come back.
I2D_TEST(unit_joint_trees_without_a_hold_clear_their_marks_and_build_again_after) {
    Layout l;
    const int32_t ceiling = l.body(BodyType::static_body);
    const int32_t hung = chain(l, {ceiling, l.dynamic(), l.dynamic()});
    const int32_t free_tree = chain(l, {l.dynamic(), l.dynamic(), l.dynamic()});
    JointTrees trees;
    trees.build(l.constraints, l.joints, l.bodies, l.states, true);
    I2D_CHECK(trees.tree_count() == 1 && all_exact(l, hung, 2) && all_exact(l, free_tree, 2, 0));

    trees.build(l.constraints, l.joints, l.bodies, l.states, false);
    I2D_CHECK(trees.tree_count() == 0 && trees.cut_count() == 0);
    I2D_CHECK(all_exact(l, hung, 2, 0) && all_exact(l, free_tree, 2, 0));
    trees.build(l.constraints, l.joints, l.bodies, l.states, true);
    I2D_CHECK(trees.tree_count() == 1 && all_exact(l, hung, 2));

    // The hung chain's hold let go: only free groups are left, found by the grouping.
    l.joints[l.constraints[std::size_t(hung)].joint].def.type = JointType::filter;
    trees.build(l.constraints, l.joints, l.bodies, l.states, true);
    I2D_CHECK(trees.tree_count() == 0 && trees.cut_count() == 0);
    I2D_CHECK(all_exact(l, hung, 2, 0) && all_exact(l, free_tree, 2, 0));
}
