// SPDX-License-Identifier: MIT
// World::check_loaded: what joins the stages of a world just loaded from a snapshot,
// checked before the world is used.
//
// A snapshot whose checksum matches was, nearly always, saved by a world; but a caller
// can hand any bytes with a matching checksum, and the step follows indices without
// checking them (its speed depends on that). So every list the step or a later call
// walks (a body's shapes, contacts and joints, an island's bodies, a chain's segments)
// is walked here once, bounded, with every index checked before it is followed, and
// every link is checked from both ends. The stages checked their own lists as they
// loaded (stage_snapshots.cpp, broad_phase_snapshot.cpp).
#include <algorithm>

#include "dynamics/world/world.hpp"
#include "dynamics/world/world_stages.hpp"

namespace i2d {

namespace {

// Walks the list a body heads (keys of two-sided edges, as contacts and joints keep
// them), checking each edge names the body and the one before it; returns the length,
// or -1 when the list is broken.
template <class T>
int32_t walk_edges(const Pool<T>& pool, int32_t body, int32_t head) {
    int32_t length = 0, prev = null_index;
    for (int32_t key = head; key != null_index; ++length) {
        const int32_t item = key >> 1, side = key & 1;
        if (key < 0 || !pool.is_live(item) || length > 2 * pool.count()) {
            return -1;
        }
        const auto& edge = pool[item].edges[side];
        if (edge.body != body || edge.prev_key != prev) {
            return -1;
        }
        prev = key;
        key = edge.next_key;
    }
    return length;
}

}  // namespace

const char* World::check_loaded() const {
    const WorldStages& stages = *stages_;
    const Pool<Joint>& joints = stages.joints.pool();
    const Pool<Contact>& contacts = stages.contacts.pool();
    const std::vector<int32_t>& awake_bodies = stages.islands.awake_bodies();
    int32_t shapes_listed = 0, contact_edges = 0, joint_edges = 0, island_members = 0;
    for (int32_t i = 0; i < bodies_.capacity(); ++i) {
        if (!bodies_.is_live(i)) {
            continue;
        }
        const Body& b = bodies_[i];
        if (b.type == BodyType::dynamic ? !(b.mass > 0.0f) : b.inv_mass != 0.0f) {
            return "a body's mass does not suit its type";
        }
        // A disabled body is neither awake nor asleep, and keeps its velocity.
        if (b.type != BodyType::static_body && b.enabled && b.awake_index == null_index &&
            !(b.linear_velocity == Vec2{} && b.angular_velocity == 0.0f)) {
            return "a sleeping body moves";
        }
        if (!b.enabled && (b.contact_count != 0 || b.needs_cover)) {
            return "a disabled body has contacts or boxes to cover";
        }
        int32_t count = 0;
        for (int32_t s = b.head_shape, prev = null_index; s != null_index; prev = s, s = shapes_[s].next_in_body) {
            if (!shapes_.is_live(s) || shapes_[s].body != i || shapes_[s].prev_in_body != prev ||
                ++count > shapes_.count()) {
                return "a body's shape list is broken";
            }
        }
        if (count != b.shape_count) {
            return "a body's shape count is wrong";
        }
        shapes_listed += count;
        const int32_t body_contacts = walk_edges(contacts, i, b.head_contact_key);
        const int32_t body_joints = walk_edges(joints, i, b.head_joint_key);
        if (body_contacts != b.contact_count || body_joints != b.joint_count) {
            return "a body's contact or joint list is broken";
        }
        contact_edges += body_contacts;
        joint_edges += body_joints;
        const bool moves = b.type != BodyType::static_body && b.enabled;
        if (moves != (b.island != null_index) || (!moves && b.awake_index != null_index)) {
            return "a body's island does not suit its type or its being disabled";
        }
        island_members += moves ? 1 : 0;
        if (b.awake_index != null_index &&
            (b.awake_index < 0 || b.awake_index >= int32_t(awake_bodies.size()) || awake_bodies[b.awake_index] != i)) {
            return "a body's place in the awake list is wrong";
        }
    }
    if (shapes_listed != shapes_.count() || contact_edges != 2 * contacts.count() || joint_edges != 2 * joints.count()) {
        return "a shape, contact or joint is in no body's list";
    }
    for (std::size_t k = 0; k < awake_bodies.size(); ++k) {
        const int32_t body = awake_bodies[k];
        if (!bodies_.is_live(body) || bodies_[body].awake_index != int32_t(k)) {
            return "the awake body list and the bodies disagree";
        }
    }
    if (const char* problem = check_loaded_islands(island_members)) {
        return problem;
    }
    if (const char* problem = check_loaded_shapes()) {
        return problem;
    }
    for (int32_t j = 0; j < joints.capacity(); ++j) {
        if (!joints.is_live(j)) {
            continue;
        }
        const Joint& joint = joints[j];
        const JointDef& d = joint.def;
        if (d.body_a == d.body_b || d.body_a != joint.edges[0].body || d.body_b != joint.edges[1].body) {
            return "a joint's bodies and its links disagree";
        }
        const bool links = stages.joints.should_link(joint);
        if (joint.island_link != links || (links && bodies_[d.body_a].island != bodies_[d.body_b].island) ||
            !angles_wound(d)) {
            return "a joint's island link or its angles are wrong";
        }
    }
    for (int32_t c = 0; c < contacts.capacity(); ++c) {
        if (!contacts.is_live(c)) {
            continue;
        }
        const Contact& contact = contacts[c];
        if (!shapes_.is_live(contact.shape_a) || !shapes_.is_live(contact.shape_b) ||
            shapes_[contact.shape_a].body != contact.edges[0].body || shapes_[contact.shape_b].body != contact.edges[1].body) {
            return "a contact's shapes and its bodies disagree";
        }
        const bool has_awake_body = is_awake(contact.edges[0].body) || is_awake(contact.edges[1].body);
        if (has_awake_body != (contact.awake_index != null_index)) {
            return "a contact is awake without an awake body, or asleep beside one";
        }
        const int32_t island = bodies_[contact.edges[0].body].island;
        if ((contact.flags & contact_island_link) != 0 &&
            (island == null_index || bodies_[contact.edges[1].body].island != island)) {
            return "a contact links bodies of two islands, or of none";
        }
    }
    return check_loaded_island_links();
}

// Each island counts the joints and contacts that link its bodies: unlinking one takes it
// off that count, which a count too small would take below zero. Run once the links
// themselves were checked to join bodies of one island.
const char* World::check_loaded_island_links() const {
    const WorldStages& stages = *stages_;
    const Pool<Island>& islands = stages.islands.pool();
    std::vector<int32_t> links(std::size_t(islands.capacity()), 0);
    const Pool<Joint>& joints = stages.joints.pool();
    for (int32_t j = 0; j < joints.capacity(); ++j) {
        if (joints.is_live(j) && joints[j].island_link) {
            ++links[std::size_t(bodies_[joints[j].def.body_a].island)];
        }
    }
    const Pool<Contact>& contacts = stages.contacts.pool();
    for (int32_t c = 0; c < contacts.capacity(); ++c) {
        if (contacts.is_live(c) && (contacts[c].flags & contact_island_link) != 0) {
            ++links[std::size_t(bodies_[contacts[c].edges[0].body].island)];
        }
    }
    for (int32_t i = 0; i < islands.capacity(); ++i) {
        if (islands.is_live(i) && islands[i].link_count != links[std::size_t(i)]) {
            return "an island's link count is not the number of joints and contacts linking its bodies";
        }
    }
    return nullptr;
}

// Every island's body list is whole, and its bodies are awake together.
const char* World::check_loaded_islands(int32_t island_members) const {
    const Pool<Island>& islands = stages_->islands.pool();
    int32_t members = 0;
    for (int32_t i = 0; i < islands.capacity(); ++i) {
        if (!islands.is_live(i)) {
            continue;
        }
        const Island& island = islands[i];
        const bool awake = island.awake_index != null_index;
        int32_t count = 0, prev = null_index;
        for (int32_t body = island.head_body; body != null_index; prev = body, body = bodies_[body].island_next) {
            if (!bodies_.is_live(body) || bodies_[body].island != i || bodies_[body].island_prev != prev ||
                ++count > island_members || is_awake(body) != awake) {
                return "an island's body list is broken";
            }
        }
        if (count == 0 || count != island.body_count || island.tail_body != prev || island.removed_links < 0 ||
            island.removed_links > max_removed_links) {
            return "an island's counts are wrong";
        }
        members += count;
    }
    return members == island_members ? nullptr : "a moving body is in no island's list";
}

// Every shape of an enabled body has a proxy that names it back, every proxy belongs to
// such a shape, a disabled body's shapes have none, every chain's segments name their
// chain.
const char* World::check_loaded_shapes() const {
    const BroadPhase& broad_phase = stages_->broad_phase;
    int32_t proxies = 0;
    for (int32_t k = 0; k < int32_t(ProxyKind::count); ++k) {
        proxies += broad_phase.tree(ProxyKind(k)).proxy_count();
    }
    int32_t shapes_with_proxies = 0;
    std::vector<int32_t> segments(std::size_t(chains_.capacity()), 0);  // per chain, the shapes naming it
    for (int32_t s = 0; s < shapes_.capacity(); ++s) {
        if (!shapes_.is_live(s)) {
            continue;
        }
        const Shape& shape = shapes_[s];
        if (shape.chain != null_index) {
            if (!chains_.is_live(shape.chain) || chains_[shape.chain].body != shape.body) {
                return "a chain segment's chain is wrong";
            }
            ++segments[std::size_t(shape.chain)];
        }
        if (!bodies_[shape.body].enabled) {
            if (shape.proxy_key != null_index || shape.enlarged ||
                !(shape.aabb.lower.x <= shape.aabb.upper.x && shape.aabb.lower.y <= shape.aabb.upper.y)) {
                return "a disabled body's shape is in the broadphase, or its box is wrong";
            }
            continue;
        }
        ++shapes_with_proxies;
        const int32_t key = shape.proxy_key;
        if (key < 0 || (key & 3) >= int32_t(ProxyKind::count)) {
            return "a shape's proxy is out of range";
        }
        const DynamicTree& tree = broad_phase.tree(proxy_kind(key));
        const int32_t proxy = proxy_id(key);
        if (proxy >= tree.proxy_slots() || !tree.is_live_proxy(proxy) || tree.user_value(proxy) != s) {
            return "a shape and its proxy do not name each other";
        }
        // The boxes the broadphase keeps are the shape's, nested as the step leaves them.
        const AABB& fat = broad_phase.fat_aabb(key);
        const AABB& ahead = broad_phase.ahead_aabb(key);
        if (!(fat.lower == shape.fat_aabb.lower && fat.upper == shape.fat_aabb.upper) ||
            !(ahead.lower == shape.ahead_aabb.lower && ahead.upper == shape.ahead_aabb.upper) ||
            !(shape.aabb.lower.x <= shape.aabb.upper.x && shape.aabb.lower.y <= shape.aabb.upper.y) ||
            !contains(shape.ahead_aabb, shape.fat_aabb) || !contains(shape.fat_aabb, shape.aabb)) {
            return "a shape's boxes and its proxy's disagree";
        }
    }
    if (proxies != shapes_with_proxies) {
        return "the broadphase and the shapes disagree";
    }
    for (int32_t c = 0; c < chains_.capacity(); ++c) {
        if (!chains_.is_live(c)) {
            continue;
        }
        // Each shape naming the chain is listed once: a count and the names agree.
        for (const int32_t s : chains_[c].shapes) {
            if (!shapes_.is_live(s) || shapes_[s].chain != c) {
                return "a chain's segments are wrong";
            }
        }
        std::vector<int32_t> listed = chains_[c].shapes;
        std::sort(listed.begin(), listed.end());
        if (std::adjacent_find(listed.begin(), listed.end()) != listed.end() ||
            int32_t(listed.size()) != segments[std::size_t(c)]) {
            return "a chain's segments are listed twice or not at all";
        }
    }
    return nullptr;
}

}  // namespace i2d
