// SPDX-License-Identifier: MIT
// Islands: merging on link, lazy splitting, sleeping and waking.
#include "dynamics/island/island.hpp"

#include <algorithm>
#include <cfloat>

#include "core/assert.hpp"
#include "core/dense_list.hpp"
#include "core/reserve.hpp"

namespace i2d {

void Islands::add_awake_body(int32_t body) {
    ++awake_version_;
    dense_list_add(awake_bodies_, body, [this](int32_t b) -> int32_t& { return bodies_[b].awake_index; });
}

void Islands::remove_awake_body(int32_t body) {
    ++awake_version_;
    dense_list_remove(awake_bodies_, body, [this](int32_t b) -> int32_t& { return bodies_[b].awake_index; });
}

void Islands::add_awake_island(int32_t island) {
    dense_list_add(awake_islands_, island, [this](int32_t i) -> int32_t& { return islands_[i].awake_index; });
}

void Islands::remove_awake_island(int32_t island) {
    dense_list_remove(awake_islands_, island, [this](int32_t i) -> int32_t& { return islands_[i].awake_index; });
}

void Islands::append_body(int32_t island, int32_t body) {
    Island& record = islands_[island];
    Body& b = bodies_[body];
    b.island = island;
    b.island_prev = record.tail_body;
    b.island_next = null_index;
    if (record.tail_body != null_index) {
        bodies_[record.tail_body].island_next = body;
    } else {
        record.head_body = body;
    }
    record.tail_body = body;
    ++record.body_count;
}

void Islands::detach_body(int32_t body) {
    Body& b = bodies_[body];
    Island& record = islands_[b.island];
    (b.island_prev != null_index ? bodies_[b.island_prev].island_next : record.head_body) = b.island_next;
    (b.island_next != null_index ? bodies_[b.island_next].island_prev : record.tail_body) = b.island_prev;
    --record.body_count;
    b.island = b.island_prev = b.island_next = null_index;
}

void Islands::add_body(int32_t body) {
    // Room in the awake lists for every slot first, so that waking never allocates.
    reserve_room(awake_bodies_, std::size_t(bodies_.capacity()) + 1);
    const int32_t island = islands_.allocate();
    reserve_room(awake_islands_, std::size_t(islands_.capacity()) + 1);
    append_body(island, body);
    add_awake_island(island);
    add_awake_body(body);
}

// Its links went with its contacts, so the rest of the island may be in pieces: that
// was counted when they were unlinked.
void Islands::remove_body(int32_t body) {
    wake_body(body);
    const int32_t island = bodies_[body].island;
    detach_body(body);
    remove_awake_body(body);
    if (islands_[island].body_count == 0) {
        remove_awake_island(island);
        islands_.free(island);
    }
}

void Islands::link(int32_t body_a, int32_t body_b) {
    const int32_t a = bodies_[body_a].island, b = bodies_[body_b].island;
    if (a == b) {
        ++islands_[a].link_count;
        return;
    }
    // The smaller joins the larger, so that a body changes island O(log n) times.
    if (islands_[a].body_count >= islands_[b].body_count) {
        merge(b, a);
        ++islands_[a].link_count;
    } else {
        merge(a, b);
        ++islands_[b].link_count;
    }
}

void Islands::unlink(int32_t body) {
    Island& record = islands_[bodies_[body].island];
    --record.link_count;
    record.removed_links = std::min(record.removed_links + 1, max_removed_links);
}

void Islands::apply(const std::vector<LinkChange>& changes) {
    for (const LinkChange& change : changes) {
        if (change.links) {
            link(change.body_a, change.body_b);
        } else {
            unlink(change.body_a);
        }
    }
}

void Islands::merge(int32_t from, int32_t into) {
    Island& source = islands_[from];
    Island& target = islands_[into];
    for (int32_t body = source.head_body; body != null_index; body = bodies_[body].island_next) {
        bodies_[body].island = into;
    }
    bodies_[target.tail_body].island_next = source.head_body;
    bodies_[source.head_body].island_prev = target.tail_body;
    target.tail_body = source.tail_body;
    target.body_count += source.body_count;
    target.link_count += source.link_count;
    target.removed_links = std::min(target.removed_links + source.removed_links, max_removed_links);
    remove_awake_island(from);
    islands_.free(from);
}

void Islands::wake_body(int32_t body) {
    Body& b = bodies_[body];
    b.sleep_time = 0.0f;
    if (b.island != null_index && islands_[b.island].awake_index == null_index) {
        wake_island(b.island);
    }
}

void Islands::wake_island(int32_t island) {
    if (islands_[island].awake_index != null_index) {
        return;
    }
    add_awake_island(island);
    for (int32_t body = islands_[island].head_body; body != null_index; body = bodies_[body].island_next) {
        bodies_[body].sleep_time = 0.0f;
        add_awake_body(body);
        woken_.push_back(body);
    }
}

void Islands::wake_all() {
    for (int32_t i = 0; i < islands_.capacity(); ++i) {
        if (islands_.is_live(i)) {
            wake_island(i);
        }
    }
}

void Islands::put_to_sleep(int32_t island) {
    for (int32_t body = islands_[island].head_body; body != null_index; body = bodies_[body].island_next) {
        Body& b = bodies_[body];
        b.linear_velocity = {};
        b.angular_velocity = 0.0f;
        b.force = {};
        b.torque = 0.0f;
        b.sleep_time = 0.0f;
        remove_awake_body(body);
    }
    remove_awake_island(island);
}

// Depth first over the links from each body not yet placed, in the island's list order,
// so that the same island always splits the same way.
void Islands::split(int32_t island, LinkVisitor links) {
    members_.clear();
    for (int32_t body = islands_[island].head_body; body != null_index; body = bodies_[body].island_next) {
        members_.push_back(body);
        bodies_[body].island = null_index;  // not placed yet
    }
    const bool awake = islands_[island].awake_index != null_index;
    island_pieces_.clear();
    int32_t links_seen = 0;
    for (const int32_t seed : members_) {
        if (bodies_[seed].island != null_index) {
            continue;
        }
        int32_t piece = island;
        if (!island_pieces_.empty()) {
            piece = islands_.allocate();
            if (awake) {
                add_awake_island(piece);
            }
        }
        Island& record = islands_[piece];
        record.head_body = record.tail_body = null_index;
        record.body_count = record.link_count = record.removed_links = 0;
        island_pieces_.push_back(piece);
        links_seen = 0;
        stack_.assign(1, seed);
        bodies_[seed].island = piece;
        while (!stack_.empty()) {
            const int32_t body = stack_.back();
            stack_.pop_back();
            append_body(piece, body);
            const auto follow = [&](int32_t other) {
                ++links_seen;
                if (bodies_[other].island == null_index) {
                    bodies_[other].island = piece;
                    stack_.push_back(other);
                }
            };
            links(body, follow);
        }
        islands_[piece].link_count = links_seen / 2;  // each link seen from both ends
    }
}

void Islands::begin_rest_times() { island_rest_.assign(awake_islands_.size(), FLT_MAX); }

void Islands::validate() const {
#if defined(I2D_VALIDATE)
    for (int32_t k = 0; k < int32_t(awake_bodies_.size()); ++k) {
        I2D_ASSERT(bodies_.is_live(awake_bodies_[k]) && bodies_[awake_bodies_[k]].awake_index == k);
        I2D_ASSERT(islands_[bodies_[awake_bodies_[k]].island].awake_index != null_index);
    }
    for (int32_t k = 0; k < int32_t(awake_islands_.size()); ++k) {
        I2D_ASSERT(islands_.is_live(awake_islands_[k]) && islands_[awake_islands_[k]].awake_index == k);
    }
    for (int32_t i = 0; i < islands_.capacity(); ++i) {
        if (!islands_.is_live(i)) {
            continue;
        }
        const Island& record = islands_[i];
        const bool awake = record.awake_index != null_index;
        int32_t count = 0, prev = null_index;
        for (int32_t body = record.head_body; body != null_index; body = bodies_[body].island_next) {
            const Body& b = bodies_[body];
            I2D_ASSERT(bodies_.is_live(body) && b.island == i && b.island_prev == prev);
            I2D_ASSERT((b.awake_index != null_index) == awake);
            I2D_ASSERT(count <= record.body_count);  // no cycle
            prev = body;
            ++count;
        }
        I2D_ASSERT(count == record.body_count && count > 0 && record.tail_body == prev);
        I2D_ASSERT(record.link_count >= 0 && record.removed_links >= 0);
    }
#endif
}

}  // namespace i2d
