#include <cmath>
#include <core/Scene.hpp>
#include <pkg/dem/Law2_ScGeom_MindlinPhys_Mindlin.hpp>

namespace yade {

namespace {
void atomicAdd(Real& target, Real x) {
#pragma omp atomic
    target += x;
}
} // namespace

void Law2_ScGeom_MindlinPhys_Mindlin::prepare() { shearEnergyIter.v = -1; }

void Law2_ScGeom_MindlinPhys_Mindlin::startShearEnergySum(long long iter) {
    if (shearEnergyIter.v.load(std::memory_order_acquire) == iter) return;
#pragma omp critical(mindlinShearEnergy)
    if (shearEnergyIter.v.load(std::memory_order_relaxed) != iter) {
        shearEnergy = 0;
        shearEnergyIter.v.store(iter, std::memory_order_release);
    }
}

template <class F> static void forEachMindlin(const Scene& s, F f) {
    const InteractionContainer& ic = s.interactions;
    for (size_t k = 0; k < ic.size(); ++k)
        if (ic.isReal(k))
            if (const auto* p = dynamic_cast<const MindlinPhys*>(ic.phys(k))) f(*p, ic.geom(k));
}

Real Law2_ScGeom_MindlinPhys_Mindlin::normElastEnergy(const Scene& s) {
    Real e = 0;
    forEachMindlin(s, [&](const MindlinPhys& p, const IGeom* g) {
        const Real u = static_cast<const ScGeom*>(g)->penetrationDepth;
        if (u > 0) e += 0.4 * p.kno * std::pow(u, 2.5);
    });
    return e;
}

Real Law2_ScGeom_MindlinPhys_Mindlin::ratioSlidingContacts(const Scene& s) {
    long all = 0, sliding = 0;
    forEachMindlin(s, [&](const MindlinPhys& p, const IGeom*) {
        ++all;
        sliding += p.isSliding;
    });
    return all ? Real(sliding) / all : 0;
}

long Law2_ScGeom_MindlinPhys_Mindlin::contactsAdhesive(const Scene& s) {
    long n = 0;
    forEachMindlin(s, [&](const MindlinPhys& p, const IGeom*) { n += p.isAdhesive; });
    return n;
}

bool Law2_ScGeom_MindlinPhys_Mindlin::go(ScGeom& geom, MindlinPhys& phys, const Contact& c) {
    const Real u = geom.penetrationDepth;
    if (u < 0) { // the bodies separated
        if (!neverErase) return false;
        phys.normalForce = phys.shearForce = phys.normalViscous = phys.shearViscous = Vector3r::Zero();
        phys.kn = phys.ks = 0;
        return true;
    }
    const Scene& s = *scene;
    const Real dt = s.dt;
    const BodyStore::Columns b = const_cast<Scene&>(s).bodies.hot().columns();
    const Vector3r n = geom.normal, cp = geom.contactPoint;
    const Vector3r x1 = b.pos[c.id1], x2 = b.pos[c.id2];
    const Real sqrtU = std::sqrt(u);
    const Real mbar = effectiveMass(b, c.id1, c.id2);
    phys.kn = 1.5 * phys.kno * sqrtU; // tangent stiffnesses
    phys.ks = phys.kso * sqrtU;

    // normal: elastic (Hertz) minus viscous; cut at zero (no attraction) unless adhesive
    const Vector3r relVel = (b.vel[c.id2] + b.angVel[c.id2].cross(cp - x2)) - (b.vel[c.id1] + b.angVel[c.id1].cross(cp - x1));
    const Real vn = relVel.dot(n);
    const Real fnElastic = phys.kno * u * sqrtU;
    const Real cn = phys.betan > 0 ? 2 * phys.betan * std::sqrt(mbar * phys.kn) : 0;
    phys.normalViscous = (cn * vn) * n;
    Real fn = fnElastic - cn * vn;
    if (includeAdhesion) {
        fn -= phys.extra.get().adhesionForce;
        phys.isAdhesive = fn < 0;
    } else if (fn < 0) {
        fn = 0;
    }
    phys.normalForce = fn * n;

    // shear: incremental elastic part, Coulomb limit, viscous part while sticking
    const Vector3r shearInc = geom.shearInc;
    Vector3r fsElastic = geom.rotated(phys.shearElastic) - phys.ks * shearInc;
    phys.usTotal = geom.rotated(phys.usTotal) - shearInc;
    Vector3r usElastic = geom.rotated(phys.usElastic) - shearInc;
    const Real fnForFriction = includeAdhesion ? fn + phys.extra.get().adhesionForce : fn;
    const Real maxFs = phys.tangensOfFrictionAngle * std::max(fnForFriction, Real(0));
    const Real fsNorm = fsElastic.norm();
    Vector3r shearForce;
    if (fsNorm > maxFs) { // sliding
        const Real ratio = fsNorm > 0 ? maxFs / fsNorm : 0;
        if (calcEnergy) atomicAdd(frictionDissipation, (fsElastic * (1 - ratio)).dot(fsElastic * ratio) / std::max(phys.ks, Real(1e-300)));
        fsElastic *= ratio;
        usElastic *= ratio;
        phys.isSliding = true;
        phys.shearViscous = Vector3r::Zero();
        shearForce = fsElastic;
    } else {
        phys.isSliding = false;
        const Real cs = phys.betas > 0 ? 2 * phys.betas * std::sqrt(mbar * phys.ks) : 0;
        phys.shearViscous = cs * (shearInc / dt);
        shearForce = fsElastic - phys.shearViscous;
    }
    phys.shearElastic = fsElastic;
    phys.usElastic = usElastic;
    phys.shearForce = shearForce;

    if (calcEnergy) {
        startShearEnergySum(s.iter);
        if (phys.ks > 0) atomicAdd(shearEnergy, 0.5 * fsElastic.squaredNorm() / phys.ks);
        atomicAdd(normDampDissip, std::abs(cn * vn * vn) * dt);
        atomicAdd(shearDampDissip, std::abs(phys.shearViscous.dot(shearInc)));
    }

    const Vector3r f1 = -(phys.normalForce + shearForce); // on body 1
    Vector3r t1 = (cp - x1).cross(f1), t2 = (cp - x2).cross(-f1);
    if (includeMoment) {
        const Vector3r relRot = (b.angVel[c.id2] - b.angVel[c.id1]) * dt;
        const Vector3r twist = relRot.dot(n) * n, bend = relRot - twist;
        MindlinPhys::Extra& x = phys.extra.edit();
        x.momentTwist = geom.rotated(x.momentTwist) - x.ktw * twist;
        x.momentBend = geom.rotated(x.momentBend) - x.kr * bend;
        if (x.maxBendPl > 0) {
            const Real maxBend = x.maxBendPl * std::abs(fn);
            const Real m = x.momentBend.norm();
            if (m > maxBend) x.momentBend *= maxBend / m;
        }
        t1 -= x.momentBend + x.momentTwist;
        t2 += x.momentBend + x.momentTwist;
    }
    scene->forces.addContact(c.id1, c.id2, f1, t1, t2);
    return true;
}

} // namespace yade
