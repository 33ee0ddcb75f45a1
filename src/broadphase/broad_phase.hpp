// SPDX-License-Identifier: MIT
// BroadPhase: one dynamic tree per body type, a move buffer, and pair finding.
//
// Design note: static shapes sit in their own tree and are never re-inserted, so a large
// static level costs nothing per step; only proxies whose tight box left their fat box
// (the move buffer) are queried, against the trees they can pair with: every pair but
// static against static (a moved dynamic or kinematic proxy against all three trees, a
// moved static one against the dynamic and kinematic trees). Pairs without a dynamic
// proxy are few, as kinematic proxies are, and only sensors keep them (the caller's
// test): a world without kinematic bodies pays nothing for them. When most dynamic
// proxies moved, one search of the dynamic tree against itself replaces their queries
// of it: each overlapping pair is met once, not once from each side, and neighbouring
// leaves share the tests of their ancestors. A dynamic proxy has a second box, stretched
// along its coming motion (shape_bounds.hpp), which it meets the static and kinematic
// trees with; two dynamic proxies meet by their fat boxes. Pairs come out in the storage
// order of the moved proxies (below) and, per proxy, in tree order, after those of the
// self search in its order: the same inputs give the same pairs in the same order.
// Existing pairs are skipped through a caller's test (the world keeps the set of shape
// pairs that have a contact).
#pragma once

#include <cstdint>
#include <vector>

#include "broadphase/dynamic_tree.hpp"
#include "broadphase/proxy_key.hpp"
#include "core/bit_set.hpp"
#include "core/radix_sort.hpp"
#include "core/stage_runner.hpp"

namespace i2d {

struct ShapePairCandidate {
    int32_t shape_a, shape_b;  // shape_a < shape_b
};

class BroadPhase {
public:
    /// Adds a proxy; it is queried for pairs at the next update_pairs unless it is
    /// static and `query_now` is false (static against static never pairs). A dynamic
    /// proxy meets static and kinematic ones by `ahead_aabb`, which holds its fat box;
    /// without it, by the fat box.
    int32_t create_proxy(const AABB& fat_aabb, const AABB& ahead_aabb, uint64_t category_bits, int32_t shape,
                         ProxyKind kind, bool query_now);
    int32_t create_proxy(const AABB& fat_aabb, uint64_t category_bits, int32_t shape, ProxyKind kind,
                         bool query_now) {
        return create_proxy(fat_aabb, fat_aabb, category_bits, shape, kind, query_now);
    }
    void destroy_proxy(int32_t key);
    /// Queues a re-insertion with a new fat box (done by commit_moves; a second move
    /// before then replaces the box) and queues the proxy for pair finding. Until the
    /// commit the trees and fat_aabb() still show the old box.
    void move_proxy(int32_t key, const AABB& fat_aabb, const AABB& ahead_aabb);
    void move_proxy(int32_t key, const AABB& fat_aabb) { move_proxy(key, fat_aabb, fat_aabb); }
    /// Performs the queued moves in the order their leaves lie in the tree's node array
    /// (see storage order below), each a re-insertion: for a few moves at a time (a
    /// caller placing bodies one by one).
    void commit_moves();
    /// The same for the many moves of a step: in a tree where many proxies moved, each
    /// leaf takes its box where it is and the grown part of the tree is rebuilt once, its
    /// lower parts shared by the workers of `tasks` when given.
    void commit_moves_in_place(TaskSystem* tasks = nullptr);
    /// Grows the fat box in place (or the queued box of a pending move), and the box
    /// ahead with it, and queues the proxy for pair finding.
    void enlarge_proxy(int32_t key, const AABB& fat_aabb);
    /// Queues the proxy for pair finding where it is: a pair it was refused may now be
    /// wanted (a joint that kept two bodies apart went).
    void requery_proxy(int32_t key) { buffer_move(key); }
    /// Every box seen from `new_origin`: the trees', the boxes ahead and those of the
    /// moves waiting for the commit. Trees, orders and queued proxies stay as they were.
    void shift_origin(Vec2 new_origin);

    /// Finds new candidate pairs of the queued proxies and clears the queue. Appends each
    /// pair once to `out` (shape_a < shape_b) if `accept(shape_a, shape_b)` says so; the
    /// caller's accept rejects pairs that already have a contact or must not collide.
    template <class Accept>
    void update_pairs(Accept&& accept, std::vector<ShapePairCandidate>& out);

    // update_pairs in parts, so that workers can share the queries: begin (one thread)
    // commits the moves and orders the queued proxies, returning how many there are;
    // self_pairs does parts [begin, end) of the dynamic tree's search against itself
    // (self_part_count() of them, none unless most dynamic proxies moved, see the .cpp)
    // and query_pairs queries [begin, end); both may run on several threads at once over
    // disjoint ranges, reading only. end_pair_queries (one thread) clears the queue. The
    // self parts' pairs in order, then the queries', are the pairs update_pairs gives.
    // `ahead(a, b)` is called for each candidate as it is found, some time before
    // accept(a, b) is.
    int32_t begin_pair_queries();
    int32_t self_part_count() const { return dynamic_pairs_by_self_search_ ? int32_t(self_parts_.size()) : 0; }
    template <class Accept, class Ahead>
    void self_pairs(int32_t begin, int32_t end, Accept&& accept, std::vector<ShapePairCandidate>& out,
                    Ahead&& ahead) const;
    template <class Accept, class Ahead>
    void query_pairs(int32_t begin, int32_t end, Accept&& accept, std::vector<ShapePairCandidate>& out,
                     Ahead&& ahead) const;
    void end_pair_queries();

    const DynamicTree& tree(ProxyKind kind) const { return trees_[int32_t(kind)]; }
    DynamicTree& tree(ProxyKind kind) { return trees_[int32_t(kind)]; }
    const AABB& fat_aabb(int32_t key) const { return tree(proxy_kind(key)).fat_aabb(proxy_id(key)); }
    /// The box the proxy meets static and kinematic ones by (its fat box unless dynamic).
    const AABB& ahead_aabb(int32_t key) const {
        return proxy_kind(key) == ProxyKind::dynamic_proxy ? ahead_[std::size_t(proxy_id(key))] : fat_aabb(key);
    }
    /// Where the proxy's leaf lies in its tree's node array (see storage order below).
    uint32_t storage_order_of(int32_t key) const { return storage_order(key); }
    /// Proxies waiting for pair finding (destroyed ones no longer count).
    int32_t move_count() const { return move_set_.count(); }

    /// Saves the trees, the boxes ahead and the moves waiting for the next step, or loads
    /// and checks them (core/field_io.hpp; broad_phase_snapshot.cpp).
    void save(SaveIo& io) const;
    void load(LoadIo& io);

private:
    void buffer_move(int32_t key);
    void check_loaded(LoadIo& io);
    void set_ahead(int32_t key, const AABB& ahead_aabb);
    void order_pending_moves();
    void finish_commit(TaskSystem* tasks);
    static void build_tree_parts(const BroadPhase& self, DynamicTree& tree, const NoStageArg& arg, int32_t begin,
                                 int32_t end, int32_t worker);
    int32_t& pending_slot(int32_t key) { return slot_of(pending_slot_, key); }
    int32_t& move_slot(int32_t key) { return slot_of(move_slot_, key); }
    /// slots[key], growing slots (with null_index) to hold it.
    static int32_t& slot_of(std::vector<int32_t>& slots, int32_t key);
    // Storage order: re-insertions and pair queries are made in the order of the
    // proxies' leaves in the node array, which compact() keeps depth-first. In caller
    // order (random in space) a tree larger than the cache misses it at nearly every
    // node; in storage order consecutive proxies are neighbours in the tree, share most
    // of their paths, and walk memory forwards, which the hardware prefetches. Sorting
    // by a Morton code of the boxes instead was 19 % slower at 64k moving shapes.
    struct MoveEntry {
        uint32_t order;  // the leaf's storage order
        int32_t key;
        AABB box;
    };
    struct QueryEntry {
        uint32_t order;
        int32_t key;
    };
    uint32_t storage_order(int32_t key) const {
        // Trees of other kinds interleave; each one's leaves still come in order.
        return uint32_t(tree(proxy_kind(key)).storage_order(proxy_id(key)));
    }

    DynamicTree trees_[int32_t(ProxyKind::count)];
    std::vector<AABB> ahead_;           // dynamic proxy id -> its box ahead
    std::vector<int32_t> move_buffer_;  // proxy keys, in the order they moved
    BitSet move_set_;                   // the same keys, for "did the other one move too"
    // key -> index in move_buffer_, or null_index: a proxy destroyed after it moved is
    // blanked there at once, not searched for (a level torn down before its first step
    // would take time quadratic in its size).
    std::vector<int32_t> move_slot_;
    std::vector<MoveEntry> pending_moves_;  // re-insertions waiting for commit_moves
    std::vector<int32_t> pending_slot_;     // key -> index in pending_moves_, or null_index
    std::vector<MoveEntry> move_scratch_;
    std::vector<QueryEntry> queries_;       // the move buffer in storage order
    std::vector<QueryEntry> query_scratch_;
    // Set by begin_pair_queries when the dynamic tree's pairs come from self_pairs.
    bool dynamic_pairs_by_self_search_ = false;
    bool self_search_marked_ = false;  // the moved dynamic proxies are marked in their tree
    std::vector<TreeNodePair> self_parts_;
    // The commit's shared tree builds.
    StageRunner runner_;
    std::vector<Stage> stages_;
};

}  // namespace i2d

#include "broadphase/broad_phase_pairs.inl"
