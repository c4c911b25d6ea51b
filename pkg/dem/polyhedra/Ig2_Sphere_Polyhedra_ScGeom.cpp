#include <core/Scene.hpp>
#include <pkg/dem/polyhedra/Ig2_Sphere_Polyhedra_ScGeom.hpp>

namespace yade {

namespace {

Vector3r closestOnSegment(const Vector3r& q, const Vector3r& a, const Vector3r& b) {
    const Vector3r e = b - a;
    const Real t = std::clamp(e.dot(q - a) / e.squaredNorm(), Real(0), Real(1));
    return a + t * e;
}

// The point of the polyhedron's surface closest to q (all in the polyhedron's frame), q outside it.
Vector3r closestOnSurface(const Polyhedra& p, const Vector3r& q) {
    Vector3r best = p.v[0];
    for (size_t k = 0; k < p.faces.size(); ++k) {
        const auto& f = p.faces[k];
        const Vector3r& n = p.planes[k].normal;
        const Vector3r proj = q - (n.dot(q) - p.planes[k].offset) * n;
        bool inside = true; // the projection within the face: on the inner side of each edge
        for (size_t i = 0; i < f.size(); ++i) {
            const Vector3r& a = p.v[f[i]];
            const Vector3r& b = p.v[f[(i + 1) % f.size()]];
            inside = inside && (b - a).cross(proj - a).dot(n) >= 0;
            const Vector3r c = closestOnSegment(q, a, b);
            if ((c - q).squaredNorm() < (best - q).squaredNorm()) best = c;
        }
        if (inside && (proj - q).squaredNorm() < (best - q).squaredNorm()) best = proj;
    }
    return best;
}

} // namespace

bool Ig2_Sphere_Polyhedra_ScGeom::go(const Sphere& s, const Polyhedra& p, const State& s1, const State& s2, const Vector3r& shift2,
        bool force, Interaction& I) {
    if (!p.initialized) return false;
    const Real r = s.radius;
    const Vector3r x2 = s2.pos() + shift2;
    const Vector3r& center = s1.pos();
    const Vector3r q = s2.ori().conjugate() * (center - x2); // the sphere's center in the polyhedron's frame
    if (q.norm() > p.radius + r && !I.isReal() && !force) return false;
    int deepest = 0; // the face nearest to an inner center, or the one it is out of the farthest
    Real out = -INFINITY;
    for (size_t k = 0; k < p.planes.size(); ++k) {
        const Real d = p.planes[k].normal.dot(q) - p.planes[k].offset;
        if (d > out) out = d, deepest = (int)k;
    }
    Vector3r normal; // from the sphere's center towards the polyhedron
    Real penetrationDepth;
    if (out <= 0) { // the center inside: push out through the nearest face
        normal = -(s2.ori() * p.planes[deepest].normal);
        penetrationDepth = r - out;
    } else {
        const Vector3r c = closestOnSurface(p, q);
        normal = s2.ori() * (c - q);
        penetrationDepth = r - normal.norm();
        if (penetrationDepth <= 0 && !I.isReal() && !force) return false;
        normal.normalize();
    }
    const bool isNew = !I.geom;
    if (isNew) I.geom = std::make_shared<ScGeom>();
    auto& g = static_cast<ScGeom&>(*I.geom);
    g.contactPoint = center + (r - 0.5 * penetrationDepth) * normal;
    g.penetrationDepth = penetrationDepth;
    g.refR1 = g.refR2 = r;
    g.precompute(s1.kinematics(), s2.kinematics(), scene->dt, normal, isNew, shift2, false);
    return true;
}

} // namespace yade
