// SPDX-License-Identifier: MIT
// World::validate: cross-checks bodies, shapes, contacts, joints, islands and their links
// (I2D_VALIDATE).
#include <cmath>

#include "core/assert.hpp"
#include "dynamics/world/world.hpp"
#include "dynamics/world/world_stages.hpp"
#include "math/math.hpp"

namespace i2d {

void World::validate() const {
#if defined(I2D_VALIDATE)
    int32_t shapes_seen = 0, contact_edges_seen = 0;
    for (int32_t i = 0; i < bodies_.capacity(); ++i) {
        if (!bodies_.is_live(i)) {
            continue;
        }
        const Body& b = bodies_[i];
        I2D_ASSERT(is_finite(b.transform.p) && is_finite(b.center) && is_finite(b.linear_velocity));
        I2D_ASSERT(std::isfinite(b.mass) && std::isfinite(b.inv_mass));
        I2D_ASSERT(b.type == BodyType::dynamic ? b.mass > 0.0f : b.inv_mass == 0.0f);
        int32_t count = 0;
        int32_t prev = null_index;
        for (int32_t s = b.head_shape; s != null_index; s = shapes_[s].next_in_body) {
            I2D_ASSERT(shapes_.is_live(s) && shapes_[s].body == i && shapes_[s].prev_in_body == prev);
            I2D_ASSERT(count <= b.shape_count);  // no cycle
            prev = s;
            ++count;
        }
        I2D_ASSERT(count == b.shape_count);
        shapes_seen += count;

        count = 0;
        int32_t prev_key = null_index;
        const Pool<Contact>& contacts = stages_->contacts.pool();
        for (int32_t key = b.head_contact_key; key != null_index;) {
            const Contact& c = contacts[key >> 1];
            const ContactEdge& edge = c.edges[key & 1];
            I2D_ASSERT(contacts.is_live(key >> 1) && edge.body == i && edge.prev_key == prev_key);
            I2D_ASSERT(count <= b.contact_count);
            prev_key = key;
            key = edge.next_key;
            ++count;
        }
        I2D_ASSERT(count == b.contact_count);
        contact_edges_seen += count;
        validate_body(i);
    }
    I2D_ASSERT(shapes_seen == shapes_.count());
    I2D_ASSERT(contact_edges_seen == 2 * stages_->contacts.pool().count());
    for (int32_t i = 0; i < shapes_.capacity(); ++i) {
        if (!shapes_.is_live(i)) {
            continue;
        }
        const Shape& s = shapes_[i];
        I2D_ASSERT(is_finite(s.aabb.lower) && is_finite(s.aabb.upper));
        I2D_ASSERT(s.aabb.lower.x <= s.aabb.upper.x && s.aabb.lower.y <= s.aabb.upper.y);
        if (!bodies_[s.body].enabled) {
            I2D_ASSERT(s.proxy_key == null_index && !s.enlarged);  // out of the broadphase
            continue;
        }
        const AABB& fat = stages_->broad_phase.fat_aabb(s.proxy_key);
        I2D_ASSERT(fat.lower == s.fat_aabb.lower && fat.upper == s.fat_aabb.upper);
        const AABB& ahead = stages_->broad_phase.ahead_aabb(s.proxy_key);
        I2D_ASSERT(ahead.lower == s.ahead_aabb.lower && ahead.upper == s.ahead_aabb.upper);
        I2D_ASSERT(contains(s.ahead_aabb, s.fat_aabb));
        I2D_ASSERT(fat.lower.x <= s.aabb.lower.x && fat.lower.y <= s.aabb.lower.y);
        I2D_ASSERT(s.aabb.upper.x <= fat.upper.x && s.aabb.upper.y <= fat.upper.y);
        I2D_ASSERT(stages_->broad_phase.tree(proxy_kind(s.proxy_key)).user_value(proxy_id(s.proxy_key)) == i);
    }
    stages_->contacts.validate();
    stages_->joints.validate();
    stages_->islands.validate();
    for (int32_t k = 0; k < int32_t(ProxyKind::count); ++k) {
        stages_->broad_phase.tree(ProxyKind(k)).validate();
    }
#endif
}

// A moving body belongs to an island, and one asleep does not move; a static body is
// in no island and never awake. A disabled body is in no stage: no island, no awake list,
// no contacts, nothing to cover; it may keep a velocity.
void World::validate_body(int32_t body) const {
#if defined(I2D_VALIDATE)
    const Body& b = bodies_[body];
    if (!b.enabled) {
        I2D_ASSERT(b.awake_index == null_index && b.island == null_index);
        I2D_ASSERT(b.contact_count == 0 && !b.needs_cover);
        return;
    }
    if (b.type == BodyType::static_body) {
        I2D_ASSERT(b.awake_index == null_index && b.island == null_index);
        return;
    }
    I2D_ASSERT(b.island != null_index);
    if (b.awake_index == null_index) {
        I2D_ASSERT(b.linear_velocity == Vec2{} && b.angular_velocity == 0.0f);
    }
#else
    (void)body;
#endif
}

}  // namespace i2d
