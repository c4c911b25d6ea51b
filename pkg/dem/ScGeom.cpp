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

} // namespace yade
