#include <core/Scene.hpp>
#include <lib/base/Logging.hpp>
#include <pkg/common/FrictMat.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/Shop.hpp>
#include <pkg/dem/triaxial/TriaxialCompressionEngine.hpp>
#include <cmath>
#include <stdexcept>

namespace yade {

// The transitions and the loading were found by running the reference (Yade 2023.02a): see doc/triaxial.md.

// Share of the gap to strainRate that currentStrainRate closes each step (the reference's ramp).
static constexpr Real strainRateRamp = 3e-4;
// The mean stress must be this close (relative) to sigma_iso for the packing to count as stable.
static constexpr Real stressTolerance = 0.005;

void TriaxialCompressionEngine::setContactProperties(Scene& s, Real frictionDegree) {
    if (!std::isfinite(frictionDegree) || frictionDegree < 0) throw std::invalid_argument("TriaxialCompressionEngine.setContactProperties: the friction angle must be finite and non-negative [deg]");
    const Real angle = frictionDegree * M_PI / 180;
    for (const auto& b : s.bodies)
        if (b && b->isDynamic())
            if (auto* m = dynamic_cast<FrictMat*>(b->material.get())) m->frictionAngle = angle;
    // the contacts between two dynamic bodies (those with a wall keep theirs, as in the reference)
    auto dynamic = [&](Body::id_t id) { return s.bodies.exists(id) && s.bodies[id]->isDynamic(); };
    for (size_t k = 0; k < s.interactions.size(); ++k) {
        if (!s.interactions.isReal(k) || !dynamic(s.interactions.pairIds[2 * k]) || !dynamic(s.interactions.pairIds[2 * k + 1])) continue;
        if (auto* p = dynamic_cast<FrictPhys*>(s.interactions.phys(k))) p->tangensOfFrictionAngle = std::tan(angle);
    }
}

void TriaxialCompressionEngine::startLoading() {
    Scene& s = *scene;
    currentState = STATE_TRIAX_LOADING;
    internalCompaction = false;
    if (frictionAngleDegree > 0) setContactProperties(s, frictionAngleDegree);
    // the strain of the loading counts from here
    width0 = width;
    height0 = height;
    depth0 = depth;
    wall_bottom_activated = wall_top_activated = false;
    s.bodies[wall_bottom_id]->state->vel() = Vector3r::Zero();
    s.bodies[wall_top_id]->state->vel() = Vector3r::Zero();
}

void TriaxialCompressionEngine::updateState() {
    Scene& s = *scene;
    if (currentState == STATE_UNINITIALIZED) {
        currentState = STATE_ISO_COMPACTION;
        sigma_iso = sigmaIsoCompaction;
    }
    if (s.iter % testEquilibriumInterval != 0) return;
    UnbalancedForce = Shop::unbalancedForce(s, false);
    maxStress = std::max(maxStress, std::abs(stress[top][1]));
    if (currentState != STATE_ISO_COMPACTION && currentState != STATE_ISO_UNLOADING) return;
    const bool stable = UnbalancedForce <= StabilityCriterion && std::abs(meanStress - sigma_iso) <= stressTolerance * std::abs(sigma_iso);
    if (!stable) return;
    if (currentState == STATE_ISO_COMPACTION && autoUnload && sigmaLateralConfinement != sigmaIsoCompaction) {
        currentState = STATE_ISO_UNLOADING;
        sigma_iso = sigmaLateralConfinement;
        internalCompaction = false;
    } else if (autoCompressionActivation) {
        sigma_iso = sigmaLateralConfinement;
        startLoading();
    }
}

void TriaxialCompressionEngine::moveAxialWalls() {
    Scene& s = *scene;
    if (std::abs(strain[1]) >= epsilonMax) { // the end of the loading
        if (autoStopSimulation) s.stopAtIter = s.iter + 1;
        return;
    }
    currentStrainRate += strainRateRamp * (strainRate - currentStrainRate);
    const Real move = 0.5 * currentStrainRate * height * s.dt;
    s.bodies[wall_bottom_id]->state->pos() += move * translationAxis;
    s.bodies[wall_top_id]->state->pos() -= move * translationAxis;
    s.motion.invalidate(); // (not the integrator's move: the collider checks the positions again)
    uniaxialEpsilonCurr = -strain[1];
}

void TriaxialCompressionEngine::action() {
    if (warn++ == 0) logWarning("TriaxialCompressionEngine is deprecated, please switch to TriaxialStressController if you expect long term support.");
    if (fixedPoroCompaction != 0) throw std::invalid_argument("TriaxialCompressionEngine.fixedPoroCompaction (compaction to a fixed porosity) is not implemented: leave it 0");
    if (!std::isfinite(sigmaIsoCompaction) || !std::isfinite(sigmaLateralConfinement) || !std::isfinite(strainRate))
        throw std::invalid_argument("TriaxialCompressionEngine: sigmaIsoCompaction, sigmaLateralConfinement and strainRate must be finite");
    if (testEquilibriumInterval < 1) throw std::invalid_argument("TriaxialCompressionEngine.testEquilibriumInterval must be at least 1");
    checkAndInit();
    updateState(); // (on the stresses of the last computation, before this step's, as the reference)
    measure();
    updateStiffness(); // (every step: the reference's engine does not follow stiffnessUpdateInterval)
    if (isAxisymetric || currentState == STATE_ISO_COMPACTION || currentState == STATE_ISO_UNLOADING) goal1 = goal2 = goal3 = sigma_iso;
    if (currentState == STATE_TRIAX_LOADING) moveAxialWalls();
    previousState = currentState;
    previousSigmaIso = sigma_iso;
    control();
}

} // namespace yade
