#include <pkg/dem/ScGeom.hpp>

namespace yade {

void ScGeom::precompute(const Kinematics& s1, const Kinematics& s2, Real dt, const Vector3r& currentNormal, bool isNew,
        const Vector3r& shift2, bool avoidRatcheting) {
    // (members read once into locals and written once: see rotated())
    const Vector3r n = currentNormal, oldNormal = normal;
    if (isNew) {
        orthonormalAxis = twistAxis = Vector3r::Zero();
    } else {
        orthonormalAxis = oldNormal.cross(n);                                   // tilt
        twistAxis = (dt * 0.5 * oldNormal.dot(s1.angVel + s2.angVel)) * oldNormal; // twist
    }
    normal = n;
    Vector3r relVel;
    if (avoidRatcheting) {
        // Points as if the spheres kept their reference radii (no granular ratcheting): lever arms
        // refR1, refR2, and the translational part scaled by (r1+r2)/distance accordingly.
        const Real r1 = refR1, r2 = refR2;
        const Vector3r c1x = r1 * n, c2x = -r2 * n;
        const Real alpha = (r1 + r2) / (r1 + r2 - penetrationDepth);
        relVel = (s2.vel - s1.vel) * alpha + s2.angVel.cross(c2x) - s1.angVel.cross(c1x);
    } else { // material points of both bodies at the contact point
        const Vector3r c1x = contactPoint - s1.pos, c2x = contactPoint - (s2.pos + shift2);
        relVel = (s2.vel + s2.angVel.cross(c2x)) - (s1.vel + s1.angVel.cross(c1x));
    }
    relVel -= n.dot(relVel) * n; // shear part only
    shearInc = relVel * dt;
}

} // namespace yade
