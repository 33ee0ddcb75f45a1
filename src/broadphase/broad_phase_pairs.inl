// SPDX-License-Identifier: MIT
// BroadPhase::update_pairs, templated on the caller's accept test so that it inlines.
#pragma once

namespace i2d {

template <class Accept>
void BroadPhase::update_pairs(Accept&& accept, std::vector<ShapePairCandidate>& out) {
    const int32_t count = begin_pair_queries();
    query_pairs(0, count, accept, out, [](int32_t, int32_t) {});
    end_pair_queries();
}

// Candidates are handed to accept a few dozen at a time, in the order they were found,
// after `ahead` has been told of each as it was found: the caller's own lookup for a
// pair (the contact set's hash of known pairs, a cache miss per candidate in a large
// world) can then be asked for while the traversal goes on.
template <class Accept, class Ahead>
void BroadPhase::query_pairs(int32_t begin, int32_t end, Accept&& accept, std::vector<ShapePairCandidate>& out,
                             Ahead&& ahead) const {
    constexpr int32_t batch = 32;
    ShapePairCandidate found[batch];
    int32_t found_count = 0;
    const auto flush = [&]() {
        for (int32_t i = 0; i < found_count; ++i) {
            if (accept(found[i].shape_a, found[i].shape_b)) {
                out.push_back(found[i]);
            }
        }
        found_count = 0;
    };
    for (int32_t q = begin; q < end; ++q) {
        const QueryEntry& entry = queries_[std::size_t(q)];
        const int32_t key = entry.key;
        const ProxyKind kind = proxy_kind(key);
        const DynamicTree& own = tree(kind);
        const AABB box = own.fat_aabb_at(int32_t(entry.order));
        const AABB box_ahead = kind == ProxyKind::dynamic_proxy ? ahead_[std::size_t(proxy_id(key))] : box;
        const int32_t shape = own.user_value_at(int32_t(entry.order));
        // Static and kinematic proxies only pair with dynamic ones.
        for (int32_t t = 0; t < int32_t(ProxyKind::count); ++t) {
            const ProxyKind other_kind = ProxyKind(t);
            if (kind != ProxyKind::dynamic_proxy && other_kind != ProxyKind::dynamic_proxy) {
                continue;
            }
            const AABB& query_box = other_kind == ProxyKind::dynamic_proxy ? box : box_ahead;
            tree(other_kind).query(query_box, [&](int32_t proxy, int32_t other_shape) {
                const int32_t other_key = make_proxy_key(proxy, other_kind);
                // Itself, or a pair both of whose proxies moved: between two dynamic ones
                // the lower key reports it, else the dynamic one, whose box ahead finds
                // all the other's fat box would.
                if (other_key == key ||
                    (move_set_.contains(other_key) && (kind == other_kind ? other_key < key
                                                                          : kind != ProxyKind::dynamic_proxy))) {
                    return true;
                }
                const int32_t a = shape < other_shape ? shape : other_shape;
                const int32_t b = shape < other_shape ? other_shape : shape;
                ahead(a, b);
                found[found_count++] = {a, b};
                if (found_count == batch) {
                    flush();
                }
                return true;
            });
        }
    }
    flush();
}

}  // namespace i2d
