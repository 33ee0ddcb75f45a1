// SPDX-License-Identifier: MIT
// The broadphase saved and loaded node by node (core/field_io.hpp), so that a restored
// world finds its pairs in the very order the saved one would have: the trees' shapes,
// not only their leaves, decide that order.
//
// A load checks that what it read is a forest of trees it can walk: every child and
// parent in range and agreeing, heights right, each node reached once, the free list a
// chain of free nodes, each proxy's leaf naming it back, the move buffer naming live
// proxies. A buffer that passes them can be stepped without reading out of bounds or
// looping; what the checks cannot see (a box a little off) only changes which pairs are
// found, as any other input would.
#include <algorithm>

#include "broadphase/broad_phase.hpp"
#include "core/field_io.hpp"

namespace i2d {

namespace {

// Largest node or proxy count a load accepts: a pool's slot limit (24 bits of an id).
constexpr int32_t max_tree_items = Pool<int32_t>::max_slots;

}  // namespace

// One list of fields for both directions: Self is a const tree to save, a tree to load.
template <class Io, class Self>
void DynamicTree::transfer(Io& io, Self& self) {
    const auto node_fields = [&io](auto& node) {
        io(node.aabb);
        io(node.parent);
        io(node.height);
        io(node.grown);
        io(node.child1());
        io(node.child2());
    };
    if constexpr (!Io::loading) {
        io.count(int32_t(self.nodes_.size()));
    } else {
        self.nodes_.resize(
            std::size_t(io.count(31, max_tree_items, "a tree has more nodes than the bytes left could hold")));
    }
    for (auto& node : self.nodes_) {
        node_fields(node);
    }
    list_fields(io, self.proxy_nodes_, max_tree_items, "a tree has more proxies than the bytes left could hold");
    list_fields(io, self.proxy_categories_, max_tree_items, "a tree has more proxies than the bytes left could hold");
    list_fields(io, self.free_proxies_, max_tree_items, "a tree frees more proxies than the bytes left could hold");
    io(self.root_);
    io(self.free_list_);
    io(self.moves_since_compact_);
}

void DynamicTree::save(SaveIo& io) const { transfer(io, *this); }

void DynamicTree::load(LoadIo& io) {
    // Emptied but not freed: a tree loaded again and again (a rollback) allocates nothing.
    nodes_.clear();
    proxy_nodes_.clear();
    proxy_categories_.clear();
    free_proxies_.clear();
    root_ = free_list_ = null_index;
    proxy_count_ = moves_since_compact_ = 0;
    transfer(io, *this);
    check_loaded(io);
}

// Every node is either reached once from the root or on the free list; proxies and
// leaves name each other.
void DynamicTree::check_loaded(LoadIo& io) {
    if (io.failed()) {
        return;
    }
    const int32_t n = int32_t(nodes_.size());
    const int32_t proxies = int32_t(proxy_nodes_.size());
    const auto in_nodes = [n](int32_t i) { return i >= 0 && i < n; };
    if (!io.check(proxy_categories_.size() == proxy_nodes_.size(), "a tree's proxy tables differ in length") ||
        !io.check(root_ == null_index || in_nodes(root_), "a tree's root is out of range") ||
        !io.check(free_list_ == null_index || in_nodes(free_list_), "a tree's free list is out of range") ||
        !io.check(moves_since_compact_ >= 0 && moves_since_compact_ <= max_tree_items,
                  "a tree's move count is out of range")) {
        return;
    }
    std::vector<uint8_t> seen(std::size_t(n), 0);
    for (int32_t node = free_list_; node != null_index; node = nodes_[std::size_t(node)].parent) {
        if (!io.check(in_nodes(node) && seen[std::size_t(node)] == 0 && nodes_[std::size_t(node)].height == -1,
                      "a tree's free list is broken")) {
            return;
        }
        seen[std::size_t(node)] = 1;
    }
    proxy_count_ = 0;
    if (root_ != null_index) {
        if (!io.check(nodes_[std::size_t(root_)].parent == null_index, "a tree's root has a parent")) {
            return;
        }
        std::vector<int32_t> stack{root_};
        while (!stack.empty()) {
            const int32_t node = stack.back();
            stack.pop_back();
            const TreeNode& t = nodes_[std::size_t(node)];
            if (!io.check(seen[std::size_t(node)] == 0 && t.height >= 0, "a tree node is reached twice or is free")) {
                return;
            }
            seen[std::size_t(node)] = 1;
            if (t.is_leaf()) {
                const int32_t proxy = t.proxy();
                // Only inner nodes are marked grown: a rebuild takes a grown node's children.
                if (!io.check(proxy >= 0 && proxy < proxies && proxy_nodes_[std::size_t(proxy)] == node && !t.grown,
                              "a tree leaf and its proxy do not name each other, or the leaf is marked grown")) {
                    return;
                }
                ++proxy_count_;
                continue;
            }
            const int32_t a = t.child1(), b = t.child2();
            if (!io.check(in_nodes(a) && in_nodes(b) && a != b && nodes_[std::size_t(a)].parent == node &&
                              nodes_[std::size_t(b)].parent == node,
                          "a tree node's children are out of range or do not name it")) {
                return;
            }
            const int32_t taller = std::max(nodes_[std::size_t(a)].height, nodes_[std::size_t(b)].height);
            if (!io.check(t.height == 1 + taller, "a tree node's height is wrong")) {
                return;
            }
            // A node's box is its children's union, or holds it while the node waits for the
            // rebuild (grown), and then so does its parent.
            const AABB both = union_of(nodes_[std::size_t(a)].aabb, nodes_[std::size_t(b)].aabb);
            const bool exact = t.aabb.lower == both.lower && t.aabb.upper == both.upper;
            const bool parent_grown = t.parent == null_index || nodes_[std::size_t(t.parent)].grown;
            if (!io.check(t.grown ? contains(t.aabb, both) && parent_grown : exact, "a tree node's box is wrong")) {
                return;
            }
            stack.push_back(a);
            stack.push_back(b);
        }
    }
    if (!io.check(std::count(seen.begin(), seen.end(), uint8_t(1)) == n, "a tree node is neither in the tree nor free")) {
        return;
    }
    std::vector<uint8_t> freed(std::size_t(proxies), 0);
    for (const int32_t proxy : free_proxies_) {
        if (!io.check(proxy >= 0 && proxy < proxies && proxy_nodes_[std::size_t(proxy)] == null_index &&
                          freed[std::size_t(proxy)] == 0,
                      "a tree's free proxy list is broken")) {
            return;
        }
        freed[std::size_t(proxy)] = 1;
    }
    const int32_t live = proxies - int32_t(free_proxies_.size());
    io.check(live == proxy_count_, "a tree has proxies that no leaf holds");
    // destroy_proxy never allocates: room for every proxy in the free list.
    free_proxies_.reserve(proxy_nodes_.capacity());
}

void BroadPhase::save(SaveIo& io) const {
    for (const DynamicTree& tree : trees_) {
        tree.save(io);
    }
    list_fields(io, ahead_, max_tree_items, "");
    list_fields(io, move_buffer_, max_tree_items, "");
    int32_t pending = 0;
    for (const MoveEntry& e : pending_moves_) {
        pending += e.key != null_index ? 1 : 0;
    }
    io.count(pending);
    for (const MoveEntry& e : pending_moves_) {
        if (e.key != null_index) {  // dropped: the commit would skip it
            io(e.key);
            io(e.box);
        }
    }
}

void BroadPhase::load(LoadIo& io) {
    for (DynamicTree& tree : trees_) {
        tree.load(io);
    }
    list_fields(io, ahead_, max_tree_items, "a broadphase has more boxes ahead than the bytes left could hold");
    list_fields(io, move_buffer_, max_tree_items, "a broadphase moved more proxies than the bytes left could hold");
    pending_moves_.resize(
        std::size_t(io.count(20, max_tree_items, "a broadphase has more pending moves than the bytes left could hold")));
    for (MoveEntry& e : pending_moves_) {
        e.order = 0;
        io(e.key);
        io(e.box);
    }
    check_loaded(io);
}

// The move buffer and the pending moves name live proxies; the sets that find them fast
// are made again from the lists.
void BroadPhase::check_loaded(LoadIo& io) {
    move_set_ = BitSet{};
    move_slot_.clear();
    pending_slot_.clear();
    if (io.failed()) {
        return;
    }
    const auto live = [this](int32_t key) {
        const int32_t kind = key & 3, proxy = key >> 2;
        return key >= 0 && kind < int32_t(ProxyKind::count) && proxy < int32_t(trees_[kind].proxy_slots()) &&
               trees_[kind].is_live_proxy(proxy);
    };
    for (std::size_t k = 0; k < move_buffer_.size(); ++k) {
        const int32_t key = move_buffer_[k];
        if (key == null_index) {
            continue;
        }
        if (!io.check(live(key) && move_set_.insert(key), "a broadphase's move buffer names a dead proxy or one twice")) {
            return;
        }
        move_slot(key) = int32_t(k);
    }
    for (std::size_t k = 0; k < pending_moves_.size(); ++k) {
        const int32_t key = pending_moves_[k].key;
        if (!io.check(live(key) && pending_slot(key) == null_index,
                      "a broadphase's pending moves name a dead proxy or one twice")) {
            return;
        }
        pending_slot(key) = int32_t(k);
    }
    const DynamicTree& dynamic = trees_[int32_t(ProxyKind::dynamic_proxy)];
    io.check(ahead_.size() >= std::size_t(dynamic.proxy_slots()), "a broadphase lacks a box ahead for a proxy");
}

}  // namespace i2d
