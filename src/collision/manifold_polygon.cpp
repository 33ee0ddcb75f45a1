// SPDX-License-Identifier: MIT
// Contact manifolds of polygons: polygon against polygon (capsules and segments enter as
// 2-gons) and polygon against circle.
#include <cfloat>
#include <cmath>

#include "collision/distance.hpp"
#include "collision/manifold.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

// A polygon expressed in the frame of the reference computation (A's frame, shifted to
// A's first vertex so that coordinates stay small and precise). Plain float arrays, left
// uninitialised past `count`: zeroing eight vertices and normals per polygon per call
// was a fifth of a box-box manifold's cost.
struct LocalPolygon {
    float vx[max_polygon_vertices], vy[max_polygon_vertices];
    float nx[max_polygon_vertices], ny[max_polygon_vertices];
    int32_t count;
    float radius;
    Vec2 v(int32_t i) const { return {vx[i], vy[i]}; }
    Vec2 n(int32_t i) const { return {nx[i], ny[i]}; }
    int32_t next(int32_t i) const { return i + 1 == count ? 0 : i + 1; }
};

void place(const Polygon& poly, const Transform& xf, LocalPolygon& out) {
    out.count = poly.count;
    out.radius = poly.radius;
    for (int32_t i = 0; i < poly.count; ++i) {
        const Vec2 v = transform_point(xf, poly.vertices[i]);
        const Vec2 n = rotate(xf.q, poly.normals[i]);
        out.vx[i] = v.x, out.vy[i] = v.y;
        out.nx[i] = n.x, out.ny[i] = n.y;
    }
}

struct FaceQuery {
    int32_t edge = 0;
    float separation = -FLT_MAX;
};

// The face of p1 that separates p2 the most: for each face, the deepest vertex of p2
// below it (Gregorius, "The Separating Axis Test between Convex Polyhedra", GDC 2013, in
// 2D). The largest of these is the signed distance along the best face axis.
FaceQuery max_separation(const LocalPolygon& p1, const LocalPolygon& p2) {
    FaceQuery best;
    for (int32_t i = 0; i < p1.count; ++i) {
        float deepest = FLT_MAX;
        const Vec2 normal = p1.n(i), vertex = p1.v(i);
        for (int32_t j = 0; j < p2.count; ++j) {
            deepest = min_of(deepest, dot(normal, p2.v(j) - vertex));
        }
        if (deepest > best.separation) {
            best.separation = deepest;
            best.edge = i;
        }
    }
    return best;
}

// The incident edge is the one most anti-parallel to the reference normal.
int32_t incident_edge(const LocalPolygon& inc, Vec2 ref_normal) {
    int32_t edge = 0;
    float lowest = FLT_MAX;
    for (int32_t i = 0; i < inc.count; ++i) {
        const float d = dot(ref_normal, inc.n(i));
        if (d < lowest) {
            lowest = d;
            edge = i;
        }
    }
    return edge;
}

// Points beyond the speculative margin are dropped; the margin never moves a point, so a
// larger one only keeps clipped ends that lie on the incident edge inside the reference
// face's slab, at their true height above the face.
void add_point(Manifold& m, Vec2 point, float penetration, uint32_t id, float speculative) {
    if (penetration < -speculative) {
        return;  // too far apart to matter this step
    }
    ManifoldPoint& mp = m.points[m.point_count++];
    mp.point = point;
    mp.penetration = penetration;
    mp.id = id;
}

// Box2D's b2ClipPolygons (Box2D v3 manifold.c), the Sutherland-Hodgman step reduced to
// one edge: the incident edge v21-v22 is clipped to the slab between the side planes of
// the reference edge v11-v12, and each surviving end becomes a point whose separation
// is its height above the reference face. Because the winding is counter-clockwise the
// incident edge runs against the reference edge's tangent. Normal: reference to incident.
Manifold clip_edges(const LocalPolygon& ref, int32_t i11, const LocalPolygon& inc, int32_t i21, bool flip,
                    bool overlapping, float speculative) {
    const int32_t i12 = ref.next(i11), i22 = inc.next(i21);
    const Vec2 normal = ref.n(i11);
    const Vec2 v11 = ref.v(i11), v12 = ref.v(i12);
    const Vec2 v21 = inc.v(i21), v22 = inc.v(i22);
    const Vec2 tangent = left_perp(normal);

    const float lower1 = 0.0f, upper1 = dot(v12 - v11, tangent);
    const float upper2 = dot(v21 - v11, tangent), lower2 = dot(v22 - v11, tangent);
    const float span = upper2 - lower2;
    Vec2 v_lower = v22, v_upper = v21;
    if (lower2 < lower1 && span > FLT_EPSILON) {
        v_lower = lerp(v22, v21, min_of((lower1 - lower2) / span, 1.0f));
    }
    if (upper2 > upper1 && span > FLT_EPSILON) {
        v_upper = lerp(v22, v21, max_of((upper1 - lower2) / span, 0.0f));
    }
    const float sep_lower = dot(v_lower - v11, normal);
    const float sep_upper = dot(v_upper - v11, normal);
    const float r1 = ref.radius, r2 = inc.radius;

    // Overlapping cores: a clipped-away incident vertex may be deeper than its clipped
    // point (past the reference face's side plane but still inside the other polygon).
    // Its depth is kept on the clipped point so that the deepest penetration is the
    // separating-axis depth and pushing by it along the normal separates the polygons.
    // Box2D keeps the clipped depth, which can fall short by a fraction of a millimetre.
    // Apart cores keep the clipped depth: there the face separation of a vertex outside
    // the slab understates its true distance.
    const float vertex_lower = overlapping ? dot(v22 - v11, normal) : sep_lower;
    const float vertex_upper = overlapping ? dot(v21 - v11, normal) : sep_upper;
    const float pen_lower = r1 + r2 - min_of(sep_lower, vertex_lower);
    const float pen_upper = r1 + r2 - min_of(sep_upper, vertex_upper);

    Manifold m;
    m.normal = normal;
    // Midway between the surfaces: the incident core point is r2 beyond its surface and
    // the reference surface lies r1 above the reference core.
    add_point(m, v_lower + (0.5f * (r1 - r2 - sep_lower)) * normal, pen_lower, make_feature_id(i11, i22, flip),
              speculative);
    add_point(m, v_upper + (0.5f * (r1 - r2 - sep_upper)) * normal, pen_upper, make_feature_id(i12, i21, flip),
              speculative);
    return m;
}

float deepest_penetration(const Manifold& m) {
    float deepest = -FLT_MAX;
    for (int32_t i = 0; i < m.point_count; ++i) {
        deepest = max_of(deepest, m.points[i].penetration);
    }
    return deepest;
}

// Cores apart (by more than a tenth of the slop): when the closest points of the
// reference and incident edges are two vertices, the face normal may misdescribe the
// contact (rounded corners meeting, an incident corner just past the reference face's
// end), and one point along the vertex-vertex direction is right. The clipped points
// win when one of them is as close as those vertices (edges lying along each other):
// they then carry the true depth and a second point.
Manifold apart_contact(const LocalPolygon& ref, int32_t i11, const LocalPolygon& inc, int32_t i21, bool flip,
                       float speculative, float slop) {
    const int32_t i12 = ref.next(i11), i22 = inc.next(i21);
    const SegmentDistance sd = segment_distance(ref.v(i11), ref.v(i12), inc.v(i21), inc.v(i22));
    const bool ref_vertex = sd.fraction1 == 0.0f || sd.fraction1 == 1.0f;
    const bool inc_vertex = sd.fraction2 == 0.0f || sd.fraction2 == 1.0f;
    const Manifold clipped = clip_edges(ref, i11, inc, i21, flip, false, speculative);
    if (!ref_vertex || !inc_vertex) {
        return clipped;
    }
    const float radius = ref.radius + inc.radius;
    const float distance = std::sqrt(sd.distance_squared);
    // Clipped points inside the slab are never closer than the edges' distance; one that
    // is closer lies outside it (the edges do not overlap along the face) and is wrong.
    if (clipped.point_count > 0 && std::fabs(radius - deepest_penetration(clipped) - distance) <= 0.01f * slop) {
        return clipped;
    }
    if (distance - radius > speculative) {
        return {};
    }
    const Vec2 normal = (1.0f / distance) * (sd.closest2 - sd.closest1);
    const int32_t ref_index = sd.fraction1 == 0.0f ? i11 : i12;
    const int32_t inc_index = sd.fraction2 == 0.0f ? i21 : i22;
    return single_contact(sd.closest1, sd.closest2, normal, distance, ref.radius, inc.radius,
                          make_feature_id(ref_index, inc_index, flip));
}

}  // namespace

// Separating axis test over both polygons' face normals, then reference and incident
// faces and clipping (Box2D v3 manifold.c b2CollidePolygons; Gregorius GDC 2013 for the
// SAT; Ericson 5.1.9 for the closest points of the vertex case). Radii are handled by
// subtracting them from the core separations.
Manifold collide_polygons(const Polygon& a, const Transform& xf_a, const Polygon& b, const Transform& xf_b,
                          float speculative, float slop) {
    const Vec2 origin = a.vertices[0];
    const Transform frame{transform_point(xf_a, origin), xf_a.q};
    LocalPolygon pa, pb;
    place(a, Transform{-origin, Rot{}}, pa);
    place(b, inv_mul_transforms(frame, xf_b), pb);

    const float radius = pa.radius + pb.radius;
    const FaceQuery qa = max_separation(pa, pb);
    if (qa.separation > speculative + radius) {
        return {};  // A's face separates them: B's faces need not be tried
    }
    const FaceQuery qb = max_separation(pb, pa);
    if (qb.separation > speculative + radius) {
        return {};
    }
    // Prefer A's face unless B's is clearly better: with nearly equal separations the
    // reference face would otherwise flicker between steps and the ids with it.
    const bool flip = qb.separation > qa.separation + 0.1f * slop;
    const LocalPolygon& ref = flip ? pb : pa;
    const LocalPolygon& inc = flip ? pa : pb;
    const int32_t ref_edge = flip ? qb.edge : qa.edge;
    const int32_t inc_edge = incident_edge(inc, ref.n(ref_edge));
    const float separation = flip ? qb.separation : qa.separation;

    // Overlapping or nearly touching cores: the face normal is right. The tenth of the
    // slop also keeps the vertex-vertex direction long enough to normalise.
    Manifold m = separation <= 0.1f * slop ? clip_edges(ref, ref_edge, inc, inc_edge, flip, true, speculative)
                                           : apart_contact(ref, ref_edge, inc, inc_edge, flip, speculative, slop);
    if (m.point_count == 0) {
        return {};
    }
    if (flip) {
        m.normal = -m.normal;
    }
    return to_world(m, frame);
}

// The face of deepest separation decides; beyond the ends of that face (and outside the
// core) the nearest vertex gives the normal (Box2D v3 b2CollidePolygonAndCircle; Ericson
// 5.2.8 for the Voronoi regions).
Manifold collide_polygon_circle(const Polygon& a, const Transform& xf_a, const Circle& b, const Transform& xf_b,
                                float speculative) {
    const Transform xf = inv_mul_transforms(xf_a, xf_b);
    const Vec2 c = transform_point(xf, b.center);
    const float radius = a.radius + b.radius;
    int32_t face = 0;
    float separation = -FLT_MAX;
    for (int32_t i = 0; i < a.count; ++i) {
        const float s = dot(a.normals[i], c - a.vertices[i]);
        if (s > separation) {
            separation = s;
            face = i;
        }
    }
    if (separation > radius + speculative) {
        return {};
    }
    const int32_t next = face + 1 == a.count ? 0 : face + 1;
    const Vec2 v1 = a.vertices[face], v2 = a.vertices[next];
    const bool beyond_v1 = dot(c - v1, v2 - v1) < 0.0f;
    const bool beyond_v2 = dot(c - v2, v1 - v2) < 0.0f;
    Manifold m;
    if (separation > FLT_EPSILON && (beyond_v1 || beyond_v2)) {
        const Vec2 vertex = beyond_v1 ? v1 : v2;
        const float distance = length(c - vertex);
        if (distance - radius > speculative) {
            return {};
        }
        m = single_contact(vertex, c, (1.0f / distance) * (c - vertex), distance, a.radius, b.radius,
                           make_feature_id(beyond_v1 ? face : next, 0));
    } else {
        const Vec2 normal = a.normals[face];
        m = single_contact(c - separation * normal, c, normal, separation, a.radius, b.radius,
                           make_feature_id(face, 0));
    }
    return to_world(m, xf_a);
}

}  // namespace i2d
