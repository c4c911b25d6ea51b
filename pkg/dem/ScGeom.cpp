#include <pkg/dem/ScGeom.hpp>

namespace yade {

void ScGeom::precompute(const Kinematics& s1, const Kinematics& s2, Real dt, const Vector3r& currentNormal, bool isNew,
        const Vector3r& shift2, bool avoidRatcheting) {
    Values<Real> g = Values<Real>::of(*this);
    const Vec3<Real> oldNormal = g.normal;
    g.normal = vec3(currentNormal);
    const PairMotion<Real> m{vec3(s1.pos), vec3(s2.pos), vec3(s1.vel), vec3(s2.vel), vec3(s1.angVel), vec3(s2.angVel)};
    g.precompute(oldNormal, isNew, m, dt, avoidRatcheting, vec3(shift2));
    g.store(*this);
}

Vector3r ScGeom::incidentVel(const Kinematics& s1, const Kinematics& s2, const Vector3r& shift2, const Vector3r& shiftVel2, bool avoidRatcheting) const {
    const Vector3r vel2 = s2.vel + shiftVel2;
    if (avoidRatcheting) {
        const Real alpha = (refR1 + refR2) / (refR1 + refR2 - penetrationDepth);
        return (vel2 - s1.vel) * alpha + s2.angVel.cross(-refR2 * normal) - s1.angVel.cross(refR1 * normal);
    }
    return (vel2 + s2.angVel.cross(contactPoint - (s2.pos + shift2))) - (s1.vel + s1.angVel.cross(contactPoint - s1.pos));
}

} // namespace yade
