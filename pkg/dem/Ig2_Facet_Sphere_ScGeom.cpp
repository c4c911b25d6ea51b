#include <core/Scene.hpp>
#include <pkg/dem/Ig2_Facet_Sphere_ScGeom.hpp>

namespace yade {

bool Ig2_Facet_Sphere_ScGeom::go(const Facet& f, const Sphere& s, const Kinematics& st1, const Kinematics& st2,
        const Vector3r& shift2, bool force, Contact& contact) {
    return go(f, s.radius, st1, st2, shift2, force, contact);
}

void Ig2_Facet_Sphere_ScGeom::goBatch(const BodyColumns& b, Contact* c, size_t n, char* result) {
    const BodyStore::Columns cols = b.store; // (locals: the char stores to result may alias anything in memory)
    const Shape* const* shape = b.shape;
    const Real* radius = b.radius;
    for (size_t j = 0; j < n; ++j) {
        Contact& x = c[j];
        result[j] = go(static_cast<const Facet&>(*shape[x.id1]), radius[x.id2], cols.kinematics(x.id1), cols.kinematics(x.id2), Vector3r::Zero(),
                false, x);
    }
}

bool Ig2_Facet_Sphere_ScGeom::go(const Facet& f, Real r, const Kinematics& st1, const Kinematics& st2, const Vector3r& shift2, bool force,
        Contact& contact) {
    const Matrix3r toGlobal = st1.ori.toRotationMatrix();
    const Vector3r c = toGlobal.transpose() * (st2.pos + shift2 - st1.pos); // sphere center, facet frame
    Vector3r normal = f.normal;
    Real L = normal.dot(c); // distance from the facet plane
    if (L < 0) {
        normal = -normal;
        L = -L;
    }
    if (L > r && !contact.isReal() && !force) return false;
    Vector3r cp = c - L * normal; // projection of the center on the plane
    // The edge whose outward normal points most towards cp decides face / edge / vertex contact.
    int m = 0;
    Real bm = f.ne[0].dot(cp);
    for (int i = 1; i < 3; ++i) {
        const Real b = f.ne[i].dot(cp);
        if (bm < b) {
            bm = b;
            m = i;
        }
    }
    const Real shrink = r * shrinkFactor;
    const Real icr = std::max(Real(0), f.icr - shrink);
    Real penetrationDepth;
    if (bm < icr) { // inside the (shrunk) triangle: contact with the face
        penetrationDepth = r - L;
    } else {
        cp += f.ne[m] * (icr - bm); // onto edge m
        const int prev = m == 0 ? 2 : m - 1, next = m == 2 ? 0 : m + 1;
        if (cp.dot(f.ne[prev]) > icr) cp = f.vu[m] * (f.vl[m] - shrink);               // past vertex m
        else if (cp.dot(f.ne[next]) > icr) cp = f.vu[next] * (f.vl[next] - shrink);    // past vertex m+1
        normal = c - cp;
        penetrationDepth = r - normal.norm();
        normal.normalize();
    }
    if (penetrationDepth <= 0 && !contact.isReal()) return false;
    const bool isNew = !contact.geom;
    ScGeom& g = isNew ? contact.makeGeom<ScGeom>() : static_cast<ScGeom&>(*contact.geom);
    normal = toGlobal * normal;
    g.contactPoint = st2.pos + shift2 - (r - 0.5 * penetrationDepth) * normal;
    g.penetrationDepth = penetrationDepth;
    // A facet has no radius: it counts as a sphere twice as big in the linear stiffness, or, with
    // hertzian, as a very large one (the effective radius of the Hertz contact is then r).
    g.refR1 = hertzian ? hertzianFacetRadius : 2 * r;
    g.refR2 = r;
    g.precompute(st1, st2, scene->dt, normal, isNew, shift2, false);
    return true;
}

} // namespace yade
