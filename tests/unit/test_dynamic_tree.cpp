// SPDX-License-Identifier: MIT
// DynamicTree against brute force: queries and ray casts over thousands of proxies that move,
// grow, appear and disappear give exactly the proxies a linear scan of the fat boxes gives;
// invariants that the public interface shows (counts, height bounds, stored boxes) hold after
// every round; rebuild keeps the leaves and the quality; early stops stop.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "broadphase/dynamic_tree.hpp"
#include "brute_geometry.hpp"
#include "check.h"
#include "test_rng.hpp"

using namespace i2d;
using brute::boxes_overlap;
using brute::same_box;

namespace {

constexpr uint64_t all_bits = ~uint64_t(0);

// ---- Brute force, written independently of the library ----------------------------------

// Slab test in double: does origin + t * d, t in [0, t_max], meet the box grown by `grow`
// on every side? A negative `grow` shrinks the box, except along an axis where it is thinner
// than 4 |grow| (a zero-width box stays a segment: crossing it is not a matter of rounding
// unless the ray runs along it). On a hit, *t_enter is the first t inside (0 when the origin
// is inside).
bool bf_segment_hits(Vec2 origin, Vec2 d, double t_max, const AABB& box, double grow, double* t_enter) {
    double lo = 0.0, hi = t_max;
    const double o[2] = {origin.x, origin.y}, dir[2] = {d.x, d.y};
    double bmin[2] = {double(box.lower.x), double(box.lower.y)};
    double bmax[2] = {double(box.upper.x), double(box.upper.y)};
    for (int axis = 0; axis < 2; ++axis) {
        if (grow > 0.0 || bmax[axis] - bmin[axis] > -4.0 * grow) {
            bmin[axis] -= grow;
            bmax[axis] += grow;
        }
        if (dir[axis] == 0.0) {
            if (o[axis] < bmin[axis] || o[axis] > bmax[axis]) {
                return false;
            }
            continue;
        }
        double t1 = (bmin[axis] - o[axis]) / dir[axis], t2 = (bmax[axis] - o[axis]) / dir[axis];
        if (t1 > t2) {
            std::swap(t1, t2);
        }
        lo = std::max(lo, t1);
        hi = std::min(hi, t2);
        if (lo > hi) {
            return false;
        }
    }
    if (t_enter) {
        *t_enter = lo;
    }
    return true;
}

// Rays and boxes are in floats; the tree decides in floats. Boxes within this distance of the
// segment may go either way; further inside must be visited, further outside must not.
constexpr double ray_tolerance = 1e-3;

int32_t ceil_log2(int32_t n) {
    int32_t h = 0;
    while ((int64_t(1) << h) < n) {
        ++h;
    }
    return h;
}

// Upper bound on the height a tree of n leaves may reach (brief: about 2.5 log2 n + 2).
double height_bound(int32_t n) { return n <= 1 ? 1.0 : 2.5 * std::log2(double(n)) + 2.0; }

// ---- A model of the tree's contents -------------------------------------------------------

struct Entry {
    int32_t proxy = null_index;
    AABB box;
    uint64_t category = 0;
    bool alive = false;
};

const uint64_t category_choices[] = {1, 2, 4, 8, 1 | 4, 2 | 8, all_bits, uint64_t(1) << 63};
const uint64_t mask_choices[] = {all_bits, all_bits, all_bits, 1, 2, 4 | 8, 1 | 2, 0, uint64_t(1) << 63};

uint64_t pick(TestRng& rng, const uint64_t* choices, int32_t count) { return choices[rng.below(count)]; }

// Half the boxes on an integer grid (so exact touching happens all the time), the rest
// anywhere; sizes mostly small, some large, some zero-width.
AABB random_box(TestRng& rng, float world) {
    const int32_t kind = rng.below(10);
    if (kind < 5) {
        const float x = float(rng.below(int32_t(2 * world)) - int32_t(world));
        const float y = float(rng.below(int32_t(2 * world)) - int32_t(world));
        const float w = float(rng.below(kind == 0 ? 12 : 4)), h = float(rng.below(kind == 0 ? 12 : 4));
        return {{x, y}, {x + w, y + h}};
    }
    const float x = rng.uniform(-world, world), y = rng.uniform(-world, world);
    float w = rng.uniform(0.0f, 3.0f), h = rng.uniform(0.0f, 3.0f);
    if (kind == 9) {
        w *= 6.0f;
        h *= 6.0f;
    } else if (kind == 8) {
        w = 0.0f;  // a segment or a point
    }
    return {{x, y}, {x + w, y + h}};
}

class TreeModel {
public:
    DynamicTree tree;
    std::vector<Entry> entries;  // index = user value; never reused
    int32_t live = 0;
    int32_t moves = 0;

    int32_t create(const AABB& box, uint64_t category) {
        Entry e;
        e.box = box;
        e.category = category;
        e.alive = true;
        const int32_t user = int32_t(entries.size());
        e.proxy = tree.create_proxy(box, category, user);
        entries.push_back(e);
        ++live;
        return user;
    }
    void destroy(int32_t user) {
        tree.destroy_proxy(entries[user].proxy);
        entries[user].alive = false;
        --live;
    }
    // Every other move goes through the leaf's storage order, as the broadphase moves.
    void move(int32_t user, const AABB& box) {
        const int32_t proxy = entries[user].proxy;
        if (++moves % 2 == 0) {
            tree.move_proxy(proxy, box);
        } else {
            tree.move_proxy_at(tree.storage_order(proxy), box);
        }
        entries[user].box = box;
    }
    // The step's way: the leaf takes its box where it is, rebuilt with the rest later.
    void move_in_place(int32_t user, const AABB& box) {
        tree.move_proxy_in_place_at(tree.storage_order(entries[user].proxy), box);
        entries[user].box = box;
    }
    void enlarge(int32_t user, const AABB& box) {
        tree.enlarge_proxy(entries[user].proxy, box);
        entries[user].box = box;
    }
    int32_t random_live(TestRng& rng) const {
        for (;;) {
            const int32_t u = rng.below(int32_t(entries.size()));
            if (entries[u].alive) {
                return u;
            }
        }
    }

    std::vector<int32_t> brute_query(const AABB& box, uint64_t mask) const {
        std::vector<int32_t> out;
        for (size_t u = 0; u < entries.size(); ++u) {
            const Entry& e = entries[u];
            if (e.alive && (e.category & mask) != 0 && boxes_overlap(e.box, box)) {
                out.push_back(int32_t(u));
            }
        }
        return out;
    }

    // The tree's answer as sorted user values; counts visits that disagree with the model
    // (a proxy id that is not the entry's, a dead entry, a repeated visit).
    std::vector<int32_t> tree_query(const AABB& box, uint64_t mask, int32_t* bad) const {
        std::vector<int32_t> out;
        tree.query(box, mask, [&](int32_t proxy, int32_t user) {
            if (user < 0 || user >= int32_t(entries.size()) || !entries[user].alive || entries[user].proxy != proxy) {
                ++*bad;
            } else {
                out.push_back(user);
            }
            return true;
        });
        std::sort(out.begin(), out.end());
        const size_t n = out.size();
        out.erase(std::unique(out.begin(), out.end()), out.end());
        *bad += int32_t(n - out.size());
        return out;
    }

    // Stored boxes, categories and user values equal the model's, whether reached by proxy
    // or by storage order; the count matches.
    int32_t check_storage() const {
        int32_t bad = tree.proxy_count() == live ? 0 : 1;
        for (size_t u = 0; u < entries.size(); ++u) {
            const Entry& e = entries[u];
            const int32_t order = e.alive ? tree.storage_order(e.proxy) : null_index;
            if (e.alive && (!same_box(tree.fat_aabb(e.proxy), e.box) || tree.user_value(e.proxy) != int32_t(u) ||
                            tree.category_bits(e.proxy) != e.category || !same_box(tree.fat_aabb_at(order), e.box) ||
                            tree.user_value_at(order) != int32_t(u))) {
                ++bad;
            }
        }
        return bad;
    }
};

// Height within [ceil(log2 n), bound]; prints the numbers when not.
bool height_ok(const DynamicTree& tree, const char* when) {
    const int32_t n = tree.proxy_count(), h = tree.height();
    const bool ok = n == 0 ? h == 0 : (h >= ceil_log2(n) && double(h) <= height_bound(n));
    if (!ok) {
        std::fprintf(stderr, "%s: height %d with %d proxies (allowed %d..%.1f)\n", when, h, n, ceil_log2(n),
                     height_bound(n));
    }
    return ok;
}

AABB random_query_box(TestRng& rng, float world) {
    const float x = rng.uniform(-world - 2.0f, world), y = rng.uniform(-world - 2.0f, world);
    // Integer-aligned half the time, so query edges touch grid boxes exactly.
    if (rng.below(2) == 0) {
        const float xi = std::floor(x), yi = std::floor(y);
        return {{xi, yi}, {xi + float(rng.below(10)), yi + float(rng.below(10))}};
    }
    const float s = rng.below(8) == 0 ? rng.uniform(0.0f, world) : rng.uniform(0.0f, 6.0f);
    return {{x, y}, {x + s, y + rng.uniform(0.0f, 6.0f)}};
}

// Counts query mismatches over `count` random boxes and masks.
int32_t check_queries(const TreeModel& m, TestRng& rng, float world, int32_t count) {
    int32_t mismatches = 0;
    for (int32_t q = 0; q < count; ++q) {
        const AABB box = random_query_box(rng, world);
        const uint64_t mask = pick(rng, mask_choices, int32_t(sizeof mask_choices / sizeof mask_choices[0]));
        int32_t bad = 0;
        const std::vector<int32_t> got = m.tree_query(box, mask, &bad);
        const std::vector<int32_t> expected = m.brute_query(box, mask);
        if (bad != 0 || got != expected) {
            if (mismatches < 3) {
                std::fprintf(stderr,
                             "query [%g %g]-[%g %g] mask %llx: tree %zu proxies, brute force %zu, %d bad visits\n",
                             double(box.lower.x), double(box.lower.y), double(box.upper.x), double(box.upper.y),
                             (unsigned long long)mask, got.size(), expected.size(), bad);
            }
            ++mismatches;
        }
    }
    return mismatches;
}

struct RayStats {
    int32_t casts = 0, mismatches = 0, borderline = 0, visits = 0;
};

TreeRayInput random_ray(TestRng& rng, float world) {
    TreeRayInput in;
    in.origin = {rng.uniform(-world - 5.0f, world + 5.0f), rng.uniform(-world - 5.0f, world + 5.0f)};
    const int32_t kind = rng.below(6);
    const float len = rng.uniform(0.5f, 2.0f * world);
    if (kind == 0) {
        in.translation = {rng.below(2) ? len : -len, 0.0f};  // horizontal
    } else if (kind == 1) {
        in.translation = {0.0f, rng.below(2) ? len : -len};  // vertical
    } else {
        const float a = rng.uniform(0.0f, 6.2831853f);
        in.translation = {len * std::cos(a), len * std::sin(a)};
    }
    in.max_fraction = rng.below(3) == 0 ? rng.uniform(0.05f, 1.0f) : 1.0f;
    return in;
}

// Which proxies must (strict) and may (loose) be visited by a segment up to t_max.
void classify(const TreeModel& m, const TreeRayInput& in, uint64_t mask, double t_max, std::vector<char>& must,
              std::vector<char>& may) {
    must.assign(m.entries.size(), 0);
    may.assign(m.entries.size(), 0);
    for (size_t u = 0; u < m.entries.size(); ++u) {
        const Entry& e = m.entries[u];
        if (!e.alive || (e.category & mask) == 0) {
            continue;
        }
        must[u] = bf_segment_hits(in.origin, in.translation, t_max, e.box, -ray_tolerance, nullptr);
        may[u] = bf_segment_hits(in.origin, in.translation, t_max, e.box, ray_tolerance, nullptr);
    }
}

// One ray, four ways of answering the visits:
//  1. always -1: the visits are exactly the proxies the segment crosses;
//  2. always 2 (>= max): the same set;
//  3. the entry fraction of the box (a closest-hit search): every visit crosses the ray as
//     clipped so far, every box crossing the final clipped ray was visited, and the final
//     clip is the brute-force closest entry;
//  4. 0 at the k-th visit: exactly k visits.
void check_ray(const TreeModel& m, TestRng& rng, float world, RayStats& stats) {
    const TreeRayInput in = random_ray(rng, world);
    const uint64_t mask = pick(rng, mask_choices, int32_t(sizeof mask_choices / sizeof mask_choices[0]));
    std::vector<char> must, may;
    classify(m, in, mask, in.max_fraction, must, may);
    ++stats.casts;
    bool bad = false;

    auto valid_visit = [&](const TreeRayInput& input, int32_t proxy, int32_t user) {
        return user >= 0 && user < int32_t(m.entries.size()) && m.entries[user].alive &&
               m.entries[user].proxy == proxy && input.origin == in.origin && input.translation == in.translation;
    };

    // 1 and 2.
    std::vector<int32_t> first;
    for (int32_t variant = 0; variant < 2; ++variant) {
        std::vector<char> seen(m.entries.size(), 0);
        std::vector<int32_t> visited;
        m.tree.ray_cast(in, mask, [&](const TreeRayInput& input, int32_t proxy, int32_t user) {
            if (!valid_visit(input, proxy, user) || seen[user]) {
                bad = true;
            } else {
                seen[user] = 1;
                visited.push_back(user);
            }
            return variant == 0 ? -1.0f : 2.0f;
        });
        for (size_t u = 0; u < m.entries.size(); ++u) {
            if (must[u] && !seen[u]) {
                bad = true;  // crosses the segment but was not visited
            }
            if (seen[u] && !may[u]) {
                bad = true;  // visited but clearly missed by the segment
            }
            if (seen[u] && !must[u]) {
                ++stats.borderline;
            }
        }
        std::sort(visited.begin(), visited.end());
        if (variant == 0) {
            first = visited;
            stats.visits += int32_t(visited.size());
        } else if (visited != first) {
            bad = true;
        }
    }

    // 3: closest hit by clipping.
    {
        float clip = in.max_fraction;
        std::vector<char> seen(m.entries.size(), 0);
        m.tree.ray_cast(in, mask, [&](const TreeRayInput& input, int32_t proxy, int32_t user) {
            if (!valid_visit(input, proxy, user) || seen[user]) {
                bad = true;
                return -1.0f;
            }
            seen[user] = 1;
            // The ray was clipped at `clip`: this box must (loosely) cross what is left.
            if (!bf_segment_hits(in.origin, in.translation, double(clip), m.entries[user].box, ray_tolerance,
                                 nullptr)) {
                bad = true;
            }
            double t = 0.0;
            if (!bf_segment_hits(in.origin, in.translation, double(in.max_fraction), m.entries[user].box, 0.0, &t) ||
                !(float(t) > 0.0f)) {
                return -1.0f;  // grazed within tolerance, or the origin is inside: ignore
            }
            const float f = float(t);
            if (f < clip) {
                clip = f;
            }
            return f;  // clips when below the current end, leaves the ray as is otherwise
        });
        double closest = double(in.max_fraction);
        for (size_t u = 0; u < m.entries.size(); ++u) {
            const Entry& e = m.entries[u];
            double t = 0.0;
            if (e.alive && (e.category & mask) != 0 &&
                bf_segment_hits(in.origin, in.translation, double(in.max_fraction), e.box, 0.0, &t) &&
                float(t) > 0.0f) {
                closest = std::min(closest, double(float(t)));
            }
            // Every box that clearly crosses the final, shortest ray was visited.
            if (e.alive && (e.category & mask) != 0 && !seen[u] &&
                bf_segment_hits(in.origin, in.translation, double(clip), e.box, -ray_tolerance, nullptr)) {
                bad = true;
            }
        }
        // The length is at most ~2 world; 1e-4 of the fraction is well below a box size.
        if (std::fabs(double(clip) - closest) > 1e-4) {
            std::fprintf(stderr, "closest hit: tree clipped at %.7g, brute force %.7g\n", double(clip), closest);
            bad = true;
        }
    }

    // 4: stop at the k-th visit.
    if (!first.empty()) {
        const int32_t k = 1 + rng.below(int32_t(first.size()));
        int32_t visits = 0;
        m.tree.ray_cast(in, mask, [&](const TreeRayInput&, int32_t, int32_t) {
            ++visits;
            return visits == k ? 0.0f : -1.0f;
        });
        if (visits != k) {
            std::fprintf(stderr, "ray stopped at visit %d but %d visits happened\n", k, visits);
            bad = true;
        }
    }
    if (bad) {
        if (stats.mismatches < 3) {
            std::fprintf(stderr, "ray (%g, %g) + t (%g, %g), t <= %g, mask %llx: wrong visits\n",
                         double(in.origin.x), double(in.origin.y), double(in.translation.x),
                         double(in.translation.y), double(in.max_fraction), (unsigned long long)mask);
        }
        ++stats.mismatches;
    }
}

// Grows a box by non-negative amounts on each side (the result contains the box).
AABB grown(TestRng& rng, const AABB& b, float most) {
    return {{b.lower.x - rng.uniform(0.0f, most), b.lower.y - rng.uniform(0.0f, most)},
            {b.upper.x + rng.uniform(0.0f, most), b.upper.y + rng.uniform(0.0f, most)}};
}

AABB moved(TestRng& rng, const AABB& b, float world) {
    if (rng.below(8) == 0) {
        return random_box(rng, world);  // teleport
    }
    // Integer steps keep grid boxes on the grid.
    const bool grid = b.lower.x == std::floor(b.lower.x) && b.lower.y == std::floor(b.lower.y);
    const Vec2 d = grid ? Vec2{float(rng.below(5) - 2), float(rng.below(5) - 2)}
                        : Vec2{rng.uniform(-1.5f, 1.5f), rng.uniform(-1.5f, 1.5f)};
    return {b.lower + d, b.upper + d};
}

struct SceneStats {
    int32_t query_mismatches = 0, storage_errors = 0, height_errors = 0, max_height = 0;
    RayStats rays;
};

// Rounds of moves, enlargements, creations and destructions, checking after each round.
SceneStats run_random_scene(uint32_t seed, int32_t initial, int32_t rounds, float world, int32_t queries_per_round,
                            int32_t rays_per_round) {
    TestRng rng(seed);
    TreeModel m;
    SceneStats s;
    for (int32_t i = 0; i < initial; ++i) {
        m.create(random_box(rng, world), pick(rng, category_choices, 8));
    }
    for (int32_t round = 0; round < rounds; ++round) {
        const int32_t ops = m.live / 5 + 1;
        for (int32_t op = 0; op < ops; ++op) {
            const int32_t what = rng.below(20);
            if (m.live == 0 || what < 2) {
                m.create(random_box(rng, world), pick(rng, category_choices, 8));
            } else if (what < 4) {
                m.destroy(m.random_live(rng));
            } else if (what < 7) {
                const int32_t u = m.random_live(rng);
                m.enlarge(u, grown(rng, m.entries[u].box, rng.below(4) == 0 ? 10.0f : 0.5f));
            } else {
                const int32_t u = m.random_live(rng);
                m.move(u, moved(rng, m.entries[u].box, world));
            }
        }
        // Some rounds shed or add many at once, so the count swings.
        if (round % 10 == 5) {
            for (int32_t i = m.live / 3; i > 0; --i) {
                m.destroy(m.random_live(rng));
            }
        } else if (round % 10 == 8) {
            for (int32_t i = initial / 3; i > 0; --i) {
                m.create(random_box(rng, world), pick(rng, category_choices, 8));
            }
        }
        m.tree.validate();
        s.storage_errors += m.check_storage();
        s.height_errors += height_ok(m.tree, "after a round") ? 0 : 1;
        s.max_height = std::max(s.max_height, m.tree.height());
        s.query_mismatches += check_queries(m, rng, world, queries_per_round);
        for (int32_t r = 0; r < rays_per_round; ++r) {
            check_ray(m, rng, world, s.rays);
        }
    }
    return s;
}

}  // namespace

// Query and ray cast against brute force over 40 rounds of changes to ~3000 proxies, on three
// seeds and two densities.
I2D_TEST(unit_tree_random_rounds_match_brute_force) {
    const struct {
        uint32_t seed;
        int32_t count;
        float world;
    } scenes[] = {{101, 3000, 60.0f}, {202, 3000, 25.0f}, {303, 1500, 100.0f}};
    for (const auto& sc : scenes) {
        const SceneStats s = run_random_scene(sc.seed, sc.count, 40, sc.world, 60, 12);
        std::printf("tree seed %u: %d proxies in [-%g, %g]^2, max height %d, %d rays (%d visits, %d borderline)\n",
                    sc.seed, sc.count, double(sc.world), double(sc.world), s.max_height, s.rays.casts,
                    s.rays.visits, s.rays.borderline);
        I2D_CHECK(s.query_mismatches == 0);
        I2D_CHECK(s.storage_errors == 0);
        I2D_CHECK(s.height_errors == 0);
        I2D_CHECK(s.rays.mismatches == 0);
        // The rays must have had something to find, or the checks above prove little.
        I2D_CHECK(s.rays.visits > s.rays.casts);
    }
}

// Boxes that only touch, along an edge or at a corner, overlap; a gap of one float does not.
I2D_TEST(unit_tree_touching_boxes_overlap) {
    DynamicTree tree;
    const AABB unit{{0.0f, 0.0f}, {1.0f, 1.0f}};
    const int32_t p = tree.create_proxy(unit, 1, 7);
    // Fill the tree so the query goes through internal nodes.
    for (int32_t i = 0; i < 64; ++i) {
        const float x = 10.0f + float(i % 8) * 2.0f, y = float(i / 8) * 2.0f;
        tree.create_proxy({{x, y}, {x + 1.0f, y + 1.0f}}, 1, 100 + i);
    }
    auto hits_p = [&](const AABB& box) {
        bool hit = false;
        tree.query(box, all_bits, [&](int32_t proxy, int32_t user) {
            hit = hit || (proxy == p && user == 7);
            return true;
        });
        return hit;
    };
    I2D_CHECK(hits_p({{1.0f, 0.0f}, {2.0f, 1.0f}}));    // right edge
    I2D_CHECK(hits_p({{-1.0f, 1.0f}, {0.0f, 2.0f}}));   // top-left corner
    I2D_CHECK(hits_p({{0.5f, -3.0f}, {0.5f, 0.0f}}));   // a segment touching the bottom
    I2D_CHECK(hits_p({{1.0f, 1.0f}, {1.0f, 1.0f}}));    // a point at the corner
    I2D_CHECK(!hits_p({{std::nextafter(1.0f, 2.0f), 0.0f}, {2.0f, 1.0f}}));
    I2D_CHECK(!hits_p({{0.0f, std::nextafter(1.0f, 2.0f)}, {1.0f, 2.0f}}));
    // A zero-size proxy is found by a query that touches it.
    const int32_t point = tree.create_proxy({{-5.0f, -5.0f}, {-5.0f, -5.0f}}, 1, 8);
    int32_t found = 0;
    tree.query({{-6.0f, -5.0f}, {-5.0f, -4.0f}}, all_bits, [&](int32_t proxy, int32_t) {
        found += proxy == point ? 1 : 0;
        return true;
    });
    I2D_CHECK(found == 1);
    tree.validate();
}

// Category and mask: a proxy is visited only when its category shares a bit with the mask.
I2D_TEST(unit_tree_query_filters_by_category) {
    DynamicTree tree;
    const AABB box{{0.0f, 0.0f}, {1.0f, 1.0f}};
    const uint64_t cats[] = {1, 2, 4, 2 | 4, uint64_t(1) << 40, all_bits};
    for (int32_t i = 0; i < 6; ++i) {
        tree.create_proxy(box, cats[i], i);
    }
    const uint64_t masks[] = {0, 1, 2, 4, 6, uint64_t(1) << 40, 8, all_bits};
    for (uint64_t mask : masks) {
        int32_t visited = 0, expected = 0;
        for (uint64_t c : cats) {
            expected += (c & mask) != 0 ? 1 : 0;
        }
        tree.query(box, mask, [&](int32_t, int32_t user) {
            if ((cats[user] & mask) != 0) {
                ++visited;
            } else {
                visited += 1000;  // a filtered proxy was visited
            }
            return true;
        });
        I2D_CHECK(visited == expected);
        int32_t ray_visited = 0;
        TreeRayInput in;
        in.origin = {-1.0f, 0.5f};
        in.translation = {3.0f, 0.0f};
        tree.ray_cast(in, mask, [&](const TreeRayInput&, int32_t, int32_t user) {
            ray_visited += (cats[user] & mask) != 0 ? 1 : 1000;
            return -1.0f;
        });
        I2D_CHECK(ray_visited == expected);
    }
}

// A visit that returns false ends the query there, however many more would match.
I2D_TEST(unit_tree_query_stops_when_visit_returns_false) {
    TestRng rng(5);
    DynamicTree tree;
    for (int32_t i = 0; i < 2000; ++i) {
        const float x = rng.uniform(-20.0f, 20.0f), y = rng.uniform(-20.0f, 20.0f);
        tree.create_proxy({{x, y}, {x + 1.0f, y + 1.0f}}, 1, i);
    }
    const AABB everything{{-100.0f, -100.0f}, {100.0f, 100.0f}};
    int32_t total = 0;
    tree.query(everything, all_bits, [&](int32_t, int32_t) {
        ++total;
        return true;
    });
    I2D_CHECK(total == 2000);
    for (int32_t k : {1, 2, 3, 17, 1000, 1999, 2000}) {
        int32_t visits = 0;
        tree.query(everything, all_bits, [&](int32_t, int32_t) { return ++visits < k; });
        I2D_CHECK(visits == k);
    }
}

// Enlarging proxies (far beyond their old boxes, so that ancestors must grow) keeps queries
// exact, and the stored box is the enlarged one.
I2D_TEST(unit_tree_enlarge_keeps_queries_correct) {
    TestRng rng(11);
    TreeModel m;
    for (int32_t i = 0; i < 2000; ++i) {
        m.create(random_box(rng, 50.0f), 1);
    }
    int32_t mismatches = 0;
    for (int32_t round = 0; round < 20; ++round) {
        for (int32_t i = 0; i < 100; ++i) {
            const int32_t u = m.random_live(rng);
            m.enlarge(u, grown(rng, m.entries[u].box, round % 5 == 4 ? 40.0f : 1.0f));
        }
        // An enlarge that does not change the box is allowed too.
        const int32_t u = m.random_live(rng);
        m.enlarge(u, m.entries[u].box);
        m.tree.validate();
        I2D_CHECK(m.check_storage() == 0);
        mismatches += check_queries(m, rng, 50.0f, 50);
        RayStats rays;
        for (int32_t r = 0; r < 10; ++r) {
            check_ray(m, rng, 50.0f, rays);
        }
        mismatches += rays.mismatches;
    }
    I2D_CHECK(mismatches == 0);
}

// Moves in place, as the step makes them (a share of the proxies at a time, each leaf taking
// its new box where it is, its ancestors marked but not grown): the rebuild leaves every
// leaf as the model has it, queries exact, a tree as shallow as the rounds of single changes
// allow, and its total perimeter within a fifth of a full SAH rebuild's. Single creations,
// destructions and re-insertions between the batches rebuild the grown part first.
I2D_TEST(unit_tree_moves_in_place_then_rebuild_match_brute_force) {
    const struct {
        uint32_t seed;
        int32_t count;
        float world;
        int32_t share_denominator;  // 1 / share of the live proxies moved per batch
    } scenes[] = {{41, 3000, 60.0f, 1}, {42, 3000, 25.0f, 4}, {43, 2000, 100.0f, 8}};
    for (const auto& sc : scenes) {
        TestRng rng(sc.seed);
        TreeModel m;
        for (int32_t i = 0; i < sc.count; ++i) {
            m.create(random_box(rng, sc.world), pick(rng, category_choices, 8));
        }
        int32_t mismatches = 0, storage_errors = 0, height_errors = 0, built = 0;
        float worst_perimeter_ratio = 0.0f;
        for (int32_t round = 0; round < 20; ++round) {
            for (int32_t i = m.live / sc.share_denominator; i > 0; --i) {
                const int32_t u = m.random_live(rng);
                m.move_in_place(u, moved(rng, m.entries[u].box, sc.world));
            }
            m.tree.validate();
            storage_errors += m.check_storage();
            built += m.tree.rebuild_grown();
            m.tree.validate();
            storage_errors += m.check_storage();
            mismatches += check_queries(m, rng, sc.world, 30);
            height_errors += height_ok(m.tree, "after a rebuild of grown nodes") ? 0 : 1;
            RayStats rays;
            for (int32_t r = 0; r < 8; ++r) {
                check_ray(m, rng, sc.world, rays);
            }
            mismatches += rays.mismatches;
            if (round % 5 == 4) {
                DynamicTree fresh = m.tree;
                fresh.rebuild();
                worst_perimeter_ratio = std::max(worst_perimeter_ratio, m.tree.total_perimeter() / fresh.total_perimeter());
            }
            // A few single changes, then in-place moves that the next change must rebuild.
            for (int32_t i = 0; i < 20; ++i) {
                const int32_t u = m.random_live(rng);
                m.move_in_place(u, moved(rng, m.entries[u].box, sc.world));
                if (i % 4 == 0) {
                    m.destroy(m.random_live(rng));
                    m.create(random_box(rng, sc.world), pick(rng, category_choices, 8));
                } else if (i % 4 == 1) {
                    m.move(m.random_live(rng), moved(rng, m.entries[u].box, sc.world));
                }
            }
            m.tree.validate();
            storage_errors += m.check_storage();
            built += m.tree.rebuild_grown();  // the last moves wait for it
            mismatches += check_queries(m, rng, sc.world, 10);
        }
        std::printf("in place, seed %u: %d proxies, 1/%d moved per batch: %d nodes rebuilt, height %d, "
                    "perimeter %.3f x a full rebuild's at worst\n",
                    sc.seed, m.live, sc.share_denominator, built, m.tree.height(), double(worst_perimeter_ratio));
        I2D_CHECK(mismatches == 0);
        I2D_CHECK(storage_errors == 0);
        I2D_CHECK(height_errors == 0);
        I2D_CHECK(built > 0);
        I2D_CHECK(worst_perimeter_ratio < 1.2f);
    }
}

// The broadphase's commit after a batch of in-place moves builds straight into the compact
// layout when a compaction is due: the array it leaves is the one a rebuild of the grown
// nodes followed by compact() leaves (every leaf at the same place with the same box, the
// same height and internal boxes), and where no compaction is due it is the plain rebuild.
// Shared by three workers, its parts built in reverse order, it leaves the same array.
I2D_TEST(unit_tree_commit_lays_out_the_nodes_as_rebuild_then_compact) {
    const struct {
        uint32_t seed;
        int32_t share_denominator;  // 1 / share of the live proxies moved per batch
        bool compacts;              // whether the share makes every commit compact
    } cases[] = {{51, 1, true}, {52, 2, true}, {53, 400, false}};
    for (const auto& c : cases) {
        TestRng rng(c.seed);
        TreeModel m;
        for (int32_t i = 0; i < 2000; ++i) {
            m.create(random_box(rng, 50.0f), pick(rng, category_choices, 8));
        }
        m.tree.compact();
        int32_t differences = 0, compactions = 0, shared_builds = 0;
        for (int32_t round = 0; round < 5; ++round) {
            for (int32_t i = m.live / c.share_denominator; i > 0; --i) {
                const int32_t u = m.random_live(rng);
                m.move_in_place(u, moved(rng, m.entries[u].box, 50.0f));
            }
            DynamicTree separate = m.tree;
            DynamicTree shared = m.tree;
            const int32_t parts = shared.begin_commit(3);
            for (int32_t part = parts - 1; part >= 0; --part) {
                shared.build_part(part, part % 3);
            }
            if (parts > 0) {
                shared.finish_commit_parts();
                ++shared_builds;
            }
            shared.validate();
            const bool due = 4 * (separate.moves_since_compact() + separate.rebuild_grown()) > separate.proxy_count();
            if (due) {
                separate.compact();
                ++compactions;
            }
            m.tree.commit_in_place_moves();
            m.tree.validate();
            differences += m.tree.height() == separate.height() && m.tree.height() == shared.height() ? 0 : 1;
            differences += m.tree.total_perimeter() == separate.total_perimeter() ? 0 : 1;
            differences += m.tree.total_perimeter() == shared.total_perimeter() ? 0 : 1;
            differences += m.tree.moves_since_compact() == separate.moves_since_compact() ? 0 : 1;
            for (const auto& e : m.entries) {
                if (!e.alive) {
                    continue;
                }
                const int32_t order = m.tree.storage_order(e.proxy);
                differences += order == separate.storage_order(e.proxy) ? 0 : 1;
                differences += order == shared.storage_order(e.proxy) ? 0 : 1;
                const AABB a = m.tree.fat_aabb_at(order), b = separate.fat_aabb_at(order);
                const AABB c = shared.fat_aabb_at(order);
                differences += a.lower == b.lower && a.upper == b.upper ? 0 : 1;
                differences += a.lower == c.lower && a.upper == c.upper ? 0 : 1;
            }
            differences += check_queries(m, rng, 50.0f, 10);
        }
        std::printf("commit, seed %u: 1/%d moved per batch, %d of 5 commits compacted (%d shared), %d differences\n",
                    c.seed, c.share_denominator, compactions, shared_builds, differences);
        I2D_CHECK(differences == 0);
        I2D_CHECK(c.compacts ? compactions == 5 : compactions < 5);
        I2D_CHECK(shared_builds == compactions);
    }
}

// Destroying every proxy leaves an empty tree that answers nothing and can be filled again;
// freed proxy ids are reused without confusion.
I2D_TEST(unit_tree_destroy_all_then_reuse) {
    TestRng rng(21);
    TreeModel m;
    for (int32_t cycle = 0; cycle < 3; ++cycle) {
        for (int32_t i = 0; i < 1000; ++i) {
            m.create(random_box(rng, 30.0f), pick(rng, category_choices, 8));
        }
        m.tree.validate();
        I2D_CHECK(m.check_storage() == 0);
        I2D_CHECK(check_queries(m, rng, 30.0f, 30) == 0);
        while (m.live > 0) {
            m.destroy(m.random_live(rng));
            if (m.live % 97 == 0) {
                m.tree.validate();
                I2D_CHECK(m.check_storage() == 0);
                I2D_CHECK(height_ok(m.tree, "while emptying"));
            }
        }
        I2D_CHECK(m.tree.proxy_count() == 0);
        I2D_CHECK(m.tree.height() == 0);
        I2D_CHECK(m.tree.total_perimeter() == 0.0f);
        int32_t visits = 0;
        m.tree.query({{-1e6f, -1e6f}, {1e6f, 1e6f}}, all_bits, [&](int32_t, int32_t) {
            ++visits;
            return true;
        });
        TreeRayInput in;
        in.origin = {-100.0f, -100.0f};
        in.translation = {200.0f, 200.0f};
        m.tree.ray_cast(in, all_bits, [&](const TreeRayInput&, int32_t, int32_t) {
            ++visits;
            return -1.0f;
        });
        I2D_CHECK(visits == 0);
        m.tree.rebuild();  // empty: nothing to do, nothing to break
        I2D_CHECK(m.tree.proxy_count() == 0 && m.tree.height() == 0);
    }
}

// rebuild() keeps every leaf (ids, boxes, categories, user values), keeps queries exact, does
// not make the tree worse by more than 10% in total perimeter, and leaves a tree that keeps
// working under further changes.
I2D_TEST(unit_tree_rebuild_keeps_leaves_and_quality) {
    const struct {
        uint32_t seed;
        int32_t count;
        float world;
    } scenes[] = {{31, 3000, 60.0f}, {32, 3000, 20.0f}};
    for (const auto& sc : scenes) {
        TestRng rng(sc.seed);
        TreeModel m;
        for (int32_t i = 0; i < sc.count; ++i) {
            m.create(random_box(rng, sc.world), pick(rng, category_choices, 8));
        }
        // Degrade it with moves and destructions first.
        for (int32_t i = 0; i < 3 * sc.count; ++i) {
            const int32_t u = m.random_live(rng);
            if (i % 10 == 0) {
                m.destroy(u);
                m.create(random_box(rng, sc.world), pick(rng, category_choices, 8));
            } else {
                m.move(u, moved(rng, m.entries[u].box, sc.world));
            }
        }
        const float perimeter_before = m.tree.total_perimeter();
        const int32_t height_before = m.tree.height(), count_before = m.tree.proxy_count();
        m.tree.rebuild();
        const float perimeter_after = m.tree.total_perimeter();
        std::printf("tree rebuild, %d proxies: height %d -> %d, total perimeter %.1f -> %.1f (x%.3f)\n",
                    count_before, height_before, m.tree.height(), double(perimeter_before),
                    double(perimeter_after), double(perimeter_after / perimeter_before));
        m.tree.validate();
        I2D_CHECK(m.tree.proxy_count() == count_before);
        I2D_CHECK(m.check_storage() == 0);
        I2D_CHECK(height_ok(m.tree, "after rebuild"));
        I2D_CHECK(perimeter_after > 0.0f);
        I2D_CHECK(perimeter_after <= 1.10f * perimeter_before);
        // The set of leaves seen by a query of everything is the same.
        int32_t bad = 0;
        const AABB everything{{-1e6f, -1e6f}, {1e6f, 1e6f}};
        I2D_CHECK(m.tree_query(everything, all_bits, &bad) == m.brute_query(everything, all_bits));
        I2D_CHECK(bad == 0);
        I2D_CHECK(check_queries(m, rng, sc.world, 200) == 0);
        RayStats rays;
        for (int32_t r = 0; r < 50; ++r) {
            check_ray(m, rng, sc.world, rays);
        }
        I2D_CHECK(rays.mismatches == 0);
        // Further changes after a rebuild.
        for (int32_t i = 0; i < sc.count; ++i) {
            const int32_t what = rng.below(4);
            if (what == 0) {
                m.destroy(m.random_live(rng));
            } else if (what == 1) {
                m.create(random_box(rng, sc.world), 1);
            } else {
                const int32_t u = m.random_live(rng);
                m.move(u, moved(rng, m.entries[u].box, sc.world));
            }
        }
        m.tree.validate();
        I2D_CHECK(m.check_storage() == 0);
        I2D_CHECK(height_ok(m.tree, "after changes following a rebuild"));
        I2D_CHECK(check_queries(m, rng, sc.world, 200) == 0);
        // Rebuilding twice in a row changes nothing a query could see.
        m.tree.rebuild();
        m.tree.rebuild();
        m.tree.validate();
        I2D_CHECK(m.check_storage() == 0);
        I2D_CHECK(check_queries(m, rng, sc.world, 50) == 0);
    }
    // One proxy: a leaf for a root.
    DynamicTree one;
    const int32_t p = one.create_proxy({{1.0f, 2.0f}, {3.0f, 4.0f}}, 1, 5);
    one.rebuild();
    one.validate();
    I2D_CHECK(one.proxy_count() == 1 && one.height() == 0);
    int32_t found = 0;
    one.query({{0.0f, 0.0f}, {1.0f, 2.0f}}, all_bits, [&](int32_t proxy, int32_t user) {
        found += proxy == p && user == 5 ? 1 : 0;
        return true;
    });
    I2D_CHECK(found == 1);
}

// Quality of incremental insertion: 10k random boxes inserted one by one, compared with a
// fresh rebuild of the same boxes (numbers printed). Incremental must stay within the height
// bound and within 1.5x of the rebuilt tree's total perimeter.
I2D_TEST(unit_tree_quality_random_insertion_vs_rebuild) {
    TestRng rng(4242);
    DynamicTree tree;
    const int32_t n = 10000;
    const float world = 100.0f;  // 0.5-1.5 m boxes, one per 4 m^2
    for (int32_t i = 0; i < n; ++i) {
        const float x = rng.uniform(-world, world), y = rng.uniform(-world, world);
        const float w = rng.uniform(0.5f, 1.5f), h = rng.uniform(0.5f, 1.5f);
        tree.create_proxy({{x, y}, {x + w, y + h}}, 1, i);
    }
    tree.validate();
    const int32_t h_inc = tree.height();
    const float p_inc = tree.total_perimeter();
    tree.rebuild();
    tree.validate();
    const int32_t h_reb = tree.height();
    const float p_reb = tree.total_perimeter();
    std::printf("tree quality, %d random insertions: height %d (rebuild %d, minimum %d), total perimeter %.0f "
                "(rebuild %.0f, ratio %.3f)\n",
                n, h_inc, h_reb, ceil_log2(n), double(p_inc), double(p_reb), double(p_inc / p_reb));
    I2D_CHECK(tree.proxy_count() == n);
    I2D_CHECK(h_inc >= ceil_log2(n) && double(h_inc) <= height_bound(n));
    I2D_CHECK(h_reb >= ceil_log2(n) && double(h_reb) <= height_bound(n));
    I2D_CHECK(p_inc <= 1.5f * p_reb);
}

// The same box inserted thousands of times (bodies made at one spot) costs the same
// wherever it goes: the tree must still stay within the height bound, through removals
// and moves away, or every removal refits through a chain as deep as the boxes are many.
I2D_TEST(unit_tree_coincident_boxes_stay_shallow) {
    const int32_t n = 4096;
    const AABB spot{{-0.1f, -0.1f}, {0.1f, 0.1f}};
    DynamicTree tree;
    std::vector<int32_t> proxies;
    for (int32_t i = 0; i < n; ++i) {
        proxies.push_back(tree.create_proxy(spot, 1, i));
    }
    tree.validate();
    I2D_CHECK(height_ok(tree, "after inserting one box 4096 times"));
    for (int32_t i = 0; i < n; i += 2) {
        tree.destroy_proxy(proxies[std::size_t(i)]);
    }
    tree.validate();
    I2D_CHECK(height_ok(tree, "after destroying every other coincident box"));
    // Placed one by one on a grid, as a loader places bodies it made at the origin.
    for (int32_t i = 1; i < n; i += 2) {
        const float x = float(i % 64), y = float(i / 64);
        tree.move_proxy(proxies[std::size_t(i)], {{x, y}, {x + 0.5f, y + 0.5f}});
    }
    tree.validate();
    I2D_CHECK(height_ok(tree, "after moving the coincident boxes apart"));
    // A cluster at one spot beside boxes elsewhere: the cluster's subtree stays shallow too.
    DynamicTree mixed;
    for (int32_t i = 0; i < n; ++i) {
        const float x = float(i % 64) * 3.0f, y = float(i / 64) * 3.0f;
        mixed.create_proxy(i % 2 == 0 ? spot : AABB{{x, y}, {x + 1.0f, y + 1.0f}}, 1, i);
    }
    mixed.validate();
    I2D_CHECK(height_ok(mixed, "with half the boxes at one spot"));
}

// Insertion in sorted order (a row-by-row grid, as scenes are built) is the classic way to
// unbalance an incremental tree; rotations must keep it within the height bound.
I2D_TEST(unit_tree_quality_sorted_insertion_stays_shallow) {
    const int32_t side = 100;  // 10k boxes
    DynamicTree grid, line;
    for (int32_t row = 0; row < side; ++row) {
        for (int32_t col = 0; col < side; ++col) {
            const float x = 1.1f * float(col), y = 1.1f * float(row);
            grid.create_proxy({{x, y}, {x + 1.0f, y + 1.0f}}, 1, row * side + col);
        }
    }
    for (int32_t i = 0; i < side * side; ++i) {
        const float x = 1.1f * float(i);
        line.create_proxy({{x, 0.0f}, {x + 1.0f, 1.0f}}, 1, i);
    }
    grid.validate();
    line.validate();
    const int32_t n = side * side;
    const int32_t h_grid = grid.height(), h_line = line.height();
    const float p_grid = grid.total_perimeter(), p_line = line.total_perimeter();
    grid.rebuild();
    line.rebuild();
    std::printf("tree quality, %d sorted insertions: grid height %d (rebuild %d), perimeter %.0f (rebuild %.0f); "
                "line height %d (rebuild %d), perimeter %.0f (rebuild %.0f)\n",
                n, h_grid, grid.height(), double(p_grid), double(grid.total_perimeter()), h_line, line.height(),
                double(p_line), double(line.total_perimeter()));
    I2D_CHECK(double(h_grid) <= height_bound(n));
    I2D_CHECK(double(h_line) <= height_bound(n));
    I2D_CHECK(double(grid.height()) <= height_bound(n));
    I2D_CHECK(double(line.height()) <= height_bound(n));
}

// The self search cut finer finds the same pairs in the same order: split_self_overlaps
// with its heavy parts cut (a 64th and a 1024th of the tree at most) gives, part after
// part, the pairs the level split alone gives (max_share 1 cuts nothing), and those are
// every two overlapping boxes once (brute force). The workers' results are put together
// part by part, so a cut that changed the order would change a world's bits.
I2D_TEST(unit_tree_self_search_cut_finer_finds_the_same_pairs_in_the_same_order) {
    constexpr int32_t count = 3000, level_parts = 32;
    TestRng rng(404);
    DynamicTree tree;
    std::vector<AABB> boxes;
    for (int32_t i = 0; i < count; ++i) {
        boxes.push_back(random_box(rng, 40.0f));
        tree.create_proxy(boxes.back(), 1, i);
    }
    tree.rebuild();  // balanced, as the step's rebuilds leave the tree
    struct Search {
        std::vector<std::pair<int32_t, int32_t>> pairs;
        std::size_t parts = 0, most_in_a_part = 0;
    };
    const auto search = [&](int32_t max_share) {
        Search s;
        std::vector<TreeNodePair> parts;
        tree.split_self_overlaps(level_parts, max_share, parts);
        s.parts = parts.size();
        for (const TreeNodePair part : parts) {
            const std::size_t before = s.pairs.size();
            tree.self_overlaps(part, [&](int32_t, int32_t a, int32_t, int32_t b) { s.pairs.push_back({a, b}); });
            s.most_in_a_part = std::max(s.most_in_a_part, s.pairs.size() - before);
        }
        return s;
    };
    const Search level = search(1), fine = search(64), finest = search(1024);
    std::printf("self search of %d boxes (height %d): %zu pairs; parts %zu / %zu / %zu, "
                "most pairs in one part %zu / %zu / %zu\n",
                count, tree.height(), level.pairs.size(), level.parts, fine.parts, finest.parts, level.most_in_a_part,
                fine.most_in_a_part, finest.most_in_a_part);
    I2D_CHECK(fine.pairs == level.pairs);
    I2D_CHECK(finest.pairs == level.pairs);
    I2D_CHECK(level.parts >= std::size_t(level_parts) && fine.parts > level.parts && finest.parts > fine.parts);
    I2D_CHECK(fine.most_in_a_part < level.most_in_a_part);
    std::size_t overlapping = 0;
    for (int32_t i = 0; i < count; ++i) {
        for (int32_t j = i + 1; j < count; ++j) {
            overlapping += boxes_overlap(boxes[std::size_t(i)], boxes[std::size_t(j)]) ? 1 : 0;
        }
    }
    std::vector<std::pair<int32_t, int32_t>> unique = level.pairs;
    for (auto& p : unique) {
        p = {std::min(p.first, p.second), std::max(p.first, p.second)};
    }
    std::sort(unique.begin(), unique.end());
    I2D_CHECK(std::unique(unique.begin(), unique.end()) == unique.end());
    I2D_CHECK(unique.size() == overlapping);
    for (const auto& p : unique) {
        I2D_CHECK(boxes_overlap(boxes[std::size_t(p.first)], boxes[std::size_t(p.second)]));
    }
}

// Marked moves keep the self search to the pairs with a moved leaf: part after part it
// gives, in the same order, the pairs of the unmarked search that have a marked leaf
// (the world's bits depend on that order), and once the marks are cleared it gives every
// pair again.
I2D_TEST(unit_tree_self_search_with_marked_moves_finds_the_moved_pairs_in_order) {
    constexpr int32_t count = 3000, level_parts = 32, marked_every = 3;
    TestRng rng(405);
    DynamicTree tree;
    std::vector<int32_t> proxies;
    for (int32_t i = 0; i < count; ++i) {
        proxies.push_back(tree.create_proxy(random_box(rng, 40.0f), 1, i));
    }
    tree.rebuild();
    const auto search = [&tree]() {
        std::vector<std::pair<int32_t, int32_t>> pairs;
        std::vector<TreeNodePair> parts;
        tree.split_self_overlaps(level_parts, 64, parts);
        for (const TreeNodePair part : parts) {
            tree.self_overlaps(part, [&](int32_t, int32_t a, int32_t, int32_t b) { pairs.push_back({a, b}); });
        }
        return pairs;
    };
    const auto marked = [](int32_t shape) { return shape % marked_every == 0; };
    const std::vector<std::pair<int32_t, int32_t>> every = search();
    std::vector<std::pair<int32_t, int32_t>> expected;
    for (const auto& p : every) {
        if (marked(p.first) || marked(p.second)) {
            expected.push_back(p);
        }
    }
    for (int32_t i = 0; i < count; ++i) {
        if (marked(i)) {
            tree.mark_moved(proxies[std::size_t(i)]);
        }
    }
    const std::vector<std::pair<int32_t, int32_t>> moved = search();
    tree.clear_moved_marks();
    std::printf("self search of %d boxes, one in %d marked: %zu pairs, %zu with a marked box\n", count,
                marked_every, every.size(), moved.size());
    I2D_CHECK(!expected.empty() && expected.size() < every.size());
    I2D_CHECK(moved == expected);
    I2D_CHECK(search() == every);
}
