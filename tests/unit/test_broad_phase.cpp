// SPDX-License-Identifier: MIT
// BroadPhase against brute force, driven the way the world drives it: proxies move (re-inserted
// or enlarged when their tight box leaves the fat box), appear and disappear over many rounds;
// the caller's accept keeps a set of known pairs and rejects them, and pairs whose fat boxes
// stop overlapping are dropped. After every update the known set must equal the brute-force set
// of overlapping fat-box pairs with at least one dynamic side. Also: each pair once per update,
// accept sees only pairs with a dynamic side, and two identical runs give identical sequences.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <iterator>
#include <set>
#include <utility>
#include <vector>

#include "broadphase/broad_phase.hpp"
#include "brute_geometry.hpp"
#include "check.h"
#include "test_rng.hpp"

using namespace i2d;
using brute::boxes_overlap;
using brute::same_box;

namespace {

using Pair = std::pair<int32_t, int32_t>;  // shape ids, first < second

constexpr float margin = 0.1f;  // fat box = tight box grown by this, as the engine does

bool inside(const AABB& inner, const AABB& outer) {
    return inner.lower.x >= outer.lower.x && inner.lower.y >= outer.lower.y && inner.upper.x <= outer.upper.x &&
           inner.upper.y <= outer.upper.y;
}

AABB fatten(const AABB& b) { return {{b.lower.x - margin, b.lower.y - margin}, {b.upper.x + margin, b.upper.y + margin}}; }

struct Shape {
    int32_t key = null_index;
    ProxyKind kind = ProxyKind::dynamic_proxy;
    AABB tight, fat;
    Vec2 velocity;
    bool alive = false;
};

struct Options {
    uint32_t seed = 1;
    int32_t initial = 2000;
    int32_t rounds = 40;
    float world = 45.0f;     // shapes live in [-world, world]^2
    bool filter = false;     // accept also rejects pairs with (a + b) % 5 == 0 (a custom filter)
    bool rebuild_static = false;  // rebuild the static tree after creating the level
    bool in_parts = false;   // find pairs through the parts API, each range split in two as workers would
    bool calm_even_rounds = false;  // even rounds move at a tenth of the speed: few proxies leave their boxes
};

// What went wrong, counted; and the sequence of every update's pairs for the determinism test.
struct Report {
    int32_t not_ordered = 0;        // accept(a, b) with a >= b, or out with shape_a >= shape_b
    int32_t dead_shape = 0;         // accept saw a destroyed or unknown shape
    int32_t static_static = 0;      // accept saw two static proxies (never paired)
    int32_t without_dynamic = 0;    // accept saw a kinematic proxy with a static or kinematic one
    int32_t not_overlapping = 0;    // accept saw a pair whose fat boxes do not overlap
    int32_t accepted_twice = 0;     // accept called twice for a pair in one update
    int32_t out_mismatch = 0;       // out is not the sequence of accepted pairs
    int32_t known_mismatch = 0;     // rounds where the known set differs from brute force
    int32_t storage_errors = 0;     // fat boxes, counts, move buffer after the update
    int64_t pairs_reported = 0, accept_calls = 0;
    int32_t max_known = 0;
    std::vector<Pair> sequence;     // every pair appended to out, in order
    std::vector<int32_t> per_update;
    int32_t self_search_updates = 0;  // in_parts only: updates that searched the dynamic tree against itself
};

class Harness {
public:
    explicit Harness(const Options& o) : opt_(o), rng_(o.seed) {}

    Report run() {
        // A static level first (floors, walls, scattered blocks), then everything else.
        const int32_t statics = opt_.initial / 5;
        for (int32_t i = 0; i < statics; ++i) {
            create(ProxyKind::static_proxy);
        }
        if (opt_.rebuild_static) {
            bp_.tree(ProxyKind::static_proxy).rebuild();
        }
        for (int32_t i = statics; i < opt_.initial; ++i) {
            create(random_moving_kind());
        }
        update();
        for (int32_t round = 1; round < opt_.rounds; ++round) {
            mutate(round);
            update();
        }
        return std::move(report_);
    }

private:
    ProxyKind random_moving_kind() {
        return rng_.below(5) == 0 ? ProxyKind::kinematic_proxy : ProxyKind::dynamic_proxy;
    }

    AABB random_tight(ProxyKind kind) {
        const float w = opt_.world;
        const float x = rng_.uniform(-w, w), y = rng_.uniform(-w, w);
        if (kind == ProxyKind::static_proxy && rng_.below(4) == 0) {
            // A floor or a wall: long and thin.
            const float len = rng_.uniform(5.0f, 20.0f);
            return rng_.below(2) ? AABB{{x, y}, {x + len, y + 0.5f}} : AABB{{x, y}, {x + 0.5f, y + len}};
        }
        const float s = rng_.uniform(0.2f, 2.0f);
        return {{x, y}, {x + s, y + rng_.uniform(0.2f, 2.0f)}};
    }

    int32_t new_shape_id() {
        // Reused like the engine's pool: lowest freed ids come back first.
        if (!free_ids_.empty()) {
            std::sort(free_ids_.begin(), free_ids_.end(), std::greater<int32_t>());
            const int32_t id = free_ids_.back();
            free_ids_.pop_back();
            return id;
        }
        shapes_.emplace_back();
        return int32_t(shapes_.size()) - 1;
    }

    void create(ProxyKind kind) {
        const int32_t id = new_shape_id();
        Shape& s = shapes_[id];
        s.kind = kind;
        s.tight = random_tight(kind);
        s.fat = fatten(s.tight);
        const float v = kind == ProxyKind::static_proxy ? 0.0f : 0.3f;
        s.velocity = {rng_.uniform(-v, v), rng_.uniform(-v, v)};
        s.alive = true;
        // Statics ask for pairs now too: otherwise a new static next to a resting dynamic
        // proxy would (by design) not pair until that proxy moves, and brute force would differ.
        s.key = bp_.create_proxy(s.fat, 1, id, kind, true);
    }

    void destroy(int32_t id) {
        Shape& s = shapes_[id];
        bp_.destroy_proxy(s.key);
        s.alive = false;
        s.key = null_index;
        free_ids_.push_back(id);
        // The engine destroys the shape's contacts.
        for (auto it = known_.begin(); it != known_.end();) {
            it = (it->first == id || it->second == id) ? known_.erase(it) : std::next(it);
        }
    }

    int32_t random_alive() {
        for (;;) {
            const int32_t id = rng_.below(int32_t(shapes_.size()));
            if (shapes_[id].alive) {
                return id;
            }
        }
    }

    // Moves a shape's tight box; when it leaves the fat box, re-inserts it (or, a third of
    // the time, enlarges the fat box to cover the new one, as the engine does for fast bodies).
    void displace(int32_t id, Vec2 d) {
        Shape& s = shapes_[id];
        s.tight = {s.tight.lower + d, s.tight.upper + d};
        if (inside(s.tight, s.fat)) {
            return;
        }
        if (rng_.below(3) == 0) {
            s.fat = union_of(s.fat, fatten(s.tight));
            bp_.enlarge_proxy(s.key, s.fat);
        } else {
            s.fat = fatten(s.tight);
            bp_.move_proxy(s.key, s.fat);
        }
    }

    void mutate(int32_t round) {
        // Every moving shape drifts; a few jump; statics move rarely.
        for (int32_t id = 0; id < int32_t(shapes_.size()); ++id) {
            Shape& s = shapes_[id];
            if (!s.alive) {
                continue;
            }
            if (s.kind == ProxyKind::static_proxy) {
                if (rng_.below(200) == 0) {
                    displace(id, {rng_.uniform(-3.0f, 3.0f), rng_.uniform(-3.0f, 3.0f)});
                }
                continue;
            }
            Vec2 d = opt_.calm_even_rounds && round % 2 == 0 ? 0.1f * s.velocity : s.velocity;
            if (rng_.below(100) == 0) {
                d = {rng_.uniform(-8.0f, 8.0f), rng_.uniform(-8.0f, 8.0f)};
            }
            // Bounce inside the region.
            const Vec2 c = center(s.tight) + d;
            if (c.x < -opt_.world || c.x > opt_.world) {
                s.velocity.x = -s.velocity.x;
                d.x = -d.x;
            }
            if (c.y < -opt_.world || c.y > opt_.world) {
                s.velocity.y = -s.velocity.y;
                d.y = -d.y;
            }
            displace(id, d);
        }
        // Destroy some (including some that moved this round and sit in the move buffer), and
        // create some (reusing freed ids, and so often the freed proxy ids too).
        const int32_t changes = opt_.initial / 50 + (round % 7 == 3 ? opt_.initial / 5 : 0);
        for (int32_t i = 0; i < changes; ++i) {
            destroy(random_alive());
        }
        for (int32_t i = 0; i < changes; ++i) {
            create(rng_.below(6) == 0 ? ProxyKind::static_proxy : random_moving_kind());
        }
        // A destroy and a create right after a move: the new proxy may take the moved one's key.
        for (int32_t i = 0; i < 3; ++i) {
            const int32_t id = random_alive();
            displace(id, {5.0f, 5.0f});
            const ProxyKind kind = shapes_[id].kind;
            destroy(id);
            create(kind);
        }
    }

    bool filtered_out(int32_t a, int32_t b) const { return opt_.filter && (a + b) % 5 == 0; }

    void update() {
        std::set<Pair> called;
        std::vector<ShapePairCandidate> accepted, out;
        out.push_back({-7, -3});  // update_pairs appends: what is there must stay
        const auto accept = [&](int32_t a, int32_t b) {
                ++report_.accept_calls;
                const int32_t n = int32_t(shapes_.size());
                if (a < 0 || b < 0 || a >= n || b >= n || !shapes_[a].alive || !shapes_[b].alive) {
                    ++report_.dead_shape;
                    return false;
                }
                if (a >= b) {
                    ++report_.not_ordered;
                }
                const ProxyKind ka = shapes_[a].kind, kb = shapes_[b].kind;
                if (ka == ProxyKind::static_proxy && kb == ProxyKind::static_proxy) {
                    ++report_.static_static;
                } else if (ka != ProxyKind::dynamic_proxy && kb != ProxyKind::dynamic_proxy) {
                    ++report_.without_dynamic;
                }
                if (!boxes_overlap(shapes_[a].fat, shapes_[b].fat)) {
                    ++report_.not_overlapping;
                }
                if (!called.insert({a, b}).second) {
                    ++report_.accepted_twice;
                }
                // The engine's answer: no second contact for a pair, none for filtered pairs.
                const bool ok = known_.count({a, b}) == 0 && !filtered_out(a, b);
                if (ok) {
                    accepted.push_back({a, b});
                }
                return ok;
            };
        if (opt_.in_parts) {
            find_pairs_in_parts(accept, out);
        } else {
            bp_.update_pairs(accept, out);
        }

        // out holds the old entry and then exactly the accepted pairs, in order.
        bool same = out.size() == accepted.size() + 1 && out[0].shape_a == -7 && out[0].shape_b == -3;
        for (size_t i = 0; same && i < accepted.size(); ++i) {
            same = out[i + 1].shape_a == accepted[i].shape_a && out[i + 1].shape_b == accepted[i].shape_b;
        }
        report_.out_mismatch += same ? 0 : 1;
        for (size_t i = 1; i < out.size(); ++i) {
            const ShapePairCandidate& p = out[i];
            report_.not_ordered += p.shape_a < p.shape_b ? 0 : 1;
            report_.sequence.push_back({p.shape_a, p.shape_b});
            if (p.shape_a >= 0 && p.shape_b >= 0) {
                known_.insert({p.shape_a, p.shape_b});
            }
        }
        report_.pairs_reported += int64_t(out.size()) - 1;
        report_.per_update.push_back(int32_t(out.size()) - 1);

        // The narrowphase drops contacts whose fat boxes stopped overlapping.
        for (auto it = known_.begin(); it != known_.end();) {
            it = boxes_overlap(shapes_[it->first].fat, shapes_[it->second].fat) ? std::next(it) : known_.erase(it);
        }
        report_.max_known = std::max(report_.max_known, int32_t(known_.size()));
        check_against_brute_force();
        check_storage();
    }

    // As two workers would: each half of each range into a list of its own, the lists
    // then appended in order.
    template <class Accept>
    void find_pairs_in_parts(Accept& accept, std::vector<ShapePairCandidate>& out) {
        const int32_t queries = bp_.begin_pair_queries();
        const int32_t parts = bp_.self_part_count();
        report_.self_search_updates += parts > 0 ? 1 : 0;
        const auto no_ahead = [](int32_t, int32_t) {};
        std::vector<ShapePairCandidate> lists[4];
        bp_.self_pairs(0, parts / 2, accept, lists[0], no_ahead);
        bp_.self_pairs(parts / 2, parts, accept, lists[1], no_ahead);
        bp_.query_pairs(0, queries / 2, accept, lists[2], no_ahead);
        bp_.query_pairs(queries / 2, queries, accept, lists[3], no_ahead);
        bp_.end_pair_queries();
        for (const std::vector<ShapePairCandidate>& list : lists) {
            out.insert(out.end(), list.begin(), list.end());
        }
    }

    void check_against_brute_force() {
        std::vector<Pair> expected;
        const int32_t n = int32_t(shapes_.size());
        for (int32_t a = 0; a < n; ++a) {
            const Shape& sa = shapes_[a];
            if (!sa.alive) {
                continue;
            }
            for (int32_t b = a + 1; b < n; ++b) {
                const Shape& sb = shapes_[b];
                const bool both_static = sa.kind == ProxyKind::static_proxy && sb.kind == ProxyKind::static_proxy;
                if (sb.alive && !both_static && boxes_overlap(sa.fat, sb.fat) && !filtered_out(a, b)) {
                    expected.push_back({a, b});
                }
            }
        }
        const std::vector<Pair> known(known_.begin(), known_.end());
        if (known != expected) {
            if (report_.known_mismatch < 3) {
                std::vector<Pair> missing, extra;
                std::set_difference(expected.begin(), expected.end(), known.begin(), known.end(),
                                    std::back_inserter(missing));
                std::set_difference(known.begin(), known.end(), expected.begin(), expected.end(),
                                    std::back_inserter(extra));
                std::fprintf(stderr, "update %zu: %zu pairs never reported, %zu extra", report_.per_update.size(),
                             missing.size(), extra.size());
                if (!missing.empty()) {
                    const Shape& a = shapes_[missing[0].first];
                    const Shape& b = shapes_[missing[0].second];
                    std::fprintf(stderr, "; first missing: shapes %d (kind %d) and %d (kind %d)", missing[0].first,
                                 int(a.kind), missing[0].second, int(b.kind));
                }
                std::fprintf(stderr, "\n");
            }
            ++report_.known_mismatch;
        }
    }

    void check_storage() {
        int32_t counts[3] = {0, 0, 0};
        for (const Shape& s : shapes_) {
            if (!s.alive) {
                continue;
            }
            ++counts[int32_t(s.kind)];
            if (proxy_kind(s.key) != s.kind || !same_box(bp_.fat_aabb(s.key), s.fat)) {
                ++report_.storage_errors;
            }
        }
        for (int32_t k = 0; k < 3; ++k) {
            const DynamicTree& tree = bp_.tree(ProxyKind(k));
            tree.validate();
            if (tree.proxy_count() != counts[k]) {
                ++report_.storage_errors;
            }
        }
        if (bp_.move_count() != 0) {
            ++report_.storage_errors;
        }
    }

    Options opt_;
    TestRng rng_;
    BroadPhase bp_;
    std::vector<Shape> shapes_;  // index = shape id, the user value of the proxy
    std::vector<int32_t> free_ids_;
    std::set<Pair> known_;       // the engine's contacts
    Report report_;
};

bool report_ok(const Report& r, const char* name) {
    std::printf("broadphase %s: %zu updates, %lld accept calls, %lld pairs reported, up to %d pairs alive\n", name,
                r.per_update.size(), (long long)r.accept_calls, (long long)r.pairs_reported, r.max_known);
    // Pairs without a dynamic side (kinematic with static or kinematic) are offered, for
    // sensors: the scenes have them, so they must show up.
    const bool ok = r.not_ordered == 0 && r.dead_shape == 0 && r.static_static == 0 && r.without_dynamic > 0 &&
                    r.not_overlapping == 0 && r.accepted_twice == 0 && r.out_mismatch == 0 && r.known_mismatch == 0 &&
                    r.storage_errors == 0;
    if (!ok) {
        std::fprintf(stderr,
                     "broadphase %s: not ordered %d, dead shape %d, static-static %d, without a dynamic side %d, "
                     "not overlapping %d, accepted twice %d, out mismatch %d, rounds with wrong pairs %d, storage "
                     "errors %d\n",
                     name, r.not_ordered, r.dead_shape, r.static_static, r.without_dynamic, r.not_overlapping,
                     r.accepted_twice, r.out_mismatch, r.known_mismatch, r.storage_errors);
    }
    return ok;
}

}  // namespace

// The differential test: three seeds, a sparse and a crowded world, with and without a filter.
I2D_TEST(unit_broad_phase_pairs_match_brute_force_over_rounds) {
    Options sparse;
    sparse.seed = 11;
    Report r = Harness(sparse).run();
    I2D_CHECK(report_ok(r, "sparse"));
    I2D_CHECK(r.pairs_reported > 1000);  // the scene must make pairs, or the check is empty

    Options crowded;
    crowded.seed = 12;
    crowded.initial = 1500;
    crowded.world = 15.0f;
    r = Harness(crowded).run();
    I2D_CHECK(report_ok(r, "crowded"));
    I2D_CHECK(r.pairs_reported > 5000);

    Options filtered;
    filtered.seed = 13;
    filtered.filter = true;
    filtered.rebuild_static = true;
    r = Harness(filtered).run();
    I2D_CHECK(report_ok(r, "filtered, rebuilt static tree"));
    I2D_CHECK(r.pairs_reported > 1000);
}

// When most dynamic proxies moved, their pairs come from the dynamic tree searched against
// itself, cut into parts: the rounds alternate between that and the queries, both against
// brute force, and the parts shared as two workers would share them give update_pairs'
// sequence.
I2D_TEST(unit_broad_phase_self_search_matches_brute_force_and_queries) {
    Options o;
    o.seed = 21;
    o.initial = 1500;
    o.world = 20.0f;
    o.calm_even_rounds = true;
    o.in_parts = true;
    const Report parts = Harness(o).run();
    I2D_CHECK(report_ok(parts, "self search in parts"));
    I2D_CHECK(parts.self_search_updates >= o.rounds / 3);
    I2D_CHECK(parts.self_search_updates < int32_t(parts.per_update.size()) - o.rounds / 3);
    I2D_CHECK(parts.pairs_reported > 5000);
    o.in_parts = false;
    const Report whole = Harness(o).run();
    I2D_CHECK(whole.sequence == parts.sequence);
}

// Same inputs, same pairs in the same order.
I2D_TEST(unit_broad_phase_order_is_deterministic) {
    Options o;
    o.seed = 99;
    o.initial = 1500;
    o.rounds = 25;
    const Report a = Harness(o).run();
    const Report b = Harness(o).run();
    I2D_CHECK(a.per_update == b.per_update);
    I2D_CHECK(a.sequence == b.sequence);
    I2D_CHECK(a.sequence.size() > 500);
    // A different seed gives a different sequence: the comparison can tell runs apart.
    o.seed = 100;
    const Report c = Harness(o).run();
    I2D_CHECK(c.sequence != a.sequence);
}

// A static proxy created with query_now false is not queued, with true it is; moving
// proxies are always queued; update_pairs empties the queue.
I2D_TEST(unit_broad_phase_static_query_now) {
    BroadPhase bp;
    const AABB box{{0.0f, 0.0f}, {1.0f, 1.0f}};
    std::vector<ShapePairCandidate> out;
    auto accept_all = [](int32_t, int32_t) { return true; };
    const int32_t dynamic = bp.create_proxy(box, 1, 0, ProxyKind::dynamic_proxy, false);
    I2D_CHECK(bp.move_count() == 1);
    bp.update_pairs(accept_all, out);
    I2D_CHECK(out.empty());
    I2D_CHECK(bp.move_count() == 0);

    bp.create_proxy(box, 1, 1, ProxyKind::static_proxy, false);
    I2D_CHECK(bp.move_count() == 0);
    bp.update_pairs(accept_all, out);
    I2D_CHECK(out.empty());  // nobody asked: the resting dynamic proxy does not see it yet

    bp.create_proxy(box, 1, 2, ProxyKind::static_proxy, true);
    I2D_CHECK(bp.move_count() == 1);
    bp.update_pairs(accept_all, out);
    I2D_REQUIRE(out.size() == 1);
    I2D_CHECK(out[0].shape_a == 0 && out[0].shape_b == 2);

    out.clear();
    bp.create_proxy(box, 1, 3, ProxyKind::kinematic_proxy, false);
    I2D_CHECK(bp.move_count() == 1);
    bp.update_pairs(accept_all, out);
    I2D_REQUIRE(out.size() == 3);  // with the two static proxies (for sensors) and the dynamic one
    std::vector<int32_t> partners;
    for (const ShapePairCandidate& p : out) {
        I2D_CHECK(p.shape_b == 3);
        partners.push_back(p.shape_a);
    }
    std::sort(partners.begin(), partners.end());
    I2D_CHECK(partners == (std::vector<int32_t>{0, 1, 2}));

    // Moving the dynamic proxy finds all three others, each once.
    out.clear();
    bp.move_proxy(dynamic, {{0.5f, 0.5f}, {1.5f, 1.5f}});
    bp.update_pairs(accept_all, out);
    std::vector<int32_t> others;
    for (const ShapePairCandidate& p : out) {
        I2D_CHECK(p.shape_a == 0);
        others.push_back(p.shape_b);
    }
    std::sort(others.begin(), others.end());
    I2D_CHECK(others == (std::vector<int32_t>{1, 2, 3}));
}

// Static proxies never pair among themselves, however they move: accept is not even asked.
// Kinematic ones are offered to accept with static and kinematic ones too (the caller keeps
// those pairs for sensors only), each pair once.
I2D_TEST(unit_broad_phase_static_proxies_never_pair_among_themselves) {
    BroadPhase bp;
    std::vector<int32_t> keys;
    for (int32_t i = 0; i < 40; ++i) {
        const float x = 0.1f * float(i);
        keys.push_back(bp.create_proxy({{x, 0.0f}, {x + 2.0f, 2.0f}}, 1, i, ProxyKind::static_proxy, true));
    }
    std::vector<Pair> calls;
    std::vector<ShapePairCandidate> out;
    auto record = [&](int32_t a, int32_t b) {
        calls.push_back({a, b});
        return true;
    };
    bp.update_pairs(record, out);
    for (int32_t i = 0; i < 40; ++i) {
        const float x = 0.1f * float(i) + 0.05f;
        if (i % 3 == 0) {
            bp.enlarge_proxy(keys[i], {{x - 1.0f, -1.0f}, {x + 3.0f, 3.0f}});
        } else {
            bp.move_proxy(keys[i], {{x, 0.0f}, {x + 2.0f, 2.0f}});
        }
    }
    bp.update_pairs(record, out);
    I2D_CHECK(calls.empty());
    I2D_CHECK(out.empty());
    // A kinematic proxy among them pairs with all 40.
    const AABB wide{{0.0f, 0.0f}, {5.0f, 2.0f}};
    const int32_t first = bp.create_proxy(wide, 1, 40, ProxyKind::kinematic_proxy, true);
    bp.update_pairs(record, out);
    I2D_CHECK(calls.size() == 40 && out.size() == 40);
    // A second one, while the first moves: the two meet once, and each meets the 40 again.
    calls.clear();
    out.clear();
    bp.move_proxy(first, wide);
    bp.create_proxy(wide, 1, 41, ProxyKind::kinematic_proxy, true);
    bp.update_pairs(record, out);
    I2D_CHECK(calls.size() == 81 && out.size() == 81);
    I2D_CHECK(std::count(calls.begin(), calls.end(), Pair{40, 41}) == 1);
    // One dynamic proxy among them pairs with all 42.
    calls.clear();
    out.clear();
    bp.create_proxy(wide, 1, 42, ProxyKind::dynamic_proxy, false);
    bp.update_pairs(record, out);
    I2D_CHECK(calls.size() == 42 && out.size() == 42);
}

// A dynamic proxy meets static and kinematic proxies by its box ahead and other dynamic ones
// by its fat box only: a falling body's stretch pairs it with the floor it is about to reach,
// not with every body along its way (shape_bounds.hpp). Each pair is found once.
I2D_TEST(unit_broad_phase_box_ahead_meets_static_and_kinematic_only) {
    BroadPhase bp;
    std::vector<ShapePairCandidate> out;
    auto accept_all = [](int32_t, int32_t) { return true; };
    const AABB fat{{0.0f, 0.0f}, {1.0f, 1.0f}};
    const AABB ahead{{0.0f, -3.0f}, {1.0f, 1.0f}};          // stretched 3 m down
    const AABB in_the_way{{0.0f, -2.5f}, {1.0f, -1.5f}};   // inside the stretch, clear of the fat box
    bp.create_proxy(in_the_way, 1, 1, ProxyKind::static_proxy, false);
    bp.create_proxy(in_the_way, 1, 2, ProxyKind::kinematic_proxy, true);
    bp.create_proxy(in_the_way, 1, 3, ProxyKind::dynamic_proxy, true);
    const auto new_pairs = [&]() {
        out.clear();
        bp.update_pairs(accept_all, out);
        std::vector<Pair> got;
        for (const ShapePairCandidate& p : out) {
            got.push_back({p.shape_a, p.shape_b});
        }
        std::sort(got.begin(), got.end());
        return got;
    };
    // The dynamic one meets the others; the static one meets the kinematic one too (for sensors).
    I2D_CHECK(new_pairs() == (std::vector<Pair>{{1, 2}, {1, 3}, {2, 3}}));

    const int32_t falling = bp.create_proxy(fat, ahead, 1, 0, ProxyKind::dynamic_proxy, true);
    I2D_CHECK(same_box(bp.fat_aabb(falling), fat));
    I2D_CHECK(same_box(bp.ahead_aabb(falling), ahead));
    I2D_CHECK(new_pairs() == (std::vector<Pair>{{0, 1}, {0, 2}}));

    // A static proxy that appears in the stretch as the dynamic one moves: both are queried,
    // and only the dynamic one's box ahead reaches the other, so it must report the pair
    // (the static proxy's key is the lower).
    bp.move_proxy(falling, fat, ahead);
    const int32_t appearing = bp.create_proxy(in_the_way, 1, 4, ProxyKind::static_proxy, true);
    I2D_CHECK(appearing < falling);
    I2D_CHECK(new_pairs() == (std::vector<Pair>{{0, 1}, {0, 2}, {0, 4}, {2, 4}, {3, 4}}));

    // Moved without a stretch, its box ahead is its fat box again.
    bp.move_proxy(falling, fat);
    I2D_CHECK(same_box(bp.ahead_aabb(falling), fat));
    I2D_CHECK(new_pairs().empty());
}

// Both proxies of a pair moved: reported once; accept asked once. Accept saying no leaves the
// pair out, and it comes back only when one of the two moves again.
I2D_TEST(unit_broad_phase_pair_once_and_rejected_pairs_return_on_move) {
    BroadPhase bp;
    const int32_t a = bp.create_proxy({{0.0f, 0.0f}, {1.0f, 1.0f}}, 1, 10, ProxyKind::dynamic_proxy, true);
    const int32_t b = bp.create_proxy({{1.0f, 0.0f}, {2.0f, 1.0f}}, 1, 4, ProxyKind::dynamic_proxy, true);
    const int32_t c = bp.create_proxy({{0.5f, 0.5f}, {1.5f, 1.5f}}, 1, 7, ProxyKind::kinematic_proxy, true);
    std::vector<Pair> calls;
    std::vector<ShapePairCandidate> out;
    auto reject_all = [&](int32_t x, int32_t y) {
        calls.push_back({x, y});
        return false;
    };
    bp.update_pairs(reject_all, out);
    std::sort(calls.begin(), calls.end());
    I2D_CHECK(calls == (std::vector<Pair>{{4, 7}, {4, 10}, {7, 10}}));
    I2D_CHECK(out.empty());
    // Nothing moved: not asked again.
    calls.clear();
    bp.update_pairs(reject_all, out);
    I2D_CHECK(calls.empty());
    // b moves (still touching a and c): asked again for b's pairs only.
    bp.move_proxy(b, {{1.0f, 0.1f}, {2.0f, 1.1f}});
    bp.update_pairs(reject_all, out);
    std::sort(calls.begin(), calls.end());
    I2D_CHECK(calls == (std::vector<Pair>{{4, 7}, {4, 10}}));
    // Accepted now.
    calls.clear();
    bp.enlarge_proxy(a, {{-1.0f, -1.0f}, {1.0f, 1.0f}});
    bp.update_pairs([](int32_t, int32_t) { return true; }, out);
    std::vector<Pair> got;
    for (const ShapePairCandidate& p : out) {
        got.push_back({p.shape_a, p.shape_b});
    }
    std::sort(got.begin(), got.end());
    I2D_CHECK(got == (std::vector<Pair>{{4, 10}, {7, 10}}));
    (void)c;
}

// A proxy that moved and was then destroyed is not queried; a new proxy that takes its key in
// the same update is queried once.
I2D_TEST(unit_broad_phase_destroyed_after_move_and_key_reused) {
    BroadPhase bp;
    const AABB box{{0.0f, 0.0f}, {1.0f, 1.0f}};
    std::vector<ShapePairCandidate> out;
    auto accept_all = [](int32_t, int32_t) { return true; };
    bp.create_proxy(box, 1, 0, ProxyKind::static_proxy, false);
    const int32_t a = bp.create_proxy({{5.0f, 5.0f}, {6.0f, 6.0f}}, 1, 1, ProxyKind::dynamic_proxy, true);
    bp.create_proxy({{20.0f, 0.0f}, {21.0f, 1.0f}}, 1, 2, ProxyKind::dynamic_proxy, true);
    bp.update_pairs(accept_all, out);
    I2D_CHECK(out.empty());

    bp.move_proxy(a, box);  // now overlaps the static proxy...
    bp.destroy_proxy(a);    // ...but is gone before the update
    std::vector<Pair> calls;
    auto record = [&](int32_t x, int32_t y) {
        calls.push_back({x, y});
        return true;
    };
    bp.update_pairs(record, out);
    I2D_CHECK(calls.empty());

    // Destroyed after moving, and its proxy id (so its key) most likely reused right away.
    const int32_t d = bp.create_proxy({{40.0f, 0.0f}, {41.0f, 1.0f}}, 1, 4, ProxyKind::dynamic_proxy, true);
    bp.move_proxy(d, {{0.5f, 0.5f}, {20.5f, 0.6f}});  // overlaps shapes 0 and 2
    bp.destroy_proxy(d);
    const int32_t e = bp.create_proxy({{0.5f, 0.5f}, {20.5f, 0.6f}}, 1, 5, ProxyKind::dynamic_proxy, true);
    bp.update_pairs(record, out);
    std::sort(calls.begin(), calls.end());
    I2D_CHECK(calls == (std::vector<Pair>{{0, 5}, {2, 5}}));
    I2D_CHECK(same_box(bp.fat_aabb(e), {{0.5f, 0.5f}, {20.5f, 0.6f}}));
}

// Proxies destroyed oldest first before any update, as a level torn down and rebuilt
// before its first step: each is blanked in the move buffer where it stands (its slot
// kept by key), so the update queries exactly the survivors and the proxies made since,
// some on reused keys.
I2D_TEST(unit_broad_phase_many_destroyed_before_the_update_leave_only_survivors_queried) {
    BroadPhase bp;
    std::vector<ShapePairCandidate> out;
    bp.create_proxy({{-1000.0f, -1.0f}, {1000.0f, 0.0f}}, 1, 0, ProxyKind::static_proxy, false);
    constexpr int32_t count = 300;
    std::vector<int32_t> keys;
    for (int32_t i = 0; i < count; ++i) {
        const float x = 2.0f * float(i);
        keys.push_back(bp.create_proxy({{x, -0.5f}, {x + 1.0f, 0.5f}}, 1, 1 + i, ProxyKind::dynamic_proxy, true));
    }
    for (int32_t i = 0; i < count; i += 2) {
        bp.destroy_proxy(keys[std::size_t(i)]);
    }
    for (int32_t i = 0; i < 10; ++i) {
        const float x = 2.0f * float(i) + 0.25f;  // under the boxes, clear of them, on the ground
        bp.create_proxy({{x, -0.95f}, {x + 0.5f, -0.9f}}, 1, 1000 + i, ProxyKind::dynamic_proxy, true);
    }
    std::vector<int32_t> queried;
    bp.update_pairs(
        [&](int32_t a, int32_t b) {
            if (a == 0 || b == 0) {  // each box and ground pair: the moved proxies queried
                queried.push_back(a == 0 ? b : a);
            }
            return true;
        },
        out);
    std::sort(queried.begin(), queried.end());
    std::vector<int32_t> expected;
    for (int32_t i = 1; i < count; i += 2) {
        expected.push_back(1 + i);
    }
    for (int32_t i = 0; i < 10; ++i) {
        expected.push_back(1000 + i);
    }
    I2D_CHECK(queried == expected);
}

// The step's commit (a tree where many proxies moved is rebuilt where they moved) and the
// one-by-one re-insertion find the same new pairs, and both the brute-force set: half the
// proxies of a crowded world move a little, then all of them, then one in twenty.
I2D_TEST(unit_broad_phase_moves_in_place_find_the_pairs_reinsertion_finds) {
    TestRng rng(31);
    BroadPhase in_place, reinserted;
    std::vector<AABB> fat;
    std::vector<int32_t> keys;
    for (int32_t i = 0; i < 1500; ++i) {
        const float x = rng.uniform(-20.0f, 20.0f), y = rng.uniform(-20.0f, 20.0f), s = rng.uniform(0.2f, 1.5f);
        fat.push_back(fatten({{x, y}, {x + s, y + s}}));
        const ProxyKind kind = i % 10 == 0 ? ProxyKind::static_proxy : ProxyKind::dynamic_proxy;
        keys.push_back(in_place.create_proxy(fat.back(), 1, i, kind, true));
        I2D_REQUIRE(reinserted.create_proxy(fat.back(), 1, i, kind, true) == keys.back());
    }
    std::set<Pair> known;
    const auto update = [&](BroadPhase& bp, bool reinsert) {
        if (reinsert) {
            bp.commit_moves();
        }
        std::vector<ShapePairCandidate> out;
        bp.update_pairs([&](int32_t a, int32_t b) { return known.count({a, b}) == 0; }, out);
        std::set<Pair> found;
        for (const ShapePairCandidate& p : out) {
            found.insert({p.shape_a, p.shape_b});
        }
        return found;
    };
    const auto brute_new_pairs = [&](const std::vector<int32_t>& moved) {
        std::set<Pair> expected;
        for (const int32_t i : moved) {
            for (int32_t j = 0; j < int32_t(fat.size()); ++j) {
                const bool both_static = i % 10 == 0 && j % 10 == 0;
                const Pair p{std::min(i, j), std::max(i, j)};
                if (j != i && !both_static && boxes_overlap(fat[i], fat[j]) && known.count(p) == 0) {
                    expected.insert(p);
                }
            }
        }
        return expected;
    };
    const std::set<Pair> first_in_place = update(in_place, false), first_reinserted = update(reinserted, true);
    I2D_CHECK(first_in_place == first_reinserted);
    known = first_in_place;
    const int32_t shares[] = {2, 1, 20};
    for (const int32_t share : shares) {
        std::vector<int32_t> moved;
        for (int32_t i = 0; i < int32_t(fat.size()); ++i) {
            if (i % 10 != 0 && rng.below(share) == 0) {
                const Vec2 d{rng.uniform(-0.6f, 0.6f), rng.uniform(-0.6f, 0.6f)};
                fat[i] = {fat[i].lower + d, fat[i].upper + d};
                in_place.move_proxy(keys[i], fat[i]);
                reinserted.move_proxy(keys[i], fat[i]);
                moved.push_back(i);
            }
        }
        for (auto it = known.begin(); it != known.end();) {
            it = boxes_overlap(fat[it->first], fat[it->second]) ? std::next(it) : known.erase(it);
        }
        const std::set<Pair> expected = brute_new_pairs(moved);
        const std::set<Pair> got_in_place = update(in_place, false), got_reinserted = update(reinserted, true);
        std::printf("1 in %d moved (%zu): %zu new pairs, in place %zu, re-inserted %zu\n", share, moved.size(),
                    expected.size(), got_in_place.size(), got_reinserted.size());
        I2D_CHECK(got_in_place == expected);
        I2D_CHECK(got_reinserted == expected);
        I2D_CHECK(!expected.empty());
        known.insert(expected.begin(), expected.end());
        for (const int32_t i : moved) {
            I2D_CHECK(same_box(in_place.fat_aabb(keys[i]), fat[i]) && same_box(reinserted.fat_aabb(keys[i]), fat[i]));
        }
        in_place.tree(ProxyKind::dynamic_proxy).validate();
    }
}
