// SPDX-License-Identifier: MIT
// The rules of a body's own state: mass, speed limits, type.
#include "dynamics/body/body_rules.hpp"

#include <cfloat>
#include <cmath>

#include "collision/geometry.hpp"
#include "dynamics/constants.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

// Inertia is summed about the body origin, then moved to the centre of mass by the
// parallel axis theorem.
void sum_shape_masses(Body& b, const Pool<Shape>& shapes) {
    float mass = 0.0f, inertia_about_origin = 0.0f;
    Vec2 moment;
    for (int32_t s = b.head_shape; s != null_index; s = shapes[s].next_in_body) {
        const MassData md = compute_mass(shapes[s].geometry, shapes[s].density);
        mass += md.mass;
        moment += md.mass * md.center;
        inertia_about_origin += md.rotational_inertia + md.mass * length_squared(md.center);
    }
    // Below FLT_MIN the inverse would overflow; such a body counts as massless.
    if (mass >= FLT_MIN) {
        b.mass = mass;
        b.local_center = (1.0f / mass) * moment;
        b.inertia = inertia_about_origin - mass * length_squared(b.local_center);
    } else {
        b.mass = 1.0f;
    }
}

}  // namespace

// A mass the caller set (mass_overridden) stays; the extents always follow the shapes.
void update_mass_from_shapes(Body& b, const Pool<Shape>& shapes, float slop) {
    const bool overridden = b.mass_overridden && b.type == BodyType::dynamic;
    if (!overridden) {
        b.mass = 0.0f;
        b.local_center = {};
    }
    b.inv_mass = b.inertia = b.inv_inertia = 0.0f;
    b.max_extent = 0.0f;
    if (b.type == BodyType::dynamic) {
        if (overridden) {
            b.inertia = b.override_inertia;
        } else {
            sum_shape_masses(b, shapes);
        }
        b.inv_mass = 1.0f / b.mass;
        if (b.fixed_rotation) {
            b.inertia = 0.0f;  // it never turns
            b.angular_velocity = 0.0f;
        } else if (b.inertia >= FLT_MIN) {
            b.inv_inertia = 1.0f / b.inertia;
        } else {
            b.inertia = 0.0f;  // no shapes yet, or a point mass: torque cannot turn it
        }
    }
    // How fast the body's farthest point moves when it spins: a spinning kinematic
    // drum is not resting. A static body never moves and its extents are never read (0,
    // as Box2D v3 has them): summed over every shape at each change, they made a static
    // body of 16,000 boxes (a tile map) take 1.3 s to build and 1.0 s to take half apart.
    b.min_extent = 0.0f;
    if (b.type != BodyType::static_body && b.head_shape != null_index) {
        b.min_extent = FLT_MAX;
        for (int32_t s = b.head_shape; s != null_index; s = shapes[s].next_in_body) {
            b.max_extent = max_of(b.max_extent, extent_from(shapes[s].geometry, b.local_center));
            if (!shapes[s].is_sensor) {
                b.min_extent = min_of(b.min_extent, max_of(inner_radius(shapes[s].geometry), slop));
            }
        }
        b.min_extent = b.min_extent == FLT_MAX ? 0.0f : b.min_extent;
    }
    b.center = transform_point(b.transform, b.local_center);
}

// Velocities enter the world already within its limits: the solver's first use of a
// velocity (the impact speed it tracks for restitution) squares it before the substep
// clamp, and a finite 1e20 m/s squared is infinite.
Vec2 limited_linear_velocity(Vec2 v, float speed_limit) {
    const double x = v.x, y = v.y;
    const double speed = std::sqrt(x * x + y * y);
    const double max_speed = speed_limit;
    if (speed <= max_speed) {
        return v;
    }
    const double scale = max_speed / speed;
    return Vec2{static_cast<float>(x * scale), static_cast<float>(y * scale)};
}

float limited_angular_velocity(float w) {
    return w > max_angular_speed ? max_angular_speed : (w < -max_angular_speed ? -max_angular_speed : w);
}

void change_type(Body& b, BodyType type) {
    b.type = type;
    b.quarantined = false;
    b.sleep_time = 0.0f;
    if (type == BodyType::static_body) {
        b.linear_velocity = {};
        b.angular_velocity = 0.0f;
    }
    if (type != BodyType::dynamic) {
        b.force = {};
        b.torque = 0.0f;
        b.mass_overridden = false;  // only a dynamic body has a mass to set
    }
}

bool can_turn(const Body& b) {
    return b.type == BodyType::kinematic || (b.type == BodyType::dynamic && b.inv_inertia != 0.0f);
}

}  // namespace i2d
