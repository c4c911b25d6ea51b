// Uniaxial tension or compression of a specimen: two groups of bodies, at its two ends, moved apart
// (or together) along an axis at a constant strain rate; the strain and the mean stress on the ends.
#pragma once
#include <pkg/dem/BoundaryController.hpp>
#include <vector>

namespace yade {

class UniaxialStrainer : public BoundaryController {
public:
    static constexpr const char* classDoc =
            "Strains a specimen along an axis by moving two groups of bodies (posIds at its positive end, negIds at its negative end) "
            "in opposite directions at a constant strain rate. At its first run: originalLength = the distance of posIds[0] and "
            "negIds[0] along axis, absSpeed = strainRate·originalLength (or strainRate = absSpeed/originalLength), and the bodies' "
            "blockedDOFs: the axis, all translations with blockDisplacements, the rotations with blockRotations. Every step: strain = "
            "(that distance)/originalLength - 1, then the velocity along axis of posIds is +absSpeed/2 and of negIds -absSpeed/2 "
            "(asymmetry 1: posIds +absSpeed and negIds still; -1 the opposite). With setSpeeds, the first run also gives every body the "
            "velocity along axis of the uniform strain field, v_neg + strainRate·(x - x_neg) (v_neg the velocity of negIds). Every stressUpdateInterval steps: avgStress = "
            "(Σ forces on negIds - Σ forces on posIds along axis)/(2·crossSectionArea), positive in tension. The ends' speed is full from the "
            "first step, as in the reference's runs (initAccelTime is stored and changes nothing). stopStrain: the last "
            "step lands on it, then the engine turns inactive and pauses the simulation (after idleIterations more steps); limitStrain "
            "reverses the straining once (not checked against the reference).";
    Real strainRate = NaN, absSpeed = NaN, initAccelTime = -200, stopStrain = NaN, limitStrain = 0, crossSectionArea = NaN;
    int axis = 2, asymmetry = 0, stressUpdateInterval = 10;
    long long idleIterations = 0;
    bool active = true, blockDisplacements = false, blockRotations = false, setSpeeds = false, notYetReversed = true;
    std::vector<int> posIds, negIds;
    Real strain = 0, avgStress = 0, currentStrainRate = NaN, originalLength = NaN;
    template <class V> void visit(V& v) {
        BoundaryController::visit(v);
        v.attr("strainRate", strainRate, "Rate of strain [1/s] (or give absSpeed); negative: compression");
        v.attr("absSpeed", absSpeed, "Speed of the ends moving apart, used at the first run when strainRate is not given [m/s]");
        v.attr("initAccelTime", initAccelTime, "Time for the strain rate to reach strainRate (negative: that many first time steps); "
                                               "stored only: as in the reference's runs, the speed is full from the first step [s]");
        v.attr("stopStrain", stopStrain, "Strain at which the straining stops and the simulation pauses; reached from below in "
                                         "absolute value (NaN: never)");
        v.attr("limitStrain", limitStrain, "Strain at which the sense of straining is reversed, once (0: never)");
        v.attr("crossSectionArea", crossSectionArea, "Cross-section of the specimen perpendicular to axis, for avgStress; must be given [m²]");
        v.attr("axis", axis, "Axis of straining: 0, 1, 2 for x, y, z");
        v.attr("asymmetry", asymmetry, "0: both ends move; 1: only posIds move (negIds stay); -1: only negIds move");
        v.attr("stressUpdateInterval", stressUpdateInterval, "Steps between two computations of avgStress", Attr::positive);
        v.attr("idleIterations", idleIterations, "Steps to run after stopStrain was reached, before the pause", Attr::nonNegative);
        v.attr("active", active, "Whether the engine strains the specimen");
        v.attr("blockDisplacements", blockDisplacements, "Block the ends' displacements perpendicular to axis (else free)");
        v.attr("blockRotations", blockRotations, "Block the ends' rotations");
        v.attr("setSpeeds", setSpeeds, "At the first run, give every body the velocity along axis of the uniform strain field "
                                         "(v_neg + strainRate·(x - x_neg)), instead of moving only the ends");
        v.attr("notYetReversed", notYetReversed, "Whether the sense of straining has not been reversed yet (limitStrain)");
        v.attr("posIds", posIds, "Bodies at the positive end of the specimen along axis");
        v.attr("negIds", negIds, "Bodies at the negative end of the specimen along axis");
        v.attr("strain", strain, "Current strain: elongation/originalLength [-]");
        v.attr("avgStress", avgStress, "Mean stress on the two ends, positive in tension (every stressUpdateInterval steps) [Pa]");
        v.attr("currentStrainRate", currentStrainRate, "Current strain rate [1/s]");
        v.attr("originalLength", originalLength, "Distance of posIds[0] and negIds[0] along axis at the first run (NaN until then: the "
                                                 "engine starts when it is NaN) [m]");
    }
    void action() override;

private:
    long long idleLeft = -1; // steps before the pause once stopStrain was reached (-1: not reached)
    void init();
    Real length() const; // the distance of posIds[0] and negIds[0] along axis
    void moveEnds(Real speed); // the ends' velocities for an elongation speed `speed`
};

} // namespace yade
