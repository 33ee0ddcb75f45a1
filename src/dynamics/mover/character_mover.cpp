// SPDX-License-Identifier: MIT
// The character mover's one-call move (character_mover.hpp).
//
// Design note: the character is a capsule that is not in the world. Game code gives it a
// velocity each frame; this moves it as far as the shapes around it allow, the way Box2D
// v3.1's mover sample and Rapier's KinematicCharacterController do, in five parts:
//
// 1. Skin. Every query uses the capsule grown by `skin`, so the real capsule keeps that
//    gap to every surface, plus at most the mover slop: casts stop at a gap between a
//    half and three quarters of it (mover_contact.hpp), and planes are solved to keep
//    the grown capsule 7/8 of it clear (rest_gap). Resting beyond the casts' band means
//    that what the mover slides along, and a shape level with it (the next tile of a
//    tiled floor, whose corner comes exactly as near as the floor), is never within the
//    band, so a cast neither stops at a seam nor counts a slide as moving deeper; resting
//    within the slop means a collide still finds the ground it stands on.
// 2. Slide (cast and slide, max_iterations rounds): collide the grown capsule into
//    planes, solve the rest of the move against them (solve_planes: the nearest move
//    that goes into none), cast along the solved move, which stops short of anything in
//    the way however long the move is (so it never tunnels), and go as far as the cast
//    allows. The rest is asked for again next round against the planes found there: what
//    a wall refuses becomes a slide along it. A round that goes the whole way ends the
//    slide. Planes stand in for the surfaces to first order and so refuse a little more
//    than the shapes do (a tiled floor's next corner, no nearer than the floor, looks
//    like a ramp up); when the mover rests clear of everything it touches and the planes
//    would bend its move, the move as asked is cast first and taken if nothing is in its way.
// 3. Slopes. "Up" is opposite the world's gravity (+y without gravity). A plane whose
//    normal is within max_slope_angle of up is ground, which the slide climbs like any
//    plane; a steeper one is a wall. Walking into a wall that faces up would slide up its
//    plane, so before solving the move loses its horizontal part into such a wall: it
//    does not climb it (the plane itself still holds the character off it, so falling
//    onto it slides down). The velocity returned is clipped by the same walls, so it
//    does not rise along them. Upright walls and overhangs push level or down: their
//    planes alone do. Ground clips only the velocity's downward part: a level walk onto
//    a ramp or a step's edge stays level (the next move follows the slope again) rather
//    than coming back as a climb that would throw the character off the top.
// 4. Steps. A character that started on the ground and is walked into a wall tries, once
//    per move, to step: cast up by step_height, forward by the walk (at least the
//    capsule's radius, to see past the edge), down again; if that lands on ground whose
//    surface is higher than the ground under the feet by no more than step_height, the
//    ledge is low enough. It then goes up and forward by the walk, or
//    by the least that stands its round foot on the ledge's edge
//    (radius (1 - sin max_slope_angle)), and down onto it. Otherwise the wall stops it.
// 5. Snap, then push. A character that started on the ground, is not on it at the end
//    and is not moving up is cast down by snap_distance onto ground, so it keeps its feet
//    going down slopes and steps. Then each dynamic body it ends up touching whose
//    surface its velocity runs into gets an impulse, as if a body of push_mass moving at
//    that velocity met it in a plastic collision: the velocity into it less the body's
//    own at the point, over 1/push_mass + 1/m + (r x n)^2 / I. That is the only change
//    the move makes to the world.
//
// Every query goes to a MoverNeighbourhood gathered once for the whole move, and every
// array is of fixed size: a move allocates nothing.
#include "dynamics/mover/character_mover.hpp"

#include <cfloat>

#include "collision/mover_planes.hpp"
#include "dynamics/mover/mover_neighbourhood.hpp"
#include "dynamics/world/world.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

/// Planes kept per collide; a character touches two or three, a heap of debris a few more.
constexpr int32_t max_touches = 16;

/// Ground up to this much beyond max_slope_angle's cosine still counts: a ramp built at
/// exactly the limit is walkable, whatever its rounding.
constexpr float slope_cosine_tolerance = 1.0e-4f;

/// A slide move shorter than this share of the mover slop is no move: the slide ends.
constexpr float settle_share = 0.01f;

/// The planes a mover solves against keep it this share of the mover slop clear: beyond
/// the band its casts stop in (up to 3/4, mover_contact.hpp), within the reach of its
/// collides (1). See the design note, part 1.
constexpr float rest_gap_share = 0.875f;
static_assert(rest_gap_share > mover_stop_share + mover_stop_tolerance_share && rest_gap_share < 1.0f,
              "rest between the casts' stop band and the collides' reach");

/// A shape this share of the mover slop nearer than the rest gap is still at it: the
/// rounding of a push to the rest gap, not an overlap to push out of.
constexpr float rest_gap_tolerance_share = 1.0f / 16.0f;

using Touch = MoverNeighbourhood::Touch;

struct Touches {
    Touch items[max_touches];
    int32_t count = 0;
};

Vec2 up_of(Vec2 gravity) {
    const Vec2 down = unit_direction(gravity);
    return down.x == 0.0f && down.y == 0.0f ? Vec2{0.0f, 1.0f} : -down;
}

class CharacterMove {
public:
    CharacterMove(World& world, const CharacterDef& def, const Capsule& capsule, Vec2 position, Vec2 velocity,
                  float time_step);
    CharacterResult run();

private:
    static AABB reach_of(const World& world, const CharacterDef& def, const Capsule& capsule, Vec2 position,
                         Vec2 move);
    ShapeProxy at(Vec2 p) const;
    void collide(Vec2 p, Touches& out) const;
    MoverNeighbourhood::Hit cast(Vec2 from, Vec2 translation) const;
    bool is_ground(Vec2 normal) const { return dot(normal, up_) >= cos_max_slope_ - slope_cosine_tolerance; }
    const Touch* ground_of(const Touches& touches) const;
    Vec2 horizontal(Vec2 v) const { return v - dot(v, up_) * up_; }
    Vec2 level_normal(Vec2 normal) const;
    Vec2 climbable_normal(Vec2 normal) const;
    bool walks_into_wall(Vec2 move, const Touches& touches) const;
    Vec2 without_climb(Vec2 move, const Touches& touches) const;
    bool rests_clear(const Touches& touches) const;
    Vec2 solve(Vec2 move, const Touches& touches) const;
    bool land(Vec2 from, float depth, Vec2& out, Touches& out_touches) const;
    void note_hits(const Touches& touches);
    void slide();
    bool step_up(Vec2& remaining);
    void snap(Touches& touches);
    void push(const Touches& touches);
    Vec2 clipped_velocity(const Touches& touches) const;
    Vec2 ground_velocity(const Touch& ground) const;

    World& world_;
    const CharacterDef& def_;
    Capsule capsule_;
    Vec2 position_;
    Vec2 velocity_;
    Vec2 move_;
    Vec2 up_;
    float cos_max_slope_, sin_max_slope_;
    float slop_, radius_, settle_;
    MoverNeighbourhood near_;
    bool was_on_ground_ = false;
    Vec2 start_ground_point_;  // where the feet stood when the move began
    int32_t hits_[max_counted_hits];
    int32_t hit_count_ = 0;
};

// The box no query of the move leaves: the capsule swept by the move, grown by the step
// and snap reach, the step's look past an edge (a radius) and a push out of an overlap
// (a radius), and the slop.
AABB CharacterMove::reach_of(const World& world, const CharacterDef& def, const Capsule& capsule, Vec2 position,
                             Vec2 move) {
    const float radius = capsule.radius + def.skin;
    const Capsule placed{position + capsule.center1, position + capsule.center2, radius};
    const float margin = def.step_height + def.snap_distance + 2.0f * radius + 2.0f * world.mover_slop();
    return grown(swept(proxy_aabb(capsule_proxy(placed)), move), margin);
}

CharacterMove::CharacterMove(World& world, const CharacterDef& def, const Capsule& capsule, Vec2 position,
                             Vec2 velocity, float time_step)
    : world_(world),
      def_(def),
      capsule_(capsule),
      position_(position),
      velocity_(velocity),
      move_(time_step * velocity),
      up_(up_of(world.settings().gravity)),
      slop_(world.mover_slop()),
      radius_(capsule.radius + def.skin),
      settle_(settle_share * world.mover_slop()),
      near_(world, def.filter, reach_of(world, def, capsule, position, time_step * velocity)) {
    const SinCos slope = sin_cos(def.max_slope_angle);
    cos_max_slope_ = slope.c;
    sin_max_slope_ = slope.s;
}

ShapeProxy CharacterMove::at(Vec2 p) const {
    return capsule_proxy(Capsule{p + capsule_.center1, p + capsule_.center2, radius_});
}

void CharacterMove::collide(Vec2 p, Touches& out) const {
    out.count = near_.collide(at(p), slop_, out.items, max_touches);
}

MoverNeighbourhood::Hit CharacterMove::cast(Vec2 from, Vec2 translation) const {
    if (!(length_squared(translation) > 0.0f)) {
        return {};
    }
    return near_.cast(at(from), translation, mover_stop_share * slop_, mover_stop_tolerance_share * slop_);
}

// The most level ground touched: what the feet stand on.
const Touch* CharacterMove::ground_of(const Touches& touches) const {
    const Touch* best = nullptr;
    for (int32_t i = 0; i < touches.count; ++i) {
        const Touch& t = touches.items[i];
        if (is_ground(t.contact.normal) && (best == nullptr || dot(t.contact.normal, up_) > dot(best->contact.normal, up_))) {
            best = &t;
        }
    }
    return best;
}

// A wall's normal turned level: the way it pushes across "up". Zero for ground, and for
// a ceiling, which has no level part.
Vec2 CharacterMove::level_normal(Vec2 normal) const {
    return is_ground(normal) ? Vec2{} : normalize(horizontal(normal));
}

// The level normal of a wall that faces up (too steep to walk): sliding up its plane
// would climb it. Zero for the rest: ground, upright walls, overhangs and ceilings,
// whose planes push level or down.
Vec2 CharacterMove::climbable_normal(Vec2 normal) const {
    return dot(normal, up_) > 0.0f ? level_normal(normal) : Vec2{};
}

bool CharacterMove::walks_into_wall(Vec2 move, const Touches& touches) const {
    const Vec2 walk = horizontal(move);
    for (int32_t i = 0; i < touches.count; ++i) {
        if (dot(walk, level_normal(touches.items[i].contact.normal)) < -settle_) {
            return true;
        }
    }
    return false;
}

// In 2D every wall faces one of the two level directions, so taking away the part that
// runs into each in turn leaves none that runs into any.
Vec2 CharacterMove::without_climb(Vec2 move, const Touches& touches) const {
    for (int32_t i = 0; i < touches.count; ++i) {
        const Vec2 level = climbable_normal(touches.items[i].contact.normal);
        const float into = dot(move, level);
        if (into < 0.0f) {
            move -= into * level;
        }
    }
    return move;
}

// Whether every touched shape is at least the rest gap away (within rounding): nothing to
// push out of.
bool CharacterMove::rests_clear(const Touches& touches) const {
    const float clear = (rest_gap_share - rest_gap_tolerance_share) * slop_;
    for (int32_t i = 0; i < touches.count; ++i) {
        if (!(touches.items[i].contact.separation >= clear)) {
            return false;
        }
    }
    return true;
}

Vec2 CharacterMove::solve(Vec2 move, const Touches& touches) const {
    CollisionPlane planes[max_touches];
    const float rest_gap = rest_gap_share * slop_;
    for (int32_t i = 0; i < touches.count; ++i) {
        const MoverContact& c = touches.items[i].contact;
        planes[i].plane = Plane{c.normal, c.separation - rest_gap};
    }
    return solve_planes(move, planes, touches.count).translation;
}

// Straight down from `from`, at most `depth`, onto ground: where the character stands
// then, with what it touches there. False when it meets nothing, or nothing walkable.
bool CharacterMove::land(Vec2 from, float depth, Vec2& out, Touches& out_touches) const {
    const MoverNeighbourhood::Hit hit = cast(from, -depth * up_);
    if (!(hit.fraction < 1.0f)) {
        return false;
    }
    out = from - (hit.fraction * depth) * up_;
    collide(out, out_touches);
    return ground_of(out_touches) != nullptr;
}

void CharacterMove::note_hits(const Touches& touches) {
    for (int32_t i = 0; i < touches.count; ++i) {
        const int32_t shape = touches.items[i].shape;
        bool seen = false;
        for (int32_t k = 0; k < hit_count_ && !seen; ++k) {
            seen = hits_[k] == shape;
        }
        if (!seen && hit_count_ < max_counted_hits) {
            hits_[hit_count_++] = shape;
        }
    }
}

void CharacterMove::slide() {
    Vec2 remaining = move_;
    bool tried_step = false;
    Touches touches;
    for (int32_t round = 0; round < def_.max_iterations; ++round) {
        collide(position_, touches);
        note_hits(touches);
        if (round == 0) {
            const Touch* ground = ground_of(touches);
            was_on_ground_ = ground != nullptr;
            start_ground_point_ = ground != nullptr ? ground->contact.point : position_;
        }
        if (!tried_step && was_on_ground_ && def_.step_height > 0.0f && walks_into_wall(remaining, touches)) {
            tried_step = true;
            if (step_up(remaining)) {
                continue;
            }
        }
        remaining = without_climb(remaining, touches);
        Vec2 delta = solve(remaining, touches);
        if (!(length_squared(delta) > settle_ * settle_)) {
            break;
        }
        MoverNeighbourhood::Hit hit;
        if (!(delta == remaining) && rests_clear(touches)) {
            // Planes stand in for the surfaces to first order and so refuse more than the
            // shapes do: the next tile of a tiled floor, whose corner comes no nearer than
            // the floor, looks like a ramp. With nothing to push out of, the move as asked
            // goes when the exact cast lets it.
            hit = cast(position_, remaining);
            if (hit.fraction < 1.0f) {
                hit = cast(position_, delta);
            } else {
                delta = remaining;
            }
        } else {
            hit = cast(position_, delta);
        }
        const Vec2 moved = hit.fraction * delta;
        position_ += moved;
        remaining -= moved;
        if (!(hit.fraction < 1.0f)) {
            break;  // the whole way: what is left the planes refused
        }
    }
}

// Up, forward and down (see the design note); the character's position and the rest of
// its move change only when the step is taken.
bool CharacterMove::step_up(Vec2& remaining) {
    const Vec2 walk = horizontal(remaining);
    const float walk_length = length(walk);
    if (!(walk_length > settle_)) {
        return false;
    }
    const Vec2 ahead = (1.0f / walk_length) * walk;
    const float rise = def_.step_height * cast(position_, def_.step_height * up_).fraction;
    if (!(rise > slop_)) {
        return false;
    }
    const Vec2 raised = position_ + rise * up_;
    const float look = max_of(walk_length, radius_);
    const float room = look * cast(raised, look * ahead).fraction;
    Vec2 landing;
    Touches touches;
    if (!(room > slop_) || !land(raised + room * ahead, rise, landing, touches)) {
        return false;  // a wall higher than the step, or nothing to stand on ahead
    }
    // The ledge's height is that of the ground found on it over the ground stood on: the
    // capsule's round foot can rest on an edge a little higher than it was lifted.
    const float ledge = dot(ground_of(touches)->contact.point - start_ground_point_, up_);
    if (!(ledge > slop_ && ledge <= def_.step_height)) {
        return false;
    }
    const float edge_reach = radius_ * (1.0f - sin_max_slope_) + 2.0f * slop_;
    const float tries[2] = {min_of(walk_length, room), min_of(max_of(walk_length, edge_reach), room)};
    for (int32_t i = 0; i < 2; ++i) {
        if ((i == 0 || tries[1] > tries[0]) && land(raised + tries[i] * ahead, rise, landing, touches)) {
            note_hits(touches);
            position_ = landing;
            remaining -= min_of(tries[i], walk_length) * ahead;
            return true;
        }
    }
    return false;
}

void CharacterMove::snap(Touches& touches) {
    // Rising less than the settle distance this move is rounding (a ground normal off by
    // 1e-5 rad lifts a clipped 4 m/s by 4e-5 m/s), not moving up.
    if (ground_of(touches) != nullptr || !was_on_ground_ || dot(move_, up_) > settle_ ||
        !(def_.snap_distance > 0.0f)) {
        return;
    }
    Vec2 landing;
    Touches below;
    if (land(position_, def_.snap_distance, landing, below)) {
        position_ = landing;
        touches = below;
    }
}

void CharacterMove::push(const Touches& touches) {
    if (!(def_.push_mass > 0.0f)) {
        return;
    }
    int32_t pushed[max_touches];
    int32_t pushed_count = 0;
    for (int32_t i = 0; i < touches.count; ++i) {
        const Touch& t = touches.items[i];
        const int32_t body = world_.shapes()[t.shape].body;
        const Body& b = world_.bodies()[body];
        bool done = b.type != BodyType::dynamic;
        for (int32_t k = 0; k < pushed_count && !done; ++k) {
            done = pushed[k] == body;
        }
        if (done) {
            continue;
        }
        const Vec2 into = -t.contact.normal;
        const Vec2 arm = t.contact.point - b.center;
        const Vec2 body_velocity = b.linear_velocity + cross(b.angular_velocity, arm);
        const float approach = dot(velocity_ - body_velocity, into);
        if (!(approach > 0.0f)) {
            continue;
        }
        const float turn = cross(arm, into);
        const float inv_effective_mass = 1.0f / def_.push_mass + b.inv_mass + b.inv_inertia * turn * turn;
        world_.apply_linear_impulse(body, (approach / inv_effective_mass) * into, t.contact.point, true);
        pushed[pushed_count++] = body;
    }
}

// Ground takes away the velocity's downward part only: the character walks on along it
// (the next move follows its slope), and a level walk onto a ramp or a step's rounded
// edge does not come back as a climb that would carry it into the air at the top. Walls
// and ceilings clip as planes, and a wall that faces up clips its level part too, so the
// velocity neither runs into them nor rises along them.
Vec2 CharacterMove::clipped_velocity(const Touches& touches) const {
    CollisionPlane planes[2 * max_touches];
    int32_t count = 0;
    for (int32_t i = 0; i < touches.count; ++i) {
        const Vec2 normal = touches.items[i].contact.normal;
        planes[count++].plane = Plane{is_ground(normal) ? up_ : normal, 0.0f};
        const Vec2 level = climbable_normal(normal);
        if (level.x != 0.0f || level.y != 0.0f) {
            planes[count++].plane = Plane{level, 0.0f};
        }
    }
    return clip_vector(velocity_, planes, count);
}

Vec2 CharacterMove::ground_velocity(const Touch& ground) const {
    const Body& b = world_.bodies()[world_.shapes()[ground.shape].body];
    return b.linear_velocity + cross(b.angular_velocity, ground.contact.point - b.center);
}

CharacterResult CharacterMove::run() {
    slide();
    Touches touches;
    collide(position_, touches);
    snap(touches);
    note_hits(touches);
    push(touches);
    CharacterResult result;
    result.position = position_;
    result.velocity = clipped_velocity(touches);
    if (const Touch* ground = ground_of(touches)) {
        result.on_ground = true;
        result.ground_normal = ground->contact.normal;
        result.ground_shape = ground->shape;
        result.ground_velocity = ground_velocity(*ground);
    }
    result.hit_count = hit_count_;
    return result;
}

}  // namespace

CharacterResult move_character(World& world, const CharacterDef& def, const Capsule& capsule, Vec2 position,
                               Vec2 velocity, float time_step) {
    CharacterMove move(world, def, capsule, position, velocity, time_step);
    return move.run();
}

}  // namespace i2d
