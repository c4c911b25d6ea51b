// The classic triaxial test as a state machine over TriaxialStressController: isotropic compaction to
// sigmaIsoCompaction, optional unloading to sigmaLateralConfinement, then axial loading at strainRate
// under constant lateral stress until the axial strain reaches epsilonMax. Rules: doc/triaxial.md.
#pragma once
#include <pkg/dem/triaxial/TriaxialStressController.hpp>

namespace yade {

class TriaxialCompressionEngine : public TriaxialStressController {
public:
    static constexpr const char* classDoc =
            "The triaxial test as a state machine (deprecated in the reference in favour of TriaxialStressController): "
            "1 STATE_ISO_COMPACTION (isotropic compaction to sigmaIsoCompaction, by the walls or, with internalCompaction, by growing the spheres) until the "
            "packing is stable (UnbalancedForce below StabilityCriterion and the mean stress within 0.5 % of sigma_iso, tested every testEquilibriumInterval steps); "
            "2 STATE_ISO_UNLOADING (to sigmaLateralConfinement, skipped when it equals sigmaIsoCompaction or without autoUnload); "
            "3 STATE_TRIAX_LOADING (the top and bottom walls strain the sample at currentStrainRate, which converges to strainRate, while the lateral walls keep "
            "sigmaLateralConfinement, until the axial strain reaches epsilonMax); 4 STATE_FIXED_POROSITY_COMPACTION (not implemented here); 5 STATE_LIMBO. "
            "The move to loading is automatic with autoCompressionActivation.";
    enum State { STATE_UNINITIALIZED = 0, STATE_ISO_COMPACTION = 1, STATE_ISO_UNLOADING = 2, STATE_TRIAX_LOADING = 3, STATE_FIXED_POROSITY_COMPACTION = 4, STATE_LIMBO = 5 };

    std::string Key;
    Real StabilityCriterion = 0.001, UnbalancedForce = 1;
    bool autoCompressionActivation = true, autoStopSimulation = false, autoUnload = true;
    int currentState = STATE_UNINITIALIZED, previousState = STATE_UNINITIALIZED;
    Real currentStrainRate = 0, strainRate = 0, epsilonMax = 0.5;
    Real fixedPoroCompaction = 0, fixedPorosity = 0, frictionAngleDegree = -1;
    bool isAxisymetric = true, noFiles = false;
    Real maxStress = 0, previousSigmaIso = 0, sigmaIsoCompaction = 1, sigmaLateralConfinement = 1, sigma_iso = 0;
    int testEquilibriumInterval = 20, warn = 0;
    Vector3r translationAxis = Vector3r::UnitY();
    Real uniaxialEpsilonCurr = 1;

    template <class V> void visit(V& v) {
        TriaxialStressController::visit(v);
        v.attr("Key", Key, "A string appended to the names of the files the reference writes (kept for compatibility: no file is written here)");
        v.attr("StabilityCriterion", StabilityCriterion, "The packing is stable when UnbalancedForce is below this (and the mean stress within 0.5 % of sigma_iso)", Attr::nonNegative);
        v.attr("UnbalancedForce", UnbalancedForce, "Mean resultant force on the dynamic bodies over the mean contact force, computed every testEquilibriumInterval steps");
        v.attr("autoCompressionActivation", autoCompressionActivation, "Move on to the axial loading once stable after compaction (or unloading)");
        v.attr("autoStopSimulation", autoStopSimulation, "Stop the run when the axial strain reaches epsilonMax");
        v.attr("autoUnload", autoUnload, "Move from compaction to unloading once stable (when sigmaLateralConfinement differs from sigmaIsoCompaction)");
        v.attr("currentState", currentState, "The state: 0 uninitialized, 1 isotropic compaction, 2 isotropic unloading, 3 axial loading, 4 fixed-porosity compaction, 5 limbo");
        v.attr("previousState", previousState, "The state at the previous step (a change of currentState from Python is detected by it)");
        v.attr("currentStrainRate", currentStrainRate, "The axial strain rate applied now, converging to strainRate [1/s]");
        v.attr("strainRate", strainRate, "Target axial strain rate of the loading (positive: compression) [1/s]", Attr::finite);
        v.attr("epsilonMax", epsilonMax, "Axial strain at which the loading stops", Attr::finite);
        v.attr("fixedPoroCompaction", fixedPoroCompaction, "Compaction to the porosity fixedPorosity instead of a stress (not implemented here: non-zero is refused)");
        v.attr("fixedPorosity", fixedPorosity, "Porosity of the fixed-porosity compaction (see fixedPoroCompaction)");
        v.attr("frictionAngleDegree", frictionAngleDegree, "Friction angle given to the dynamic bodies and their contacts just before the axial loading (negative: unchanged) [deg]");
        v.attr("isAxisymetric", isAxisymetric, "Set goal1, goal2, goal3 to sigma_iso at every step");
        v.attr("noFiles", noFiles, "Write no files (here no file is ever written)");
        v.attr("maxStress", maxStress, "Largest axial stress magnitude met at the equilibrium tests [Pa]");
        v.attr("previousSigmaIso", previousSigmaIso, "sigma_iso at the previous step (a change from Python is detected by it)");
        v.attr("sigmaIsoCompaction", sigmaIsoCompaction, "Isotropic stress of the compaction (negative: compression) [Pa]", Attr::finite);
        v.attr("sigmaLateralConfinement", sigmaLateralConfinement, "Lateral stress of the unloading and of the axial loading (negative: compression) [Pa]", Attr::finite);
        v.attr("sigma_iso", sigma_iso, "The confining stress now prescribed (see isAxisymetric) [Pa]", Attr::finite);
        v.attr("testEquilibriumInterval", testEquilibriumInterval, "Iteration period of the stability tests that move from one state to the next", Attr::positive);
        v.attr("warn", warn, "Counter of the deprecation warning (printed once)");
        v.attr("translationAxis", translationAxis, "Axis of the axial loading (the walls bottom/top move along it)");
        v.attr("uniaxialEpsilonCurr", uniaxialEpsilonCurr, "Axial strain of the loading, -strain[1] (1 until the loading starts)");
    }
    void action() override;
    // Gives the dynamic bodies' FrictMat and their contacts' FrictPhys the friction angle (degrees).
    static void setContactProperties(Scene& s, Real frictionDegree);

private:
    void updateState();
    void startLoading();
    void moveAxialWalls();
};

} // namespace yade
