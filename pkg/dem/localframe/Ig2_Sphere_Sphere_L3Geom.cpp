#include <core/Scene.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/localframe/Ig2_Sphere_Sphere_L3Geom.hpp>
#include <pkg/dem/localframe/L6Geom.hpp>
#include <pkg/dem/localframe/LocalFrameMath.hpp>

namespace yade {

bool Ig2_Sphere_Sphere_L3Geom::go(const Shape& s1, const Shape& s2, const State& st1, const State& st2, const Vector3r& shift2, bool force,
        Interaction& I) {
    Contact c(I);
    const Kinematics k2 = st2.kinematics();
    const Vector3r pos2 = k2.pos + shift2;
    return goContact(s1, s2, st1.kinematics(), Kinematics{pos2, k2.vel, k2.angVel, k2.ori}, force, c);
}

void Ig2_Sphere_Sphere_L3Geom::goBatch(const BodyColumns& b, Contact* c, size_t n, char* result) {
    const BodyStore::Columns cols = b.store;
    for (size_t j = 0; j < n; ++j) {
        Contact& x = c[j];
        const Kinematics k2 = cols.kinematics(x.id2);
        const Vector3r pos2 = x.shift ? Vector3r(k2.pos + x.shift->shift2) : k2.pos;
        const Vector3r vel2 = x.shift ? Vector3r(k2.vel + x.shift->shiftVel2) : k2.vel;
        result[j] = goContact(*b.shape[x.id1], *b.shape[x.id2], cols.kinematics(x.id1), Kinematics{pos2, vel2, k2.angVel, k2.ori}, false, x);
    }
}

bool Ig2_Sphere_Sphere_L3Geom::goContact(const Shape& s1, const Shape& s2, const Kinematics& k1, const Kinematics& k2, bool force, Contact& c) {
    const Real r1 = static_cast<const Sphere&>(s1).radius, r2 = static_cast<const Sphere&>(s2).radius;
    const Vector3r relPos = k2.pos - k1.pos;
    const Real dist = localframe::norm(relPos);
    if (!c.geom && !force && dist - std::abs(distFactor) * (r1 + r2) >= 0) return false; // not (yet) a contact
    // Centres at the same point have no normal: the last one stays (x for a new contact). (Throwing here would abort the
    // process: the geometry pass reports no exceptions. A non-finite position gives NaN, which the integrator reports.)
    const Vector3r normal = dist != 0 ? Vector3r(relPos / dist) : c.geom ? Vector3r(static_cast<const L3Geom&>(*c.geom).trsf.row(0)) : Vector3r(Vector3r::UnitX());
    const Real uN = dist - (r1 + r2);
    const Vector3r contPt = k1.pos + (r1 + 0.5 * uN) * normal;
    handleSpheresLikeContact(c, k1, k2, normal, contPt, uN, r1, r2);
    return true;
}

Matrix3r Ig2_Sphere_Sphere_L3Geom::initialTrsf(const Vector3r& normal) {
    Matrix3r t;
    t.row(0) = normal;
    // y in the xz plane when |n_y| < |n_z|, else in the xy plane (deterministic)
    const Vector3r y = std::abs(normal.y()) < std::abs(normal.z()) ? normal.cross(Vector3r::UnitY()) : normal.cross(Vector3r::UnitZ());
    t.row(1) = localframe::normalized(y);
    t.row(2) = normal.cross(t.row(1).transpose());
    return t;
}

void Ig2_Sphere_Sphere_L3Geom::handleSpheresLikeContact(Contact& c, const Kinematics& k1, const Kinematics& k2, const Vector3r& normal,
        const Vector3r& contPt, Real uN, Real r1, Real r2) const {
    const bool l6 = makesL6();
    if (!c.geom) { // a new contact: the initial frame, u = (uN, 0, 0)
        L3Geom& g = l6 ? c.makeGeom<L6Geom>() : c.makeGeom<L3Geom>();
        g.contactPoint = contPt;
        g.normal = normal;
        g.refR1 = r1;
        g.refR2 = r2;
        g.trsf = initialTrsf(normal);
        g.u = Vector3r(uN, 0, 0);
        if (distFactor < 0) g.u0 = g.u; // the initial distance is the zero
        return;
    }
    L3Geom& g = static_cast<L3Geom&>(*c.geom);
    const Real dt = scene->dt;
    const Vector3r prevNormal = g.trsf.row(0);
    Vector3r midNormal = (approxMask & 2) ? prevNormal : Vector3r(0.5 * (prevNormal + normal));
    if (!(approxMask & 4) && !(approxMask & 2)) midNormal = localframe::normalized(midNormal);
    const Vector3r tilt = prevNormal.cross(normal);                                                      // o_r
    const Vector3r twist = midNormal * (localframe::dot(midNormal, 0.5 * (k1.angVel + k2.angVel)) * dt); // o_t
    const Vector3r b1 = contPt - k1.pos; // (with noRatch too: the reference's rule, found by running it)
    const Vector3r b2 = noRatch ? Vector3r(-r2 * normal) : Vector3r(contPt - k2.pos);
    Vector3r relVel = (k2.vel + k2.angVel.cross(b2)) - (k1.vel + k1.angVel.cross(b1));
    relVel -= localframe::dot(midNormal, relVel) * midNormal; // the normal part is computed directly
    const Matrix3r prevTrsf = g.trsf;
    Matrix3r trsf;
    trsf.row(0) = normal;
    for (int i = 1; i < 3; ++i) {
        const Vector3r row = prevTrsf.row(i);
        trsf.row(i) = row - row.cross(tilt) - row.cross(twist);
    }
    if (trsfRenorm > 0 && scene->iter % trsfRenorm == 0) {
        // orthonormal again (Gram-Schmidt from the normal, as the reference)
        const Vector3r x = localframe::normalized(trsf.row(0));
        Vector3r y = trsf.row(1);
        y = localframe::normalized(y - localframe::dot(y, x) * x);
        trsf.row(0) = x;
        trsf.row(1) = y;
        trsf.row(2) = x.cross(y);
    }
    // (approxMask 1: the previous trsf, through a quaternion as the slerp: the reference's numbers)
    const Quaternionr prevOri(prevTrsf);
    const Matrix3r midTrsf = ((approxMask & 1) ? prevOri : prevOri.slerp(0.5, Quaternionr(trsf))).toRotationMatrix();
    g.u += localframe::times(midTrsf, relVel) * dt;
    g.u[0] = uN; // not incremental
    if (l6) static_cast<L6Geom&>(g).phi += localframe::times(midTrsf, dt * (k2.angVel - k1.angVel));
    g.trsf = trsf;
    g.contactPoint = contPt;
    g.normal = normal;
    g.refR1 = r1;
    g.refR2 = r2;
}

} // namespace yade
