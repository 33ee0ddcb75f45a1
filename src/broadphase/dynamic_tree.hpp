// SPDX-License-Identifier: MIT
// DynamicTree: a bounding volume hierarchy of fat AABBs with incremental insert, remove
// and move, kept shallow by the surface-area heuristic and tree rotations.
//
// Design note: nodes live in one array with a free list and index links (no pointers),
// leaves hold a proxy's fat box and user value (a shape index). Inserting
// walks down choosing the sibling that adds the least perimeter (2D's surface area),
// counting the growth of every ancestor (Bittner et al., "Fast, Effective BVH Updates
// for Animated Scenes", as Box2D v3 uses it); rotations on the way back up keep the
// height near log2(n). A top-down build serves bulk creation (binned SAH) and the step:
// when many proxies move at once, each leaf takes its new box where it is (its ancestors
// grow and are marked), and one build, splitting at the middle of the centres, then
// replaces every marked node, taking the unmarked subtrees below them whole (Box2D v3
// does the same). That costs less than re-inserting each leaf, and the rebuilt part is
// a fresh tree rather than the sum of greedy insertions. The alternative, a loose grid,
// needs a cell size that suits every scene.
//
// Proxy ids are not node indices: a small table maps each proxy to its leaf, so that
// compact() can move nodes. Once a tree outgrows the cache, nodes scattered through
// memory by creation order and free-list reuse cost a cache miss at nearly every step of
// a traversal; compact() lays the nodes out depth-first, which puts every subtree in one
// contiguous run (64k moving shapes cost 8x 16k before, close to 4x after).
//
// A node is 32 bytes, two to a cache line. Category bits live beside the proxy table
// and are tested at the leaves only, and only by queries with a mask: pair finding, the
// hot traversal, never reads them. Internal nodes keep no union of their leaves'
// categories, so a masked query cannot skip a subtree early; with 40-byte nodes that
// kept it, 64k moving shapes cost 5.3 to 6.0x 16k, with 32-byte nodes 5.1x.
#pragma once

#include <cstdint>
#include <vector>

#include "core/pool.hpp"
#include "math/vec2.hpp"

namespace i2d {

class SaveIo;
class LoadIo;

struct alignas(32) TreeNode {
    AABB aabb;
    int32_t parent = null_index; // also the free list link for free nodes
    int16_t height = 0;          // leaves 0; -1 when free
    bool grown = false;          // internal: a leaf below moved in place; rebuilt by rebuild_grown()
    bool moved_below = false;    // a leaf at or below is marked moved (mark_moved); never saved

    // Two slots shared by both kinds of node, which keeps a node at 32 bytes (two per
    // cache line): internal nodes hold their children, leaves their user value (a
    // shape) and proxy id.
    int32_t& child1() { return slot_[0]; }
    int32_t& child2() { return slot_[1]; }
    int32_t child1() const { return slot_[0]; }
    int32_t child2() const { return slot_[1]; }
    int32_t& user_value() { return slot_[0]; }
    int32_t& proxy() { return slot_[1]; }
    int32_t user_value() const { return slot_[0]; }
    int32_t proxy() const { return slot_[1]; }
    bool is_leaf() const { return height == 0; }

private:
    int32_t slot_[2] = {null_index, null_index};
};
static_assert(sizeof(TreeNode) == 32, "tree nodes are the hot data of every query: keep them small");

/// Two nodes whose leaves are to be paired with each other; a == b pairs one node's
/// leaves among themselves.
struct TreeNodePair {
    int32_t a, b;
};

struct TreeRayInput {
    Vec2 origin;
    Vec2 translation;
    float max_fraction = 1.0f;
};

class DynamicTree {
public:
    /// Adds a leaf; returns its proxy id (a node index).
    int32_t create_proxy(const AABB& fat_aabb, uint64_t category_bits, int32_t user_value);
    void destroy_proxy(int32_t proxy);
    /// Gives the leaf a new fat box: removes and re-inserts it, unless its parent still
    /// holds the box (then the leaf keeps its place and its ancestors are refitted).
    void move_proxy(int32_t proxy, const AABB& fat_aabb);
    /// Grows the leaf's box in place (ancestors grow to contain it); cheaper than a move
    /// when the box only gets bigger. The box must contain the old one.
    void enlarge_proxy(int32_t proxy, const AABB& fat_aabb);
    /// Gives the leaf a new box where it is, for many moves at once: its ancestors are
    /// marked, and rebuild_grown() then rebuilds them. Their boxes are left as they were,
    /// so the tree answers no query until then; any other change rebuilds first.
    void move_proxy_in_place_at(int32_t order, const AABB& fat_aabb);
    /// Rebuilds every node marked by move_proxy_in_place_at, keeping the unmarked subtrees
    /// below them as they are; returns how many internal nodes it made.
    int32_t rebuild_grown();
    /// What the broadphase calls after a batch of moves: rebuild_grown(), and compact()
    /// once a quarter of the tree has been rebuilt or re-inserted since the last one.
    void commit_in_place_moves();
    /// The same in three calls, for workers to share: begin_commit does what one thread
    /// must and returns how many parts are left to build (0: the commit is done); then
    /// build_part(part, worker) for each part, on workers in [0, worker_count), in any
    /// order or at once; then finish_commit_parts(). The tree is the same whoever builds.
    int32_t begin_commit(int32_t worker_count);
    void build_part(int32_t part, int32_t worker);
    void finish_commit_parts();
    /// Every box seen from `new_origin` (relative_to): the same tree, each internal box
    /// still exactly the union of its children.
    void shift_origin(Vec2 new_origin);

    const AABB& fat_aabb(int32_t proxy) const { return nodes_[proxy_nodes_[proxy]].aabb; }
    int32_t user_value(int32_t proxy) const { return nodes_[proxy_nodes_[proxy]].user_value(); }

    /// Where the proxy's leaf lies in the node array: handling proxies in this order walks
    /// memory forwards. The value also reaches the leaf without the proxy table, whose
    /// random reads cost a cache miss each in a large tree; it holds until the next
    /// compact() or rebuild() (moves and inserts leave leaves where they are).
    int32_t storage_order(int32_t proxy) const { return proxy_nodes_[proxy]; }
    const AABB& fat_aabb_at(int32_t order) const { return nodes_[order].aabb; }
    int32_t user_value_at(int32_t order) const { return nodes_[order].user_value(); }
    void move_proxy_at(int32_t order, const AABB& fat_aabb);
    uint64_t category_bits(int32_t proxy) const { return proxy_categories_[proxy]; }

    /// Calls visit(proxy, user_value) for every leaf whose box overlaps `box` (touching
    /// included); visit returns false to stop.
    template <class Visit>
    void query(const AABB& box, Visit&& visit) const;
    /// The same, for the leaves whose category bits meet `mask_bits`.
    template <class Visit>
    void query(const AABB& box, uint64_t mask_bits, Visit&& visit) const;

    /// The search for every two leaves whose boxes overlap, cut into independent parts:
    /// node pairs that between them hold each such leaf pair once, at least `target` of
    /// them where the tree has that many, none of more than about 1 / max_share of the
    /// tree's leaves unless it cannot be cut. The same tree gives the same parts in the
    /// same order, so results put together part by part do not depend on who searched
    /// which; `max_share` changes the cut but not the order of the pairs found.
    void split_self_overlaps(int32_t target, int32_t max_share, std::vector<TreeNodePair>& out);
    /// Calls visit(proxy_a, user_a, proxy_b, user_b) for each two distinct leaves of
    /// `part` whose boxes overlap (touching included), each pair once.
    template <class Visit>
    void self_overlaps(TreeNodePair part, Visit&& visit) const;
    /// From the first mark until clear_moved_marks, self_overlaps reports only pairs with a
    /// marked leaf, and skips without walking them the node pairs with none below: the
    /// pairs of proxies that did not move were paired, or refused, when one of them last
    /// moved. The parts (split_self_overlaps) stay those of the whole tree, so the pairs
    /// come in the order an unmarked search gives them. The tree must not change in between.
    void mark_moved(int32_t proxy);
    void clear_moved_marks();

    /// Calls visit(input, proxy, user_value) -> float for every leaf whose box the ray
    /// (origin + t translation, t up to the current max fraction) crosses and whose
    /// category bits meet `mask_bits`. The returned value: 0 stops, a value in (0, max)
    /// clips the ray, -1 or >= max leaves it as is.
    template <class Visit>
    void ray_cast(const TreeRayInput& input, uint64_t mask_bits, Visit&& visit) const;

    /// Rebuilds the whole tree top-down with a binned surface-area heuristic.
    void rebuild();
    /// Lays the nodes out depth-first in one array (same tree, same proxy ids).
    void compact();
    /// Re-insertions and rebuilt nodes since the last compact() or rebuild(): how
    /// scattered the nodes are.
    int32_t moves_since_compact() const { return moves_since_compact_; }

    int32_t height() const { return root_ == null_index ? 0 : nodes_[root_].height; }
    int32_t proxy_count() const { return proxy_count_; }
    /// Sum of the perimeters of all internal nodes: the quality measure the SAH minimises.
    float total_perimeter() const;
    /// Proxy ids handed out so far (live or freed), and whether one is live.
    int32_t proxy_slots() const { return int32_t(proxy_nodes_.size()); }
    bool is_live_proxy(int32_t proxy) const { return proxy_nodes_[std::size_t(proxy)] != null_index; }
    /// Saves every node, or loads them and checks the tree can be walked (core/field_io.hpp;
    /// broad_phase_snapshot.cpp).
    void save(SaveIo& io) const;
    void load(LoadIo& io);
    /// Aborts on a broken invariant (parent links, heights, counts, internal boxes that
    /// are not exactly their children's union); a no-op unless the build defines
    /// I2D_VALIDATE.
    void validate() const;

private:
    /// No leaf has moved in place since the last rebuild_grown(): every box is current.
    bool answers_queries() const { return root_ == null_index || !nodes_[root_].grown; }
    /// Sets a node's flag to `value`, and its ancestors' up to the first that has it already:
    /// a flag that says something of the nodes below (grown, moved_below) is set on whole
    /// paths from the root, so the one found set has its ancestors set too.
    void set_flag_up_from(int32_t node, bool TreeNode::*flag, bool value) {
        for (int32_t index = node; index != null_index && nodes_[index].*flag != value; index = nodes_[index].parent) {
            nodes_[index].*flag = value;
        }
    }
    void prefetch_node(int32_t node) const {
#if defined(__GNUC__)
        __builtin_prefetch(&nodes_[node]);
#else
        (void)node;
#endif
    }
    /// Hands push() the node pairs one level down from `pair` that can still hold an
    /// overlapping leaf pair: a node with itself gives its children with themselves and
    /// with each other; two nodes give the taller one's children with the other.
    /// moved_only: as the search does, only pairs with a marked leaf below (mark_moved).
    template <class Push>
    void expand_pair(TreeNodePair pair, Push&& push, bool moved_only = false) const;
    /// Whether a marked leaf lies below either node, or nothing is marked.
    bool holds_moved_leaf(int32_t a, int32_t b) const {
        return moved_leaves_.empty() || nodes_[a].moved_below || nodes_[b].moved_below;
    }
    void refine_parts(int32_t max_share, std::vector<TreeNodePair>& parts);
    void refine_part(TreeNodePair part, int64_t max_weight, std::vector<TreeNodePair>& out) const;
    int64_t leaf_weight(TreeNodePair part) const;
    /// Two distinct leaves: a pair to report, not to expand.
    bool is_leaf_pair(TreeNodePair pair) const {
        return pair.a != pair.b && nodes_[pair.a].is_leaf() && nodes_[pair.b].is_leaf();
    }
    int32_t allocate_node();
    void free_node(int32_t node);
    template <class Io, class Self>
    static void transfer(Io& io, Self& self);
    void check_loaded(LoadIo& io);
    /// Inserts below `start`, which must contain the leaf's box (or be the root).
    void insert_leaf(int32_t leaf, int32_t start);
    /// Returns the lowest node the leaf's removal left in its place (null if none).
    int32_t remove_leaf(int32_t leaf);
    int32_t find_best_sibling(const AABB& box, int32_t start) const;
    /// True if it rotated.
    bool rotate(int32_t node);
    void refit_upward(int32_t node, bool rotate_nodes);
    /// How a build splits a set of items in two: by the surface-area heuristic (better
    /// trees, for a tree built once) or at the middle of their centres (a third of the
    /// cost, for the rebuild every step, whose queries were as fast in the tumbler).
    enum class Split : uint8_t { sah, midpoint };
    /// Builds a tree over build_items_ (leaves and whole subtrees); returns its root.
    int32_t build_top_down(Split rule);
    int32_t split_items(int32_t begin, int32_t end, int32_t depth, Split rule);
    int32_t rebuild_marked(Split rule);
    void collect_marked();
    int32_t finish_build(Split rule);
    int32_t begin_compacted_build(Split rule, int32_t worker_count);
    void count_item_nodes();
    static void set_from_children(std::vector<TreeNode>& nodes, int32_t index);
    bool scattered(int32_t moves) const;
    struct CompactItem {
        int32_t old_index;
        int32_t new_parent;
    };
    int32_t copy_in_preorder(int32_t old_root, int32_t new_parent, int32_t place, std::vector<CompactItem>& stack);
    void link_placed(int32_t index, int32_t parent);
    void adopt_compacted();
    template <class Left>
    int32_t partition_items(int32_t begin, int32_t end, Left&& left);

    std::vector<TreeNode> nodes_;
    std::vector<int32_t> proxy_nodes_;  // proxy id -> leaf node; null_index when free
    std::vector<uint64_t> proxy_categories_;  // proxy id -> category bits
    std::vector<int32_t> free_proxies_;
    std::vector<int32_t> moved_leaves_;  // marked by mark_moved, for clear_moved_marks
    std::vector<TreeNode> compact_scratch_;
    std::vector<CompactItem> compact_stack_;
    int32_t root_ = null_index;
    int32_t free_list_ = null_index;
    int32_t proxy_count_ = 0;
    int32_t moves_since_compact_ = 0;
    // Build scratch, kept between builds so that the step allocates nothing.
    struct BuildItem {
        AABB box;
        Vec2 centre;
        int32_t node;
        int32_t bin;         // scratch of split_items
        int32_t node_count;  // nodes in the item's subtree, when the build is shared
    };
    struct BuildTask {
        int32_t begin, end;  // a range of build_items_
        int32_t parent;      // null_index for the root
        int32_t depth;
        bool first_child;
        int32_t place = null_index;  // in a compacted build: where its first node goes
    };
    // A shared compacted build: its rule, the parts left for the workers, the places of
    // the nodes made above them (in the order they were made), and each worker's own
    // scratch.
    // Trees of fewer items are built by one thread; each worker gets a few parts, so that
    // one that runs slow leaves the others something to take.
    static constexpr int32_t min_items_to_share = 256;
    static constexpr int32_t min_nodes_to_split = 128;
    static constexpr int32_t parts_per_worker = 4;
    // A part of the self search this light (in leaves by height) is never cut, whatever
    // the share: in a small tree a 64th would be under a leaf, and every overlapping leaf
    // pair would become a part of its own.
    static constexpr int64_t min_part_weight = 16;
    struct PartScratch {
        std::vector<BuildTask> tasks;
        std::vector<CompactItem> copies;
        std::vector<int32_t> built;
    };
    Split build_rule_ = Split::midpoint;
    std::vector<BuildTask> parts_;
    std::vector<int32_t> top_nodes_;
    std::vector<int32_t> task_nodes_;  // per task while the top is split: its node count
    std::vector<PartScratch> part_scratch_;
    std::vector<BuildItem> build_items_;
    std::vector<BuildTask> build_tasks_;
    std::vector<int32_t> built_nodes_;  // internal nodes in the order the build made them
    std::vector<int32_t> collect_stack_;
    std::vector<TreeNodePair> split_scratch_;  // split_self_overlaps
};

// Node allocation is called from insertion and from the rebuild (two files): inline, so
// that neither pays a call per node.
inline int32_t DynamicTree::allocate_node() {
    if (free_list_ != null_index) {
        const int32_t index = free_list_;
        free_list_ = nodes_[index].parent;
        nodes_[index] = TreeNode{};
        return index;
    }
    nodes_.emplace_back();
    return int32_t(nodes_.size()) - 1;
}

inline void DynamicTree::free_node(int32_t node) {
    nodes_[node].height = -1;
    nodes_[node].parent = free_list_;
    free_list_ = node;
}

}  // namespace i2d

#include "broadphase/dynamic_tree_query.inl"
