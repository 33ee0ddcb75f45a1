// SPDX-License-Identifier: MIT
// BroadPhase: proxies in three trees and the move buffer.
#include "broadphase/broad_phase.hpp"

namespace i2d {

int32_t BroadPhase::create_proxy(const AABB& fat_aabb, uint64_t category_bits, int32_t shape, ProxyKind kind,
                                 bool query_now) {
    const int32_t proxy = tree(kind).create_proxy(fat_aabb, category_bits, shape);
    const int32_t key = make_proxy_key(proxy, kind);
    if (kind != ProxyKind::static_proxy || query_now) {
        buffer_move(key);
    }
    return key;
}

void BroadPhase::destroy_proxy(int32_t key) {
    if (move_set_.remove(uint64_t(key) + 1)) {
        // Blank the entry rather than erase it: the buffer's order is the pair order.
        for (int32_t& moved : move_buffer_) {
            if (moved == key) {
                moved = null_index;
                break;
            }
        }
    }
    tree(proxy_kind(key)).destroy_proxy(proxy_id(key));
}

void BroadPhase::move_proxy(int32_t key, const AABB& fat_aabb) {
    tree(proxy_kind(key)).move_proxy(proxy_id(key), fat_aabb);
    buffer_move(key);
}

void BroadPhase::enlarge_proxy(int32_t key, const AABB& fat_aabb) {
    tree(proxy_kind(key)).enlarge_proxy(proxy_id(key), fat_aabb);
    buffer_move(key);
}

void BroadPhase::buffer_move(int32_t key) {
    if (move_set_.insert(uint64_t(key) + 1)) {
        move_buffer_.push_back(key);
    }
}

}  // namespace i2d
