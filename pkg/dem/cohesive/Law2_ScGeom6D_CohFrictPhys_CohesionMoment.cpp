#include <atomic>
#include <core/Scene.hpp>
#include <iostream>
#include <pkg/dem/cohesive/Law2_ScGeom6D_CohFrictPhys_CohesionMoment.hpp>
#include <stdexcept>

namespace yade {

void Law2_ScGeom6D_CohFrictPhys_CohesionMoment::prepare() {
    if (shear_creep || twist_creep)
        throw std::runtime_error(getClassName() + ": shear_creep and twist_creep are not implemented in this engine; set them to False");
    plastId = scene && (scene->trackEnergy || traceEnergy) ? scene->energy.term("plastDissip", true) : -1;
}

void Law2_ScGeom6D_CohFrictPhys_CohesionMoment::dissipate(Real e) {
    if (plastId >= 0 && e > 0) scene->energy.add(plastId, e);
}

bool Law2_ScGeom6D_CohFrictPhys_CohesionMoment::go(ScGeom6D& geom, CohFrictPhys& phys, const Contact& c) {
    const Vector3r& n = geom.normal;
    const Real un = geom.penetrationDepth;
    // normal: positive in compression; the bond holds up to normalAdhesion in tension
    Real fn = phys.kn * (un - phys.unp);
    if (-fn > phys.normalAdhesion) {
        if (phys.fragile) return false; // the contact ends (no bond: normalAdhesion is 0 and any tension ends it)
        fn = -phys.normalAdhesion; // perfectly plastic
        phys.unp = un + phys.normalAdhesion / phys.kn;
        if (phys.unpMax >= 0 && -phys.unp > phys.unpMax) return false;
    }
    phys.normalForce = fn * n;
    // shear: incremental (3.3.2), Mohr-Coulomb with adhesion
    Vector3r& fs = phys.shearForce;
    fs = geom.rotated(fs) - phys.ks * geom.shearInc;
    Real maxFs = phys.shearAdhesion;
    if (!phys.cohesionDisablesFriction || maxFs == 0) maxFs += fn * phys.tangensOfFrictionAngle;
    maxFs = std::max<Real>(0, maxFs);
    const Real fs2 = fs.squaredNorm();
    if (fs2 > maxFs * maxFs) {
        if (phys.fragile && !phys.cohesionBroken) {
            breakBond(phys);
            maxFs = std::max<Real>(0, fn * phys.tangensOfFrictionAngle);
        }
        const Vector3r trial = fs;
        fs *= maxFs / std::sqrt(fs2);
        if (plastId >= 0 && phys.ks > 0) dissipate((trial - fs).dot(fs) / phys.ks);
        if (fn < 0) phys.normalForce = Vector3r::Zero(); // (a sliding contact does not pull)
    }
    const Vector3r f1 = -phys.normalForce - fs; // on body 1
    const Vector3r arm = n.cross(f1);
    Vector3r t1 = (geom.refR1 - 0.5 * un) * arm, t2 = (geom.refR2 - 0.5 * un) * arm;
    if (phys.momentRotationLaw && (!phys.cohesionBroken || always_use_moment_law)) {
        const Vector3r m = moments(geom, phys, c);
        t1 -= m;
        t2 += m;
    }
    scene->forces.addContact(c.id1, c.id2, f1, t1, t2);
    return true;
}

Vector3r Law2_ScGeom6D_CohFrictPhys_CohesionMoment::moments(const ScGeom6D& geom, CohFrictPhys& phys, const Contact& c) {
    const Vector3r& n = geom.normal;
    if (!useIncrementalForm) {
        phys.moment_twist = (geom.twist * phys.ktw) * n;
        phys.moment_bending = geom.bending * phys.kr;
    } else {
        const BodyStore::Columns cols = scene->bodies.hot().columns();
        const Vector3r relAngVel = cols.angVel[c.id2] - cols.angVel[c.id1];
        const Vector3r twistVel = relAngVel.dot(n) * n, bendVel = relAngVel - twistVel;
        phys.moment_twist = geom.rotated(phys.moment_twist) - phys.ktw * twistVel * scene->dt;
        phys.moment_bending = geom.rotated(phys.moment_bending) - phys.kr * bendVel * scene->dt;
    }
    const Real fn = phys.normalForce.norm();
    const Real plastic = capMoment(phys.moment_bending, phys.maxRollPl, fn, phys.kr) + capMoment(phys.moment_twist, phys.maxTwistPl, fn, phys.ktw);
    if (plastic > 0) {
        if (plastId >= 0) dissipate(plastic);
        if (!useIncrementalForm) {
            static std::atomic<bool> warned{false};
            if (!warned.exchange(true))
                std::cerr << "WARNING: " << getClassName() << ": with useIncrementalForm false, capped moments are not irreversible "
                          << "(the total form forgets the plastic rotation); use useIncrementalForm=True for rolling/twisting plasticity\n";
        }
    }
    return phys.moment_twist + phys.moment_bending;
}

Real Law2_ScGeom6D_CohFrictPhys_CohesionMoment::capMoment(Vector3r& m, Real maxPl, Real fn, Real stiffness) {
    if (maxPl < 0) return 0; // elastic
    const Real max = maxPl * fn, norm = m.norm();
    if (norm <= max) return 0;
    const Vector3r trial = m;
    m *= norm > 0 ? max / norm : 0;
    return stiffness > 0 ? (trial - m).dot(m) / stiffness : 0;
}

} // namespace yade
