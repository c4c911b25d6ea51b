#include <pkg/dem/ScGeom.hpp>

namespace yade {

void ScGeom::precompute(const Kinematics& s1, const Kinematics& s2, Real dt, const Vector3r& currentNormal, bool isNew,
        const Vector3r& shift2, bool avoidRatcheting) {
    if (isNew) {
        orthonormalAxis = twistAxis = Vector3r::Zero();
    } else {
        orthonormalAxis = normal.cross(currentNormal);                    // tilt
        twistAxis = (dt * 0.5 * normal.dot(s1.angVel + s2.angVel)) * normal; // twist
    }
    normal = currentNormal;
    Vector3r relVel;
    if (avoidRatcheting) {
        // Points as if the spheres kept their reference radii (no granular ratcheting): lever arms
        // refR1, refR2, and the translational part scaled by (r1+r2)/distance accordingly.
        const Vector3r c1x = refR1 * normal, c2x = -refR2 * normal;
        const Real alpha = (refR1 + refR2) / (refR1 + refR2 - penetrationDepth);
        relVel = (s2.vel - s1.vel) * alpha + s2.angVel.cross(c2x) - s1.angVel.cross(c1x);
    } else { // material points of both bodies at the contact point
        const Vector3r c1x = contactPoint - s1.pos, c2x = contactPoint - (s2.pos + shift2);
        relVel = (s2.vel + s2.angVel.cross(c2x)) - (s1.vel + s1.angVel.cross(c1x));
    }
    relVel -= normal.dot(relVel) * normal; // shear part only
    shearInc = relVel * dt;
}

} // namespace yade
