/* SPDX-License-Identifier: MIT */
/* Shape primitives and the pure, world-free collision functions. They know no world, so
 * they work in metres whatever a world's length unit (i2d_world_def.length_units_per_meter):
 * their tolerances (the 0.005 m welding of i2d_make_polygon and i2d_make_proxy, the 0.02 m
 * speculative distance and 0.005 m slop of the manifolds) are those of a world in metres,
 * taken as numbers in whatever unit the input is in: a polygon made for a world in pixels
 * is welded at 0.005 pixels, and a manifold of shapes in pixels keeps points 0.02 pixels
 * apart. */
#ifndef IMPULSE2D_COLLISION_H
#define IMPULSE2D_COLLISION_H

#include "base.h"
#include "types.h"

/** A circle: centre (in the body frame when attached to a body, else world) and radius (m). */
typedef struct i2d_circle {
    i2d_vec2 center;
    float radius;
} i2d_circle;

/* World-space tests. Touching shapes (distance exactly zero) report a contact with
 * penetration 0; separated shapes report point_count 0. Invalid input (NaN, inf, negative
 * radius, min > max) reports point_count 0 and sets I2D_ERR_INVALID_ARGUMENT.
 *
 * Range of every pure function here (collide, make, mass, ray cast): each coordinate
 * (centres, corners, vertices, transform positions) and each radius must be within
 * 1e9 m of zero; input beyond it is refused with I2D_ERR_INVALID_ARGUMENT, since the
 * products inside would overflow float. Within it, results are finite and normals unit. */

/** Circle against circle. Same centres: normal (1, 0), penetration ra + rb. */
I2D_API i2d_manifold i2d_collide_circles(i2d_circle a, i2d_circle b);
/** Box against box along the axis of least penetration; up to 2 points on the
 *  overlap's contact edge. Equal overlap on both axes resolves along x. */
I2D_API i2d_manifold i2d_collide_aabbs(i2d_aabb a, i2d_aabb b);
/** Box against circle. A centre inside the box leaves through the nearest face. */
I2D_API i2d_manifold i2d_collide_aabb_circle(i2d_aabb a, i2d_circle b);

/* ---- Rotation and more shapes: local geometry placed by a transform ----------------- */

/** The most vertices a polygon may have. */
#define I2D_MAX_POLYGON_VERTICES 8

/** A convex polygon, counter-clockwise, with outward unit edge normals (normals[i] belongs
 *  to the edge from vertices[i] to vertices[i + 1]) and its area centroid. radius > 0
 *  rounds it: the shape is every point within radius of the polygon. Build it with
 *  i2d_make_polygon or i2d_make_box rather than by hand. */
typedef struct i2d_polygon {
    i2d_vec2 vertices[I2D_MAX_POLYGON_VERTICES];
    i2d_vec2 normals[I2D_MAX_POLYGON_VERTICES];
    i2d_vec2 centroid;
    float radius;
    int32_t count; /**< 3 to 8 */
} i2d_polygon;

/** Every point within radius of the segment center1-center2. */
typedef struct i2d_capsule {
    i2d_vec2 center1, center2;
    float radius;
} i2d_capsule;

/** A two-sided line segment: no area, no mass; meant for static geometry. */
typedef struct i2d_segment {
    i2d_vec2 point1, point2;
} i2d_segment;

/** Mass properties of a shape at a uniform density (kg/m^2). */
typedef struct i2d_mass_data {
    float mass;               /**< kg */
    i2d_vec2 center;          /**< centroid, in the shape's frame */
    float rotational_inertia; /**< kg m^2, about the centroid */
} i2d_mass_data;

/** Result of a ray cast against one shape. */
typedef struct i2d_cast_output {
    i2d_vec2 point;  /**< world point where the ray enters the shape */
    i2d_vec2 normal; /**< unit surface normal there, facing the ray */
    float fraction;  /**< of the translation, in [0, 1] */
    bool hit;
} i2d_cast_output;

/** A convex shape for shape casts and overlap queries: the convex hull of up to 8 points,
 *  rounded by radius (1 point and a radius: a circle; 2: a capsule; more: a rounded
 *  polygon). Build it with i2d_make_proxy. */
typedef struct i2d_shape_proxy {
    i2d_vec2 points[8];
    int32_t count;  /**< 1 to 8 */
    float radius;   /**< m, >= 0 */
} i2d_shape_proxy;

/** The closest points of two shapes, and how far apart they are. */
typedef struct i2d_distance_result {
    i2d_vec2 point_a;  /**< on shape A's surface (its outline grown by its radius) */
    i2d_vec2 point_b;  /**< on shape B's surface */
    i2d_vec2 normal;   /**< unit, from A towards B; (0, 0) when the shapes overlap */
    float distance;    /**< m between the surfaces; 0 when they touch or overlap */
} i2d_distance_result;

/** A proxy from 1..8 points (world space for the queries) and a radius in [0, 1e5] m:
 *  their convex hull, counter-clockwise; points along one line give a segment. NULL
 *  points, a count outside 1..8, NaN, infinite or out-of-range values give a proxy of
 *  count 0 (which every query refuses) and I2D_ERR_INVALID_ARGUMENT. */
I2D_API i2d_shape_proxy i2d_make_proxy(const i2d_vec2* points, int32_t count, float radius);
/** The distance between two proxies (each placed by its transform, whose rotation must be
 *  normalised within 1e-3): the closest points of their rounded hulls. Touching shapes give
 *  distance 0 with their normal. Overlapping shapes give distance 0, a zero normal and
 *  point_a = point_b: a point both hold while their cores (the hulls before rounding)
 *  are apart, else a point of A's core. A NULL proxy, one of count 0 or over 8, NaN or
 *  values out of range, or a bad rotation gives a zero result and
 *  I2D_ERR_INVALID_ARGUMENT (i2d_last_status). */
I2D_API i2d_distance_result i2d_shape_distance(const i2d_shape_proxy* a, i2d_transform xa, const i2d_shape_proxy* b,
                                               i2d_transform xb);

/** Convex hull of 3..8 points, counter-clockwise, rounded by radius (m, >= 0). Points
 *  closer than 0.005 m are welded and points within 0.005 m of a hull edge's line are
 *  dropped. Returns I2D_ERR_INVALID_ARGUMENT (out untouched) for NULL pointers, a count
 *  outside 3..8, NaN or infinite values, a negative radius, and collinear, duplicate or
 *  tiny (area below 0.005^2 m^2) input; the message says which. */
I2D_API i2d_status i2d_make_polygon(const i2d_vec2* points, int32_t count, float radius, i2d_polygon* out);
/** A box centred on the origin. Half sizes must be finite and > 0; otherwise a zero
 *  polygon (count 0) and I2D_ERR_INVALID_ARGUMENT. */
I2D_API i2d_polygon i2d_make_box(float half_width, float half_height);
/** A box centred on center and turned by rotation (normalised within 1e-3). */
I2D_API i2d_polygon i2d_make_offset_box(float half_width, float half_height, i2d_vec2 center, i2d_rot rotation);

/** Mass properties at density (kg/m^2, >= 0). Invalid input gives zeros and
 *  I2D_ERR_INVALID_ARGUMENT. */
I2D_API i2d_mass_data i2d_compute_circle_mass(const i2d_circle* shape, float density);
I2D_API i2d_mass_data i2d_compute_capsule_mass(const i2d_capsule* shape, float density);
I2D_API i2d_mass_data i2d_compute_polygon_mass(const i2d_polygon* shape, float density);

/** Ray origin + t * translation, t in [0, 1], against one shape placed by xf. A ray that
 *  starts inside a shape does not hit it; segments are hit from either side. */
I2D_API i2d_cast_output i2d_ray_cast_circle(const i2d_circle* shape, i2d_transform xf, i2d_vec2 origin,
                                            i2d_vec2 translation);
I2D_API i2d_cast_output i2d_ray_cast_capsule(const i2d_capsule* shape, i2d_transform xf, i2d_vec2 origin,
                                             i2d_vec2 translation);
I2D_API i2d_cast_output i2d_ray_cast_segment(const i2d_segment* shape, i2d_transform xf, i2d_vec2 origin,
                                             i2d_vec2 translation);
I2D_API i2d_cast_output i2d_ray_cast_polygon(const i2d_polygon* shape, i2d_transform xf, i2d_vec2 origin,
                                             i2d_vec2 translation);

/* Manifolds of shapes given in their own frame and placed by transforms (rotations
 * normalised within 1e-3). Points whose separation is within the speculative distance
 * (0.02 m, in any world's unit: see the top of this file) are included with a negative penetration, so point_count > 0 does not by
 * itself mean touching. Invalid input (NULL, NaN, inf, negative radius, a polygon count
 * outside 3..8, a capsule shorter than 0.005 m) reports point_count 0 and sets
 * I2D_ERR_INVALID_ARGUMENT. Two segments never collide (there is no function for them).
 * Moving B along the normal by the largest point penetration separates the shapes. */
I2D_API i2d_manifold i2d_collide_capsule_circle(const i2d_capsule* a, i2d_transform xfa, const i2d_circle* b,
                                                i2d_transform xfb);
I2D_API i2d_manifold i2d_collide_segment_circle(const i2d_segment* a, i2d_transform xfa, const i2d_circle* b,
                                                i2d_transform xfb);
I2D_API i2d_manifold i2d_collide_polygon_circle(const i2d_polygon* a, i2d_transform xfa, const i2d_circle* b,
                                                i2d_transform xfb);
/** Up to 2 points when the capsules lie along each other. */
I2D_API i2d_manifold i2d_collide_capsules(const i2d_capsule* a, i2d_transform xfa, const i2d_capsule* b,
                                          i2d_transform xfb);
I2D_API i2d_manifold i2d_collide_segment_capsule(const i2d_segment* a, i2d_transform xfa, const i2d_capsule* b,
                                                 i2d_transform xfb);
I2D_API i2d_manifold i2d_collide_polygon_capsule(const i2d_polygon* a, i2d_transform xfa, const i2d_capsule* b,
                                                 i2d_transform xfb);
I2D_API i2d_manifold i2d_collide_segment_polygon(const i2d_segment* a, i2d_transform xfa, const i2d_polygon* b,
                                                 i2d_transform xfb);
/** Separating axis test and clipping: up to 2 points on the reference face. */
I2D_API i2d_manifold i2d_collide_polygons(const i2d_polygon* a, i2d_transform xfa, const i2d_polygon* b,
                                          i2d_transform xfb);

#endif
