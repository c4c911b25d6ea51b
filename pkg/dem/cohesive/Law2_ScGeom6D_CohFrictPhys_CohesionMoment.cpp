#include <atomic>
#include <core/Scene.hpp>
#include <iostream>
#include <pkg/dem/cohesive/Law2_ScGeom6D_CohFrictPhys_CohesionMoment.hpp>
#include <stdexcept>

namespace yade {

void Law2_ScGeom6D_CohFrictPhys_CohesionMoment::prepare() {
    if (twist_creep) throw std::runtime_error(getClassName() + ": twist_creep is not implemented in this engine; set it to False");
    if (shear_creep && !(creep_viscosity > 0))
        throw std::invalid_argument(getClassName() + ": shear_creep needs a positive creep_viscosity, got " + std::to_string(creep_viscosity));
    const bool track = scene && scene->trackEnergy;
    shearId = track ? scene->energy.term("shearDissip", true) : -1;
    bendingId = track ? scene->energy.term("bendingDissip", true) : -1;
    twistId = track ? scene->energy.term("twistDissip", true) : -1;
}

void Law2_ScGeom6D_CohFrictPhys_CohesionMoment::dissipate(int term, Real e) {
    if (term >= 0) scene->energy.add(term, e);
}

Real Law2_ScGeom6D_CohFrictPhys_CohesionMoment::elasticEnergy(const Scene& scene, Spring which) {
    const auto half = [](const Vector3r& f, Real k) { return k > 0 ? 0.5 * f.squaredNorm() / k : 0; };
    const InteractionContainer& ic = scene.interactions;
    Real e = 0;
    for (size_t k = 0; k < ic.size(); ++k) {
        if (!ic.isReal(k)) continue;
        const auto* p = dynamic_cast<const CohFrictPhys*>(ic.phys(k));
        if (!p) continue;
        if (which == Spring::normal || which == Spring::all) e += half(p->normalForce, p->kn);
        if (which == Spring::shear || which == Spring::all) e += half(p->shearForce, p->ks);
        if (which == Spring::bending || which == Spring::all) e += half(p->moment_bending, p->kr);
        if (which == Spring::twist || which == Spring::all) e += half(p->moment_twist, p->ktw);
    }
    return e;
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
    fs = geom.rotated(fs);
    if (shear_creep) fs -= phys.ks * fs * (scene->dt / creep_viscosity); // the elastic shear displacement creeps: du/dt = -Fs/creep_viscosity
    fs -= phys.ks * geom.shearInc;
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
        if ((traceEnergy || shearId >= 0) && phys.ks > 0) {
            const Real e = (trial - fs).dot(fs) / phys.ks;
#pragma omp atomic
            plasticDissipation += e;
            dissipate(shearId, e);
        }
        if (fn < 0) phys.normalForce = Vector3r::Zero(); // (a sliding contact does not pull)
    }
    // on body 1, at the contact point (a sphere's lever arm is (R - u/2)·n; a facet's, from its centre)
    const Vector3r f1 = -phys.normalForce - fs;
    const BodyStore::Columns cols = scene->bodies.hot().columns();
    const Vector3r pos2 = c.shift ? Vector3r(cols.pos[c.id2] + c.shift->shift2) : Vector3r(cols.pos[c.id2]);
    Vector3r t1 = (geom.contactPoint - cols.pos[c.id1]).cross(f1), t2 = (geom.contactPoint - pos2).cross(-f1);
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
    const Real bending = capMoment(phys.moment_bending, phys.maxRollPl, fn, phys.kr), twist = capMoment(phys.moment_twist, phys.maxTwistPl, fn, phys.ktw);
    if (bending > 0 || twist > 0) {
        dissipate(bendingId, bending);
        dissipate(twistId, twist);
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
