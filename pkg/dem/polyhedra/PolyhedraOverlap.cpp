#include <pkg/dem/polyhedra/PolyhedraGeom.hpp>
#include <pkg/dem/polyhedra/PolyhedraOverlap.hpp>
#include <cmath>

namespace yade {

Vector3r overlapNormal(const polyhedron::Faces& overlap, const Vector3r& fallback) {
    Vector3r s = Vector3r::Zero();
    Real total = 0;
    for (const auto& f : overlap) {
        const Vector3r a = polyhedron::areaVector(f.pts);
        total += a.norm();
        if (f.origin == 0) s += a;
    }
    if (!(s.norm() > 1e-9 * total)) return fallback.normalized();
    return s.normalized();
}

bool setPolyhedraGeom(const polyhedron::Faces& overlap, const Vector3r& origin, const Vector3r& normal, const State& s1, const State& s2,
        const Vector3r& shift2, Real dt, Interaction& I) {
    const polyhedron::MassProperties m = polyhedron::massProperties(overlap);
    if (!(m.volume > 0)) return false;
    const bool isNew = !I.geom;
    if (isNew) I.geom = std::make_shared<PolyhedraGeom>();
    auto& g = static_cast<PolyhedraGeom&>(*I.geom);
    const Vector3r oldNormal = g.normal;
    g.penetrationVolume = m.volume;
    g.equivalentCrossSection = std::pow(m.volume, 2. / 3.);
    g.equivalentPenetrationDepth = m.volume / g.equivalentCrossSection;
    g.contactPoint = origin + m.centroid;
    g.normal = normal;
    if (isNew) {
        g.orthonormal_axis = g.twist_axis = g.shearInc = Vector3r::Zero();
        return true;
    }
    // the turn of the contact plane in this step, and the tangential displacement of the contact point
    g.orthonormal_axis = oldNormal.cross(normal);
    g.twist_axis = 0.5 * dt * (s1.angVel() + s2.angVel()).dot(normal) * normal;
    const Vector3r c = g.contactPoint;
    const Vector3r rel = (s2.vel() + s2.angVel().cross(c - (s2.pos() + shift2))) - (s1.vel() + s1.angVel().cross(c - s1.pos()));
    g.shearInc = (rel - rel.dot(normal) * normal) * dt;
    return true;
}

} // namespace yade
