// SPDX-License-Identifier: MIT
// ContactSet: new contacts from the broadphase's pairs, found by the workers and made
// on one thread in the broadphase's order.
#include "core/prefetch.hpp"
#include "core/radix_sort.hpp"
#include "dynamics/constants.hpp"
#include "dynamics/contact/contact_set.hpp"
#include "dynamics/joint/joint_set.hpp"

namespace i2d {

// Most candidates are pairs that have a contact already: the pair set answers that
// with one lookup, before the shapes and bodies are read. Solid shapes need a dynamic
// body between them to push; a sensor reports whatever enters it, whatever moves either
// (box2d#739): a trigger zone on a static body sees a kinematic platform. Static against
// static never reaches here (the broadphase never pairs it). The custom filter hook comes
// last: game code is asked only about pairs that could otherwise touch.
// The shapes' own refusals come before the look-up of known pairs: in rain, 86 % of the
// candidates are two limbs of one ragdoll (one filter group), and 5 % two shapes of one
// body, against 8 % known pairs. pair_range asks for both shapes' lines ahead.
bool ContactSet::may_pair(int32_t shape_a, int32_t shape_b) const {
    const Shape& a = shapes_[shape_a];
    const Shape& b = shapes_[shape_b];
    if (a.body == b.body || (a.is_sensor && b.is_sensor) || !should_collide(a.filter, b.filter)) {
        return false;
    }
    if (pair_set_.contains(pair_key(shape_a, shape_b))) {
        return false;
    }
    if (bodies_[a.body].type != BodyType::dynamic && bodies_[b.body].type != BodyType::dynamic &&
        !a.is_sensor && !b.is_sensor) {
        return false;
    }
    return !joints_.keeps_apart(a.body, b.body) && hooks_.allows_pair(events_.ids, shapes_, shape_a, shape_b);
}

// One pair-finding stage's range: the self search's parts, or the queries.
template <bool SelfSearch>
void ContactSet::pair_range(const StepContext&, ContactSet& self, const PairStage& arg, int32_t begin, int32_t end,
                            int32_t) {
    std::vector<ShapePairCandidate>& out = self.search_.block_pairs[arg.list][std::size_t(begin / arg.items_per_block)];
    out.clear();
    const auto accept = [&self](int32_t a, int32_t b) { return self.may_pair(a, b); };
    // The lines may_pair reads: each shape's body and flags, and its filter.
    const auto ahead = [&self](int32_t a, int32_t b) {
        for (const int32_t shape : {a, b}) {
            const Shape& s = self.shapes_[shape];
            prefetch_line(&s);
            prefetch_line(&s.filter);
        }
        self.pair_set_.prefetch(pair_key(a, b));
    };
    if constexpr (SelfSearch) {
        self.search_.broad_phase->self_pairs(begin, end, accept, out, ahead);
    } else {
        self.search_.broad_phase->query_pairs(begin, end, accept, out, ahead);
    }
}

// New pairs, block by block in the broadphase's order, become contacts on this thread.
// Creation order is the awake list's order, which the colouring follows, and so the order
// of solving: the self search's pairs are first put in the order of their earlier leaf
// in the tree's storage, close to the order the queries give. Made as the search found
// them, many_pyramids' step took 8 % longer (its solve 10 %); sorted by shape ids (row by
// row), the 70-row pyramid crept 5.9 cm sideways in 2000 steps instead of 0.35 cm (row
// order gives every box's contacts the same pattern of colours: a bias to one side).
void ContactSet::find_new_contacts(const StepContext& step, BroadPhase& broad_phase, WakeBody wake) {
    const int32_t queries = broad_phase.begin_pair_queries();
    const int32_t self_parts = broad_phase.self_part_count();
    const int32_t workers = tasks_.worker_count();
    const bool parallel = workers > 1 && (queries >= parallel_min_moved_proxies || self_parts > 0);
    stages_.clear();
    stages_.push_back(make_stage<&ContactSet::pair_range<true>>(*this, PairStage{0}, self_parts, workers, parallel,
                                                                self_search_parts_per_work_block));
    if (parallel) {
        stages_[0].items_per_block = self_search_parts_per_work_block;
    }
    stages_.push_back(make_stage<&ContactSet::pair_range<false>>(*this, PairStage{1}, queries, workers, parallel,
                                                                 proxies_per_work_block));
    for (int32_t s = 0; s < 2; ++s) {
        Stage& stage = stages_[std::size_t(s)];
        stage.set_arg(PairStage{s, stage.items_per_block});
        const std::size_t blocks = std::size_t(stage.block_count());
        if (search_.block_pairs[s].size() < blocks) {
            search_.block_pairs[s].resize(blocks);
        }
    }
    search_.broad_phase = &broad_phase;
    runner_.run(tasks_, stages_, parallel, &step);
    search_.broad_phase = nullptr;
    broad_phase.end_pair_queries();
    for (int32_t s = 0; s < 2; ++s) {
        search_.pairs.clear();
        const Stage& stage = stages_[std::size_t(s)];
        for (int32_t b = 0; b < (stage.item_count > 0 ? stage.block_count() : 0); ++b) {
            const std::vector<ShapePairCandidate>& found = search_.block_pairs[s][std::size_t(b)];
            search_.pairs.insert(search_.pairs.end(), found.begin(), found.end());
        }
        if (s == 0) {
            radix_sort(search_.pairs, search_.sort_scratch, [&](const ShapePairCandidate& p) {
                const uint32_t a = broad_phase.storage_order_of(shapes_[p.shape_a].proxy_key);
                const uint32_t b = broad_phase.storage_order_of(shapes_[p.shape_b].proxy_key);
                return a < b ? a : b;
            });
        }
        for (const ShapePairCandidate& pair : search_.pairs) {
            create_contact(pair.shape_a, pair.shape_b, wake);
        }
    }
}

}  // namespace i2d
