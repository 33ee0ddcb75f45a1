/* SPDX-License-Identifier: MIT */
/* Shape primitives and the pure, world-free collision functions. */
#ifndef IMPULSE2D_COLLISION_H
#define IMPULSE2D_COLLISION_H

#include "base.h"
#include "types.h"

/** A circle: centre (in the body frame when attached to a body, else world) and radius (m). */
typedef struct i2d_circle {
    i2d_vec2 center;
    float radius;
} i2d_circle;

typedef struct i2d_manifold_point {
    i2d_vec2 point;    /**< world point midway between the two surfaces */
    float penetration; /**< > 0 overlapping, 0 touching */
    uint32_t id;       /**< feature key, stable from step to step for the same features */
} i2d_manifold_point;

/** Contact between two shapes. Moving B along normal by the largest penetration (or A
 *  against it) separates them. */
typedef struct i2d_manifold {
    i2d_vec2 normal;     /**< unit, points from shape A to shape B */
    int32_t point_count; /**< 0 = not touching; up to 2 */
    i2d_manifold_point points[2];
} i2d_manifold;

/* World-space tests. Touching shapes (distance exactly zero) report a contact with
 * penetration 0; separated shapes report point_count 0. Invalid input (NaN, inf, negative
 * radius, min > max) reports point_count 0 and sets I2D_ERR_INVALID_ARGUMENT. */

/** Circle against circle. Same centres: normal (1, 0), penetration ra + rb. */
I2D_API i2d_manifold i2d_collide_circles(i2d_circle a, i2d_circle b);
/** Box against box along the axis of least penetration; up to 2 points on the
 *  overlap's contact edge. Equal overlap on both axes resolves along x. */
I2D_API i2d_manifold i2d_collide_aabbs(i2d_aabb a, i2d_aabb b);
/** Box against circle. A centre inside the box leaves through the nearest face. */
I2D_API i2d_manifold i2d_collide_aabb_circle(i2d_aabb a, i2d_circle b);

#endif
