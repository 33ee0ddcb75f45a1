// SPDX-License-Identifier: MIT
// ProxyKind and proxy keys: which tree a shape's proxy lives in (one per body type), and
// the key that names the proxy across the trees.
#pragma once

#include <cstdint>

namespace i2d {

enum class ProxyKind : uint8_t { static_proxy = 0, kinematic_proxy = 1, dynamic_proxy = 2, count };

/// A proxy key packs the tree (low 2 bits) and the proxy id within it.
inline int32_t make_proxy_key(int32_t proxy, ProxyKind kind) { return (proxy << 2) | int32_t(kind); }
inline ProxyKind proxy_kind(int32_t key) { return ProxyKind(key & 3); }
inline int32_t proxy_id(int32_t key) { return key >> 2; }

}  // namespace i2d
