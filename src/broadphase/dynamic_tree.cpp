// SPDX-License-Identifier: MIT
// DynamicTree: insertion by surface-area heuristic, removal, rotations, rebuild, checks.
#include "broadphase/dynamic_tree.hpp"

#include <algorithm>
#include <cfloat>

#include "core/assert.hpp"

namespace i2d {

namespace {

// 2D's surface area: what the cost of a node in a ray or box query grows with.
float perimeter(const AABB& a) { return 2.0f * ((a.upper.x - a.lower.x) + (a.upper.y - a.lower.y)); }

}  // namespace

int32_t DynamicTree::allocate_node() {
    if (free_list_ != null_index) {
        const int32_t index = free_list_;
        free_list_ = nodes_[index].parent;
        nodes_[index] = TreeNode{};
        return index;
    }
    nodes_.emplace_back();
    return int32_t(nodes_.size()) - 1;
}

void DynamicTree::free_node(int32_t node) {
    nodes_[node].height = -1;
    nodes_[node].parent = free_list_;
    free_list_ = node;
}

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

// Every ancestor is marked, not only those that grew, so that the rebuild finds each
// marked node by descending from the root through marked nodes alone.
void DynamicTree::move_proxy_in_place_at(int32_t leaf, const AABB& fat_aabb) {
    I2D_ASSERT(nodes_[leaf].is_leaf());
    nodes_[leaf].aabb = fat_aabb;
    int32_t index = nodes_[leaf].parent;
    for (; index != null_index; index = nodes_[index].parent) {
        TreeNode& node = nodes_[index];
        node.grown = true;
        if (contains(node.aabb, fat_aabb)) {
            index = node.parent;
            break;
        }
        node.aabb = union_of(node.aabb, fat_aabb);
    }
    for (; index != null_index && !nodes_[index].grown; index = nodes_[index].parent) {
        nodes_[index].grown = true;
    }
}

// Branch and bound down one path: the cost of making node X the new leaf's sibling is
// the perimeter of X grown by the leaf plus how much every ancestor of X grows (the
// "inherited" cost). Descending into a child can never cost less than the inherited
// cost plus the child's own growth plus the leaf's perimeter, which prunes the search.
// The search may start below the root at a node that already contains the box: nothing
// above it grows, so the costs inside it compare the same as from the root.
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

float DynamicTree::total_perimeter() const {
    float total = 0.0f;
    for (const TreeNode& node : nodes_) {
        if (node.height > 0) {
            total += perimeter(node.aabb);
        }
    }
    return total;
}

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
    rebuild_marked(Split::sah);
    compact();
}

int32_t DynamicTree::rebuild_grown() { return rebuild_marked(Split::midpoint); }

// Level by level from the root with itself: each round expands every part that is not a
// single leaf pair, keeping the order, until there are enough parts or none can expand.
void DynamicTree::split_self_overlaps(int32_t target, std::vector<TreeNodePair>& out) {
    out.clear();
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

// The marked nodes are freed; what hangs below them unmarked (leaves, and subtrees no
// moved leaf reached) becomes the items of one build.
int32_t DynamicTree::rebuild_marked(Split rule) {
    if (root_ == null_index || !nodes_[root_].grown) {
        return 0;
    }
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
    moves_since_compact_ = 0;
    compact_scratch_.clear();
    compact_scratch_.reserve(size_t(2 * proxy_count_));
    if (root_ != null_index) {
        // Each stacked node carries its new parent, so links are set as nodes are placed:
        // no second pass through the old array to translate indices.
        compact_stack_.clear();
        compact_stack_.push_back({root_, null_index});
        while (!compact_stack_.empty()) {
            const CompactItem item = compact_stack_.back();
            compact_stack_.pop_back();
            const int32_t new_index = int32_t(compact_scratch_.size());
            compact_scratch_.push_back(nodes_[item.old_index]);
            TreeNode& node = compact_scratch_.back();
            node.parent = item.new_parent;
            if (item.new_parent != null_index) {
                TreeNode& parent = compact_scratch_[item.new_parent];
                // The first child is placed right after its parent.
                (new_index == item.new_parent + 1 ? parent.child1() : parent.child2()) = new_index;
            }
            if (node.is_leaf()) {
                proxy_nodes_[node.proxy()] = new_index;
            } else {
                compact_stack_.push_back({node.child2(), new_index});
                compact_stack_.push_back({node.child1(), new_index});
            }
        }
        root_ = 0;
    }
    nodes_.swap(compact_scratch_);
    free_list_ = null_index;
    validate();
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
            const int32_t split = split_items(task.begin, task.end, task.depth, rule, nodes_[node].aabb);
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
    for (auto it = built_nodes_.rbegin(); it != built_nodes_.rend(); ++it) {
        TreeNode& n = nodes_[*it];
        n.height = int16_t(1 + std::max(nodes_[n.child1()].height, nodes_[n.child2()].height));
    }
    return root;
}

namespace {

constexpr AABB empty_box{{FLT_MAX, FLT_MAX}, {-FLT_MAX, -FLT_MAX}};

}  // namespace

// Along the axis where the items' centres spread most, binned SAH over the centres (the
// split that minimises perimeter(left) * count(left) + perimeter(right) * count(right))
// or the middle of the spread. Partitions [begin, end), writes the union of the items'
// boxes to `bounds` and returns where the second half starts.
int32_t DynamicTree::split_items(int32_t begin, int32_t end, int32_t depth, Split rule, AABB& bounds) {
    BuildItem* items = build_items_.data();
    const int32_t count = end - begin;
    AABB centres{items[begin].centre, items[begin].centre};
    bounds = items[begin].box;
    for (int32_t i = begin + 1; i < end; ++i) {
        centres.lower = min(centres.lower, items[i].centre);
        centres.upper = max(centres.upper, items[i].centre);
        bounds = union_of(bounds, items[i].box);
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
        // Only a node marked for the rebuild may hold more, and its parent is marked too.
        const AABB both = union_of(c1.aabb, c2.aabb);
        I2D_ASSERT(n.grown ? contains(n.aabb, both) : n.aabb.lower == both.lower && n.aabb.upper == both.upper);
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
