// Drives the periodic cell (3.6) to a mixed goal: along each axis whose bit is set in stressMask
// the normal stress of the packing goes to goal[i], along the others the strain log(F_ii) does.
// Each step it sets the diagonal of O.cell.velGrad, at most maxStrainRate; when every goal is met
// and the unbalanced force is below maxUnbalanced it runs doneHook. Formulas: doc/periodic.md.
#pragma once
#include <pkg/dem/BoundaryController.hpp>

namespace yade {

class PeriTriaxController : public BoundaryController {
public:
    static constexpr const char* classDoc =
            "Engine controlling the periodic cell (O.cell) so that the normal stress along the axes set in stressMask reaches goal, and the strain log(trsf[i,i]) along the other axes; it sets the diagonal of O.cell.velGrad every step (at most maxStrainRate) and runs doneHook once every goal is met and the unbalanced force is below maxUnbalanced. The stress is the Love-Weber average -1/V Σ f⊗l over the contacts (compression negative).";
    bool dynCell = false;
    Vector3r goal = Vector3r::Zero();
    int stressMask = 0;
    Vector3r maxStrainRate = Vector3r::Ones();
    Real maxUnbalanced = 1e-4;
    Real absStressTol = 1e3;
    Real relStressTol = 3e-5;
    Real growDamping = .25;
    int globUpdate = 5;
    std::string doneHook;
    Vector3r maxBodySpan = Vector3r::Zero();
    Matrix3r stressTensor = Matrix3r::Zero();
    Vector3r stress = Vector3r::Zero();
    Vector3r strain = Vector3r::Zero();
    Vector3r strainRate = Vector3r::Zero();
    Vector3r stiff = Vector3r::Zero();
    Real currUnbalanced = NaN;
    Vector3r prevGrow = Vector3r::Zero();
    Real mass = NaN;
    Real externalWork = 0;

    template <class V> void visit(V& v) {
        BoundaryController::visit(v);
        v.attr("dynCell", dynCell, "Move the cell as a mass (mass) pushed by the difference between goal and stress, with damping growDamping, instead of from the estimated stiffness");
        v.attr("goal", goal, "Goal along each axis: stress [Pa] where the axis's bit is set in stressMask, else strain log(O.cell.trsf[i,i]) (compression negative)", Attr::finite);
        v.attr("stressMask", stressMask, "Which axes have a stress goal: bit 1 x, 2 y, 4 z (the others have a strain goal)");
        v.attr("maxStrainRate", maxStrainRate, "Largest |velGrad[i,i]| set along each axis [1/s]", Attr::nonNegative);
        v.attr("maxUnbalanced", maxUnbalanced, "doneHook runs only while the unbalanced force (utils.unbalancedForce) is below this");
        v.attr("absStressTol", absStressTol, "A stress goal is met when |stress - goal| is at most this [Pa] (and within relStressTol)", Attr::nonNegative);
        v.attr("relStressTol", relStressTol, "A stress goal is met when |stress - goal| / |goal| is at most this (and within absStressTol; not checked where goal is 0)", Attr::nonNegative);
        v.attr("growDamping", growDamping, "Damping of the cell's motion: the share of the new strain rate that does not follow the stress error (or, with dynCell, the part of the push taken off while the cell moves towards the goal)", Attr::finite);
        v.attr("globUpdate", globUpdate, "Stress, stiffness and unbalanced force are computed from the contacts every this many steps (in between, the stress is predicted from stiff)", Attr::positive);
        v.attr("doneHook", doneHook, "Python command run (in the script's namespace) at each step where every goal is met and the unbalanced force is below maxUnbalanced");
        v.attr("maxBodySpan", maxBodySpan, "Largest extent of a body's bound along each axis, found at the first step (0: not yet); the cell must stay at least 2.1 times as large");
        v.attr("stressTensor", stressTensor, "Average stress in the cell, -1/V Σ f⊗l over the contacts, at the last update [Pa]");
        v.attr("stress", stress, "Normal stresses (the diagonal of stressTensor), predicted from stiff between updates [Pa]");
        v.attr("strain", strain, "Strain along each axis, log(O.cell.trsf[i,i]), after this step's rate");
        v.attr("strainRate", strainRate, "The velGrad[i,i] set at the last step [1/s]");
        v.attr("stiff", stiff, "Mean contact stiffness along each axis, mean of |n_i| kn + (1 - |n_i|) ks over the contacts (not computed with dynCell) [N/m]");
        v.attr("currUnbalanced", currUnbalanced, "Unbalanced force at the last update where every goal was met (NaN: none yet)");
        v.attr("prevGrow", prevGrow, "The strain rate of the previous step [1/s]");
        v.attr("mass", mass, "Mass of the cell's motion with dynCell (NaN: the total mass of the bodies, set at the first step) [kg]");
        v.attr("externalWork", externalWork, "Work done on the packing by the cell's deformation [J] (-O.energy['velGradWork'])");
    }
    void action() override;

private:
    // The Love-Weber stress and the mean stiffnesses from the contacts (an update step).
    void updateStressAndStiffness();
};

} // namespace yade
