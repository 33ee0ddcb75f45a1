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
        begin_compacted_build(Split::sah, 1);  // one part, built at once
    } else {
        compact();
    }
}

int32_t DynamicTree::rebuild_grown() { return rebuild_marked(Split::midpoint); }

// With one worker the build is one part, which begin_commit builds and finishes itself.
void DynamicTree::commit_in_place_moves() { begin_commit(1); }

// Where most leaves moved (the tumbler, a rain of bodies) the rebuild is due every step
// and so is the compaction after it, which copied every node once more: when both are
// due, the build writes the nodes where compaction would have put them. The same tree,
// the same array, one pass fewer.
int32_t DynamicTree::begin_commit(int32_t worker_count) {
    if (root_ != null_index && nodes_[root_].grown) {
        collect_marked();
        const int32_t built = int32_t(build_items_.size()) - 1;
        if (scattered(moves_since_compact_ + built)) {
            return begin_compacted_build(Split::midpoint, worker_count);
        }
        finish_build(Split::midpoint);
    }
    if (scattered(moves_since_compact_)) {
        compact();
    }
    return 0;
}

// Once a quarter of a tree has been rebuilt or re-inserted its nodes are scattered again;
// the O(n) compaction is then cheaper than the cache misses it saves.
bool DynamicTree::scattered(int32_t moves) const { return proxy_count_ > 0 && 4 * moves > proxy_count_; }

// Level by level from the root with itself: each round expands every part that is not a
// single leaf pair, keeping the order, until there are enough parts or none can expand.
void DynamicTree::split_self_overlaps(int32_t target, int32_t max_share, std::vector<TreeNodePair>& out) {
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
    refine_parts(max_share, out);
}

// The level split leaves parts of very unequal weight: a node with itself beside two
// nodes that barely overlap, and a worker that drew the heavy one holds the stage up
// while the other waits. Each part heavier than 1 / max_share of the tree is cut into the
// pairs its own traversal visits, in the order it visits them (its leaf pairs at once,
// then its other pairs, the last pushed first): the leaf pairs come out in the same order
// as from the whole part, so the cut changes no result.
void DynamicTree::refine_parts(int32_t max_share, std::vector<TreeNodePair>& parts) {
    if (parts.empty()) {
        return;
    }
    std::vector<TreeNodePair>& refined = split_scratch_;
    refined.clear();
    const int64_t max_weight = std::max(leaf_weight({root_, root_}) / max_share, min_part_weight);
    for (const TreeNodePair part : parts) {
        refine_part(part, max_weight, refined);
    }
    parts.swap(refined);
}

void DynamicTree::refine_part(TreeNodePair part, int64_t max_weight, std::vector<TreeNodePair>& out) const {
    if (is_leaf_pair(part) || leaf_weight(part) <= max_weight) {
        out.push_back(part);
        return;
    }
    TreeNodePair inner[4];
    int32_t inner_count = 0;
    expand_pair(part, [&](TreeNodePair child) {
        if (is_leaf_pair(child)) {
            out.push_back(child);
        } else {
            inner[inner_count++] = child;
        }
    });
    for (int32_t i = inner_count - 1; i >= 0; --i) {
        refine_part(inner[i], max_weight, out);
    }
}

// About how many leaves a part's search walks: 2^height per node (a balanced tree's;
// heights past 61 count as 61, which keeps the sum in range).
int64_t DynamicTree::leaf_weight(TreeNodePair part) const {
    constexpr int32_t max_counted_height = 61;
    const auto leaves = [&](int32_t node) {
        return int64_t(1) << std::min<int32_t>(nodes_[node].height, max_counted_height);
    };
    return part.a == part.b ? leaves(part.a) : leaves(part.a) + leaves(part.b);
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
            build_items_.push_back({node.aabb, center(node.aabb), index, 0, 0});
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
    compact_scratch_.resize(root_ != null_index ? std::size_t(2 * proxy_count_ - 1) : 0);
    if (root_ != null_index) {
        copy_in_preorder(root_, null_index, 0, compact_stack_);
        root_ = 0;
    }
    adopt_compacted();
}

// Copies the subtree below `old_root` into compact_scratch_ in preorder from `place`, its
// root a child of `new_parent` there; returns the place after it. Each stacked node
// carries its new parent, so links are set as nodes are placed: no second pass through
// the old array to translate indices.
int32_t DynamicTree::copy_in_preorder(int32_t old_root, int32_t new_parent, int32_t place,
                                      std::vector<CompactItem>& stack) {
    stack.clear();
    stack.push_back({old_root, new_parent});
    while (!stack.empty()) {
        const CompactItem item = stack.back();
        stack.pop_back();
        const int32_t new_index = place++;
        TreeNode& node = compact_scratch_[std::size_t(new_index)];
        node = nodes_[item.old_index];
        link_placed(new_index, item.new_parent);
        if (node.is_leaf()) {
            proxy_nodes_[node.proxy()] = new_index;
        } else {
            stack.push_back({node.child2(), new_index});
            stack.push_back({node.child1(), new_index});
        }
    }
    return place;
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
// would lay it out: each node (made, a leaf, or a subtree no moved leaf reached, copied
// whole) takes its place in preorder, the array's size known from the leaf count.
// With more than one worker the top of the tree is built here, each split placing its
// halves by their node counts, and what hangs below is left in parts that build_part
// builds depth first, each from its own place: parts share nothing but their items'
// disjoint ranges and their places, so any worker may build any part, in any order, to
// the same array.
int32_t DynamicTree::begin_compacted_build(Split rule, int32_t worker_count) {
    compact_scratch_.resize(std::size_t(2 * proxy_count_ - 1));
    build_rule_ = rule;
    const int32_t item_count = int32_t(build_items_.size());
    const bool split_up = worker_count > 1 && item_count >= min_items_to_share;
    if (split_up) {
        count_item_nodes();
    }
    build_tasks_.clear();
    build_tasks_.push_back({0, item_count, null_index, 0, true, 0});
    task_nodes_.assign(1, 2 * proxy_count_ - 1);
    top_nodes_.clear();
    // The part with the most nodes is split until there are enough: parts of a size, in
    // nodes rather than items, since an item may be a whole subtree to copy.
    const int32_t target_parts = parts_per_worker * worker_count;
    while (split_up && int32_t(build_tasks_.size()) < target_parts) {
        std::size_t largest = build_tasks_.size();  // of those with two items or more
        for (std::size_t k = 0; k < build_tasks_.size(); ++k) {
            const bool splits = build_tasks_[k].end - build_tasks_[k].begin > 1;
            if (splits && (largest == build_tasks_.size() || task_nodes_[k] > task_nodes_[largest])) {
                largest = k;
            }
        }
        if (largest == build_tasks_.size() || task_nodes_[largest] < min_nodes_to_split) {
            break;
        }
        const BuildTask task = build_tasks_[largest];
        const int32_t split = split_items(task.begin, task.end, task.depth, rule);
        top_nodes_.push_back(task.place);
        compact_scratch_[std::size_t(task.place)] = TreeNode{};
        link_placed(task.place, task.parent);
        int32_t left_nodes = -1;  // k items of n nodes in all take n + k - 1 places: k - 1 made above them
        for (int32_t i = task.begin; i < split; ++i) {
            left_nodes += build_items_[std::size_t(i)].node_count + 1;
        }
        const int32_t right_nodes = task_nodes_[largest] - 1 - left_nodes;
        build_tasks_[largest] = {task.begin, split, task.place, task.depth + 1, true, task.place + 1};
        task_nodes_[largest] = left_nodes;
        build_tasks_.push_back({split, task.end, task.place, task.depth + 1, false, task.place + 1 + left_nodes});
        task_nodes_.push_back(right_nodes);
    }
    parts_.assign(build_tasks_.begin(), build_tasks_.end());
    part_scratch_.resize(std::size_t(worker_count));
    if (parts_.size() == 1) {
        build_part(0, 0);
        finish_commit_parts();
        return 0;
    }
    return int32_t(parts_.size());
}

// Each item's node count, for the places of the ranges at the top: a leaf is one node, a
// subtree no moved leaf reached is counted through.
void DynamicTree::count_item_nodes() {
    for (BuildItem& item : build_items_) {
        if (nodes_[item.node].is_leaf()) {
            item.node_count = 1;
            continue;
        }
        int32_t count = 0;
        collect_stack_.clear();
        collect_stack_.push_back(item.node);
        while (!collect_stack_.empty()) {
            const TreeNode& node = nodes_[collect_stack_.back()];
            collect_stack_.pop_back();
            ++count;
            if (!node.is_leaf()) {
                collect_stack_.push_back(node.child1());
                collect_stack_.push_back(node.child2());
            }
        }
        item.node_count = count;
    }
}

// Depth first from the part's place, a cursor giving each node the next place: a node is
// made before its first range and that range's nodes before the second's, as preorder
// lays them out. The part's made nodes take their boxes and heights here, children first.
void DynamicTree::build_part(int32_t part, int32_t worker) {
    PartScratch& scratch = part_scratch_[std::size_t(worker)];
    scratch.built.clear();
    std::vector<BuildTask>& tasks = scratch.tasks;
    tasks.clear();
    tasks.push_back(parts_[std::size_t(part)]);
    int32_t cursor = parts_[std::size_t(part)].place;
    while (!tasks.empty()) {
        const BuildTask task = tasks.back();
        tasks.pop_back();
        if (task.end - task.begin == 1) {
            cursor = copy_in_preorder(build_items_[std::size_t(task.begin)].node, task.parent, cursor, scratch.copies);
            continue;
        }
        const int32_t place = cursor++;
        compact_scratch_[std::size_t(place)] = TreeNode{};
        scratch.built.push_back(place);
        const int32_t split = split_items(task.begin, task.end, task.depth, build_rule_);
        link_placed(place, task.parent);
        tasks.push_back({split, task.end, place, task.depth + 1, false, null_index});
        tasks.push_back({task.begin, split, place, task.depth + 1, true, null_index});
    }
    for (auto it = scratch.built.rbegin(); it != scratch.built.rend(); ++it) {
        set_from_children(compact_scratch_, *it);
    }
}

// The top's nodes from their children, in the reverse of the order they were made (a
// node is split before its halves are), and the array becomes the tree.
void DynamicTree::finish_commit_parts() {
    for (auto it = top_nodes_.rbegin(); it != top_nodes_.rend(); ++it) {
        set_from_children(compact_scratch_, *it);
    }
    root_ = 0;
    adopt_compacted();
}

// A made node's box and height from its children's. The union of the children's boxes
// is the union of the node's items' boxes, bit for bit (a minimum and a maximum are exact
// in any order): unions made once per node, not in split_items over every item of every
// level.
void DynamicTree::set_from_children(std::vector<TreeNode>& nodes, int32_t index) {
    TreeNode& n = nodes[std::size_t(index)];
    const TreeNode& c1 = nodes[std::size_t(n.child1())];
    const TreeNode& c2 = nodes[std::size_t(n.child2())];
    n.aabb = union_of(c1.aabb, c2.aabb);
    n.height = int16_t(1 + std::max(c1.height, c2.height));
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
    // Children first: the nodes were made parents first.
    for (auto it = built_nodes_.rbegin(); it != built_nodes_.rend(); ++it) {
        set_from_children(nodes_, *it);
    }
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
