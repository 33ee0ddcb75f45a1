// SPDX-License-Identifier: MIT
// BroadPhase's pair finding, templated on the caller's accept test so that it inlines.
#pragma once

namespace i2d {

namespace broad_phase_detail {

// Candidates are handed to accept a few dozen at a time, in the order they were found,
// after `ahead` has been told of each as it was found: the caller's own lookup for a
// pair (the contact set's hash of known pairs, a cache miss per candidate in a large
// world) can then be asked for while the traversal goes on.
template <class Accept, class Ahead>
class CandidateBatch {
public:
    CandidateBatch(Accept& accept, Ahead& ahead, std::vector<ShapePairCandidate>& out)
        : accept_(accept), ahead_(ahead), out_(out) {}
    void add(int32_t shape, int32_t other_shape) {
        const int32_t a = shape < other_shape ? shape : other_shape;
        const int32_t b = shape < other_shape ? other_shape : shape;
        ahead_(a, b);
        found_[count_++] = {a, b};
        if (count_ == capacity) {
            flush();
        }
    }
    void flush() {
        for (int32_t i = 0; i < count_; ++i) {
            if (accept_(found_[i].shape_a, found_[i].shape_b)) {
                out_.push_back(found_[i]);
            }
        }
        count_ = 0;
    }

private:
    static constexpr int32_t capacity = 32;
    Accept& accept_;
    Ahead& ahead_;
    std::vector<ShapePairCandidate>& out_;
    ShapePairCandidate found_[capacity];
    int32_t count_ = 0;
};

}  // namespace broad_phase_detail

template <class Accept>
void BroadPhase::update_pairs(Accept&& accept, std::vector<ShapePairCandidate>& out) {
    const int32_t count = begin_pair_queries();
    const auto no_ahead = [](int32_t, int32_t) {};
    self_pairs(0, self_part_count(), accept, out, no_ahead);
    query_pairs(0, count, accept, out, no_ahead);
    end_pair_queries();
}

// A leaf pair of which neither proxy moved was paired, or refused, when one last did.
// Where the moved proxies are marked in the tree (begin_pair_queries), the search meets
// no other pairs.
template <class Accept, class Ahead>
void BroadPhase::self_pairs(int32_t begin, int32_t end, Accept&& accept, std::vector<ShapePairCandidate>& out,
                            Ahead&& ahead) const {
    broad_phase_detail::CandidateBatch<Accept, Ahead> batch(accept, ahead, out);
    const DynamicTree& dynamic = tree(ProxyKind::dynamic_proxy);
    for (int32_t part = begin; part < end; ++part) {
        dynamic.self_overlaps(self_parts_[std::size_t(part)], [&](int32_t proxy_a, int32_t shape_a, int32_t proxy_b,
                                                                  int32_t shape_b) {
            if (self_search_marked_ || move_set_.contains(make_proxy_key(proxy_a, ProxyKind::dynamic_proxy)) ||
                move_set_.contains(make_proxy_key(proxy_b, ProxyKind::dynamic_proxy))) {
                batch.add(shape_a, shape_b);
            }
        });
    }
    batch.flush();
}

template <class Accept, class Ahead>
void BroadPhase::query_pairs(int32_t begin, int32_t end, Accept&& accept, std::vector<ShapePairCandidate>& out,
                             Ahead&& ahead) const {
    broad_phase_detail::CandidateBatch<Accept, Ahead> batch(accept, ahead, out);
    for (int32_t q = begin; q < end; ++q) {
        const QueryEntry& entry = queries_[std::size_t(q)];
        const int32_t key = entry.key;
        const ProxyKind kind = proxy_kind(key);
        const DynamicTree& own = tree(kind);
        const AABB box = own.fat_aabb_at(int32_t(entry.order));
        const AABB box_ahead = kind == ProxyKind::dynamic_proxy ? ahead_[std::size_t(proxy_id(key))] : box;
        const int32_t shape = own.user_value_at(int32_t(entry.order));
        // Static proxies never pair among themselves.
        for (int32_t t = 0; t < int32_t(ProxyKind::count); ++t) {
            const ProxyKind other_kind = ProxyKind(t);
            if ((kind == ProxyKind::static_proxy && other_kind == ProxyKind::static_proxy) ||
                (kind == ProxyKind::dynamic_proxy && other_kind == kind && dynamic_pairs_by_self_search_)) {
                continue;
            }
            const AABB& query_box = other_kind == ProxyKind::dynamic_proxy ? box : box_ahead;
            tree(other_kind).query(query_box, [&](int32_t proxy, int32_t other_shape) {
                const int32_t other_key = make_proxy_key(proxy, other_kind);
                // Itself, or a pair both of whose proxies moved: between two of one kind
                // the lower key reports it, else the one of the later kind (dynamic before
                // kinematic before static), so that a dynamic proxy's box ahead finds all
                // the other's fat box would.
                if (other_key == key ||
                    (move_set_.contains(other_key) && (kind == other_kind ? other_key < key : kind < other_kind))) {
                    return true;
                }
                batch.add(shape, other_shape);
                return true;
            });
        }
    }
    batch.flush();
}

}  // namespace i2d
