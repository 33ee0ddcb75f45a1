// SPDX-License-Identifier: MIT
// DynamicTree: insertion by surface-area heuristic, removal, rotations, checks.
#include "broadphase/dynamic_tree.hpp"

#include <algorithm>
#include <cfloat>

#include "core/assert.hpp"

namespace i2d {

int32_t DynamicTree::create_proxy(const AABB& fat_aabb, uint64_t category_bits, int32_t user_value) {
    // Room for the proxy table first (growing geometrically), so that a bad_alloc
    // changes nothing and destroy_proxy never allocates.
    if (free_proxies_.empty() && proxy_nodes_.size() == proxy_nodes_.capacity()) {
        const size_t capacity = proxy_nodes_.capacity() < 16 ? 16 : 2 * proxy_nodes_.capacity();
        proxy_nodes_.reserve(capacity);
        proxy_categories_.reserve(capacity);
        free_proxies_.reserve(capacity);
    }
    rebuild_grown();  // insertions assume exact boxes
    const int32_t leaf = allocate_node();
    int32_t proxy;
    if (free_proxies_.empty()) {
        proxy = int32_t(proxy_nodes_.size());
        proxy_nodes_.push_back(leaf);
        proxy_categories_.push_back(category_bits);
    } else {
        proxy = free_proxies_.back();
        free_proxies_.pop_back();
        proxy_nodes_[proxy] = leaf;
        proxy_categories_[proxy] = category_bits;
    }
    TreeNode& node = nodes_[leaf];
    node.aabb = fat_aabb;
    node.user_value() = user_value;
    node.proxy() = proxy;
    node.height = 0;
    insert_leaf(leaf, root_);
    ++proxy_count_;
    return proxy;
}

void DynamicTree::destroy_proxy(int32_t proxy) {
    rebuild_grown();
    const int32_t leaf = proxy_nodes_[proxy];
    I2D_ASSERT(nodes_[leaf].is_leaf() && nodes_[leaf].height == 0);
    remove_leaf(leaf);
    free_node(leaf);
    proxy_nodes_[proxy] = null_index;
    free_proxies_.push_back(proxy);
    --proxy_count_;
}

void DynamicTree::move_proxy(int32_t proxy, const AABB& fat_aabb) {
    move_proxy_at(proxy_nodes_[proxy], fat_aabb);
}

// Most moves are short: the leaf goes back in below the lowest former ancestor that
// still contains its new box, not from the root, which keeps the walk local.
void DynamicTree::move_proxy_at(int32_t leaf, const AABB& fat_aabb) {
    I2D_ASSERT(nodes_[leaf].is_leaf());
    rebuild_grown();
    const int32_t parent = nodes_[leaf].parent;
    if (parent != null_index && contains(nodes_[parent].aabb, fat_aabb)) {
        // Still inside its parent (one move in five): it keeps its sibling, and only
        // boxes that shrink change above it.
        nodes_[leaf].aabb = fat_aabb;
        refit_upward(parent, false);
        return;
    }
    int32_t start = remove_leaf(leaf);
    while (start != null_index && !contains(nodes_[start].aabb, fat_aabb)) {
        start = nodes_[start].parent;
    }
    nodes_[leaf].aabb = fat_aabb;
    insert_leaf(leaf, start == null_index ? root_ : start);
    ++moves_since_compact_;
}

void DynamicTree::enlarge_proxy(int32_t proxy, const AABB& fat_aabb) {
    rebuild_grown();
    const int32_t leaf = proxy_nodes_[proxy];
    I2D_ASSERT(contains(fat_aabb, nodes_[leaf].aabb));
    nodes_[leaf].aabb = fat_aabb;
    // Ancestors grow until one already holds the new box; above it nothing changes.
    for (int32_t index = nodes_[leaf].parent; index != null_index; index = nodes_[index].parent) {
        if (contains(nodes_[index].aabb, fat_aabb)) {
            break;
        }
        nodes_[index].aabb = union_of(nodes_[index].aabb, fat_aabb);
    }
}

// As move_proxy_in_place_at marks: up to the first ancestor marked already, whose own
// ancestors are. Clearing walks the same paths and stops where an earlier leaf's walk cleared.
void DynamicTree::mark_moved(int32_t proxy) {
    const int32_t leaf = proxy_nodes_[std::size_t(proxy)];
    I2D_ASSERT(leaf != null_index && nodes_[leaf].is_leaf());
    moved_leaves_.push_back(leaf);
    set_flag_up_from(leaf, &TreeNode::moved_below, true);
}

void DynamicTree::clear_moved_marks() {
    for (const int32_t leaf : moved_leaves_) {
        set_flag_up_from(leaf, &TreeNode::moved_below, false);
    }
    moved_leaves_.clear();
}

// Every ancestor is marked, so that the rebuild finds each marked node by descending from
// the root through marked nodes alone; marking stops at a marked ancestor, whose own
// ancestors are marked already. The rebuild frees the marked nodes and makes their boxes
// anew, so they are not grown here: in the tumbler, where nearly every leaf moves each
// step, growing each path to the root was 2.5 % of the step.
void DynamicTree::move_proxy_in_place_at(int32_t leaf, const AABB& fat_aabb) {
    I2D_ASSERT(nodes_[leaf].is_leaf());
    nodes_[leaf].aabb = fat_aabb;
    set_flag_up_from(nodes_[leaf].parent, &TreeNode::grown, true);
}

// Branch and bound down one path: the cost of making node X the new leaf's sibling is
// the perimeter of X grown by the leaf plus how much every ancestor of X grows (the
// "inherited" cost). Descending into a child can never cost less than the inherited
// cost plus the child's own growth plus the leaf's perimeter, which prunes the search.
// The search may start below the root at a node that already contains the box: nothing
// above it grows, so the costs inside it compare the same as from the root.
// The same box inserted again and again (bodies made at one spot, or made at the origin
// and then placed) leaves the surface-area heuristic indifferent: a node whose box is the
// inserted box costs the same as anything below it. Taking that node made each insertion
// its sibling, a chain as deep as the boxes are many, through which every later removal
// refits: placing 16,000 bodies made at the origin took 0.77 s, and destroying half of
// 16,000 at one spot 0.27 s. So from such a node the search goes on down, always into the
// lower child, to a leaf, which keeps those boxes in a balanced subtree (9 ms and 1.4 ms).
// Boxes that differ by a bit are placed as before: the pairs, and every scene's bits, are
// unchanged.
int32_t DynamicTree::find_best_sibling(const AABB& box, int32_t start) const {
    const float box_perimeter = perimeter(box);
    int32_t best = start;
    float best_cost = perimeter(union_of(nodes_[start].aabb, box));
    float inherited = 0.0f;
    int32_t index = start;
    while (!nodes_[index].is_leaf()) {
        const TreeNode& node = nodes_[index];
        inherited += perimeter(union_of(node.aabb, box)) - perimeter(node.aabb);

        float descend_bound[2] = {FLT_MAX, FLT_MAX};
        const int32_t children[2] = {node.child1(), node.child2()};
        prefetch_node(children[0]);
        prefetch_node(children[1]);
        for (int k = 0; k < 2; ++k) {
            const TreeNode& child = nodes_[children[k]];
            const float direct = perimeter(union_of(child.aabb, box));
            const float cost = direct + inherited;
            if (cost < best_cost) {
                best_cost = cost;
                best = children[k];
            }
            if (!child.is_leaf()) {
                descend_bound[k] = inherited + (direct - perimeter(child.aabb)) + box_perimeter;
            }
        }
        const int k = descend_bound[0] <= descend_bound[1] ? 0 : 1;
        if (descend_bound[k] >= best_cost) {
            break;
        }
        index = children[k];
    }
    while (!nodes_[best].is_leaf() && nodes_[best].aabb.lower == box.lower && nodes_[best].aabb.upper == box.upper) {
        const TreeNode& twin = nodes_[best];
        best = nodes_[twin.child1()].height <= nodes_[twin.child2()].height ? twin.child1() : twin.child2();
    }
    return best;
}

void DynamicTree::insert_leaf(int32_t leaf, int32_t start) {
    if (root_ == null_index) {
        root_ = leaf;
        nodes_[leaf].parent = null_index;
        return;
    }
    const int32_t sibling = find_best_sibling(nodes_[leaf].aabb, start);
    const int32_t old_parent = nodes_[sibling].parent;
    const int32_t new_parent = allocate_node();  // may move nodes_: index from here on

    TreeNode& parent = nodes_[new_parent];
    parent.parent = old_parent;
    parent.aabb = union_of(nodes_[leaf].aabb, nodes_[sibling].aabb);
    parent.height = int16_t(nodes_[sibling].height + 1);
    parent.child1() = sibling;
    parent.child2() = leaf;
    if (old_parent == null_index) {
        root_ = new_parent;
    } else if (nodes_[old_parent].child1() == sibling) {
        nodes_[old_parent].child1() = new_parent;
    } else {
        nodes_[old_parent].child2() = new_parent;
    }
    nodes_[sibling].parent = new_parent;
    nodes_[leaf].parent = new_parent;
    refit_upward(old_parent, true);
}

int32_t DynamicTree::remove_leaf(int32_t leaf) {
    if (leaf == root_) {
        root_ = null_index;
        return null_index;
    }
    const int32_t parent = nodes_[leaf].parent;
    const int32_t grand = nodes_[parent].parent;
    const int32_t sibling = nodes_[parent].child1() == leaf ? nodes_[parent].child2() : nodes_[parent].child1();
    if (grand == null_index) {
        root_ = sibling;
        nodes_[sibling].parent = null_index;
    } else {
        if (nodes_[grand].child1() == parent) {
            nodes_[grand].child1() = sibling;
        } else {
            nodes_[grand].child2() = sibling;
        }
        nodes_[sibling].parent = grand;
        refit_upward(grand, false);
    }
    free_node(parent);
    nodes_[leaf].parent = null_index;
    return grand == null_index ? sibling : grand;
}

// Stops at the first ancestor that comes out unchanged (same box, height, no
// rotation): everything above it depends only on it.
void DynamicTree::refit_upward(int32_t index, bool rotate_nodes) {
    while (index != null_index) {
        TreeNode& node = nodes_[index];
        const TreeNode& c1 = nodes_[node.child1()];
        const TreeNode& c2 = nodes_[node.child2()];
        const AABB box = union_of(c1.aabb, c2.aabb);
        const int16_t height = int16_t(1 + std::max(c1.height, c2.height));
        bool changed = !(box.lower == node.aabb.lower && box.upper == node.aabb.upper) || height != node.height;
        node.aabb = box;
        node.height = height;
        if (rotate_nodes && rotate(index)) {
            changed = true;
        }
        if (!changed) {
            return;
        }
        index = nodes_[index].parent;
    }
}

// Tree rotation by perimeter: for node A with children B and C, try swapping B with a
// child of C, or C with a child of B, and apply the swap that shrinks the perimeter of
// the rebuilt child the most. A's own box is the same afterwards (same leaves).
bool DynamicTree::rotate(int32_t a) {
    const int32_t b = nodes_[a].child1(), c = nodes_[a].child2();
    struct Swap {
        int32_t outer;  // the child of A that moves down
        int32_t inner;  // the grandchild that moves up
        int32_t host;   // the child of A that receives `outer`
        float gain;
    } best{null_index, null_index, null_index, 0.0f};

    auto consider = [&](int32_t outer, int32_t host) {
        const TreeNode& h = nodes_[host];
        if (h.is_leaf()) {
            return;
        }
        const float before = perimeter(h.aabb);
        // Swap outer with host.child1(): host then holds outer and host.child2(), and vice versa.
        const float after1 = perimeter(union_of(nodes_[outer].aabb, nodes_[h.child2()].aabb));
        const float after2 = perimeter(union_of(nodes_[outer].aabb, nodes_[h.child1()].aabb));
        if (before - after1 > best.gain) {
            best = {outer, h.child1(), host, before - after1};
        }
        if (before - after2 > best.gain) {
            best = {outer, h.child2(), host, before - after2};
        }
    };
    consider(b, c);
    consider(c, b);
    if (best.outer == null_index) {
        return false;
    }

    TreeNode& host = nodes_[best.host];
    if (host.child1() == best.inner) {
        host.child1() = best.outer;
    } else {
        host.child2() = best.outer;
    }
    nodes_[best.outer].parent = best.host;
    TreeNode& node = nodes_[a];
    if (node.child1() == best.outer) {
        node.child1() = best.inner;
    } else {
        node.child2() = best.inner;
    }
    nodes_[best.inner].parent = a;

    const TreeNode& h1 = nodes_[host.child1()];
    const TreeNode& h2 = nodes_[host.child2()];
    host.aabb = union_of(h1.aabb, h2.aabb);
    host.height = int16_t(1 + std::max(h1.height, h2.height));
    node.height = int16_t(1 + std::max(nodes_[node.child1()].height, nodes_[node.child2()].height));
    return true;
}

void DynamicTree::shift_origin(Vec2 new_origin) {
    for (TreeNode& node : nodes_) {
        if (node.height >= 0) {  // a free node's box means nothing
            node.aabb = relative_to(node.aabb, new_origin);
        }
    }
}

float DynamicTree::total_perimeter() const {
    float total = 0.0f;
    for (const TreeNode& node : nodes_) {
        if (node.height > 0) {
            total += perimeter(node.aabb);
        }
    }
    return total;
}

void DynamicTree::validate() const {
#if defined(I2D_VALIDATE)
    int32_t leaves = 0, live = 0;
    for (int32_t i = 0; i < int32_t(nodes_.size()); ++i) {
        const TreeNode& n = nodes_[i];
        if (n.height < 0) {
            continue;
        }
        ++live;
        I2D_ASSERT(n.parent == null_index ? i == root_ : nodes_[n.parent].child1() == i || nodes_[n.parent].child2() == i);
        if (n.is_leaf()) {
            I2D_ASSERT(proxy_nodes_[n.proxy()] == i);
            ++leaves;
            continue;
        }
        const TreeNode& c1 = nodes_[n.child1()];
        const TreeNode& c2 = nodes_[n.child2()];
        I2D_ASSERT(c1.parent == i && c2.parent == i);
        I2D_ASSERT(n.height == 1 + std::max(c1.height, c2.height));
        // Exactly the union, not just containing it: a box left loose costs every query.
        // A node marked for the rebuild holds a box of before the moves (the rebuild makes
        // it anew), and its parent is marked too.
        const AABB both = union_of(c1.aabb, c2.aabb);
        I2D_ASSERT(n.grown || (n.aabb.lower == both.lower && n.aabb.upper == both.upper));
        I2D_ASSERT(!n.grown || n.parent == null_index || nodes_[n.parent].grown);
    }
    I2D_ASSERT(leaves == proxy_count_);
    int32_t free_count = 0;
    for (int32_t i = free_list_; i != null_index; i = nodes_[i].parent) {
        I2D_ASSERT(nodes_[i].height == -1);
        ++free_count;
    }
    I2D_ASSERT(live + free_count == int32_t(nodes_.size()));
    int32_t mapped = 0;
    for (int32_t proxy = 0; proxy < int32_t(proxy_nodes_.size()); ++proxy) {
        const int32_t leaf = proxy_nodes_[proxy];
        if (leaf != null_index) {
            I2D_ASSERT(nodes_[leaf].height == 0 && nodes_[leaf].proxy() == proxy);
            ++mapped;
        }
    }
    I2D_ASSERT(mapped == proxy_count_);
#endif
}

}  // namespace i2d
