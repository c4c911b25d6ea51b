// Drives all six components of the periodic cell's (3.6) strain and stress, each either to a strain
// or to a stress goal (stressMask), along load paths in nSteps steps; each step it sets
// O.cell.velGrad from the current and the next transformation. Formulas: doc/periodic.md.
#pragma once
#include <pkg/dem/BoundaryController.hpp>

namespace yade {

class Peri3dController : public BoundaryController {
public:
    static constexpr const char* classDoc =
            "Engine controlling independently the six components (xx, yy, zz, yz, zx, xy) of the strain and of the stress of the periodic cell (O.cell): a component whose bit is set in stressMask follows a stress path, the others a strain path, to goal in nSteps steps (linear, or piecewise linear from xxPath...xyPath). A strain component gets its rate directly; a stress component's rate is predicted from the stress error of this step and of the last (by mod times the largest strain rate; the first step from the compliance of youngEstimation and poissonEstimation). velGrad is set from the current transformation T = U·P and the next one, U·(P + Uᵀ·dt·ε̇·U). After nSteps (or once a strain reaches maxStrain) doneHook runs; if it is empty the engine is made dead. The stress is the Love-Weber average -1/V Σ f⊗l over the contacts (compression negative), the shear strains engineering strains (γ = 2ε).";
    Vector6r goal = Vector6r::Zero();
    int stressMask = 0;
    int nSteps = 1000;
    Real progress = 0;
    Real mod = .1;
    Real youngEstimation = 1e20;
    Real poissonEstimation = .25;
    Real maxStrain = 1e6;
    Real maxStrainRate = 1e3;
    std::string doneHook;
    Vector6r stress = Vector6r::Zero();
    Vector6r strain = Vector6r::Zero();
    Vector6r stressRate = Vector6r::Zero();
    Vector6r strainRate = Vector6r::Zero();
    Vector6r stressIdeal = Vector6r::Zero();
    Vector6r stressGoal = Vector6r::Zero();
    Vector6r strainGoal = Vector6r::Zero();
    std::vector<Vector2r> xxPath{Vector2r::Ones()}, yyPath{Vector2r::Ones()}, zzPath{Vector2r::Ones()}, yzPath{Vector2r::Ones()},
            zxPath{Vector2r::Ones()}, xyPath{Vector2r::Ones()};
    Vector6i pathSizes = Vector6i::Zero();
    Vector6i pathsCounter = Vector6i::Zero();
    Vector6i pe = Vector6i::Zero();
    Vector6i ps = Vector6i::Zero();
    int lenPe = 0;
    int lenPs = 0;

    template <class V> void visit(V& v) {
        BoundaryController::visit(v);
        v.attr("goal", goal, "Goal of each component (xx, yy, zz, yz, zx, xy) at the end, nSteps: stress [Pa] where its bit is set in stressMask, else strain (shear: engineering strain γ)", Attr::finite);
        v.attr("stressMask", stressMask, "Which components of goal are stresses (bit set) and which strains: bit 1 xx, 2 yy, 4 zz, 8 yz, 16 zx, 32 xy");
        v.attr("nSteps", nSteps, "Number of steps to reach goal", Attr::positive);
        v.attr("progress", progress, "Part of the path done: 1/nSteps is added at each step (less while maxStrainRate scales the rates down); at 1 the engine has finished");
        v.attr("mod", mod, "Predictor step of a stress component: its strain rate changes by mod times the largest |strainRate| each step", Attr::finite);
        v.attr("youngEstimation", youngEstimation, "Estimated Young's modulus of the packing, for the first step's strain rates of the stress components [Pa]", Attr::finite);
        v.attr("poissonEstimation", poissonEstimation, "Estimated Poisson's ratio of the packing, for the first step's strain rates of the stress components", Attr::finite);
        v.attr("maxStrain", maxStrain, "Once a component of |strain| reaches this, the engine has finished (doneHook, or dead)");
        v.attr("maxStrainRate", maxStrainRate, "Largest |strainRate| of a component: faster rates are all scaled down together [1/s]", Attr::nonNegative);
        v.attr("doneHook", doneHook, "Python command run (in the script's namespace) at each step once the engine has finished; if empty, the engine is made dead instead");
        v.attr("stress", stress, "Stress of the packing (xx, yy, zz, yz, zx, xy), the Love-Weber average over the contacts at this step [Pa]");
        v.attr("strain", strain, "Strain of the cell (xx, yy, zz, γyz, γzx, γxy), the sum of dt·strainRate over the steps done (a stress component's lags by a step)");
        v.attr("stressRate", stressRate, "Prescribed stress rate of each stress component, from the path's segment [Pa/s]");
        v.attr("strainRate", strainRate, "Strain rate of each component at this step [1/s]");
        v.attr("stressIdeal", stressIdeal, "Prescribed stress at this step, the sum of dt·stressRate [Pa]");
        v.attr("stressGoal", stressGoal, "goal of the stress components, 0 for the others", Attr::readonly);
        v.attr("strainGoal", strainGoal, "goal of the strain components, 0 for the others", Attr::readonly);
        v.attr("xxPath", xxPath, "Load path of xx: (time, value) points, piecewise linear from (0, 0); the last point is (nSteps, goal) and the others are relative to it (e.g. nSteps=1000, goal[0]=300, xxPath=[(2,3),(4,1),(5,2)]: 450 at step 400, 150 at step 800, 300 at step 1000)", Attr::finite);
        v.attr("yyPath", yyPath, "Load path of yy: see xxPath", Attr::finite);
        v.attr("zzPath", zzPath, "Load path of zz: see xxPath", Attr::finite);
        v.attr("yzPath", yzPath, "Load path of yz: see xxPath", Attr::finite);
        v.attr("zxPath", zxPath, "Load path of zx: see xxPath", Attr::finite);
        v.attr("xyPath", xyPath, "Load path of xy: see xxPath", Attr::finite);
        v.attr("pathSizes", pathSizes, "Number of points of each component's path", Attr::readonly);
        v.attr("pathsCounter", pathsCounter, "Segment of each component's path being followed", Attr::readonly);
        v.attr("pe", pe, "The strain components, their indices first (lenPe of them), then zeros", Attr::readonly);
        v.attr("ps", ps, "The stress components, their indices first (lenPs of them), then zeros", Attr::readonly);
        v.attr("lenPe", lenPe, "Number of strain components", Attr::readonly);
        v.attr("lenPs", lenPs, "Number of stress components", Attr::readonly);
        v.attr("prevStressError", prevStressError, "stress - stressIdeal at the last step, for the predictor", Attr::hidden);
    }
    void action() override;

    Vector6r prevStressError = Vector6r::Zero();

private:
    // The stress of the packing in Voigt order, from the contacts.
    Vector6r measureStress() const;
};

} // namespace yade
