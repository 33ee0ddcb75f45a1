// SPDX-License-Identifier: MIT
// Area, mass, centroid and rotational inertia of every shape kind, in closed form.
#include <cmath>

#include "collision/geometry.hpp"
#include "math/math.hpp"

namespace i2d {

namespace {

// Area integrals of a region about a reference point: A = int dA, S = int x dA,
// J = int |x|^2 dA. Pieces add up; the inertia about the centroid is J - |S|^2 / A
// (the parallel axis theorem).
struct Moments {
    float area = 0.0f;
    Vec2 first;
    float second = 0.0f;

    void add(const Moments& m) {
        area += m.area;
        first += m.first;
        second += m.second;
    }
};

// Triangle p0 p1 p2 (CCW gives a positive area): int |x|^2 dA over a triangle is
// A/6 (|p0|^2 + |p1|^2 + |p2|^2 + p0.p1 + p1.p2 + p2.p0), the standard quadrature that
// is exact for quadratics.
Moments triangle_moments(Vec2 p0, Vec2 p1, Vec2 p2) {
    Moments m;
    m.area = 0.5f * cross(p1 - p0, p2 - p0);
    m.first = (m.area / 3.0f) * (p0 + p1 + p2);
    m.second = (m.area / 6.0f) * (dot(p0, p0) + dot(p1, p1) + dot(p2, p2) + dot(p0, p1) + dot(p1, p2) + dot(p2, p0));
    return m;
}

// Circular sector of radius r and angle theta with its apex at p, bisected by unit u.
// About the apex: A = theta r^2 / 2, int |y|^2 dA = theta r^4 / 4, and the centroid lies
// 4 r sin(theta/2) / (3 theta) along u; shifting to the reference point adds
// 2 p.S_apex + A |p|^2.
Moments sector_moments(Vec2 p, Vec2 u, float theta, float r) {
    Moments m;
    m.area = 0.5f * theta * r * r;
    const float offset = theta > 0.0f ? 4.0f * r * i2d::sin(0.5f * theta) / (3.0f * theta) : 2.0f * r / 3.0f;
    const Vec2 apex_first = (m.area * offset) * u;
    m.first = m.area * p + apex_first;
    m.second = 0.25f * theta * r * r * r * r + 2.0f * dot(p, apex_first) + m.area * dot(p, p);
    return m;
}

MassData from_moments(const Moments& m, float density, Vec2 reference) {
    MassData md;
    md.mass = density * m.area;
    const Vec2 c = (1.0f / m.area) * m.first;
    md.center = reference + c;
    md.rotational_inertia = density * (m.second - m.area * dot(c, c));
    return md;
}

// A polygon rounded by r is the polygon, a rectangle r thick on each edge and a circular
// sector at each vertex whose angle is the turn between the adjacent normals (they sum to
// 2 pi). Everything is measured from the first vertex so that polygons far from the body
// origin keep their precision. This is exact, unlike Box2D's approximation that pushes
// the vertices out.
MassData polygon_mass(const Polygon& poly, float density) {
    const Vec2 reference = poly.vertices[0];
    Vec2 v[max_polygon_vertices];
    for (int32_t i = 0; i < poly.count; ++i) {
        v[i] = poly.vertices[i] - reference;
    }
    Moments total;
    for (int32_t i = 1; i + 1 < poly.count; ++i) {
        total.add(triangle_moments(v[0], v[i], v[i + 1]));
    }
    const float r = poly.radius;
    if (r > 0.0f) {
        for (int32_t i = 0; i < poly.count; ++i) {
            const int32_t j = i + 1 == poly.count ? 0 : i + 1;
            const Vec2 offset = r * poly.normals[i];
            // The slab v[i], v[i] + offset, v[j] + offset, v[j] is counter-clockwise.
            total.add(triangle_moments(v[i], v[i] + offset, v[j] + offset));
            total.add(triangle_moments(v[i], v[j] + offset, v[j]));
            const Vec2 n_prev = poly.normals[i == 0 ? poly.count - 1 : i - 1];
            const float theta = i2d::atan2(cross(n_prev, poly.normals[i]), dot(n_prev, poly.normals[i]));
            total.add(sector_moments(v[i], normalize(n_prev + poly.normals[i]), theta, r));
        }
    }
    return from_moments(total, density, reference);
}

// Capsule of length L (between centres) and radius r: a 2r x L rectangle, I = m (L^2 +
// 4 r^2) / 12, plus two half discs. A half disc of mass m/2 has I = (m/2) r^2 / 2 about
// its flat edge's centre and its centroid lc = 4 r / (3 pi) from it; moved to the capsule
// centre, h + lc away (h = L/2): (m/2)(r^2/2 - lc^2 + (h + lc)^2) = (m/2)(r^2/2 + h^2 +
// 2 h lc). The pair gives m_disc (r^2/2 + h^2 + 2 h lc).
MassData capsule_mass(const Capsule& c, float density) {
    const float r = c.radius;
    const float len = length(c.center2 - c.center1);
    const float h = 0.5f * len;
    const float rect_mass = density * 2.0f * r * len;
    const float disc_mass = density * pi * r * r;
    const float lc = 4.0f * r / (3.0f * pi);
    MassData md;
    md.mass = rect_mass + disc_mass;
    md.center = lerp(c.center1, c.center2, 0.5f);
    md.rotational_inertia = rect_mass * (len * len + 4.0f * r * r) / 12.0f + disc_mass * (0.5f * r * r + h * h + 2.0f * h * lc);
    return md;
}

}  // namespace

float area(const Geometry& g) {
    switch (g.type) {
        case ShapeType::circle: return pi * g.circle.radius * g.circle.radius;
        case ShapeType::capsule: {
            const float r = g.capsule.radius;
            return pi * r * r + 2.0f * r * length(g.capsule.center2 - g.capsule.center1);
        }
        case ShapeType::segment: return 0.0f;
        case ShapeType::chain_segment: return 0.0f;
        case ShapeType::polygon: return compute_mass(g, 1.0f).mass;
        case ShapeType::count: break;
    }
    return 0.0f;
}

MassData compute_mass(const Geometry& g, float density) {
    MassData md;
    switch (g.type) {
        case ShapeType::circle: {
            const float r = g.circle.radius;
            md.mass = density * pi * r * r;
            md.center = g.circle.center;
            md.rotational_inertia = 0.5f * md.mass * r * r;
            break;
        }
        case ShapeType::capsule: md = capsule_mass(g.capsule, density); break;
        case ShapeType::segment: md.center = lerp(g.segment.point1, g.segment.point2, 0.5f); break;
        case ShapeType::chain_segment:
            md.center = lerp(g.chain_segment.point1, g.chain_segment.point2, 0.5f);
            break;
        case ShapeType::polygon: md = polygon_mass(g.polygon, density); break;
        case ShapeType::count: break;
    }
    return md;
}

}  // namespace i2d
