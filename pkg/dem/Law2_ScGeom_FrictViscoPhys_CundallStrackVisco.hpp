// The Cundall-Strack contact law with viscous damping in the normal direction (FrictViscoPM): a
// linear spring and a dashpot in parallel in the normal direction, an incremental shear spring
// with Mohr-Coulomb sliding capped by the whole normal force.
#pragma once
#include <core/ContactKernel.hpp>
#include <pkg/dem/FrictViscoPhys.hpp>
#include <pkg/dem/ScGeom.hpp>

namespace yade {

class Law2_ScGeom_FrictViscoPhys_CundallStrackVisco
        : public LawKernelFunctor<Law2_ScGeom_FrictViscoPhys_CundallStrackVisco, ScGeom, FrictViscoPhys> {
public:
    static constexpr const char* classDoc =
            "Constitutive law for the FrictViscoPM: Law2_ScGeom_FrictPhys_CundallStrack with viscous damping in the normal direction. "
            "normalViscous = cn·v_n·n (v_n: the normal relative velocity, of points at the reference radii, negative while approaching), "
            "normalForce = kn·u·n - normalViscous in compression and in extension (it may pull); the shear force, "
            "rotated(Fs) - ks·Δus, is capped at |normalForce|·tan φ. With neverErase, bodies that separated keep the contact: no "
            "elastic normal force, the viscous one still acts, the shear force restarts from zero at every step.";
    bool neverErase = false, sphericalBodies = true, traceEnergy = false;
    Real plasticDissipation = 0; // (traceEnergy) the energy dissipated by sliding since initPlasticDissipation
    template <class V> void visit(V& v) {
        LawFunctor::visit(v);
        v.attr("neverErase", neverErase, "Keep contacts whose bodies separated instead of removing them (the viscous normal force still acts)");
        v.attr("sphericalBodies", sphericalBodies, "Lever arms of the torques from the radii, (refR - u/2)·n (right for sphere-sphere contacts), "
                                                   "instead of from the contact point and the bodies' positions");
        v.attr("traceEnergy", traceEnergy, "Sum the energy dissipated by sliding (plasticDissipation()) instead of O.energy's plastDissip; as "
                                           "in the reference, O.energy's elastPotential is then added to even without O.trackEnergy");
    }
    void prepare() override; // energy terms
    // Python: the elastic energy of the FrictViscoPhys contacts of the current scene, Σ (|normalForce|²/kn + |shearForce|²/ks)/2.
    static Real elasticEnergy(const Scene& scene);

    // the bodies separated: the contact ends, or, kept, the shear spring restarts and only the dashpot acts
    bool separated(FrictViscoPhys& phys) const {
        if (!neverErase) return false;
        phys.normalForce = phys.shearForce = Vector3r::Zero();
        return true;
    }
    bool computesApart() const { return neverErase; }
    template <class T>
    YADE_KERNEL ContactForce<T> kernel(const ScGeom::Values<T>& g, Rows<FrictViscoPhys, T>& phys, const ContactBodies<T>& b, const LaneEnergy<T>&) {
        using P = FrictViscoPhys;
        // (the sums x + (y + z) are the reference's: its bits)
        const auto dotRef = [](const Vec3<T>& a, const Vec3<T>& c) { return a.x * c.x + (a.y * c.y + a.z * c.z); };
        const T zero(0.0), half(0.5), depth = g.penetrationDepth, r1 = g.refR1, r2 = g.refR2;
        const Vec3<T> n = g.normal;
        // the relative velocity of points at the reference radii (ScGeom's, with avoidRatcheting)
        const Vec3<T> v = ((b.vel2() - b.vel1()) * ((r1 + r2) / (r1 + r2 - depth)) + cross(b.angVel2(), (-r2) * n)) - cross(b.angVel1(), r1 * n);
        const T kn = phys.get(&P::kn), ks = phys.get(&P::ks), cn = phys.get(&P::cn), tanPhi = phys.get(&P::tangensOfFrictionAngle);
        const T vn = dotRef(v, n); // negative while approaching
        const T elastic = kn * maxZero(depth);
        const Vec3<T> normalViscous = cn * (vn * n);
        const Vec3<T> normalForce = elastic * n - normalViscous;
        const Vec3<T> trial = g.rotated(phys.get(&P::shearForce)) - ks * g.shearInc;
        const T fs2 = dotRef(trial, trial), maxFs2 = dotRef(normalForce, normalForce) * tanPhi * tanPhi;
        const MaskOf<T> sliding = greater(fs2, maxFs2); // Mohr-Coulomb: back onto the cone
        const T ratio = select(sliding, sqrt(maxFs2) / sqrt(fs2), T(1.0));
        const Vec3<T> shearForce = select(sliding, trial * ratio, trial);
        phys.set(&P::normalViscous, normalViscous);
        phys.set(&P::normalForce, normalForce);
        phys.set(&P::shearForce, shearForce);
        if (traceEnergy || scene->trackEnergy) {
            const T dissipated = select(sliding, dotRef(trial - shearForce, shearForce) / ks, zero);
            const T stored = half * (squaredNorm(normalForce) / kn + select(greater(ks, zero), squaredNorm(shearForce) / ks, zero));
            phys.forLive([&](int i) {
                if (lane(dissipated, i) > 0) {
                    if (traceEnergy) atomicAdd(plasticDissipation, lane(dissipated, i));
                    else scene->energy.add(plastId, lane(dissipated, i));
                }
                scene->energy.add(elastId, lane(stored, i));
            });
        }
        const Vec3<T> force = -normalForce - shearForce; // on body 1
        if (sphericalBodies) {
            const Vec3<T> arm = cross(n, force);
            return {force, (r1 - half * depth) * arm, (r2 - half * depth) * arm, allSet<T>()};
        }
        const Vec3<T> cp = g.contactPoint;
        return {force, cross(cp - b.pos1(), force), cross(cp - b.pos2(), -force), allSet<T>()};
    }

private:
    int elastId = -1, plastId = -1; // O.energy terms elastPotential, plastDissip
    static void atomicAdd(Real& target, Real x) {
#pragma omp atomic
        target += x;
    }
};

} // namespace yade
