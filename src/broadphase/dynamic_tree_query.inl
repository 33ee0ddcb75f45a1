// SPDX-License-Identifier: MIT
// DynamicTree's traversals, templated on the visitor so that the per-leaf call inlines.
#pragma once

#include "core/assert.hpp"
#include "core/force_inline.hpp"
#include "core/growable_stack.hpp"

namespace i2d {

// Depth first, second child first. A node's children are tested before anything is
// pushed, so the stack holds only nodes known to overlap the box, and the overlapping
// second child is taken at once rather than through the stack; the visits come in the
// order a plain stack traversal gives.
template <class Visit>
void DynamicTree::query(const AABB& box, Visit&& visit) const {
    I2D_ASSERT(answers_queries());
    if (root_ == null_index || !overlaps(nodes_[root_].aabb, box)) {
        return;
    }
    GrowableStack<int32_t, 256> stack;
    int32_t index = root_;
    for (;;) {
        const TreeNode& node = nodes_[index];
        if (node.is_leaf()) {
            if (!visit(node.proxy(), node.user_value())) {
                return;
            }
        } else {
            const int32_t first = node.child1(), second = node.child2();
            const TreeNode& a = nodes_[first];
            const TreeNode& b = nodes_[second];
            const bool first_overlaps = overlaps(a.aabb, box), second_overlaps = overlaps(b.aabb, box);
            if (first_overlaps) {
                if (!second_overlaps) {
                    index = first;
                    continue;
                }
                // Asked for now: by the time the stack returns to it its children are in cache.
                if (!a.is_leaf()) {
                    prefetch_node(a.child1());
                    prefetch_node(a.child2());
                }
                stack.push(first);
            }
            if (second_overlaps) {
                index = second;
                continue;
            }
        }
        if (stack.empty()) {
            return;
        }
        index = stack.pop();
    }
}

// Inlined: called, it took the search's leaf visits out of line with it.
template <class Push>
I2D_FORCE_INLINE void DynamicTree::expand_pair(TreeNodePair pair, Push&& push, bool moved_only) const {
    const auto searches = [this, moved_only](int32_t a, int32_t b) { return !moved_only || holds_moved_leaf(a, b); };
    const TreeNode& a = nodes_[pair.a];
    if (pair.a == pair.b) {
        if (a.is_leaf()) {
            return;
        }
        const int32_t first = a.child1(), second = a.child2();
        if (!nodes_[first].is_leaf() && searches(first, first)) {
            push(TreeNodePair{first, first});
        }
        if (!nodes_[second].is_leaf() && searches(second, second)) {
            push(TreeNodePair{second, second});
        }
        if (searches(first, second) && overlaps(nodes_[first].aabb, nodes_[second].aabb)) {
            push(TreeNodePair{first, second});
        }
        return;
    }
    const TreeNode& b = nodes_[pair.b];
    if (!a.is_leaf() && !b.is_leaf()) {
        for (const int32_t child_a : {a.child1(), a.child2()}) {
            for (const int32_t child_b : {b.child1(), b.child2()}) {
                if (searches(child_a, child_b) && overlaps(nodes_[child_a].aabb, nodes_[child_b].aabb)) {
                    push(TreeNodePair{child_a, child_b});
                }
            }
        }
    } else if (!a.is_leaf()) {
        for (const int32_t child : {a.child1(), a.child2()}) {
            if (searches(child, pair.b) && overlaps(nodes_[child].aabb, b.aabb)) {
                push(TreeNodePair{child, pair.b});
            }
        }
    } else {
        for (const int32_t child : {b.child1(), b.child2()}) {
            if (searches(pair.a, child) && overlaps(a.aabb, nodes_[child].aabb)) {
                push(TreeNodePair{pair.a, child});
            }
        }
    }
}

// Depth first over node pairs. A pair is taken only once its two boxes are known to
// overlap, and two overlapping leaves are reported as they are found rather than pushed.
template <class Visit>
void DynamicTree::self_overlaps(TreeNodePair part, Visit&& visit) const {
    const auto report = [&](int32_t a, int32_t b) {
        visit(nodes_[a].proxy(), nodes_[a].user_value(), nodes_[b].proxy(), nodes_[b].user_value());
    };
    if (!holds_moved_leaf(part.a, part.b)) {
        return;
    }
    if (is_leaf_pair(part)) {
        report(part.a, part.b);
        return;
    }
    GrowableStack<TreeNodePair, 256> stack;
    const auto take = [&](TreeNodePair pair) {
        if (is_leaf_pair(pair)) {
            report(pair.a, pair.b);
        } else {
            stack.push(pair);
        }
    };
    TreeNodePair pair = part;
    for (;;) {
        expand_pair(pair, take, true);
        if (stack.empty()) {
            return;
        }
        pair = stack.pop();
    }
}

template <class Visit>
void DynamicTree::query(const AABB& box, uint64_t mask_bits, Visit&& visit) const {
    I2D_ASSERT(answers_queries());
    query(box, [&](int32_t proxy, int32_t user_value) {
        return (proxy_categories_[proxy] & mask_bits) == 0 || visit(proxy, user_value);
    });
}

namespace tree_detail {

// Does the segment origin + t d, t in [0, max_t], touch the box? Slab test, inclusive.
inline bool segment_touches(Vec2 origin, Vec2 d, float max_t, const AABB& box) {
    float t_min = 0.0f, t_max = max_t;
    const float o[2] = {origin.x, origin.y}, dir[2] = {d.x, d.y};
    const float lo[2] = {box.lower.x, box.lower.y}, hi[2] = {box.upper.x, box.upper.y};
    for (int axis = 0; axis < 2; ++axis) {
        if (dir[axis] == 0.0f) {
            if (o[axis] < lo[axis] || o[axis] > hi[axis]) {
                return false;
            }
            continue;
        }
        const float inv = 1.0f / dir[axis];
        float t1 = (lo[axis] - o[axis]) * inv, t2 = (hi[axis] - o[axis]) * inv;
        if (t1 > t2) {
            const float tmp = t1;
            t1 = t2, t2 = tmp;
        }
        t_min = t1 > t_min ? t1 : t_min;
        t_max = t2 < t_max ? t2 : t_max;
        if (t_min > t_max) {
            return false;
        }
    }
    return true;
}

}  // namespace tree_detail

template <class Visit>
void DynamicTree::ray_cast(const TreeRayInput& input, uint64_t mask_bits, Visit&& visit) const {
    I2D_ASSERT(answers_queries());
    if (root_ == null_index) {
        return;
    }
    TreeRayInput current = input;
    GrowableStack<int32_t, 256> stack;
    stack.push(root_);
    while (!stack.empty()) {
        const int32_t index = stack.pop();
        const TreeNode& node = nodes_[index];
        if (!tree_detail::segment_touches(current.origin, current.translation, current.max_fraction, node.aabb)) {
            continue;
        }
        if (!node.is_leaf()) {
            stack.push(node.child1());
            stack.push(node.child2());
            continue;
        }
        if ((proxy_categories_[node.proxy()] & mask_bits) == 0) {
            continue;
        }
        const float value = visit(static_cast<const TreeRayInput&>(current), node.proxy(), node.user_value());
        if (value == 0.0f) {
            return;
        }
        if (value > 0.0f && value < current.max_fraction) {
            current.max_fraction = value;  // clip: farther boxes are skipped from now on
        }
    }
}

}  // namespace i2d
