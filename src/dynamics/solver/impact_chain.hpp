// SPDX-License-Identifier: MIT
// ImpactChains: impacts that pass from body to body within one step, taken one at a time
// in the order the gaps close, before the substeps.
//
// Design note: the substeps solve every contact of a step at once. A ball that strikes a
// row of balls standing a little apart (a Newton's cradle with gaps smaller than the
// distance the balls cover in a step) then pushes the whole row inside one step: the
// struck ball's contact with the next ball was not approaching when the step began, so
// the restitution pass has no impact speed for it, and the row shares the momentum as a
// plastic collision would (the last of five balls left at 2.65 of 3 m/s). Here such a
// chain is solved as the rigid-body model of sequential impacts does: an impact is
// resolved alone (impact.hpp: -e times the approach, Coulomb friction), which sets the
// struck body moving into its neighbour, whose contact then takes its own impact, and so
// on, each contact at most once per step, earliest closing gap first. Impacts of the same
// moment that share a moving body are solved together (impact.hpp's resolve_impacts),
// the others apart: a ball struck by two at once takes both, so a rack struck on its axis
// breaks as mirror images, where one impact after the other would send its apex off to
// the side of the first.
//
// Only chains are taken. An impact whose bodies then meet nothing new within the step is
// undone and left to the substeps, whose restitution pass follows the pair's approach
// down to the contact (gravity over the gap) and keeps a bounce's energy exactly: a ball
// bouncing on the floor, a box landing on a pile, every scene without a chain steps to
// the same bits as before. A resting stack has nothing approaching and is never read
// past its contacts' restitution.
//
// Alternative rejected: tracking, in the substeps, the speed at which each contact first
// pushes. Which contact pushes first inside one Gauss-Seidel sweep is the sweep's order,
// not the order of the impacts, and the row still shares the momentum.
#pragma once

#include <cstdint>
#include <vector>

#include "core/pool.hpp"
#include "dynamics/body/body.hpp"
#include "dynamics/solver/impact.hpp"
#include "dynamics/step_context.hpp"

namespace i2d {

class ContactSet;

/// Contacts less elastic take no part in chains. As e goes to 0 a chain's impacts share
/// the momentum as the substeps' simultaneous solve does (a plastic row ends at one speed
/// either way); and trying every fast contact of a scene made of them costs: the
/// spinner's 12,000 contacts at e = 0.1 took a quarter more instructions a step for
/// chains that moved little.
constexpr float chain_min_restitution = 0.5f;
/// Impacts whose gaps close this close in time (s) are one moment, solved together: a
/// ball meeting two at once is struck by both (the order of two simultaneous impacts,
/// taken one after the other, would send a rack's apex off to one side).
constexpr float simultaneous_time = 1e-5f;

class ImpactChains {
public:
    /// Resolves the chains of impacts among the awake contacts, on the bodies' velocities,
    /// one thread, in awake contact order: the same bits for every worker count.
    void run(const StepContext& step, Pool<Body>& bodies, ContactSet& contacts);

private:
    // A contact whose gap closes within the step at the bodies' present velocities.
    struct Candidate {
        float time;  // s: the gap over the approach speed
        int32_t contact;
        bool in_chain;  // made by an impact that was kept
    };
    static bool later(const Candidate& x, const Candidate& y);
    bool candidate_of(const StepContext& step, const Pool<Body>& bodies, const ContactSet& contacts,
                      int32_t contact, Candidate& out) const;
    void push(const Candidate& c);
    Candidate pop();
    void resolve_by_bodies(const StepContext& step, Pool<Body>& bodies, ContactSet& contacts);
    void resolve(const StepContext& step, Pool<Body>& bodies, ContactSet& contacts);
    void find_neighbours(const StepContext& step, const Pool<Body>& bodies, const ContactSet& contacts);

    // A contact of an impact's bodies, and whether it was closing before the impact.
    struct Neighbour {
        int32_t contact;
        bool was_closing;
    };
    std::vector<Candidate> heap_;
    std::vector<Neighbour> neighbours_;
    std::vector<Candidate> started_;  // the chains an impact starts
    // The impacts of one moment, solved together: their contacts, the bodies they move
    // (each once, with the pool index it came from) and what each contact did.
    std::vector<Candidate> group_;
    std::vector<Candidate> part_;  // those of them joined by their moving bodies
    std::vector<ImpactContact> impacts_;
    std::vector<ImpactBody> impact_bodies_;
    std::vector<int32_t> body_of_slot_;
    std::vector<ImpactResult> results_;
    std::vector<uint8_t> taken_;  // per contact in the pool: resolved (or left) this step
    std::vector<int32_t> taken_list_;
};

}  // namespace i2d
