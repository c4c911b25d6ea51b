#include <algorithm>
#include <cmath>
#include <core/Scene.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/concrete/CpmState.hpp>
#include <pkg/dem/concrete/Law2_ScGeom_CpmPhys_Cpm.hpp>

namespace yade {

void Law2_ScGeom_CpmPhys_Cpm::initialize(const ScGeom& geom, CpmPhys& phys, const Contact& c) const {
    const BodyContainer& bodies = scene->bodies;
    const bool spheres = dynamic_cast<const Sphere*>(bodies[c.id1]->shape.get()) && dynamic_cast<const Sphere*>(bodies[c.id2]->shape.get());
    if (spheres) { // (3.3.2): the distance of the centers, the smaller radius
        const BodyStore::Columns cols = scene->bodies.hot().columns();
        const Vector3r shift2 = c.shift ? c.shift->shift2 : Vector3r::Zero();
        const Real r1 = geom.refR1, r2 = geom.refR2;
        const Real minRad = r1 <= 0 ? r2 : r2 <= 0 ? r1 : std::min(r1, r2);
        phys.refLength = (cols.pos[c.id2] - cols.pos[c.id1] + shift2).norm();
        phys.crossSection = Mathr_PI * (minRad * minRad);
        phys.refPD = r1 + r2 - phys.refLength;
    } else { // a sphere against a facet, a wall...: the sphere's radius
        const auto* s1 = dynamic_cast<const Sphere*>(bodies[c.id1]->shape.get());
        const auto* s2 = dynamic_cast<const Sphere*>(bodies[c.id2]->shape.get());
        if (!s1 && !s2)
            throw std::runtime_error("Law2_ScGeom_CpmPhys_Cpm: contact ##" + std::to_string(c.id1) + "+" + std::to_string(c.id2) +
                                     " has no sphere (the law needs at least one)");
        const Real rad = (s1 ? s1 : s2)->radius;
        phys.refLength = rad;
        phys.crossSection = Mathr_PI * (rad * rad);
        phys.refPD = 0;
    }
    phys.kn = phys.crossSection * phys.E / phys.refLength;
    phys.ks = phys.crossSection * phys.G / phys.refLength;
    phys.epsFracture = phys.relDuctility * phys.epsCrackOnset;
}

Real Law2_ScGeom_CpmPhys_Cpm::yieldSigmaTMagnitude(Real sigmaN, Real omega, Real undamagedCohesion, Real tanFrictionAngle) {
    return std::max(Real(0), undamagedCohesion * (1 - omega) - sigmaN * tanFrictionAngle); // Mohr-Coulomb, cohesion lowered by damage
}

bool Law2_ScGeom_CpmPhys_Cpm::go(ScGeom& geom, CpmPhys& phys, const Contact& c) {
    if (std::isnan(phys.refLength)) initialize(geom, phys, c);

    phys.epsN = -(-phys.refPD + geom.penetrationDepth) / phys.refLength;
    geom.rotate(phys.epsT);
    phys.epsT += geom.shearInc / phys.refLength;

    phys.epsN += phys.isoPrestress / phys.E;
    phys.kappaD = std::max(std::max(Real(0), phys.epsN), phys.kappaD); // the largest tensile strain so far
    phys.omega = phys.isCohesive ? CpmPhys::funcG(phys.kappaD, phys.epsCrackOnset, phys.epsFracture, phys.neverDamage, phys.damLaw) : 1;
    phys.sigmaN = (1 - (phys.epsN > 0 ? phys.omega : 0)) * phys.E * phys.epsN; // damage acts in tension only
    phys.sigmaT = phys.G * phys.epsT;
    const Real yieldSigmaT = yieldSigmaTMagnitude(phys.sigmaN, phys.omega, phys.undamagedCohesion, phys.tanFrictionAngle);
    if (phys.sigmaT.squaredNorm() > yieldSigmaT * yieldSigmaT) phys.sigmaT *= yieldSigmaT / phys.sigmaT.norm(); // back onto the surface
    // the stress that the bond still carries at kappaD, relative to its strength (1 before the crack onset)
    phys.relResidualStrength = !phys.isCohesive ? 0 : phys.kappaD < phys.epsCrackOnset ? 1 : (1 - phys.omega) * phys.kappaD / phys.epsCrackOnset;
    phys.sigmaN -= phys.isoPrestress;

    if (phys.epsN > 0 && (!phys.isCohesive || phys.omega > omegaThreshold)) { // broken in tension (not cohesive: at once), counted
        countBroken(c.id1);
        countBroken(c.id2);
        return false;
    }
    phys.Fn = phys.sigmaN * phys.crossSection;
    phys.normalForce = -phys.Fn * geom.normal;
    phys.Fs = phys.sigmaT * phys.crossSection;
    phys.shearForce = -phys.Fs;

    const Vector3r force = -phys.normalForce - phys.shearForce; // on body 1
    if (scene->isPeriodic) {
        const Vector3r arm = geom.normal.cross(force);
        scene->forces.addContact(c.id1, c.id2, force, (geom.refR1 - geom.penetrationDepth / 2) * arm, (geom.refR2 - geom.penetrationDepth / 2) * arm);
    } else {
        const BodyStore::Columns cols = scene->bodies.hot().columns();
        scene->forces.addContact(c.id1, c.id2, force, (geom.contactPoint - cols.pos[c.id1]).cross(force),
                (geom.contactPoint - cols.pos[c.id2]).cross(-force));
    }
    return true;
}

void Law2_ScGeom_CpmPhys_Cpm::countBroken(Body::id_t id) const {
    if (auto* s = dynamic_cast<CpmState*>(scene->bodies[id]->state.get())) {
#pragma omp atomic
        s->numBrokenCohesive += 1;
    }
}

Real Law2_ScGeom_CpmPhys_Cpm::elasticEnergy(const Scene& scene) {
    const InteractionContainer& ic = scene.interactions;
    Real e = 0;
    for (size_t k = 0; k < ic.size(); ++k)
        if (ic.isReal(k))
            if (const auto* p = dynamic_cast<const CpmPhys*>(ic.phys(k)))
                e += 0.5 * (p->normalForce.squaredNorm() / p->kn + (p->ks > 0 ? p->shearForce.squaredNorm() / p->ks : 0));
    return e;
}

} // namespace yade
