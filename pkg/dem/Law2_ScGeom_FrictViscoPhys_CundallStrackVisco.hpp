// The Cundall-Strack contact law with viscous damping in the normal direction (FrictViscoPM): a
// linear spring and a dashpot in parallel in the normal direction, an incremental shear spring
// with Mohr-Coulomb sliding capped by the whole normal force.
#pragma once
#include <cmath>
#include <core/LawDispatcher.hpp>
#include <pkg/dem/FrictViscoPhys.hpp>
#include <pkg/dem/ScGeom.hpp>

namespace yade {

// Scalar forms of the two-lane operations (pkg/dem/TwoLanes.hpp), for the law's kernel.
namespace frictViscoScalar {
inline bool greater(Real a, Real b) { return a > b; }
inline Real select(bool mask, Real a, Real b) { return mask ? a : b; }
} // namespace frictViscoScalar

class Law2_ScGeom_FrictViscoPhys_CundallStrackVisco
        : public LawFunctorBatched<Law2_ScGeom_FrictViscoPhys_CundallStrackVisco, ScGeom, FrictViscoPhys> {
public:
    static constexpr const char* classDoc =
            "Constitutive law for the FrictViscoPM: Law2_ScGeom_FrictPhys_CundallStrack with viscous damping in the normal direction. "
            "normalViscous = cn·v_n·n (v_n: the normal relative velocity, of points at the reference radii, negative while approaching), "
            "normalForce = kn·u·n - normalViscous in compression and in extension (it may pull); the shear force, "
            "rotated(Fs) - ks·Δus, is capped at |normalForce|·tan φ. With neverErase, bodies that separated keep the contact: no "
            "elastic normal force, the viscous one still acts, the shear force restarts from zero at every step.";
    bool neverErase = false, sphericalBodies = true, traceEnergy = false;
    template <class V> void visit(V& v) {
        LawFunctor::visit(v);
        v.attr("neverErase", neverErase, "Keep contacts whose bodies separated instead of removing them (the viscous normal force still acts)");
        v.attr("sphericalBodies", sphericalBodies, "Lever arms of the torques from the radii, (refR - u/2)·n (right for sphere-sphere contacts), "
                                                   "instead of from the contact point and the bodies' positions");
        v.attr("traceEnergy", traceEnergy, "Sum the energy dissipated by sliding (plasticDissipation()) instead of O.energy's plastDissip; as "
                                           "in the reference, O.energy's elastPotential is then added to even without O.trackEnergy");
    }
    bool go(ScGeom& geom, FrictViscoPhys& phys, const Contact& c);
    void prepare() override; // energy terms

    // The law's arithmetic on the values of one contact (T = Real) or of two (T = lanes::Two), nothing
    // else read or written. In: the unit normal n, the overlap u of the spring (0 once the bodies
    // separated), the relative velocity v of body 2's point at the contact with respect to body 1's,
    // the previous shear force already turned with the contact plane, the shear increment du, kn, ks,
    // cn and tan φ. Out: normalForce (on body 2), normalViscous, shearForce (on body 2) and the energy
    // dissipated by sliding (0 when it sticks).
    template <class T>
    static void kernel(const T n[3], T u, const T v[3], const T shearOld[3], const T du[3], T kn, T ks, T cn, T tanPhi, T normalForce[3],
            T normalViscous[3], T shearForce[3], T& dissipated) {
        using frictViscoScalar::greater;
        using frictViscoScalar::select;
        using std::sqrt;
        // (the sums x + (y + z) and the products' grouping are the reference's: its bits)
        const auto dot = [](const T a[3], const T b[3]) { return a[0] * b[0] + (a[1] * b[1] + a[2] * b[2]); };
        const T vn = dot(v, n); // normal relative velocity, negative while approaching
        const T elastic = kn * u;
        T trial[3];
        for (int i = 0; i < 3; ++i) {
            normalViscous[i] = cn * (vn * n[i]);
            normalForce[i] = elastic * n[i] - normalViscous[i];
            trial[i] = shearOld[i] - ks * du[i];
        }
        const T fs2 = dot(trial, trial);
        const T maxFs2 = dot(normalForce, normalForce) * tanPhi * tanPhi;
        const auto sliding = greater(fs2, maxFs2); // Mohr-Coulomb: back onto the cone
        const T ratio = select(sliding, sqrt(maxFs2) / sqrt(fs2), T(1));
        T slip[3];
        for (int i = 0; i < 3; ++i) {
            shearForce[i] = select(sliding, trial[i] * ratio, trial[i]);
            slip[i] = trial[i] - shearForce[i];
        }
        dissipated = select(sliding, dot(slip, shearForce) / ks, T(0));
    }

    // Python: the energies of the FrictViscoPhys contacts of the current scene.
    static Real elasticEnergy(const Scene& scene); // Σ (|normalForce|²/kn + |shearForce|²/ks)/2
    Real plasticDissipation = 0;                  // (traceEnergy) the energy dissipated by sliding since initPlasticDissipation

private:
    int elastId = -1, plastId = -1; // O.energy terms elastPotential, plastDissip
};

} // namespace yade
