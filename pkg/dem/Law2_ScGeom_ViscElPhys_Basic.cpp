#include <cmath>
#include <core/BodyStore.hpp>
#include <core/Scene.hpp>
#include <pkg/dem/Law2_ScGeom_ViscElPhys_Basic.hpp>

namespace yade {

bool Law2_ScGeom_ViscElPhys_Basic::go(ScGeom& geom, ViscElPhys& phys, const Contact& c) {
    const Real u = geom.penetrationDepth;
    if (u < 0) return false; // the bodies separated
    const Real dt = scene->dt;
    const BodyStore::Columns b = scene->bodies.hot().columns();
    const Vector3r n = geom.normal, cp = geom.contactPoint;
    const Vector3r arm1 = cp - b.pos[c.id1], arm2 = cp - b.pos[c.id2];
    const Vector3r spin1 = b.angVel[c.id1].cross(arm1), spin2 = b.angVel[c.id2].cross(arm2);
    const Vector3r relVel = (b.vel[c.id2] + spin2) - (b.vel[c.id1] + spin1); // of body 2's surface, at the contact point

    // normal: spring and dashpot in parallel; nothing while they pull (the contact is kept)
    const Real vn = relVel.dot(n);
    phys.Fn = phys.kn * u;
    phys.Fv = -phys.cn * vn;
    const Real fn = phys.Fn + phys.Fv;
    if (fn <= 0) {
        phys.normalForce = phys.shearForce = Vector3r::Zero();
        return true;
    }
    phys.normalForce = fn * n;

    // shear: the elastic part (kept in shearForce) capped at tan(φ)·fn; the dashpot acts while it sticks
    const Vector3r shearVel = relVel - vn * n;
    Vector3r elastic = geom.rotated(phys.shearForce) - phys.ks * dt * shearVel;
    Vector3r shear;
    const Real maxFs = fn * phys.tangensOfFrictionAngle;
    if (elastic.squaredNorm() > maxFs * maxFs) { // sliding
        elastic *= maxFs / elastic.norm();
        shear = elastic;
    } else {
        shear = elastic - phys.cs * shearVel;
    }
    phys.shearForce = elastic;

    const Vector3r f1 = -(phys.normalForce + shear); // on body 1
    Vector3r t1 = arm1.cross(f1), t2 = arm2.cross(-f1);
    if (phys.mR > 0) { // rolling resistance, against the relative spin: mRtype 1 mR·fn·Δω, mRtype 2 also times |Δ(ω × arm)|
        const Vector3r dw = b.angVel[c.id1] - b.angVel[c.id2];
        const Real k = phys.mR * fn * (phys.mRtype == 2 ? (spin1 - spin2).norm() : 1);
        t1 -= k * dw;
        t2 += k * dw;
    }
    scene->forces.addContact(c.id1, c.id2, f1, t1, t2);
    return true;
}

} // namespace yade
