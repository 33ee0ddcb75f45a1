// SPDX-License-Identifier: MIT
// DynamicTree: rebuilding (whole, or what grew) top-down by binned surface-area heuristic,
// and laying the nodes out in preorder.
#include <algorithm>
#include <cfloat>

#include "broadphase/dynamic_tree.hpp"
#include "core/assert.hpp"

namespace i2d {

namespace {

constexpr int32_t bin_count = 16;
// Beyond this depth the build halves the spread of the centres instead of asking the
// SAH, which bounds the depth whatever the geometry.
constexpr int32_t max_sah_depth = 40;

}  // namespace

void DynamicTree::rebuild() {
    for (TreeNode& node : nodes_) {
        node.grown = node.height > 0;
    }
    if (root_ != null_index && nodes_[root_].grown) {
        collect_marked();
        build_compacted(Split::sah);
    } else {
        compact();
    }
}

int32_t DynamicTree::rebuild_grown() { return rebuild_marked(Split::midpoint); }

// Where most leaves moved (the tumbler, a rain of bodies) the rebuild is due every step
// and so is the compaction after it, which copied every node once more: when both are
// due, the build writes the nodes where compaction would have put them. The same tree,
// the same array, one pass fewer.
void DynamicTree::commit_in_place_moves() {
    if (root_ != null_index && nodes_[root_].grown) {
        collect_marked();
        const int32_t built = int32_t(build_items_.size()) - 1;
        if (scattered(moves_since_compact_ + built)) {
            build_compacted(Split::midpoint);
            return;
        }
        finish_build(Split::midpoint);
    }
    if (scattered(moves_since_compact_)) {
        compact();
    }
}

// Once a quarter of a tree has been rebuilt or re-inserted its nodes are scattered again;
// the O(n) compaction is then cheaper than the cache misses it saves.
bool DynamicTree::scattered(int32_t moves) const { return proxy_count_ > 0 && 4 * moves > proxy_count_; }

// Level by level from the root with itself: each round expands every part that is not a
// single leaf pair, keeping the order, until there are enough parts or none can expand.
void DynamicTree::split_self_overlaps(int32_t target, std::vector<TreeNodePair>& out) {
    out.clear();
    I2D_ASSERT(answers_queries());
    if (root_ == null_index) {
        return;
    }
    out.push_back({root_, root_});
    std::vector<TreeNodePair>& next = split_scratch_;
    bool expanded = true;
    while (expanded && int32_t(out.size()) < target) {
        expanded = false;
        next.clear();
        for (const TreeNodePair pair : out) {
            if (is_leaf_pair(pair)) {
                next.push_back(pair);
            } else {
                expand_pair(pair, [&](TreeNodePair child) { next.push_back(child); });
                expanded = true;
            }
        }
        out.swap(next);
    }
}

int32_t DynamicTree::rebuild_marked(Split rule) {
    if (root_ == null_index || !nodes_[root_].grown) {
        return 0;
    }
    collect_marked();
    return finish_build(rule);
}

// The marked nodes are freed; what hangs below them unmarked (leaves, and subtrees no
// moved leaf reached) becomes the items of one build.
void DynamicTree::collect_marked() {
    build_items_.clear();
    collect_stack_.clear();
    collect_stack_.push_back(root_);
    while (!collect_stack_.empty()) {
        const int32_t index = collect_stack_.back();
        collect_stack_.pop_back();
        TreeNode& node = nodes_[index];
        if (node.grown) {
            collect_stack_.push_back(node.child2());
            collect_stack_.push_back(node.child1());
            free_node(index);
        } else {
            node.parent = null_index;
            build_items_.push_back({node.aabb, center(node.aabb), index, 0});
        }
    }
}

// The collected items built in place of the freed nodes; returns how many it made.
int32_t DynamicTree::finish_build(Split rule) {
    root_ = build_top_down(rule);
    nodes_[root_].parent = null_index;
    const int32_t built = int32_t(built_nodes_.size());
    moves_since_compact_ += built;
    return built;
}

// Preorder: a node, then its whole first subtree, then its second, so every subtree is
// one contiguous run of the array and a traversal reads memory mostly forwards.
void DynamicTree::compact() {
    rebuild_grown();
    compact_scratch_.clear();
    compact_scratch_.reserve(size_t(2 * proxy_count_));
    if (root_ != null_index) {
        copy_in_preorder(root_, null_index);
        root_ = 0;
    }
    adopt_compacted();
}

// Appends the subtree below `old_root` to compact_scratch_ in preorder, its root a child
// of `new_parent` there (the first child if placed right after it). Each stacked node
// carries its new parent, so links are set as nodes are placed: no second pass through
// the old array to translate indices.
void DynamicTree::copy_in_preorder(int32_t old_root, int32_t new_parent) {
    compact_stack_.clear();
    compact_stack_.push_back({old_root, new_parent});
    while (!compact_stack_.empty()) {
        const CompactItem item = compact_stack_.back();
        compact_stack_.pop_back();
        const int32_t new_index = int32_t(compact_scratch_.size());
        compact_scratch_.push_back(nodes_[item.old_index]);
        TreeNode& node = compact_scratch_.back();
        link_placed(new_index, item.new_parent);
        if (node.is_leaf()) {
            proxy_nodes_[node.proxy()] = new_index;
        } else {
            compact_stack_.push_back({node.child2(), new_index});
            compact_stack_.push_back({node.child1(), new_index});
        }
    }
}

// A node just placed in compact_scratch_ at `index` and its parent there: in preorder the
// first child comes right after its parent.
void DynamicTree::link_placed(int32_t index, int32_t parent) {
    compact_scratch_[std::size_t(index)].parent = parent;
    if (parent != null_index) {
        TreeNode& p = compact_scratch_[std::size_t(parent)];
        (index == parent + 1 ? p.child1() : p.child2()) = index;
    }
}

// The compacted array becomes the tree: no free nodes, nothing scattered.
void DynamicTree::adopt_compacted() {
    nodes_.swap(compact_scratch_);
    free_list_ = null_index;
    moves_since_compact_ = 0;
    validate();
}

// build_top_down's tree written straight into compact_scratch_ in preorder, as compact()
// would lay it out: the build already makes a node before its first subtree and that
// before its second, so each item (a leaf, or a subtree no moved leaf reached, copied
// whole) and each new node takes the next place.
void DynamicTree::build_compacted(Split rule) {
    compact_scratch_.clear();
    compact_scratch_.reserve(size_t(2 * proxy_count_));  // no reallocation: split_items writes into it
    built_nodes_.clear();
    build_tasks_.clear();
    build_tasks_.push_back({0, int32_t(build_items_.size()), null_index, 0, true});
    while (!build_tasks_.empty()) {
        const BuildTask task = build_tasks_.back();
        build_tasks_.pop_back();
        if (task.end - task.begin == 1) {
            copy_in_preorder(build_items_[std::size_t(task.begin)].node, task.parent);
            continue;
        }
        const int32_t index = int32_t(compact_scratch_.size());
        compact_scratch_.emplace_back();
        built_nodes_.push_back(index);
        const int32_t split = split_items(task.begin, task.end, task.depth, rule);
        link_placed(index, task.parent);
        build_tasks_.push_back({split, task.end, index, task.depth + 1, false});
        build_tasks_.push_back({task.begin, split, index, task.depth + 1, true});
    }
    set_built_boxes_and_heights(compact_scratch_);
    root_ = 0;
    adopt_compacted();
}

// Each made node's box and height from its children's, children first (the nodes were
// made parents first). The union of the children's boxes is the union of the node's
// items' boxes, bit for bit (a minimum and a maximum are exact in any order): unions made
// here, once per node, rather than in split_items over every item of every level.
void DynamicTree::set_built_boxes_and_heights(std::vector<TreeNode>& nodes) const {
    for (auto it = built_nodes_.rbegin(); it != built_nodes_.rend(); ++it) {
        TreeNode& n = nodes[std::size_t(*it)];
        const TreeNode& c1 = nodes[std::size_t(n.child1())];
        const TreeNode& c2 = nodes[std::size_t(n.child2())];
        n.aabb = union_of(c1.aabb, c2.aabb);
        n.height = int16_t(1 + std::max(c1.height, c2.height));
    }
}

// Top-down over build_items_, depth first: each internal node is made before its
// children, so the heights come right in one pass over the made nodes in reverse.
int32_t DynamicTree::build_top_down(Split rule) {
    built_nodes_.clear();
    build_tasks_.clear();
    build_tasks_.push_back({0, int32_t(build_items_.size()), null_index, 0, true});
    int32_t root = null_index;
    while (!build_tasks_.empty()) {
        const BuildTask task = build_tasks_.back();
        build_tasks_.pop_back();
        int32_t node;
        if (task.end - task.begin == 1) {
            node = build_items_[std::size_t(task.begin)].node;
        } else {
            node = allocate_node();
            built_nodes_.push_back(node);
            const int32_t split = split_items(task.begin, task.end, task.depth, rule);
            build_tasks_.push_back({split, task.end, node, task.depth + 1, false});
            build_tasks_.push_back({task.begin, split, node, task.depth + 1, true});
        }
        if (task.parent == null_index) {
            root = node;
        } else {
            (task.first_child ? nodes_[task.parent].child1() : nodes_[task.parent].child2()) = node;
            nodes_[node].parent = task.parent;
        }
    }
    set_built_boxes_and_heights(nodes_);
    return root;
}

namespace {

constexpr AABB empty_box{{FLT_MAX, FLT_MAX}, {-FLT_MAX, -FLT_MAX}};

}  // namespace

// Along the axis where the items' centres spread most, binned SAH over the centres (the
// split that minimises perimeter(left) * count(left) + perimeter(right) * count(right))
// or the middle of the spread. Partitions [begin, end) and returns where the second half
// starts.
int32_t DynamicTree::split_items(int32_t begin, int32_t end, int32_t depth, Split rule) {
    BuildItem* items = build_items_.data();
    const int32_t count = end - begin;
    AABB centres{items[begin].centre, items[begin].centre};
    for (int32_t i = begin + 1; i < end; ++i) {
        centres.lower = min(centres.lower, items[i].centre);
        centres.upper = max(centres.upper, items[i].centre);
    }
    if (count == 2) {
        return begin + 1;
    }
    const bool split_x = centres.upper.x - centres.lower.x >= centres.upper.y - centres.lower.y;
    const float lo = split_x ? centres.lower.x : centres.lower.y;
    const float extent = split_x ? centres.upper.x - centres.lower.x : centres.upper.y - centres.lower.y;
    const auto coord = [split_x](const BuildItem& item) { return split_x ? item.centre.x : item.centre.y; };
    if (rule == Split::sah && extent > 0.0f && depth < max_sah_depth) {
        const float scale = float(bin_count) / extent;
        AABB bin_box[bin_count];
        int32_t bin_n[bin_count] = {};
        for (int32_t b = 0; b < bin_count; ++b) {
            bin_box[b] = empty_box;
        }
        for (int32_t i = begin; i < end; ++i) {
            const int32_t b = std::min(int32_t(scale * (coord(items[i]) - lo)), bin_count - 1);
            items[i].bin = b;
            bin_box[b] = union_of(bin_box[b], items[i].box);
            ++bin_n[b];
        }
        // Sweep from the right to know every right side's cost, then from the left.
        float right_cost[bin_count] = {};
        AABB acc = empty_box;
        int32_t acc_n = 0;
        for (int32_t b = bin_count - 1; b > 0; --b) {
            acc = union_of(acc, bin_box[b]);
            acc_n += bin_n[b];
            right_cost[b] = acc_n == 0 ? 0.0f : perimeter(acc) * float(acc_n);
        }
        float best_cost = FLT_MAX;
        int32_t best_bin = -1;
        acc = empty_box;
        acc_n = 0;
        for (int32_t b = 0; b < bin_count - 1; ++b) {
            acc = union_of(acc, bin_box[b]);
            acc_n += bin_n[b];
            if (acc_n == 0 || acc_n == count) {
                continue;
            }
            const float cost = perimeter(acc) * float(acc_n) + right_cost[b + 1];
            if (cost < best_cost) {
                best_cost = cost;
                best_bin = b;
            }
        }
        if (best_bin >= 0) {
            return partition_items(begin, end, [best_bin](const BuildItem& item) { return item.bin <= best_bin; });
        }
    }
    // The midpoint of the centres' spread: cheap, and it bounds the depth whatever the
    // geometry (boxes piled on one spot give the SAH nothing to separate).
    const float middle = lo + 0.5f * extent;
    const int32_t split = partition_items(begin, end, [&](const BuildItem& item) { return coord(item) <= middle; });
    return split == begin || split == end ? begin + count / 2 : split;
}

// The standard library's partition may order items differently from one library to the
// next, and the order shapes the tree and so the pairs; this one is the same everywhere.
template <class Left>
int32_t DynamicTree::partition_items(int32_t begin, int32_t end, Left&& left) {
    BuildItem* items = build_items_.data();
    int32_t i = begin, j = end - 1;
    for (;;) {
        while (i <= j && left(items[i])) {
            ++i;
        }
        while (i <= j && !left(items[j])) {
            --j;
        }
        if (i >= j) {
            return i;
        }
        std::swap(items[i], items[j]);
        ++i;
        --j;
    }
}

}  // namespace i2d
