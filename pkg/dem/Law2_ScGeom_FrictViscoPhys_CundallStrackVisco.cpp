#include <algorithm>
#include <core/BodyStore.hpp>
#include <core/Scene.hpp>
#include <pkg/dem/Law2_ScGeom_FrictViscoPhys_CundallStrackVisco.hpp>

namespace yade {

namespace {
void atomicAdd(Real& target, Real x) {
#pragma omp atomic
    target += x;
}
} // namespace

void Law2_ScGeom_FrictViscoPhys_CundallStrackVisco::prepare() {
    if (scene->trackEnergy || traceEnergy) elastId = scene->energy.term("elastPotential", false);
    if (scene->trackEnergy && !traceEnergy) plastId = scene->energy.term("plastDissip", true);
}

Real Law2_ScGeom_FrictViscoPhys_CundallStrackVisco::elasticEnergy(const Scene& scene) {
    const InteractionContainer& ic = scene.interactions;
    Real e = 0;
    for (size_t k = 0; k < ic.size(); ++k)
        if (ic.isReal(k))
            if (const auto* p = dynamic_cast<const FrictViscoPhys*>(ic.phys(k)))
                e += 0.5 * (p->normalForce.squaredNorm() / p->kn + (p->ks > 0 ? p->shearForce.squaredNorm() / p->ks : 0));
    return e;
}

bool Law2_ScGeom_FrictViscoPhys_CundallStrackVisco::go(ScGeom& geom, FrictViscoPhys& phys, const Contact& c) {
    Real u = geom.penetrationDepth;
    if (u < 0) { // the bodies separated: the contact ends, or, kept, the shear spring restarts and the normal one does nothing
        if (!neverErase) return false;
        phys.normalForce = phys.shearForce = Vector3r::Zero();
    }
    const BodyStore::Columns b = scene->bodies.hot().columns();
    const Vector3r n = geom.normal;
    const Real r1 = geom.refR1, r2 = geom.refR2;
    // the relative velocity of points at the reference radii (ScGeom::precompute's, with avoidRatcheting)
    const Vector3r v = (b.vel[c.id2] - b.vel[c.id1]) * ((r1 + r2) / (r1 + r2 - u)) + b.angVel[c.id2].cross(-r2 * n) - b.angVel[c.id1].cross(r1 * n);
    const Vector3r shearOld = geom.rotated(phys.shearForce), du = geom.shearInc;
    Real normalForce[3], normalViscous[3], shearForce[3], dissipated;
    kernel<Real>(n.data(), std::max(u, Real(0)), v.data(), shearOld.data(), du.data(), phys.kn, phys.ks, phys.cn, phys.tangensOfFrictionAngle,
            normalForce, normalViscous, shearForce, dissipated);
    const Vector3r fn(normalForce[0], normalForce[1], normalForce[2]), fs(shearForce[0], shearForce[1], shearForce[2]);
    phys.normalViscous = Vector3r(normalViscous[0], normalViscous[1], normalViscous[2]);
    phys.normalForce = fn;
    phys.shearForce = fs;

    if (dissipated > 0) {
        if (traceEnergy) atomicAdd(plasticDissipation, dissipated);
        else if (scene->trackEnergy) scene->energy.add(plastId, dissipated);
    }
    if (scene->trackEnergy || traceEnergy)
        scene->energy.add(elastId, 0.5 * (fn.squaredNorm() / phys.kn + (phys.ks > 0 ? fs.squaredNorm() / phys.ks : 0)));

    const Vector3r force = -fn - fs; // on body 1
    if (sphericalBodies) {
        const Vector3r arm = n.cross(force);
        scene->forces.addContact(c.id1, c.id2, force, (r1 - 0.5 * u) * arm, (r2 - 0.5 * u) * arm);
    } else {
        const Vector3r cp = geom.contactPoint;
        scene->forces.addContact(c.id1, c.id2, force, (cp - b.pos[c.id1]).cross(force), (cp - b.pos[c.id2]).cross(-force));
    }
    return true;
}

} // namespace yade
