/* SPDX-License-Identifier: MIT */
/** @file impulse2d.hpp
 *  Thin C++17 wrappers over the C API: an owning World (move-only, destroys its world),
 *  Body, Shape and Joint as 8-byte value handles, and errors as the caller prefers.
 *
 *  Every call that can fail comes in two forms:
 *  - without a status argument it throws impulse2d::Error (status and the library's
 *    message) on failure;
 *  - with a trailing `impulse2d::Status&` it is noexcept and fills the status instead,
 *    leaving the world untouched on failure, as the C call does.
 *
 *  @code
 *  impulse2d::World world;                           // gravity (0, -10)
 *  impulse2d::Body ball = world.create_body(impulse2d::body_def(I2D_BODY_DYNAMIC, {0, 4}));
 *  ball.create_circle(0.5f);
 *  for (int i = 0; i < 60; ++i) world.step(1.0f / 60.0f, 4);
 *  impulse2d::Status status;
 *  ball.set_linear_velocity({NAN, 0}, status);       // refused: status.message says why
 *  @endcode
 *
 *  A World saves itself (snapshot.h): save_snapshot and World::from_snapshot or
 *  restore_snapshot bring it back bit for bit, in any process; save_state and
 *  restore_state roll it back within itself. Body::in, Shape::in and Joint::in find an
 *  object of the saved world in the restored one.
 *
 *  Nothing here is compiled into the library: the header uses only the C API, so it
 *  works with the shared and the static library alike. */
#ifndef IMPULSE2D_HPP
#define IMPULSE2D_HPP

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "impulse2d.h"

namespace impulse2d {

/** What a failed call reported: the C status and the library's message. */
struct Status {
    i2d_status code = I2D_OK;
    std::string message;
    bool ok() const noexcept { return code == I2D_OK; }
    explicit operator bool() const noexcept { return ok(); }
};

/** Thrown by the throwing forms: what() is the library's message. */
class Error : public std::runtime_error {
public:
    Error(i2d_status status, const std::string& message) : std::runtime_error(message), status_(status) {}
    i2d_status status() const noexcept { return status_; }

private:
    i2d_status status_;
};

namespace detail {

/** The thread's last status as a Status (the message is copied: the C one is overwritten
 *  by the next call). */
inline Status last_status() {
    Status s;
    s.code = i2d_last_status();
    if (s.code != I2D_OK) {
        s.message = i2d_last_error_message();
    }
    return s;
}

inline void throw_if_failed() {
    const i2d_status code = i2d_last_status();
    if (code != I2D_OK) {
        throw Error(code, i2d_last_error_message());
    }
}

/** Records the last status into out; never throws but for std::string's allocation. */
inline void record(Status& out) noexcept {
    out.code = i2d_last_status();
    try {
        out.message = out.code == I2D_OK ? std::string() : std::string(i2d_last_error_message());
    } catch (...) {
        out.message.clear();
    }
}

/** The ids of a range of Worlds, for i2d_worlds_step. */
template <class Worlds>
std::vector<i2d_world_id> world_ids(const Worlds& worlds) {
    std::vector<i2d_world_id> ids;
    for (const auto& world : worlds) {
        ids.push_back(world.id());
    }
    return ids;
}

/** Every entry of a C getter that fills up to capacity and returns how many there are
 *  (i2d_body_get_contact_data and the like): sized by the library, then filled. */

template <class Id, class T>
std::vector<T> all_of(int32_t (*getter)(Id, T*, int32_t), Id id) {
    std::vector<T> out;
    for (;;) {
        const int32_t total = getter(id, out.data(), static_cast<int32_t>(out.size()));
        throw_if_failed();
        const std::size_t had = out.size();
        out.resize(static_cast<std::size_t>(total));
        if (static_cast<std::size_t>(total) <= had) {
            return out;
        }
    }
}

}  // namespace detail

/** A body def from i2d_default_body_def() with the usual first choices set. */
inline i2d_body_def body_def(i2d_body_type type, i2d_vec2 position = {0.0f, 0.0f}, float angle = 0.0f) {
    i2d_body_def def = i2d_default_body_def();
    def.type = type;
    def.position = position;
    def.rotation = i2d_make_rot(angle);
    return def;
}

/** The default world def for a world counting lengths in other units
 *  (i2d_default_world_def_in_units): its length-bearing defaults scaled. Throws for a
 *  unit outside [1e-3, 1e4]. */
inline i2d_world_def world_def_in_units(float length_units_per_meter) {
    const i2d_world_def def = i2d_default_world_def_in_units(length_units_per_meter);
    detail::throw_if_failed();
    return def;
}
inline i2d_world_def world_def_in_units(float length_units_per_meter, Status& status) noexcept {
    const i2d_world_def def = i2d_default_world_def_in_units(length_units_per_meter);
    detail::record(status);
    return def;
}

/** The closest points of two proxies placed by their transforms (i2d_shape_distance). */
inline i2d_distance_result shape_distance(const i2d_shape_proxy& a, i2d_transform xa, const i2d_shape_proxy& b,
                                          i2d_transform xb) {
    const i2d_distance_result result = i2d_shape_distance(&a, xa, &b, xb);
    detail::throw_if_failed();
    return result;
}
inline i2d_distance_result shape_distance(const i2d_shape_proxy& a, i2d_transform xa, const i2d_shape_proxy& b,
                                          i2d_transform xb, Status& status) noexcept {
    const i2d_distance_result result = i2d_shape_distance(&a, xa, &b, xb);
    detail::record(status);
    return result;
}

/** The move nearest target_delta that runs into none of the planes (i2d_solve_planes); fills
 *  each plane's push. */
inline i2d_plane_result solve_planes(i2d_vec2 target_delta, std::vector<i2d_collision_plane>& planes) {
    const i2d_plane_result result =
        i2d_solve_planes(target_delta, planes.data(), static_cast<int32_t>(planes.size()));
    detail::throw_if_failed();
    return result;
}
/** The vector less its part that runs into the clipping planes (i2d_clip_vector). */
inline i2d_vec2 clip_vector(i2d_vec2 vector, const std::vector<i2d_collision_plane>& planes) {
    const i2d_vec2 result = i2d_clip_vector(vector, planes.data(), static_cast<int32_t>(planes.size()));
    detail::throw_if_failed();
    return result;
}

class Body;
class World;

/** A shape of a body: a value handle (copying copies the id). It does not own the shape. */
class Shape {
public:
    Shape() = default;
    explicit Shape(i2d_shape_id id) noexcept : id_(id) {}
    i2d_shape_id id() const noexcept { return id_; }
    bool valid() const noexcept { return i2d_shape_is_valid(id_); }
    friend bool operator==(Shape a, Shape b) noexcept { return a.id_.bits == b.id_.bits; }
    friend bool operator!=(Shape a, Shape b) noexcept { return a.id_.bits != b.id_.bits; }

    void destroy() { i2d_shape_destroy(id_); detail::throw_if_failed(); }
    void destroy(Status& status) noexcept { i2d_shape_destroy(id_); detail::record(status); }
    inline Body body() const;
    /** The shape of the same index and generation in world (one made from a snapshot that
     *  held it); a null Shape when world has none. */
    inline Shape in(const World& world) const;
    i2d_shape_type type() const { return checked(i2d_shape_get_type(id_)); }
    i2d_aabb aabb() const { return checked(i2d_shape_get_aabb(id_)); }
    float friction() const { return checked(i2d_shape_get_friction(id_)); }
    void set_friction(float friction) { i2d_shape_set_friction(id_, friction); detail::throw_if_failed(); }
    void set_friction(float friction, Status& status) noexcept {
        i2d_shape_set_friction(id_, friction); detail::record(status);
    }
    float restitution() const { return checked(i2d_shape_get_restitution(id_)); }
    void set_restitution(float restitution) { i2d_shape_set_restitution(id_, restitution); detail::throw_if_failed(); }
    void set_restitution(float restitution, Status& status) noexcept {
        i2d_shape_set_restitution(id_, restitution); detail::record(status);
    }

    /** New geometry (the kind may change); the body's mass is made again and it wakes. */
    void set_circle(const i2d_circle& circle) { i2d_shape_set_circle(id_, &circle); detail::throw_if_failed(); }
    void set_circle(const i2d_circle& circle, Status& status) noexcept {
        i2d_shape_set_circle(id_, &circle); detail::record(status);
    }
    void set_capsule(const i2d_capsule& capsule) { i2d_shape_set_capsule(id_, &capsule); detail::throw_if_failed(); }
    void set_capsule(const i2d_capsule& capsule, Status& status) noexcept {
        i2d_shape_set_capsule(id_, &capsule); detail::record(status);
    }
    void set_segment(const i2d_segment& segment) { i2d_shape_set_segment(id_, &segment); detail::throw_if_failed(); }
    void set_segment(const i2d_segment& segment, Status& status) noexcept {
        i2d_shape_set_segment(id_, &segment); detail::record(status);
    }
    void set_polygon(const i2d_polygon& polygon) { i2d_shape_set_polygon(id_, &polygon); detail::throw_if_failed(); }
    void set_polygon(const i2d_polygon& polygon, Status& status) noexcept {
        i2d_shape_set_polygon(id_, &polygon); detail::record(status);
    }
    float density() const { return checked(i2d_shape_get_density(id_)); }
    /** kg/m^2; update_body_mass false leaves the body's mass until the next shape change. */
    void set_density(float density, bool update_body_mass = true) {
        i2d_shape_set_density(id_, density, update_body_mass); detail::throw_if_failed();
    }
    void set_density(float density, bool update_body_mass, Status& status) noexcept {
        i2d_shape_set_density(id_, density, update_body_mass); detail::record(status);
    }
    i2d_surface_material material() const { return checked(i2d_shape_get_material(id_)); }
    void set_material(const i2d_surface_material& material) {
        i2d_shape_set_material(id_, material); detail::throw_if_failed();
    }
    void set_material(const i2d_surface_material& material, Status& status) noexcept {
        i2d_shape_set_material(id_, material); detail::record(status);
    }
    bool sensor_events_enabled() const { return checked(i2d_shape_are_sensor_events_enabled(id_)); }
    void enable_sensor_events(bool flag) { i2d_shape_enable_sensor_events(id_, flag); detail::throw_if_failed(); }
    void enable_sensor_events(bool flag, Status& status) noexcept {
        i2d_shape_enable_sensor_events(id_, flag); detail::record(status);
    }
    bool contact_events_enabled() const { return checked(i2d_shape_are_contact_events_enabled(id_)); }
    void enable_contact_events(bool flag) { i2d_shape_enable_contact_events(id_, flag); detail::throw_if_failed(); }
    void enable_contact_events(bool flag, Status& status) noexcept {
        i2d_shape_enable_contact_events(id_, flag); detail::record(status);
    }
    bool hit_events_enabled() const { return checked(i2d_shape_are_hit_events_enabled(id_)); }
    void enable_hit_events(bool flag) { i2d_shape_enable_hit_events(id_, flag); detail::throw_if_failed(); }
    void enable_hit_events(bool flag, Status& status) noexcept {
        i2d_shape_enable_hit_events(id_, flag); detail::record(status);
    }
    bool pre_solve_events_enabled() const { return checked(i2d_shape_are_pre_solve_events_enabled(id_)); }
    void enable_pre_solve_events(bool flag) {
        i2d_shape_enable_pre_solve_events(id_, flag); detail::throw_if_failed();
    }
    void enable_pre_solve_events(bool flag, Status& status) noexcept {
        i2d_shape_enable_pre_solve_events(id_, flag); detail::record(status);
    }
    /** The point of the shape closest to target (world coordinates); target itself inside. */
    i2d_vec2 closest_point(i2d_vec2 target) const { return checked(i2d_shape_get_closest_point(id_, target)); }
    /** The shape's touching contacts as the last step left them. */
    std::vector<i2d_contact_data> contact_data() const {
        return detail::all_of(i2d_shape_get_contact_data, id_);
    }
    /** The shapes visiting this sensor as of the last step. */
    std::vector<Shape> sensor_overlaps() const {
        const std::vector<i2d_shape_id> ids = detail::all_of(i2d_shape_get_sensor_overlaps, id_);
        return std::vector<Shape>(ids.begin(), ids.end());
    }

private:
    template <class T>
    static T checked(T value) {
        detail::throw_if_failed();
        return value;
    }
    i2d_shape_id id_{0};
};

/** A body: a value handle (copying copies the id). It does not own the body; the World
 *  does, and destroying the world makes every Body of it invalid. */
class Body {
public:
    Body() = default;
    explicit Body(i2d_body_id id) noexcept : id_(id) {}
    i2d_body_id id() const noexcept { return id_; }
    bool valid() const noexcept { return i2d_body_is_valid(id_); }
    friend bool operator==(Body a, Body b) noexcept { return a.id_.bits == b.id_.bits; }
    friend bool operator!=(Body a, Body b) noexcept { return a.id_.bits != b.id_.bits; }

    /** Destroys the body and its shapes. */
    void destroy() { i2d_body_destroy(id_); detail::throw_if_failed(); }
    void destroy(Status& status) noexcept { i2d_body_destroy(id_); detail::record(status); }
    /** The body of the same index and generation in world (one made from a snapshot that
     *  held it, see i2d_body_in_world); a null Body when world has none. */
    inline Body in(const World& world) const;

    i2d_body_type type() const { return checked(i2d_body_get_type(id_)); }
    i2d_vec2 position() const { return checked(i2d_body_get_position(id_)); }
    i2d_rot rotation() const { return checked(i2d_body_get_rotation(id_)); }
    float angle() const { return i2d_rot_get_angle(rotation()); }
    i2d_transform transform() const { return checked(i2d_body_get_transform(id_)); }
    void set_transform(i2d_vec2 position, float angle) {
        i2d_body_set_transform(id_, position, i2d_make_rot(angle)); detail::throw_if_failed();
    }
    void set_transform(i2d_vec2 position, float angle, Status& status) noexcept {
        i2d_body_set_transform(id_, position, i2d_make_rot(angle)); detail::record(status);
    }
    i2d_vec2 linear_velocity() const { return checked(i2d_body_get_linear_velocity(id_)); }
    void set_linear_velocity(i2d_vec2 v) { i2d_body_set_linear_velocity(id_, v); detail::throw_if_failed(); }
    void set_linear_velocity(i2d_vec2 v, Status& status) noexcept {
        i2d_body_set_linear_velocity(id_, v); detail::record(status);
    }
    float angular_velocity() const { return checked(i2d_body_get_angular_velocity(id_)); }
    void set_angular_velocity(float w) { i2d_body_set_angular_velocity(id_, w); detail::throw_if_failed(); }
    void set_angular_velocity(float w, Status& status) noexcept {
        i2d_body_set_angular_velocity(id_, w); detail::record(status);
    }
    float mass() const { return checked(i2d_body_get_mass(id_)); }
    float rotational_inertia() const { return checked(i2d_body_get_rotational_inertia(id_)); }
    i2d_vec2 world_center_of_mass() const { return checked(i2d_body_get_world_center_of_mass(id_)); }
    bool awake() const { return checked(i2d_body_is_awake(id_)); }
    bool quarantined() const { return checked(i2d_body_is_quarantined(id_)); }
    void set_awake(bool awake) { i2d_body_set_awake(id_, awake); detail::throw_if_failed(); }

    /** A force (N) at a world point for the next step. */
    void apply_force(i2d_vec2 force, i2d_vec2 point, bool wake = true) {
        i2d_body_apply_force(id_, force, point, wake); detail::throw_if_failed();
    }
    void apply_force_to_center(i2d_vec2 force, bool wake = true) {
        i2d_body_apply_force_to_center(id_, force, wake); detail::throw_if_failed();
    }
    void apply_linear_impulse(i2d_vec2 impulse, i2d_vec2 point, bool wake = true) {
        i2d_body_apply_linear_impulse(id_, impulse, point, wake); detail::throw_if_failed();
    }

    /** A circle of radius at center (body frame); def defaults to i2d_default_shape_def(). */
    Shape create_circle(float radius, i2d_vec2 center = {0.0f, 0.0f},
                        const i2d_shape_def& def = i2d_default_shape_def()) {
        const i2d_circle circle = {center, radius};
        return created(i2d_shape_create_circle(id_, &def, &circle));
    }
    Shape create_circle(float radius, i2d_vec2 center, const i2d_shape_def& def, Status& status) noexcept {
        const i2d_circle circle = {center, radius};
        return recorded(i2d_shape_create_circle(id_, &def, &circle), status);
    }
    /** A box of half sizes centred on the body origin. */
    Shape create_box(float half_width, float half_height, const i2d_shape_def& def = i2d_default_shape_def()) {
        return created(i2d_shape_create_box(id_, &def, half_width, half_height));
    }
    Shape create_box(float half_width, float half_height, const i2d_shape_def& def, Status& status) noexcept {
        return recorded(i2d_shape_create_box(id_, &def, half_width, half_height), status);
    }
    /** The convex hull of 3 to 8 points (body frame). */
    Shape create_polygon(const std::vector<i2d_vec2>& points, const i2d_shape_def& def = i2d_default_shape_def()) {
        return created(i2d_shape_create_polygon(id_, &def, points.data(), static_cast<int32_t>(points.size())));
    }
    Shape create_capsule(i2d_vec2 center1, i2d_vec2 center2, float radius,
                         const i2d_shape_def& def = i2d_default_shape_def()) {
        return created(i2d_shape_create_capsule(id_, &def, center1, center2, radius));
    }
    Shape create_segment(i2d_vec2 point1, i2d_vec2 point2, const i2d_shape_def& def = i2d_default_shape_def()) {
        return created(i2d_shape_create_segment(id_, &def, point1, point2));
    }
    std::vector<Shape> shapes() const {
        const int32_t count = i2d_body_get_shape_count(id_);
        detail::throw_if_failed();
        std::vector<i2d_shape_id> ids(static_cast<std::size_t>(count));
        i2d_body_get_shapes(id_, ids.data(), count);
        return std::vector<Shape>(ids.begin(), ids.end());
    }

    /** Mass (kg), centre of mass (body frame) and rotational inertia about it. */
    i2d_mass_data mass_data() const { return checked(i2d_body_get_mass_data(id_)); }
    /** Overrides the mass the shapes give a dynamic body, until apply_mass_from_shapes. */
    void set_mass_data(const i2d_mass_data& data) { i2d_body_set_mass_data(id_, data); detail::throw_if_failed(); }
    void set_mass_data(const i2d_mass_data& data, Status& status) noexcept {
        i2d_body_set_mass_data(id_, data); detail::record(status);
    }
    void apply_mass_from_shapes() { i2d_body_apply_mass_from_shapes(id_); detail::throw_if_failed(); }
    void apply_mass_from_shapes(Status& status) noexcept { i2d_body_apply_mass_from_shapes(id_); detail::record(status); }
    /** Takes the body out of the world (i2d_body_disable) and brings it back. */
    void disable() { i2d_body_disable(id_); detail::throw_if_failed(); }
    void disable(Status& status) noexcept { i2d_body_disable(id_); detail::record(status); }
    void enable() { i2d_body_enable(id_); detail::throw_if_failed(); }
    void enable(Status& status) noexcept { i2d_body_enable(id_); detail::record(status); }
    bool enabled() const { return checked(i2d_body_is_enabled(id_)); }
    /** A kinematic body's velocities set to reach target in time_step seconds. */
    void set_target_transform(i2d_transform target, float time_step) {
        i2d_body_set_target_transform(id_, target, time_step); detail::throw_if_failed();
    }
    void set_target_transform(i2d_transform target, float time_step, Status& status) noexcept {
        i2d_body_set_target_transform(id_, target, time_step); detail::record(status);
    }
    bool bullet() const { return checked(i2d_body_is_bullet(id_)); }
    void set_bullet(bool flag) { i2d_body_set_bullet(id_, flag); detail::throw_if_failed(); }
    void set_bullet(bool flag, Status& status) noexcept { i2d_body_set_bullet(id_, flag); detail::record(status); }
    bool sleep_enabled() const { return checked(i2d_body_is_sleep_enabled(id_)); }
    void enable_sleep(bool flag) { i2d_body_enable_sleep(id_, flag); detail::throw_if_failed(); }
    void enable_sleep(bool flag, Status& status) noexcept { i2d_body_enable_sleep(id_, flag); detail::record(status); }
    /** The speed (world length units per second) below which the body counts as resting. */
    float sleep_threshold() const { return checked(i2d_body_get_sleep_threshold(id_)); }
    void set_sleep_threshold(float speed) { i2d_body_set_sleep_threshold(id_, speed); detail::throw_if_failed(); }
    void set_sleep_threshold(float speed, Status& status) noexcept {
        i2d_body_set_sleep_threshold(id_, speed); detail::record(status);
    }
    float gravity_scale() const { return checked(i2d_body_get_gravity_scale(id_)); }
    void set_gravity_scale(float scale) { i2d_body_set_gravity_scale(id_, scale); detail::throw_if_failed(); }
    void set_gravity_scale(float scale, Status& status) noexcept {
        i2d_body_set_gravity_scale(id_, scale); detail::record(status);
    }
    float linear_damping() const { return checked(i2d_body_get_linear_damping(id_)); }
    void set_linear_damping(float damping) { i2d_body_set_linear_damping(id_, damping); detail::throw_if_failed(); }
    void set_linear_damping(float damping, Status& status) noexcept {
        i2d_body_set_linear_damping(id_, damping); detail::record(status);
    }
    float angular_damping() const { return checked(i2d_body_get_angular_damping(id_)); }
    void set_angular_damping(float damping) { i2d_body_set_angular_damping(id_, damping); detail::throw_if_failed(); }
    void set_angular_damping(float damping, Status& status) noexcept {
        i2d_body_set_angular_damping(id_, damping); detail::record(status);
    }
    bool fixed_rotation() const { return checked(i2d_body_is_fixed_rotation(id_)); }
    void set_fixed_rotation(bool flag) { i2d_body_set_fixed_rotation(id_, flag); detail::throw_if_failed(); }
    void set_fixed_rotation(bool flag, Status& status) noexcept {
        i2d_body_set_fixed_rotation(id_, flag); detail::record(status);
    }
    /** The body's touching contacts as the last step left them. */
    std::vector<i2d_contact_data> contact_data() const { return detail::all_of(i2d_body_get_contact_data, id_); }

private:
    template <class T>
    static T checked(T value) {
        detail::throw_if_failed();
        return value;
    }
    static Shape created(i2d_shape_id id) {
        detail::throw_if_failed();
        return Shape(id);
    }
    static Shape recorded(i2d_shape_id id, Status& status) noexcept {
        detail::record(status);
        return Shape(id);
    }
    i2d_body_id id_{0};
};

inline Body Shape::body() const { return Body(checked(i2d_shape_get_body(id_))); }

/** A joint: a value handle (copying copies the id). It does not own the joint; destroying
 *  either body, or the world, makes it invalid. Every kind's settings go through get and
 *  set with the C accessor, which keeps one wrapper for all 130 of them:
 *  @code
 *  hinge.set(i2d_revolute_joint_set_motor_speed, 2.0f);
 *  float speed = hinge.get(i2d_revolute_joint_get_motor_speed);
 *  @endcode */
class Joint {
public:
    Joint() = default;
    explicit Joint(i2d_joint_id id) noexcept : id_(id) {}
    i2d_joint_id id() const noexcept { return id_; }
    bool valid() const noexcept { return i2d_joint_is_valid(id_); }
    friend bool operator==(Joint a, Joint b) noexcept { return a.id_.bits == b.id_.bits; }
    friend bool operator!=(Joint a, Joint b) noexcept { return a.id_.bits != b.id_.bits; }

    /** Destroys the joint; its bodies wake and may collide again. */
    void destroy() { i2d_joint_destroy(id_); detail::throw_if_failed(); }
    void destroy(Status& status) noexcept { i2d_joint_destroy(id_); detail::record(status); }
    /** As Body::in, for a joint. */
    inline Joint in(const World& world) const;

    i2d_joint_type type() const { return get(i2d_joint_get_type); }
    Body body_a() const { return Body(get(i2d_joint_get_body_a)); }
    Body body_b() const { return Body(get(i2d_joint_get_body_b)); }
    /** The force (N) and torque (N m) on body B over the last step. */
    i2d_vec2 reaction_force() const { return get(i2d_joint_get_reaction_force); }
    float reaction_torque() const { return get(i2d_joint_get_reaction_torque); }
    void* user_data() const { return get(i2d_joint_get_user_data); }
    void set_user_data(void* user_data) { set(i2d_joint_set_user_data, user_data); }
    void wake_bodies() { i2d_joint_wake_bodies(id_); detail::throw_if_failed(); }

    /** Any getter of joint.h, e.g. get(i2d_wheel_joint_get_hertz). */
    template <class T>
    T get(T (*getter)(i2d_joint_id)) const {
        const T value = getter(id_);
        detail::throw_if_failed();
        return value;
    }
    /** Any setter of joint.h, e.g. set(i2d_joint_set_collide_connected, true). */
    template <class T, class V>
    void set(i2d_status (*setter)(i2d_joint_id, T), V value) {
        setter(id_, static_cast<T>(value));
        detail::throw_if_failed();
    }
    template <class T, class V>
    void set(i2d_status (*setter)(i2d_joint_id, T), V value, Status& status) noexcept {
        setter(id_, static_cast<T>(value));
        detail::record(status);
    }
    /** Both bounds at once: i2d_revolute_joint_set_limits, ..._set_length_range. */
    void set(i2d_status (*setter)(i2d_joint_id, float, float), float lower, float upper) {
        setter(id_, lower, upper);
        detail::throw_if_failed();
    }

private:
    i2d_joint_id id_{0};
};

/** Owns a world: destroys it (and everything in it) when it goes out of scope. Move-only. */
class World {
public:
    /** A world from def (default: i2d_default_world_def()). Throws on a refused def. */
    explicit World(const i2d_world_def& def = i2d_default_world_def()) : id_(i2d_world_create(&def)) {
        detail::throw_if_failed();
    }
    /** The non-throwing form: check status (the world is null when it failed). */
    World(const i2d_world_def& def, Status& status) noexcept : id_(i2d_world_create(&def)) { detail::record(status); }
    ~World() { reset(); }
    World(const World&) = delete;
    World& operator=(const World&) = delete;
    World(World&& other) noexcept : id_(std::exchange(other.id_, i2d_world_id{0})) {}
    World& operator=(World&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, i2d_world_id{0});
        }
        return *this;
    }

    i2d_world_id id() const noexcept { return id_; }
    bool valid() const noexcept { return i2d_world_is_valid(id_); }
    /** Destroys the world now; the World becomes null. */
    void reset() noexcept {
        if (id_.bits != 0) {
            i2d_world_destroy(id_);
            id_ = i2d_world_id{0};
        }
    }
    /** Gives up ownership: the caller must call i2d_world_destroy. */
    i2d_world_id release() noexcept { return std::exchange(id_, i2d_world_id{0}); }

    void step(float time_step = 1.0f / 60.0f, int32_t substeps = 4) {
        i2d_world_step(id_, time_step, substeps); detail::throw_if_failed();
    }
    void step(float time_step, int32_t substeps, Status& status) noexcept {
        i2d_world_step(id_, time_step, substeps); detail::record(status);
    }
    i2d_vec2 gravity() const { return checked(i2d_world_get_gravity(id_)); }
    void set_gravity(i2d_vec2 gravity) { i2d_world_set_gravity(id_, gravity); detail::throw_if_failed(); }
    /** Every position from now on relative to new_origin (i2d_world_shift_origin). */
    void shift_origin(i2d_vec2 new_origin) { i2d_world_shift_origin(id_, new_origin); detail::throw_if_failed(); }
    void shift_origin(i2d_vec2 new_origin, Status& status) noexcept {
        i2d_world_shift_origin(id_, new_origin); detail::record(status);
    }
    void* user_data() const { return checked(i2d_world_get_user_data(id_)); }
    void set_user_data(void* user_data) { i2d_world_set_user_data(id_, user_data); detail::throw_if_failed(); }
    /** The world's settings as a def, ready to create a world like it. */
    i2d_world_def settings() const { return checked(i2d_world_get_settings(id_)); }
    void enable_sleeping(bool flag) { i2d_world_enable_sleeping(id_, flag); detail::throw_if_failed(); }
    void enable_sleeping(bool flag, Status& status) noexcept {
        i2d_world_enable_sleeping(id_, flag); detail::record(status);
    }
    void enable_continuous(bool flag) { i2d_world_enable_continuous(id_, flag); detail::throw_if_failed(); }
    void enable_continuous(bool flag, Status& status) noexcept {
        i2d_world_enable_continuous(id_, flag); detail::record(status);
    }
    void enable_impact_chains(bool flag) { i2d_world_enable_impact_chains(id_, flag); detail::throw_if_failed(); }
    void enable_impact_chains(bool flag, Status& status) noexcept {
        i2d_world_enable_impact_chains(id_, flag); detail::record(status);
    }
    void set_contact_tuning(float hertz, float damping_ratio, float push_max_speed) {
        i2d_world_set_contact_tuning(id_, hertz, damping_ratio, push_max_speed); detail::throw_if_failed();
    }
    void set_contact_tuning(float hertz, float damping_ratio, float push_max_speed, Status& status) noexcept {
        i2d_world_set_contact_tuning(id_, hertz, damping_ratio, push_max_speed); detail::record(status);
    }
    void set_joint_tuning(float hertz, float damping_ratio) {
        i2d_world_set_joint_tuning(id_, hertz, damping_ratio); detail::throw_if_failed();
    }
    void set_joint_tuning(float hertz, float damping_ratio, Status& status) noexcept {
        i2d_world_set_joint_tuning(id_, hertz, damping_ratio); detail::record(status);
    }
    void set_restitution_threshold(float speed) {
        i2d_world_set_restitution_threshold(id_, speed); detail::throw_if_failed();
    }
    void set_restitution_threshold(float speed, Status& status) noexcept {
        i2d_world_set_restitution_threshold(id_, speed); detail::record(status);
    }
    void set_hit_event_threshold(float speed) { i2d_world_set_hit_event_threshold(id_, speed); detail::throw_if_failed(); }
    void set_hit_event_threshold(float speed, Status& status) noexcept {
        i2d_world_set_hit_event_threshold(id_, speed); detail::record(status);
    }
    i2d_world_counters counters() const { return checked(i2d_world_get_counters(id_)); }
    uint64_t state_hash() const { return checked(i2d_world_get_state_hash(id_)); }

    /** The contact hooks (toolkit.h): plain functions, called on the step's workers, that
     *  may use only their arguments; nullptr clears. */
    void set_custom_filter(i2d_custom_filter_fn* fn, void* context = nullptr) {
        i2d_world_set_custom_filter_callback(id_, fn, context); detail::throw_if_failed();
    }
    void set_pre_solve(i2d_pre_solve_fn* fn, void* context = nullptr) {
        i2d_world_set_pre_solve_callback(id_, fn, context); detail::throw_if_failed();
    }
    /** Pushes the dynamic bodies near the blast (toolkit.h, i2d_world_explode). */
    void explode(const i2d_explosion_def& def) { i2d_world_explode(id_, &def); detail::throw_if_failed(); }
    void explode(const i2d_explosion_def& def, Status& status) noexcept {
        i2d_world_explode(id_, &def); detail::record(status);
    }

    /** The world as a portable snapshot (see snapshot.h): everything it simulates, not the
     *  host's wiring (worker_count, task callbacks, simd_path, enable_profile). */
    std::vector<std::uint8_t> save_snapshot() const {
        return save(i2d_world_get_snapshot_size, i2d_world_save_snapshot);
    }
    /** A new world from a snapshot, with runtime's host wiring (its simulation fields are
     *  checked, not used: the snapshot's are). Throws Error(I2D_ERR_INVALID_SNAPSHOT) for
     *  bytes it refuses. */
    static World from_snapshot(const std::vector<std::uint8_t>& snapshot,
                               const i2d_world_def& runtime = i2d_default_world_def()) {
        const i2d_world_id id = i2d_world_create_from_snapshot(snapshot.data(), snapshot.size(), &runtime);
        detail::throw_if_failed();
        return World(id, Adopt{});
    }
    /** The non-throwing form: a null World when refused. */
    static World from_snapshot(const std::vector<std::uint8_t>& snapshot, const i2d_world_def& runtime,
                               Status& status) noexcept {
        const i2d_world_id id = i2d_world_create_from_snapshot(snapshot.data(), snapshot.size(), &runtime);
        detail::record(status);
        return World(id, Adopt{});
    }
    /** Replaces the world's state with a snapshot's; the world keeps its id and wiring, ids
     *  made after the save become stale. A refused snapshot leaves the world as it was. */
    void restore_snapshot(const std::vector<std::uint8_t>& snapshot) {
        i2d_world_restore_snapshot(id_, snapshot.data(), snapshot.size()); detail::throw_if_failed();
    }
    void restore_snapshot(const std::vector<std::uint8_t>& snapshot, Status& status) noexcept {
        i2d_world_restore_snapshot(id_, snapshot.data(), snapshot.size()); detail::record(status);
    }
    /** A rollback state: what a step changes, for restore_state into this world while its
     *  bodies, shapes, joints and settings stay as they are. Not portable. */
    std::vector<std::uint8_t> save_state() const { return save(i2d_world_get_state_size, i2d_world_save_state); }
    /** Brings the world back to a state saved from it. Another world's state, or one saved
     *  before a structural change, is refused (I2D_ERR_INVALID_SNAPSHOT), the world unchanged. */
    void restore_state(const std::vector<std::uint8_t>& state) {
        i2d_world_restore_state(id_, state.data(), state.size()); detail::throw_if_failed();
    }
    void restore_state(const std::vector<std::uint8_t>& state, Status& status) noexcept {
        i2d_world_restore_state(id_, state.data(), state.size()); detail::record(status);
    }

    Body create_body(const i2d_body_def& def = i2d_default_body_def()) {
        const i2d_body_id id = i2d_body_create(id_, &def);
        detail::throw_if_failed();
        return Body(id);
    }
    Body create_body(const i2d_body_def& def, Status& status) noexcept {
        const i2d_body_id id = i2d_body_create(id_, &def);
        detail::record(status);
        return Body(id);
    }

    /** A joint of the def's kind (any i2d_<kind>_joint_def) between its two bodies. */
    template <class Def>
    Joint create_joint(const Def& def) {
        const i2d_joint_id id = create_joint_id(id_, def);
        detail::throw_if_failed();
        return Joint(id);
    }
    /** The non-throwing form: a null Joint when refused. */
    template <class Def>
    Joint create_joint(const Def& def, Status& status) noexcept {
        const i2d_joint_id id = create_joint_id(id_, def);
        detail::record(status);
        return Joint(id);
    }
    int32_t joint_count() const { return checked(i2d_world_get_joint_count(id_)); }
    /** Joints whose reaction passed a threshold in the last step (valid until the next step). */
    i2d_joint_events joint_events() const { return checked(i2d_world_get_joint_events(id_)); }

    /** Transforms of many bodies in one call (see i2d_world_get_body_transforms). */
    std::vector<i2d_transform> transforms(const std::vector<Body>& bodies) const {
        const std::vector<i2d_body_id> ids = to_ids(bodies);
        std::vector<i2d_transform> out(ids.size());
        i2d_world_get_body_transforms(id_, ids.data(), static_cast<int32_t>(ids.size()), out.data());
        detail::throw_if_failed();
        return out;
    }
    void set_transforms(const std::vector<Body>& bodies, const std::vector<i2d_transform>& transforms) {
        check_sizes(bodies.size(), transforms.size());
        const std::vector<i2d_body_id> ids = to_ids(bodies);
        i2d_world_set_body_transforms(id_, ids.data(), static_cast<int32_t>(ids.size()), transforms.data());
        detail::throw_if_failed();
    }
    void set_velocities(const std::vector<Body>& bodies, const std::vector<i2d_vec2>& linear,
                        const std::vector<float>& angular) {
        check_sizes(bodies.size(), linear.size());
        check_sizes(bodies.size(), angular.size());
        const std::vector<i2d_body_id> ids = to_ids(bodies);
        i2d_world_set_body_velocities(id_, ids.data(), static_cast<int32_t>(ids.size()), linear.data(),
                                      angular.data());
        detail::throw_if_failed();
    }

    /** Shapes whose geometry overlaps box. */
    std::vector<Shape> overlap_aabb(i2d_aabb box, i2d_query_filter filter = i2d_default_query_filter()) const {
        std::vector<i2d_shape_id> ids(16);
        for (;;) {
            const int32_t total = i2d_world_overlap_aabb_ids(id_, box, filter, ids.data(), static_cast<int32_t>(ids.size()));
            detail::throw_if_failed();
            if (static_cast<std::size_t>(total) <= ids.size()) {
                return std::vector<Shape>(ids.begin(), ids.begin() + total);
            }
            ids.resize(static_cast<std::size_t>(total));
        }
    }
    i2d_ray_result cast_ray_closest(i2d_vec2 origin, i2d_vec2 translation,
                                    i2d_query_filter filter = i2d_default_query_filter()) const {
        return checked(i2d_world_cast_ray_closest(id_, origin, translation, filter));
    }
    /** Draws the world through draw's callbacks (i2d_world_draw; start from
     *  i2d_default_debug_draw()). The callbacks run before it returns, with the world
     *  locked: they may read it, not change it. Throws for a refused def or bounds. */
    void draw(const i2d_debug_draw& draw) const { i2d_world_draw(id_, &draw); detail::throw_if_failed(); }
    void draw(const i2d_debug_draw& draw, Status& status) const noexcept {
        i2d_world_draw(id_, &draw); detail::record(status);
    }
    /** The character mover (toolkit.h): how far along translation the capsule (world
     *  coordinates) goes before it touches a shape, as a fraction in [0, 1]. */
    float cast_mover(const i2d_capsule& mover, i2d_vec2 translation,
                     i2d_query_filter filter = i2d_default_query_filter()) const {
        return checked(i2d_world_cast_mover(id_, &mover, translation, filter));
    }
    /** The planes of the shapes the capsule (world coordinates) touches, one per shape. */
    std::vector<i2d_collision_plane> collide_mover(const i2d_capsule& mover,
                                                   i2d_query_filter filter = i2d_default_query_filter()) const {
        std::vector<i2d_collision_plane> planes(8);
        for (;;) {
            const int32_t total =
                i2d_world_collide_mover(id_, &mover, filter, planes.data(), static_cast<int32_t>(planes.size()));
            detail::throw_if_failed();
            if (static_cast<std::size_t>(total) <= planes.size()) {
                planes.resize(static_cast<std::size_t>(total));
                return planes;
            }
            planes.resize(static_cast<std::size_t>(total));
        }
    }
    /** Moves a character (i2d_world_move_character): the capsule in its own frame, from
     *  position by velocity * time_step. Pushing (def.push_mass > 0) is its only change to
     *  the world. */
    i2d_character_result move_character(const i2d_character_def& def, const i2d_capsule& capsule, i2d_vec2 position,
                                        i2d_vec2 velocity, float time_step = 1.0f / 60.0f) {
        i2d_character_result out{};
        i2d_world_move_character(id_, &def, &capsule, position, velocity, time_step, &out);
        detail::throw_if_failed();
        return out;
    }
    /** The non-throwing form: a zeroed result when refused. */
    i2d_character_result move_character(const i2d_character_def& def, const i2d_capsule& capsule, i2d_vec2 position,
                                        i2d_vec2 velocity, float time_step, Status& status) noexcept {
        i2d_character_result out{};
        i2d_world_move_character(id_, &def, &capsule, position, velocity, time_step, &out);
        detail::record(status);
        return out;
    }
    /** The last step's contact events (arrays owned by the world, valid until the next step). */
    i2d_contact_events contact_events() const { return checked(i2d_world_get_contact_events(id_)); }
    i2d_body_events body_events() const { return checked(i2d_world_get_body_events(id_)); }

private:
    struct Adopt {};
    World(i2d_world_id id, Adopt) noexcept : id_(id) {}
    template <class T>
    static T checked(T value) {
        detail::throw_if_failed();
        return value;
    }
    // A snapshot or a rollback state, sized by the library.
    std::vector<std::uint8_t> save(std::size_t (*size_of)(i2d_world_id),
                                   i2d_status (*save_into)(i2d_world_id, void*, std::size_t, std::size_t*)) const {
        std::vector<std::uint8_t> bytes(size_of(id_));
        detail::throw_if_failed();
        std::size_t written = 0;
        save_into(id_, bytes.data(), bytes.size(), &written);
        detail::throw_if_failed();
        bytes.resize(written);
        return bytes;
    }
    // One create per kind, chosen by the def's type.
    static i2d_joint_id create_joint_id(i2d_world_id w, const i2d_revolute_joint_def& d) noexcept {
        return i2d_joint_create_revolute(w, &d);
    }
    static i2d_joint_id create_joint_id(i2d_world_id w, const i2d_prismatic_joint_def& d) noexcept {
        return i2d_joint_create_prismatic(w, &d);
    }
    static i2d_joint_id create_joint_id(i2d_world_id w, const i2d_distance_joint_def& d) noexcept {
        return i2d_joint_create_distance(w, &d);
    }
    static i2d_joint_id create_joint_id(i2d_world_id w, const i2d_weld_joint_def& d) noexcept {
        return i2d_joint_create_weld(w, &d);
    }
    static i2d_joint_id create_joint_id(i2d_world_id w, const i2d_wheel_joint_def& d) noexcept {
        return i2d_joint_create_wheel(w, &d);
    }
    static i2d_joint_id create_joint_id(i2d_world_id w, const i2d_motor_joint_def& d) noexcept {
        return i2d_joint_create_motor(w, &d);
    }
    static i2d_joint_id create_joint_id(i2d_world_id w, const i2d_mouse_joint_def& d) noexcept {
        return i2d_joint_create_mouse(w, &d);
    }
    static i2d_joint_id create_joint_id(i2d_world_id w, const i2d_filter_joint_def& d) noexcept {
        return i2d_joint_create_filter(w, &d);
    }
    static std::vector<i2d_body_id> to_ids(const std::vector<Body>& bodies) {
        std::vector<i2d_body_id> ids;
        ids.reserve(bodies.size());
        for (const Body& b : bodies) {
            ids.push_back(b.id());
        }
        return ids;
    }
    static void check_sizes(std::size_t bodies, std::size_t values) {
        if (bodies != values) {
            throw Error(I2D_ERR_INVALID_ARGUMENT, "impulse2d::World: " + std::to_string(bodies) + " bodies but " +
                                                      std::to_string(values) + " values");
        }
    }
    i2d_world_id id_{0};
};

/** Steps every world of a range of Worlds (a std::vector<World>, say) in one call, as
 *  World::step would step each, shared out among def.worker_count threads
 *  (i2d_worlds_step). A bad world, repeat or argument throws, and no world moves. */
template <class Worlds>
void step_worlds(const Worlds& worlds, float time_step = 1.0f / 60.0f, int32_t substeps = 4,
                 const i2d_batch_def& def = i2d_default_batch_def()) {
    const std::vector<i2d_world_id> ids = detail::world_ids(worlds);
    i2d_worlds_step(ids.data(), static_cast<int32_t>(ids.size()), time_step, substeps, &def);
    detail::throw_if_failed();
}
template <class Worlds>
void step_worlds(const Worlds& worlds, float time_step, int32_t substeps, const i2d_batch_def& def,
                 Status& status) {
    const std::vector<i2d_world_id> ids = detail::world_ids(worlds);
    i2d_worlds_step(ids.data(), static_cast<int32_t>(ids.size()), time_step, substeps, &def);
    detail::record(status);
}

inline Body Body::in(const World& world) const {
    const i2d_body_id id = i2d_body_in_world(id_, world.id());
    detail::throw_if_failed();
    return Body(id);
}
inline Shape Shape::in(const World& world) const { return Shape(checked(i2d_shape_in_world(id_, world.id()))); }
inline Joint Joint::in(const World& world) const {
    const i2d_joint_id id = i2d_joint_in_world(id_, world.id());
    detail::throw_if_failed();
    return Joint(id);
}

}  // namespace impulse2d

#endif
