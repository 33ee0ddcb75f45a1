// SPDX-License-Identifier: MIT
// The broadphase alone: milliseconds per update for N moving circles, with the pairs found,
// the dynamic tree's height and total perimeter against a fresh rebuild, and how the cost
// grows with N.
//
// Method: N circles of radius 0.5 m (as their boxes) in a square of 4 m^2 per circle (the
// density is the same for every N), all dynamic, moving at up to 3 m/s in random directions
// and bouncing off the sides. dt = 1/60 s. Each update: move the circles (not timed); then,
// timed, move_proxy every proxy whose tight box left its fat box (margin 0.1 m, as the
// engine gives shapes of this size) and call update_pairs with an accept that takes every
// pair (it commits the moves as the step does: re-inserted, or in a tree where at least
// an eighth of the proxies moved, rebuilt where they moved).
// Update 0 pairs everything for the first time and is not timed; ms per update = total of
// updates 1..U-1 / (U - 1). Each N runs R times from the same start; median and minimum are
// reported. For N <= 2000 the first run checks every update against brute force: the pairs
// must be exactly the overlapping fat-box pairs with at least one proxy moved, each once.
// Times are never asserted on; the exit status says whether those checks passed.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <utility>
#include <vector>

#include "broadphase/broad_phase.hpp"

using namespace i2d;

// Defined by bench/CMakeLists.txt; the fallbacks let the file build by hand.
#ifndef I2D_BENCH_BUILD_TYPE
#define I2D_BENCH_BUILD_TYPE "unknown"
#endif
#ifndef I2D_BENCH_CXX_COMPILER
#define I2D_BENCH_CXX_COMPILER "unknown"
#endif
#ifndef I2D_BENCH_CXX_FLAGS
#define I2D_BENCH_CXX_FLAGS "unknown"
#endif
#ifndef I2D_BENCH_COMMIT
#define I2D_BENCH_COMMIT "unknown"
#endif
#ifndef I2D_BENCH_SANITIZE
#define I2D_BENCH_SANITIZE "unknown"
#endif

namespace {

enum { exit_ok = 0, exit_mismatch = 1, exit_usage = 2 };

constexpr float radius = 0.5f;
constexpr float margin = 0.1f;          // the engine's fat-box margin for these circles, m
constexpr float area_per_circle = 4.0f; // m^2 of region per circle
constexpr float max_speed = 3.0f;       // m/s
constexpr float dt = 1.0f / 60.0f;
constexpr int32_t brute_force_limit = 2000;

// ---- Build description ----------------------------------------------------------------------

const char* simd_macros() {
    static const char list[] = ""
#if defined(__AVX512F__)
                               " AVX512F"
#endif
#if defined(__AVX2__)
                               " AVX2"
#endif
#if defined(__FMA__)
                               " FMA"
#endif
#if defined(__AVX__)
                               " AVX"
#endif
#if defined(__SSE4_2__)
                               " SSE4.2"
#endif
#if defined(__SSE2__)
                               " SSE2"
#endif
#if defined(__ARM_NEON)
                               " NEON"
#endif
        ;
    return list[0] ? list + 1 : "none";
}

void print_build(bool csv) {
    char date[32];
    const std::time_t now = std::time(nullptr);
    const std::tm* utc = std::gmtime(&now);
    if (!utc || !std::strftime(date, sizeof date, "%Y-%m-%d %H:%M:%S UTC", utc)) {
        std::snprintf(date, sizeof date, "unknown");
    }
#if defined(__clang__)
    const char* compiler = "clang " __clang_version__;
#elif defined(__GNUC__)
    const char* compiler = "gcc " __VERSION__;
#else
    const char* compiler = "unknown";
#endif
#if defined(I2D_VALIDATE)
    const char* validate = "ON";
#else
    const char* validate = "OFF";
#endif
    std::printf("# impulse2d broadphase bench | %s | core: static impulse2d_core (%s), I2D_VALIDATE=%s "
                "I2D_SANITIZE=%s | %s | C++ flags: %s | SIMD: %s | commit %s | %s\n",
                compiler, I2D_BENCH_CXX_COMPILER, validate, I2D_BENCH_SANITIZE, I2D_BENCH_BUILD_TYPE,
                I2D_BENCH_CXX_FLAGS, simd_macros(), I2D_BENCH_COMMIT, date);
    if (csv) {
        std::printf("n,region_m,updates,repeats,median_ms,min_ms,pairs_per_update,moves_per_update,height,"
                    "height_rebuilt,perimeter,perimeter_rebuilt,rebuild_ms,check\n");
    } else {
        std::printf("# circles r %.1f m, %.0f m^2 each, up to %.0f m/s, dt 1/60 s, margin %.1f m; timed: escape test +"
                    " move_proxy + update_pairs (accept all), updates 1..U-1; median and min over the runs\n",
                    double(radius), double(area_per_circle), double(max_speed), double(margin));
        std::printf("%8s %8s %5s %4s %10s %10s %11s %11s %7s %8s %12s %12s %6s %8s  %s\n", "N", "region m", "upd",
                    "runs", "median ms", "min ms", "pairs/upd", "moves/upd", "height", "rebuilt", "perimeter",
                    "rebuilt", "ratio", "rebuild", "check");
    }
}

// ---- Options ----------------------------------------------------------------------------------

struct Options {
    std::vector<int32_t> sizes{1000, 4000, 16000, 64000, 100000};
    int32_t updates = 100;
    int32_t repeats = 5;
    bool csv = false;
};

void usage(std::FILE* f) {
    std::fprintf(f, "usage: impulse2d_bench_broadphase [--n LIST] [--updates U] [--repeat R] [--csv]\n"
                    "  --n LIST      comma-separated circle counts, 'k' = 1000 (default 1k,4k,16k,64k,100k)\n"
                    "  --updates U   updates per run, U >= 2 (the first is untimed); default 100\n"
                    "  --repeat R    runs per size; default 5\n"
                    "  --csv         CSV rows instead of the table\n"
                    "exit status: 0 ok, 1 pairs differ from brute force (checked for N <= %d), 2 bad usage\n",
                 brute_force_limit);
}

bool parse_int(const char* text, long lo, long hi, int32_t* out) {
    if (!text) {
        return false;
    }
    char* end = nullptr;
    long value = std::strtol(text, &end, 10);
    if (end == text) {
        return false;
    }
    if (*end == 'k' || *end == 'K') {
        value *= 1000;
        ++end;
    }
    if (*end != '\0' || value < lo || value > hi) {
        return false;
    }
    *out = int32_t(value);
    return true;
}

bool parse_list(const char* text, std::vector<int32_t>* out) {
    if (!text) {
        return false;
    }
    out->clear();
    std::string s(text);
    size_t start = 0;
    while (start <= s.size()) {
        const size_t comma = s.find(',', start);
        const std::string item = s.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        int32_t n = 0;
        if (!parse_int(item.c_str(), 2, 10000000, &n)) {
            return false;
        }
        out->push_back(n);
        if (comma == std::string::npos) {
            break;
        }
        start = comma + 1;
    }
    return !out->empty();
}

bool parse_options(int argc, char** argv, Options* opt) {
    for (int i = 1; i < argc; ++i) {
        const char* arg = argv[i];
        const char* value = i + 1 < argc ? argv[i + 1] : nullptr;
        if (std::strcmp(arg, "--n") == 0 && parse_list(value, &opt->sizes)) {
            ++i;
        } else if (std::strcmp(arg, "--updates") == 0 && parse_int(value, 2, 1000000, &opt->updates)) {
            ++i;
        } else if (std::strcmp(arg, "--repeat") == 0 && parse_int(value, 1, 1000, &opt->repeats)) {
            ++i;
        } else if (std::strcmp(arg, "--csv") == 0) {
            opt->csv = true;
        } else if (std::strcmp(arg, "--help") == 0 || std::strcmp(arg, "-h") == 0) {
            usage(stdout);
            std::exit(exit_ok);
        } else {
            std::fprintf(stderr, "impulse2d_bench_broadphase: bad argument '%s'%s%s\n", arg, value ? " " : "",
                         value ? value : "");
            usage(stderr);
            return false;
        }
    }
    return true;
}

// ---- The scene ----------------------------------------------------------------------------------

// xorshift32 with a fixed seed: every run of a size starts from the same scene.
struct Rng {
    uint32_t state = 0x2545f491u;
    uint32_t next() {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        return state;
    }
    float uniform(float lo, float hi) { return lo + (hi - lo) * float(next() >> 8) * (1.0f / 16777216.0f); }
};

bool overlap(const AABB& a, const AABB& b) {
    return a.lower.x <= b.upper.x && b.lower.x <= a.upper.x && a.lower.y <= b.upper.y && b.lower.y <= a.upper.y;
}

bool inside(const AABB& inner, const AABB& outer) {
    return inner.lower.x >= outer.lower.x && inner.lower.y >= outer.lower.y && inner.upper.x <= outer.upper.x &&
           inner.upper.y <= outer.upper.y;
}

struct Circles {
    std::vector<Vec2> position, velocity;
    std::vector<AABB> fat;
    std::vector<int32_t> key;
    float half = 0.0f;  // the region is [-half, half]^2
};

AABB tight_box(Vec2 p) { return {{p.x - radius, p.y - radius}, {p.x + radius, p.y + radius}}; }
AABB fat_box(Vec2 p) {
    const float r = radius + margin;
    return {{p.x - r, p.y - r}, {p.x + r, p.y + r}};
}

void integrate(Circles& c) {
    const float lo = -c.half + radius, hi = c.half - radius;
    for (size_t i = 0; i < c.position.size(); ++i) {
        Vec2& p = c.position[i];
        Vec2& v = c.velocity[i];
        p += dt * v;
        if (p.x < lo || p.x > hi) {
            v.x = -v.x;
            p.x = std::min(hi, std::max(lo, p.x));
        }
        if (p.y < lo || p.y > hi) {
            v.y = -v.y;
            p.y = std::min(hi, std::max(lo, p.y));
        }
    }
}

// Brute force: the overlapping fat-box pairs with at least one moved proxy, sorted, against
// what update_pairs reported (which must hold each pair once). Returns false on a difference.
bool check_update(const Circles& c, const std::vector<char>& moved, const std::vector<ShapePairCandidate>& out,
                  int32_t update) {
    std::vector<std::pair<int32_t, int32_t>> expected, got;
    const int32_t n = int32_t(c.fat.size());
    for (int32_t a = 0; a < n; ++a) {
        for (int32_t b = a + 1; b < n; ++b) {
            if ((moved[a] || moved[b]) && overlap(c.fat[a], c.fat[b])) {
                expected.push_back({a, b});
            }
        }
    }
    bool ordered = true;
    for (const ShapePairCandidate& p : out) {
        ordered = ordered && p.shape_a < p.shape_b;
        got.push_back({p.shape_a, p.shape_b});
    }
    std::sort(got.begin(), got.end());
    const bool unique = std::adjacent_find(got.begin(), got.end()) == got.end();
    if (ordered && unique && got == expected) {
        return true;
    }
    std::fprintf(stderr,
                 "impulse2d_bench_broadphase: N %d update %d: %zu pairs reported%s%s, brute force finds %zu\n", n,
                 update, got.size(), ordered ? "" : " (not ordered a < b)", unique ? "" : " (with repeats)",
                 expected.size());
    return false;
}

struct RunResult {
    double ms_per_update = 0.0;
    double pairs_per_update = 0.0, moves_per_update = 0.0;
    int32_t height = 0, height_rebuilt = 0;
    double perimeter = 0.0, perimeter_rebuilt = 0.0, rebuild_ms = 0.0;
    bool checked = false, check_ok = true;
};

double ms_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

RunResult run_once(int32_t n, int32_t updates, bool check, bool measure_rebuild) {
    RunResult r;
    Rng rng;
    Circles c;
    c.half = 0.5f * std::sqrt(area_per_circle * float(n));
    c.position.resize(size_t(n));
    c.velocity.resize(size_t(n));
    c.fat.resize(size_t(n));
    c.key.resize(size_t(n));
    for (int32_t i = 0; i < n; ++i) {
        c.position[i] = {rng.uniform(-c.half + radius, c.half - radius), rng.uniform(-c.half + radius, c.half - radius)};
        const float angle = rng.uniform(0.0f, 6.2831853f), speed = rng.uniform(0.0f, max_speed);
        c.velocity[i] = {speed * std::cos(angle), speed * std::sin(angle)};
    }

    BroadPhase bp;
    std::vector<ShapePairCandidate> out;
    std::vector<char> moved(size_t(n), 1);
    auto accept_all = [](int32_t, int32_t) { return true; };
    for (int32_t i = 0; i < n; ++i) {
        c.fat[i] = fat_box(c.position[i]);
        c.key[i] = bp.create_proxy(c.fat[i], 1, i, ProxyKind::dynamic_proxy, true);
    }
    bp.update_pairs(accept_all, out);  // update 0: everything pairs for the first time, untimed
    if (check) {
        r.checked = true;
        r.check_ok = check_update(c, moved, out, 0);
    }

    double total_ms = 0.0;
    int64_t pairs = 0, moves = 0;
    for (int32_t update = 1; update < updates; ++update) {
        integrate(c);
        out.clear();
        std::fill(moved.begin(), moved.end(), 0);
        int32_t moved_now = 0;
        const auto start = std::chrono::steady_clock::now();
        for (int32_t i = 0; i < n; ++i) {
            if (!inside(tight_box(c.position[i]), c.fat[i])) {
                c.fat[i] = fat_box(c.position[i]);
                bp.move_proxy(c.key[i], c.fat[i]);
                moved[i] = 1;
                ++moved_now;
            }
        }
        bp.update_pairs(accept_all, out);
        total_ms += ms_since(start);
        pairs += int64_t(out.size());
        moves += moved_now;
        if (check && r.check_ok) {
            r.check_ok = check_update(c, moved, out, update);
        }
    }
    r.ms_per_update = total_ms / double(updates - 1);
    r.pairs_per_update = double(pairs) / double(updates - 1);
    r.moves_per_update = double(moves) / double(updates - 1);
    if (measure_rebuild) {
        DynamicTree& tree = bp.tree(ProxyKind::dynamic_proxy);
        r.height = tree.height();
        r.perimeter = double(tree.total_perimeter());
        const auto start = std::chrono::steady_clock::now();
        tree.rebuild();
        r.rebuild_ms = ms_since(start);
        r.height_rebuilt = tree.height();
        r.perimeter_rebuilt = double(tree.total_perimeter());
    }
    return r;
}

struct SizeResult {
    int32_t n = 0;
    double region = 0.0, median_ms = 0.0, min_ms = 0.0;
    RunResult last;
    const char* check = "-";
};

SizeResult run_size(int32_t n, const Options& opt) {
    SizeResult s;
    s.n = n;
    s.region = double(std::sqrt(area_per_circle * float(n)));
    std::vector<double> ms;
    bool ok = true, checked = false;
    for (int32_t run = 0; run < opt.repeats; ++run) {
        const RunResult r = run_once(n, opt.updates, run == 0 && n <= brute_force_limit, run == opt.repeats - 1);
        ms.push_back(r.ms_per_update);
        checked = checked || r.checked;
        ok = ok && r.check_ok;
        if (run == opt.repeats - 1) {
            s.last = r;
        }
    }
    std::sort(ms.begin(), ms.end());
    const size_t k = ms.size();
    s.min_ms = ms[0];
    s.median_ms = k % 2 ? ms[k / 2] : 0.5 * (ms[k / 2 - 1] + ms[k / 2]);
    s.check = !checked ? "-" : ok ? "ok" : "FAIL";
    return s;
}

void print_size(const SizeResult& s, const Options& opt) {
    const RunResult& r = s.last;
    const double ratio = r.perimeter_rebuilt > 0.0 ? r.perimeter / r.perimeter_rebuilt : 0.0;
    if (opt.csv) {
        std::printf("%d,%.1f,%d,%d,%.6f,%.6f,%.1f,%.1f,%d,%d,%.1f,%.1f,%.3f,%s\n", s.n, s.region, opt.updates,
                    opt.repeats, s.median_ms, s.min_ms, r.pairs_per_update, r.moves_per_update, r.height,
                    r.height_rebuilt, r.perimeter, r.perimeter_rebuilt, r.rebuild_ms, s.check);
    } else {
        std::printf("%8d %8.1f %5d %4d %10.4f %10.4f %11.1f %11.1f %7d %8d %12.0f %12.0f %6.3f %6.1fms  %s\n", s.n,
                    s.region, opt.updates, opt.repeats, s.median_ms, s.min_ms, r.pairs_per_update,
                    r.moves_per_update, r.height, r.height_rebuilt, r.perimeter, r.perimeter_rebuilt, ratio,
                    r.rebuild_ms, s.check);
    }
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    Options opt;
    if (!parse_options(argc, argv, &opt)) {
        return exit_usage;
    }
    print_build(opt.csv);
    std::vector<SizeResult> results;
    int exit_code = exit_ok;
    for (int32_t n : opt.sizes) {
        results.push_back(run_size(n, opt));
        print_size(results.back(), opt);
        if (std::strcmp(results.back().check, "FAIL") == 0) {
            exit_code = exit_mismatch;
        }
    }
    // Scaling: 4x the circles should cost about 4x (close to linear), at most 5x.
    const SizeResult* r16 = nullptr;
    const SizeResult* r64 = nullptr;
    for (const SizeResult& s : results) {
        r16 = s.n == 16000 ? &s : r16;
        r64 = s.n == 64000 ? &s : r64;
    }
    if (r16 && r64 && r16->median_ms > 0.0) {
        std::printf("%stime(64k) / time(16k) = %.2f (4 = linear; target <= 5)\n", opt.csv ? "# " : "",
                    r64->median_ms / r16->median_ms);
    }
    return exit_code;
}
