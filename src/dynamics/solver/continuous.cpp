// SPDX-License-Identifier: MIT
// The continuous collision stage: sweeps, times of impact, moving fast bodies back.
#include "dynamics/solver/continuous.hpp"

#include "collision/geometry.hpp"
#include "collision/manifold.hpp"
#include "dynamics/constants.hpp"
#include "dynamics/body/shape_bounds.hpp"
#include "dynamics/solver/impact.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

// The lengths below are shares of the world's linear slop (Tolerances), so that they
// scale with its length unit.

/// How close the time of impact must bring the cores, within a quarter slop: the
/// shapes end up a slop inside each other's rounding, or a slop apart when neither is
/// rounded (Box2D's target), so that the next step's contact has a point to push on.
float impact_target(const ShapeProxy& a, const ShapeProxy& b, float slop) {
    return max_of(slop, a.radius + b.radius - slop);
}

/// How far short of its target a time of impact may stop, in slops.
constexpr float impact_tolerance_share = 0.25f;

/// Manifold points at the time of impact within this many slops of touching take the
/// impact: the sweep stops a slop inside a rounded shape, or a slop apart, within a
/// quarter slop (impact_target, impact_tolerance_share), and the manifold's distance
/// differs from the sweep's by rounding. Farther points are speculative.
constexpr float impact_touching_share = 1.5f;

/// A body this close to the world's speed limit, as a share of it, was held there by the
/// integration.
constexpr float held_at_limit_share = 0.999f;

/// How close the shape's centre may come to what it touched at the start of the step,
/// in slops: a centre that got this close is stopped there, so that it never passes
/// through.
constexpr float centre_target_share = 0.5f;

// The shape's centre: what must never pass through anything. A contact may let a shape
// sink within a step (a paddle turning a third of a radian per step turns its contact
// normal with it, which the step's fixed normal does not follow), but not its centre.
ShapeProxy centre_point(const Geometry& g) {
    ShapeProxy p;
    p.count = 1;
    switch (g.type) {
        case ShapeType::circle: p.points[0] = g.circle.center; break;
        case ShapeType::capsule: p.points[0] = 0.5f * (g.capsule.center1 + g.capsule.center2); break;
        case ShapeType::segment: p.points[0] = 0.5f * (g.segment.point1 + g.segment.point2); break;
        case ShapeType::chain_segment: p.points[0] = 0.5f * (g.chain_segment.point1 + g.chain_segment.point2); break;
        default: p.points[0] = g.polygon.centroid; break;
    }
    return p;
}

// The centre against the other shape's core. A centre that starts the step closer than
// centre_target (a shape sinking into a turning paddle) may not come closer than half
// its start distance, so that sinking slows down step by step instead of crossing; one
// inside the core already is left to the contact.
ToiResult sweep_centre(const ShapeProxy& other, const Sweep& other_sweep, const ShapeProxy& centre,
                       const Sweep& sweep, float max_fraction, float slop) {
    const float start = core_distance(transformed(other, sweep_transform(other_sweep, 0.0f)),
                                      transformed(centre, sweep_transform(sweep, 0.0f)))
                            .distance -
                        other.radius;
    if (!(start > 0.0f)) {
        return ToiResult{};
    }
    const float target = min_of(centre_target_share * slop, 0.5f * start);
    const float tolerance = min_of(impact_tolerance_share * slop, 0.25f * start);
    return time_of_impact(other, other_sweep, centre, sweep, max_fraction, other.radius + target, tolerance);
}

// Whether a point lies behind a chain segment (left of point1 -> point2).
bool starts_behind(const ChainSegment& segment, const Transform& xf, Vec2 point) {
    const Vec2 p1 = transform_point(xf, segment.point1), p2 = transform_point(xf, segment.point2);
    return cross(p2 - p1, point - p1) > 0.0f;
}

}  // namespace

void Continuous::run(const StepContext& step, const std::vector<int32_t>& fast_bodies) {
    crossings_.clear();
    found_.resize(std::size_t(tasks_.worker_count()));
    non_bullets_.clear();
    for (const int32_t body : fast_bodies) {
        if (!bodies_[body].is_bullet) {
            non_bullets_.push_back(body);
        }
    }
    const bool parallel = tasks_.worker_count() > 1 && int32_t(non_bullets_.size()) >= parallel_min_fast_bodies;
    if (parallel) {
        sweep_non_bullets(step);
    }
    // Bullets last, so that they meet the other fast bodies where these were left.
    for (int32_t pass = parallel ? 1 : 0; pass < 2; ++pass) {
        const bool bullet_pass = pass == 1;
        for (const int32_t body : fast_bodies) {
            if (bodies_[body].is_bullet == bullet_pass) {
                std::vector<SensorCandidate>& found = found_[0];
                found.clear();
                const Impact first = sweep(body, bullet_pass, step.tolerances, found);
                apply(step, body, first, found.data(), found.data() + found.size());
            }
        }
    }
}

// The sweeps shared by the workers, then their results applied in awake order.
void Continuous::sweep_non_bullets(const StepContext& step) {
    const int32_t count = int32_t(non_bullets_.size());
    const int32_t workers = tasks_.worker_count();
    for (std::vector<SensorCandidate>& found : found_) {
        found.clear();
    }
    results_.resize(std::size_t(count));
    stages_.assign(1, make_stage<&Continuous::sweep_range>(*this, NoStageArg{}, count, workers, true,
                                                          fast_bodies_per_work_block));
    runner_.run(tasks_, stages_, true, &step);
    for (int32_t k = 0; k < count; ++k) {
        const SweepResult& r = results_[std::size_t(k)];
        const SensorCandidate* found = found_[std::size_t(r.worker)].data();
        apply(step, non_bullets_[std::size_t(k)], r.first, found + r.candidates_begin, found + r.candidates_end);
    }
}

void Continuous::sweep_range(const StepContext& step, Continuous& self, const NoStageArg&, int32_t begin,
                             int32_t end, int32_t worker) {
    std::vector<SensorCandidate>& found = self.found_[std::size_t(worker)];
    for (int32_t k = begin; k < end; ++k) {
        SweepResult& r = self.results_[std::size_t(k)];
        r.worker = worker;
        r.candidates_begin = int32_t(found.size());
        r.first = self.sweep(self.non_bullets_[std::size_t(k)], false, step.tolerances, found);
        r.candidates_end = int32_t(found.size());
    }
}

// A body the solver moved this step sweeps from its start pose to its pose now; static
// and sleeping bodies stay where they are.
Sweep Continuous::sweep_of(int32_t body) const {
    const Body& b = bodies_[body];
    if (b.type == BodyType::static_body || b.awake_index == null_index) {
        return still_sweep(b.transform, b.local_center);
    }
    return Sweep{b.local_center, b.center0, b.center, b.rotation0, b.transform.q};
}

bool Continuous::swept_against(const Body& fast, const Body& other, bool bullet_pass) const {
    return &fast != &other && (other.type != BodyType::dynamic || bullet_pass);
}

// The body's first impact along its sweep; the sensors it crosses go to `found`.
Continuous::Impact Continuous::sweep(int32_t body, bool bullet_pass, const Tolerances& tolerances,
                                     std::vector<SensorCandidate>& found) {
    const Body& b = bodies_[body];
    FastShape fast;
    fast.body = body;
    fast.bullet_pass = bullet_pass;
    fast.slop = tolerances.linear_slop;
    fast.margin = tolerances.speculative_distance;
    fast.sweep = sweep_of(body);
    fast.start = Transform{fast.sweep.c1 - rotate(fast.sweep.q1, fast.sweep.local_center), fast.sweep.q1};
    const bool turned = !(fast.sweep.q1.c == fast.sweep.q2.c && fast.sweep.q1.s == fast.sweep.q2.s);
    const Vec2 travel = fast.sweep.c2 - fast.sweep.c1;
    Impact first;
    const int32_t kinds = bullet_pass ? int32_t(ProxyKind::count) : int32_t(ProxyKind::dynamic_proxy);
    for (int32_t s = b.head_shape; s != null_index; s = shapes_[s].next_in_body) {
        const Shape& shape = shapes_[s];
        if (shape.is_sensor) {
            continue;
        }
        fast.shape = s;
        fast.proxy = make_shape_proxy(shape.geometry);
        // Without a turn the start box is the end box moved back.
        const AABB start_box = turned ? compute_aabb(shape.geometry, fast.start)
                                      : AABB{shape.aabb.lower - travel, shape.aabb.upper - travel};
        const AABB swept_box = union_of(start_box, shape.aabb);
        for (int32_t kind = 0; kind < kinds; ++kind) {
            broad_phase_.tree(ProxyKind(kind)).query(swept_box, [&](int32_t, int32_t other) {
                test_candidate(fast, other, first, found);
                return true;
            });
        }
    }
    return first;
}

// The sensors crossed before the impact are listed, and the body goes back to it.
void Continuous::apply(const StepContext& step, int32_t body, const Impact& first, const SensorCandidate* found_begin,
                       const SensorCandidate* found_end) {
    for (const SensorCandidate* c = found_begin; c != found_end; ++c) {
        if (c->fraction <= first.fraction) {
            crossings_.push_back(c->crossing);
        }
    }
    if (first.fraction < 1.0f) {
        const Body& other = bodies_[first.body];
        // Two bullets meeting head-on both stop where they touch.
        const bool both_stop = other.is_bullet && other.type == BodyType::dynamic && other.awake_index != null_index;
        const int32_t carrier = other.type == BodyType::kinematic ? first.body : null_index;
        if (carrier == null_index) {
            rewind_gravity(step, body, first.fraction);
        }
        if (both_stop) {
            rewind_gravity(step, first.body, first.fraction);
        }
        resolve(step, body, first);
        if (both_stop) {
            move_to(step, first.body, first.fraction, null_index);
        }
        move_to(step, body, first.fraction, carrier);
    }
}

// One shape the fast shape's sweep may reach: the earliest impact is kept in `first`;
// a sensor it crosses is remembered.
void Continuous::test_candidate(const FastShape& fast, int32_t other_index, Impact& first,
                                std::vector<SensorCandidate>& found) {
    const Shape& shape = shapes_[fast.shape];
    const Shape& other = shapes_[other_index];
    if (!swept_against(bodies_[fast.body], bodies_[other.body], fast.bullet_pass) ||
        !should_collide(shape.filter, other.filter) ||
        !hooks_.allows_pair(events_.ids, shapes_, min_of(fast.shape, other_index), max_of(fast.shape, other_index))) {
        return;
    }
    const Sweep other_sweep = sweep_of(other.body);
    if (other.geometry.type == ShapeType::chain_segment &&
        starts_behind(other.geometry.chain_segment, sweep_transform(other_sweep, 0.0f),
                      transform_point(fast.start, centre_point(shape.geometry).points[0]))) {
        return;  // one-sided: a body coming from behind passes through
    }
    const ShapeProxy other_proxy = make_shape_proxy(other.geometry);
    const float tolerance = impact_tolerance_share * fast.slop;
    if (other.is_sensor) {
        if (shape.enable_sensor_events) {
            const ToiResult r = time_of_impact(other_proxy, other_sweep, fast.proxy, fast.sweep, 1.0f,
                                               other_proxy.radius + fast.proxy.radius, tolerance);
            if (r.state == ToiState::hit) {
                found.push_back({{other_index, fast.shape}, r.fraction});
            }
        }
        return;
    }
    ToiResult r = time_of_impact(other_proxy, other_sweep, fast.proxy, fast.sweep, first.fraction,
                                 impact_target(other_proxy, fast.proxy, fast.slop), tolerance);
    // Touching at the start: the contact has the pair in hand, unless the step took the
    // shape's centre through (Box2D sweeps a small disc instead, which a sinking shape can
    // start inside of).
    if (r.state == ToiState::overlapped) {
        r = sweep_centre(other_proxy, other_sweep, centre_point(shape.geometry), fast.sweep, first.fraction,
                         fast.slop);
    }
    if (r.state == ToiState::hit && r.fraction < first.fraction &&
        !pre_solve_refuses(fast, other_index, other_sweep, r.fraction)) {
        first.fraction = r.fraction;
        first.body = other.body;
        first.shape = fast.shape;
        first.other_shape = other_index;
    }
}

// A pair that opted in to the pre-solve hook is asked about the impact with the
// manifold the shapes would have there: a one-way platform the hook turns off for a body
// coming from below must not stop it there either, however fast it moves.
bool Continuous::pre_solve_refuses(const FastShape& fast, int32_t other_index, const Sweep& other_sweep,
                                   float fraction) const {
    if (!hooks_.asks_pre_solve(shapes_[fast.shape], shapes_[other_index])) {
        return false;
    }
    const bool fast_first = fast.shape < other_index;  // contacts name the lower shape A
    const Transform fast_pose = sweep_transform(fast.sweep, fraction);
    const Transform other_pose = sweep_transform(other_sweep, fraction);
    const Shape& a = shapes_[fast_first ? fast.shape : other_index];
    const Shape& b = shapes_[fast_first ? other_index : fast.shape];
    const Manifold manifold = collide_shapes(a.geometry, fast_first ? fast_pose : other_pose, b.geometry,
                                             fast_first ? other_pose : fast_pose, fast.margin, fast.slop);
    return manifold.point_count > 0 &&
           !hooks_.allows_contact(events_.ids, shapes_, fast_first ? fast.shape : other_index,
                                  fast_first ? other_index : fast.shape, manifold);
}

// A body going back to the time of impact takes back the gravity of the time it loses,
// so that it meets what it hit at the speed it had there: a ball dropped on the ground
// bounces with e times its impact speed, not the faster speed the step ended with. (A
// body carried by a kinematic one loses no time: it ends the step where its carrier does.)
// A body at the speed limit was held there by the integration, which so gave it less than
// the gravity of a step, or none: nothing is taken back (any finite gravity is accepted;
// one of 1e6 m/s^2 sent a ball that hit a wall back at the limit, and one near the float
// range left it -5.7e36 m/s, which the impact turned into NaN).
void Continuous::rewind_gravity(const StepContext& step, int32_t body, float fraction) {
    Body& b = bodies_[body];
    const float max_speed = step.settings.maximum_linear_speed;
    const float held_speed = held_at_limit_share * max_speed;
    if (length_squared(b.linear_velocity) >= held_speed * held_speed) {
        return;
    }
    const float lost = (1.0f - fraction) * step.time_step * b.gravity_scale;
    const Vec2 v = b.linear_velocity - lost * step.settings.gravity;
    b.linear_velocity = length_squared(v) <= max_speed * max_speed
                            ? v
                            : held_to_length(double(b.linear_velocity.x) - double(lost) * double(step.settings.gravity.x),
                                             double(b.linear_velocity.y) - double(lost) * double(step.settings.gravity.y),
                                             max_speed);
}

// The body goes back to the fraction of its sweep, with the velocities resolve gave it.
// A kinematic body it hit keeps moving to the end of the step, so the body rides along
// with it from the impact (the carrier): the two end the step as they were when they
// touched, rather than the wall passing the body that waits at the impact point. A
// dynamic body it hit is not a carrier: it can be stopped by the contact, and carrying a
// bullet along with a box that lands would push the bullet into the floor.
void Continuous::move_to(const StepContext& step, int32_t body, float fraction, int32_t carrier) {
    Body& b = bodies_[body];
    Transform xf = sweep_transform(sweep_of(body), fraction);
    if (carrier != null_index) {
        const Sweep carried = sweep_of(carrier);
        const Transform relative = inv_mul_transforms(sweep_transform(carried, fraction), xf);
        xf = mul_transforms(sweep_transform(carried, 1.0f), relative);
    }
    b.transform = xf;
    b.center = transform_point(xf, b.local_center);
    update_shape_bounds(b, shapes_, broad_phase_, step.time_step * b.linear_velocity, true);
    if (b.move_event != null_index) {
        events_.current.body_moves[std::size_t(b.move_event)].transform = b.transform;
    }
}

// The impact where the sweep stopped (impact.hpp): the two shapes' manifold at their poses
// at the time of impact, and the impulse a rigid contact would give its touching points,
// with the pair's mixed friction and restitution. A dynamic body met takes its share (a
// bullet's hit pushes the box it hits); one asleep is left to the next step's contact,
// which wakes it. The impact reports a hit event as a contact would (the next step's
// contact, which starts without approach, reports none).
void Continuous::resolve(const StepContext& step, int32_t body, const Impact& impact) {
    Body& b = bodies_[body];
    Body& o = bodies_[impact.body];
    const bool other_moves = o.type == BodyType::dynamic;
    if (other_moves && o.awake_index == null_index) {
        return;
    }
    const Transform xf_b = sweep_transform(sweep_of(body), impact.fraction);
    const Transform xf_a = sweep_transform(sweep_of(impact.body), impact.fraction);
    const Shape& fast = shapes_[impact.shape];
    const Shape& other = shapes_[impact.other_shape];
    const Tolerances& tolerances = step.tolerances;
    const Manifold manifold = collide_shapes(other.geometry, xf_a, fast.geometry, xf_b,
                                             tolerances.speculative_distance, tolerances.linear_slop);
    const WorldDef& settings = step.settings;
    ImpactMaterial material;
    material.friction = mix(settings.friction_mixing, fast.friction, other.friction);
    material.restitution = mix(settings.restitution_mixing, fast.restitution, other.restitution);
    material.restitution_threshold = settings.restitution_threshold;
    // As a contact mixes it (contact_set.cpp): the same whichever shape is A.
    material.tangent_speed = fast.tangent_speed + other.tangent_speed;
    ImpactBody a{transform_point(xf_a, o.local_center), o.linear_velocity, o.angular_velocity,
                 other_moves ? o.inv_mass : 0.0f, other_moves ? o.inv_inertia : 0.0f};
    ImpactBody fast_body{transform_point(xf_b, b.local_center), b.linear_velocity, b.angular_velocity, b.inv_mass,
                         b.inv_inertia};
    const ImpactResult r = resolve_impact(manifold, impact_touching_share * tolerances.linear_slop, material, a,
                                          fast_body);
    if (r.point_index < 0) {
        return;
    }
    const float max_spin = step.max_spin();
    b.linear_velocity = fast_body.linear_velocity;
    b.angular_velocity = clamp(fast_body.angular_velocity, -max_spin, max_spin);
    if (other_moves) {
        o.linear_velocity = a.linear_velocity;
        o.angular_velocity = clamp(a.angular_velocity, -max_spin, max_spin);
        // Its boxes ahead follow its new velocity (the fast body's follow in move_to).
        update_shape_bounds(o, shapes_, broad_phase_, step.time_step * o.linear_velocity, true);
    }
    if ((fast.enable_hit_events || other.enable_hit_events) && r.approach_speed > settings.hit_event_threshold) {
        // As a contact names them: the lower shape A, the normal from A to B.
        const bool fast_first = impact.shape < impact.other_shape;
        const int32_t shape_a = fast_first ? impact.shape : impact.other_shape;
        const int32_t shape_b = fast_first ? impact.other_shape : impact.shape;
        events_.current.contact_hits.push_back({events_.ids.shape_id(shape_a, shapes_.generation(shape_a)),
                                                events_.ids.shape_id(shape_b, shapes_.generation(shape_b)),
                                                manifold.points[r.point_index].point,
                                                fast_first ? -manifold.normal : manifold.normal, r.approach_speed});
    }
}

}  // namespace i2d
