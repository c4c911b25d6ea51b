#include <pkg/common/Facet.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/localframe/Ig2_Facet_Sphere_L3Geom.hpp>

namespace yade {

namespace {
    // The point of the triangle (vertices a, b, c) nearest to p (Ericson, Real-Time Collision Detection, 5.1.5).
    Vector3r nearestOnTriangle(const Vector3r& p, const Vector3r& a, const Vector3r& b, const Vector3r& c) {
        const Vector3r ab = b - a, ac = c - a, ap = p - a;
        const Real d1 = ab.dot(ap), d2 = ac.dot(ap);
        if (d1 <= 0 && d2 <= 0) return a;
        const Vector3r bp = p - b;
        const Real d3 = ab.dot(bp), d4 = ac.dot(bp);
        if (d3 >= 0 && d4 <= d3) return b;
        const Real vc = d1 * d4 - d3 * d2;
        if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
        const Vector3r cp = p - c;
        const Real d5 = ab.dot(cp), d6 = ac.dot(cp);
        if (d6 >= 0 && d5 <= d6) return c;
        const Real vb = d5 * d2 - d1 * d6;
        if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
        const Real va = d3 * d6 - d5 * d4;
        if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
        const Real denom = 1 / (va + vb + vc);
        return a + ab * (vb * denom) + ac * (vc * denom);
    }
} // namespace

bool Ig2_Facet_Sphere_L3Geom::goContact(const Shape& s1, const Shape& s2, const Kinematics& k1, const Kinematics& k2, bool force, Contact& c) {
    const Facet& f = static_cast<const Facet&>(s1);
    const Real radius = static_cast<const Sphere&>(s2).radius;
    // the sphere's centre in the facet's frame
    const Matrix3r toGlobal = k1.ori.toRotationMatrix();
    const Vector3r centre = toGlobal.transpose() * (k2.pos - k1.pos);
    const Vector3r nearest = nearestOnTriangle(centre, f.vertices[0], f.vertices[1], f.vertices[2]);
    const Vector3r toCentre = centre - nearest;
    Real dist = toCentre.norm();
    if (!c.geom && !force && dist >= radius) return false;
    if (!(dist > 0)) return false; // the centre in the facet's plane: no normal (the reference has none either)
    Vector3r localNormal = toCentre / dist;
    const Real above = f.normal.dot(centre); // (the plane passes through the body's position)
    if (std::abs(std::abs(above) - dist) <= 1e-12 * dist) { // on the face: the facet's normal, towards the centre
        localNormal = above > 0 ? f.normal : Vector3r(-f.normal);
        dist = std::abs(above);
    }
    const Vector3r normal = toGlobal * localNormal;
    const Vector3r contPt = k1.pos + toGlobal * nearest;
    handleSpheresLikeContact(c, k1, k2, normal, contPt, dist - radius, 0, radius);
    return true;
}

} // namespace yade
