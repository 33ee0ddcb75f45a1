// SPDX-License-Identifier: MIT
// BroadPhase: proxies in three trees and the move buffer.
#include "broadphase/broad_phase.hpp"

#include <algorithm>

namespace i2d {

int32_t BroadPhase::create_proxy(const AABB& fat_aabb, const AABB& ahead_aabb, uint64_t category_bits,
                                 int32_t shape, ProxyKind kind, bool query_now) {
    const int32_t proxy = tree(kind).create_proxy(fat_aabb, category_bits, shape);
    const int32_t key = make_proxy_key(proxy, kind);
    set_ahead(key, ahead_aabb);
    if (kind != ProxyKind::static_proxy || query_now) {
        buffer_move(key);
    }
    return key;
}

void BroadPhase::destroy_proxy(int32_t key) {
    if (move_set_.remove(key)) {
        // Blank the entry rather than erase it: the buffer's order is the pair order.
        int32_t& moved = move_slot(key);
        move_buffer_[std::size_t(moved)] = null_index;
        moved = null_index;
    }
    int32_t& slot = pending_slot(key);
    if (slot != null_index) {
        pending_moves_[slot].key = null_index;  // dropped at the commit
        slot = null_index;
    }
    tree(proxy_kind(key)).destroy_proxy(proxy_id(key));
}

void BroadPhase::shift_origin(Vec2 new_origin) {
    for (DynamicTree& tree : trees_) {
        tree.shift_origin(new_origin);
    }
    for (AABB& ahead : ahead_) {
        ahead = relative_to(ahead, new_origin);
    }
    for (MoveEntry& move : pending_moves_) {
        move.box = relative_to(move.box, new_origin);
    }
}

int32_t& BroadPhase::slot_of(std::vector<int32_t>& slots, int32_t key) {
    if (key >= int32_t(slots.size())) {
        slots.resize(size_t(key) + 1, null_index);
    }
    return slots[std::size_t(key)];
}

// Queries read the box ahead only after the commit, so it changes at once.
void BroadPhase::set_ahead(int32_t key, const AABB& ahead_aabb) {
    if (proxy_kind(key) != ProxyKind::dynamic_proxy) {
        return;
    }
    const std::size_t proxy = std::size_t(proxy_id(key));
    if (proxy >= ahead_.size()) {
        ahead_.resize(proxy + 1);
    }
    ahead_[proxy] = ahead_aabb;
}

void BroadPhase::move_proxy(int32_t key, const AABB& fat_aabb, const AABB& ahead_aabb) {
    set_ahead(key, ahead_aabb);
    int32_t& slot = pending_slot(key);
    if (slot == null_index) {
        slot = int32_t(pending_moves_.size());
        pending_moves_.push_back({0, key, fat_aabb});
    } else {
        pending_moves_[slot].box = fat_aabb;
    }
    buffer_move(key);
}

void BroadPhase::enlarge_proxy(int32_t key, const AABB& fat_aabb) {
    if (proxy_kind(key) == ProxyKind::dynamic_proxy) {
        AABB& ahead = ahead_[std::size_t(proxy_id(key))];
        ahead = union_of(ahead, fat_aabb);
    }
    const int32_t slot = pending_slot(key);
    if (slot == null_index) {
        tree(proxy_kind(key)).enlarge_proxy(proxy_id(key), fat_aabb);
    } else {
        AABB& box = pending_moves_[slot].box;
        box = union_of(box, fat_aabb);
    }
    buffer_move(key);
}

// The slots are cleared in the order the moves came in, which is the order of the keys
// when bodies move in creation order: a forward walk, not a random one.
void BroadPhase::order_pending_moves() {
    pending_moves_.erase(std::remove_if(pending_moves_.begin(), pending_moves_.end(),
                                        [](const MoveEntry& e) { return e.key == null_index; }),
                         pending_moves_.end());
    for (MoveEntry& e : pending_moves_) {
        e.order = storage_order(e.key);
        pending_slot_[e.key] = null_index;
    }
    radix_sort(pending_moves_, move_scratch_, [](const MoveEntry& e) { return e.order; });
}

void BroadPhase::commit_moves() {
    order_pending_moves();
    for (const MoveEntry& e : pending_moves_) {
        tree(proxy_kind(e.key)).move_proxy_at(int32_t(e.order), e.box);
    }
    pending_moves_.clear();
    finish_commit(nullptr);
}

namespace {

// A tree in which at least this share of the proxies moved (1 / n) is rebuilt where they
// moved rather than re-inserted into. A rebuild takes the subtrees beside the moved
// leaves' paths as they are, and where few leaves moved it pairs each with a large
// subtree, deepening the tree; many moved leaves share their paths, and the rebuilt part
// is then a fresh tree (the tumbler, 2025 boxes nearly all moving: 0.25 ms a step for
// the move and rebuild against 0.4 ms for re-insertion).
constexpr int32_t rebuild_share_denominator = 8;

}  // namespace

void BroadPhase::commit_moves_in_place(TaskSystem* tasks) {
    order_pending_moves();
    int32_t moves[int32_t(ProxyKind::count)] = {};
    for (const MoveEntry& e : pending_moves_) {
        ++moves[int32_t(proxy_kind(e.key))];
    }
    for (const MoveEntry& e : pending_moves_) {
        const ProxyKind kind = proxy_kind(e.key);
        DynamicTree& t = tree(kind);
        if (rebuild_share_denominator * moves[int32_t(kind)] >= t.proxy_count()) {
            t.move_proxy_in_place_at(int32_t(e.order), e.box);
        } else {
            t.move_proxy_at(int32_t(e.order), e.box);
        }
    }
    pending_moves_.clear();
    finish_commit(tasks);
}

// A tree's commit leaves parts of its rebuild for the workers when there are several.
void BroadPhase::finish_commit(TaskSystem* tasks) {
    const int32_t workers = tasks != nullptr ? tasks->worker_count() : 1;
    for (DynamicTree& t : trees_) {
        const int32_t parts = t.begin_commit(workers);
        if (parts == 0) {
            continue;
        }
        stages_.clear();
        stages_.push_back(make_stage<&BroadPhase::build_tree_parts>(t, NoStageArg{}, parts, workers, true, 1));
        runner_.run(*tasks, stages_, true, this);
        t.finish_commit_parts();
    }
}

void BroadPhase::build_tree_parts(const BroadPhase&, DynamicTree& tree, const NoStageArg&, int32_t begin, int32_t end,
                                  int32_t worker) {
    for (int32_t part = begin; part < end; ++part) {
        tree.build_part(part, worker);
    }
}

void BroadPhase::buffer_move(int32_t key) {
    if (move_set_.insert(key)) {
        move_slot(key) = int32_t(move_buffer_.size());
        move_buffer_.push_back(key);
    }
}

namespace {

// The dynamic tree is searched against itself, rather than queried by each moved dynamic
// proxy, when at least this share (1 / n) of its proxies moved and at least this many.
// The self search meets every overlapping pair once (the queries meet a pair of two
// moved proxies from both sides) and tests each node pair once for all the leaves below
// it, but it also walks the pairs that did not move. In the tumbler (1,940 of its 2,029
// boxes move each step) the pair stage took 0.89 ms a step with the queries and 0.51
// with the search, which descends both nodes of a pair at once (0.55 descending the
// taller one only).
constexpr int32_t self_search_share_denominator = 2;
#if defined(I2D_FUZZ_SHARES_SMALL_WORLDS)
constexpr int32_t self_search_min_moved = 2;  // the fuzzer's worlds are small: search them too
#else
constexpr int32_t self_search_min_moved = 64;
#endif
// Parts the self search is cut into, for workers to share: about a dozen per worker,
// then the heavy ones cut until none holds more than a 64th of the tree. On 2 workers the
// worker done first then waited for the other 38-52 % less in spinner's and tumbler's
// self search.
constexpr int32_t self_search_parts = 32;
constexpr int32_t self_search_max_share = 64;
// Below this share of its proxies moved (tenths), the search keeps to the moved ones
// through marks in the tree (DynamicTree::mark_moved): in rain (two thirds moved) the
// pair stage then took 15.4 % of the step instead of 17.8 %. Above it the marks cost
// more than the few pairs they skip (tumbler, 96 %; spinner, 99 %), and each pair found
// asks the move set instead.
constexpr int32_t self_search_marks_below_tenths = 9;

}  // namespace

int32_t BroadPhase::begin_pair_queries() {
    commit_moves_in_place();
    queries_.clear();
    int32_t moved_dynamic = 0;
    for (const int32_t key : move_buffer_) {
        if (key != null_index) {  // blank: destroyed after it moved
            queries_.push_back({storage_order(key), key});
            moved_dynamic += proxy_kind(key) == ProxyKind::dynamic_proxy ? 1 : 0;
        }
    }
    radix_sort(queries_, query_scratch_, [](const QueryEntry& e) { return e.order; });
    DynamicTree& dynamic = tree(ProxyKind::dynamic_proxy);
    dynamic_pairs_by_self_search_ = moved_dynamic >= self_search_min_moved &&
                                    self_search_share_denominator * moved_dynamic >= dynamic.proxy_count();
    self_search_marked_ = dynamic_pairs_by_self_search_ &&
                          10 * moved_dynamic < self_search_marks_below_tenths * dynamic.proxy_count();
    if (self_search_marked_) {
        // In storage order, so that the leaves and their parents are read in order.
        for (const QueryEntry& entry : queries_) {
            if (proxy_kind(entry.key) == ProxyKind::dynamic_proxy) {
                dynamic.mark_moved(proxy_id(entry.key));
            }
        }
    }
    if (dynamic_pairs_by_self_search_) {
        dynamic.split_self_overlaps(self_search_parts, self_search_max_share, self_parts_);
    }
    return int32_t(queries_.size());
}

void BroadPhase::end_pair_queries() {
    if (self_search_marked_) {
        tree(ProxyKind::dynamic_proxy).clear_moved_marks();
    }
    dynamic_pairs_by_self_search_ = self_search_marked_ = false;
    for (const int32_t key : move_buffer_) {
        if (key != null_index) {
            move_set_.remove(key);
            move_slot_[std::size_t(key)] = null_index;
        }
    }
    move_buffer_.clear();
}

}  // namespace i2d
