#include <cmath>
#include <core/Scene.hpp>
#include <pkg/dem/Law2_ScGeom_MindlinPhys_HertzWithLinearShear.hpp>

namespace yade {

bool Law2_ScGeom_MindlinPhys_HertzWithLinearShear::go(ScGeom& geom, MindlinPhys& phys, const Contact& c) {
    const Real u = geom.penetrationDepth;
    if (u < 0) { // the bodies separated
        if (!neverErase) return false;
        phys.normalForce = phys.shearForce = Vector3r::Zero();
        return true;
    }
    const Vector3r n = geom.normal;
    const Real fn = phys.kno * std::pow(u, 1.5); // (so, not kno·sqrt(u)·u: the reference's bits)
    phys.normalForce = fn * n;
    const Real ks = nonLin > 0 ? phys.kso * std::sqrt(u) : phys.kso;
    Vector3r fs = geom.rotated(phys.shearForce) - ks * geom.shearInc;
    const Real maxFs = phys.tangensOfFrictionAngle * fn;
    if (fs.squaredNorm() > maxFs * maxFs) fs *= maxFs / fs.norm(); // sliding
    phys.shearForce = fs;
    const BodyStore::Columns b = scene->bodies.hot().columns();
    const Vector3r f1 = -(phys.normalForce + fs); // on body 1
    const Vector3r cp = geom.contactPoint;
    scene->forces.addContact(c.id1, c.id2, f1, (cp - b.pos[c.id1]).cross(f1), (cp - b.pos[c.id2]).cross(-f1));
    return true;
}

} // namespace yade
