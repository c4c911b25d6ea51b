#include <pkg/dem/ScGeom.hpp>

namespace yade {

void ScGeom::precompute(const State& s1, const State& s2, Real dt, const Vector3r& currentNormal, bool isNew,
        const Vector3r& shiftVel) {
    if (isNew) {
        orthonormalAxis = twistAxis = Vector3r::Zero();
    } else {
        orthonormalAxis = normal.cross(currentNormal);                    // tilt
        twistAxis = (dt * 0.5 * normal.dot(s1.angVel + s2.angVel)) * normal; // twist
    }
    normal = currentNormal;
    // Relative velocity at the contact point with constant lever arms refR1, refR2 (no
    // dependence on the overlap, which avoids granular ratcheting).
    const Vector3r c1x = refR1 * normal, c2x = -refR2 * normal;
    Vector3r relVel = (s2.vel + shiftVel + s2.angVel.cross(c2x)) - (s1.vel + s1.angVel.cross(c1x));
    relVel -= normal.dot(relVel) * normal; // shear part only
    shearInc = relVel * dt;
}

} // namespace yade
