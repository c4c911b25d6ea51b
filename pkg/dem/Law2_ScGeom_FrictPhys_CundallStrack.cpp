#include <core/Scene.hpp>
#include <pkg/dem/Law2_ScGeom_FrictPhys_CundallStrack.hpp>

namespace yade {

void Law2_ScGeom_FrictPhys_CundallStrack::prepare() {
    if (!scene->trackEnergy) return;
    elastId = scene->energy.term("elastPotential", false);
    plastId = scene->energy.term("plastDissip", true);
}

bool Law2_ScGeom_FrictPhys_CundallStrack::go(ScGeom& geom, FrictPhys& phys, const Contact& c) {
    if (geom.penetrationDepth < 0) { // the bodies separated
        if (!neverErase) return false;
        phys.normalForce = phys.shearForce = Vector3r::Zero();
        return true;
    }
    // (in locals, stored once: see ScGeom::rotated)
    const Vector3r normalForce = phys.kn * geom.penetrationDepth * geom.normal;
    phys.normalForce = normalForce;
    Vector3r shearForce = geom.rotated(phys.shearForce) - phys.ks * geom.shearInc; // trial shear force
    const Real maxFs2 = normalForce.squaredNorm() * phys.tangensOfFrictionAngle * phys.tangensOfFrictionAngle;
    if (shearForce.squaredNorm() > maxFs2) { // sliding: Mohr-Coulomb return
        const Vector3r trial = shearForce;
        shearForce *= std::sqrt(maxFs2) / shearForce.norm();
        if (scene->trackEnergy) {
            const Real dissipated = (trial - shearForce).dot(shearForce) / phys.ks;
            if (dissipated > 0) scene->energy.add(plastId, dissipated); // frictionless contacts dissipate nothing
        }
    }
    phys.shearForce = shearForce;
    if (scene->trackEnergy)
        scene->energy.add(elastId, 0.5 * (normalForce.squaredNorm() / phys.kn + (phys.ks > 0 ? shearForce.squaredNorm() / phys.ks : 0)));
    const Vector3r force = -normalForce - shearForce; // on body 1
    const Vector3r arm = geom.normal.cross(force);
    scene->forces.addContact(c.id1, c.id2, force, (geom.refR1 - 0.5 * geom.penetrationDepth) * arm,
            (geom.refR2 - 0.5 * geom.penetrationDepth) * arm);
    return true;
}

} // namespace yade
