// Drives the six walls of a box-shaped sample (3.x of Chareyre's triaxial set-up): along each axis
// whose bit is set in stressMask the two walls are servo-controlled towards the stress goal, along
// the others they move at the strain rate goal; or, with internalCompaction, the walls stay and the
// spheres grow until the mean stress reaches the mean goal. Formulas: doc/triaxial.md.
#pragma once
#include <pkg/dem/BoundaryController.hpp>
#include <array>

namespace yade {

class TriaxialStressController : public BoundaryController {
public:
    static constexpr const char* classDoc =
            "An engine maintaining constant stresses or constant strain rates on some boundaries of a parallelepipedic packing (six walls, "
            "wall_*_id). The control is chosen per axis by stressMask (a bit mask: 1 x, 2 y, 4 z; a set bit: goal is a stress, else a "
            "strain rate) with goals goal1, goal2, goal3. Continuum mechanics' sign convention (traction positive). With internalCompaction "
            "the walls stay and the spheres' radii are scaled until the mean stress reaches the mean of the goals.";
    enum Wall { left = 0, right = 1, bottom = 2, top = 3, back = 4, front = 5 };

    int stiffnessUpdateInterval = 10, radiusControlInterval = 10, computeStressStrainInterval = 10;
    Real stressDamping = 0.25, strainDamping = 0.99;
    Real thickness = -1;
    Real maxMultiplier = 1.001, finalMaxMultiplier = 1.00001;
    Real max_vel = 1;
    Real previousStress = 0, previousMultiplier = 1;
    bool internalCompaction = true;
    Real goal1 = 0, goal2 = 0, goal3 = 0;
    int stressMask = 7;
    bool updatePorosity = false;
    Real externalWork = 0, meanStress = 0, volumetricStrain = 0;
    Real width = 0, height = 0, depth = 0, width0 = 0, height0 = 0, depth0 = 0;
    int wall_left_id = 0, wall_right_id = 1, wall_bottom_id = 2, wall_top_id = 3, wall_back_id = 4, wall_front_id = 5;
    bool wall_left_activated = true, wall_right_activated = true, wall_bottom_activated = true, wall_top_activated = true,
         wall_back_activated = true, wall_front_activated = true;
    bool finalStage = false; // internal compaction has once passed the goal: finalMaxMultiplier from then on

    template <class V> void visit(V& v) {
        BoundaryController::visit(v);
        v.attr("stiffnessUpdateInterval", stiffnessUpdateInterval, "Iteration period of the measure of the walls' stiffnesses (the sum of kn of their contacts) used by the stress servo-control", Attr::positive);
        v.attr("radiusControlInterval", radiusControlInterval, "Iteration period of the growth of the spheres with internalCompaction", Attr::positive);
        v.attr("computeStressStrainInterval", computeStressStrainInterval, "Iteration period of the computation of the walls' stresses, meanStress, strain and volumetricStrain", Attr::positive);
        v.attr("stressDamping", stressDamping, "Wall damping of the stress control: 0 is a (theoretical) perfect control, 1 no movement", Attr::finite);
        v.attr("strainDamping", strainDamping, "Smoothing of the strain rate control: a wall's velocity reaches the target like strainDamping^n goes to 0 (n steps)", Attr::finite);
        v.attr("thickness", thickness, "Thickness of the walls, taken off the distance between their centres (negative: twice the half-size of the bottom wall's box along y, at the first run) [m]");
        v.attr("maxMultiplier", maxMultiplier, "Largest factor on the radii at one growth of internalCompaction, before the mean stress first passes the goal", Attr::positive);
        v.attr("finalMaxMultiplier", finalMaxMultiplier, "Largest factor on the radii at one growth of internalCompaction, once the mean stress has passed the goal", Attr::positive);
        v.attr("max_vel", max_vel, "Largest wall velocity [m/s]; each axis gets max_vel times its size over the mean size (max_vel1, max_vel2, max_vel3) so that the strain rate is isotropic", Attr::nonNegative);
        v.attr("previousStress", previousStress, "Mean stress at the last growth of internalCompaction [Pa]", Attr::readonly);
        v.attr("previousMultiplier", previousMultiplier, "Factor applied to the radii at the last growth of internalCompaction", Attr::readonly);
        v.attr("internalCompaction", internalCompaction, "Switch between 'external' (walls move) and 'internal' (spheres grow) compaction");
        v.attr("goal1", goal1, "Prescribed stress [Pa] or strain rate [1/s] along x, as stressMask says", Attr::finite);
        v.attr("goal2", goal2, "Prescribed stress [Pa] or strain rate [1/s] along y, as stressMask says", Attr::finite);
        v.attr("goal3", goal3, "Prescribed stress [Pa] or strain rate [1/s] along z, as stressMask says", Attr::finite);
        v.attr("stressMask", stressMask, "Bit mask of the axes whose goal is a stress (0 none, 7 all, 1 x, 2 y, 4 z, 5 x and z...); the other axes' goals are strain rates");
        v.attr("updatePorosity", updatePorosity, "Recompute the volume of the particles once at the next step (then reset to False), e.g. after particles were erased or clumped");
        v.attr("externalWork", externalWork, "Work of the walls on the packing, the sum over steps of dt Σ F·v over the six walls [J]", Attr::readonly);
        v.attr("meanStress", meanStress, "Mean of the six walls' normal stresses [Pa]", Attr::readonly);
        v.attr("volumetricStrain", volumetricStrain, "Volumetric strain, the sum of the three components of strain", Attr::readonly);
        v.attr("width", width, "Size of the box along x (between the walls' faces) [m]", Attr::readonly);
        v.attr("height", height, "Size of the box along y [m]", Attr::readonly);
        v.attr("depth", depth, "Size of the box along z [m]", Attr::readonly);
        v.attr("width0", width0, "Reference size along x for strain (0: the size at the first run) [m]");
        v.attr("height0", height0, "Reference size along y for strain (0: the size at the first run) [m]");
        v.attr("depth0", depth0, "Reference size along z for strain (0: the size at the first run) [m]");
        v.attr("wall_left_id", wall_left_id, "Id of the wall at x- (the default is right when aabbWalls are appended before the spheres)");
        v.attr("wall_right_id", wall_right_id, "Id of the wall at x+");
        v.attr("wall_bottom_id", wall_bottom_id, "Id of the wall at y-");
        v.attr("wall_top_id", wall_top_id, "Id of the wall at y+");
        v.attr("wall_back_id", wall_back_id, "Id of the wall at z-");
        v.attr("wall_front_id", wall_front_id, "Id of the wall at z+");
        v.attr("wall_left_activated", wall_left_activated, "If true, the wall at x- moves as the goal says");
        v.attr("wall_right_activated", wall_right_activated, "If true, the wall at x+ moves as the goal says");
        v.attr("wall_bottom_activated", wall_bottom_activated, "If true, the wall at y- moves as the goal says");
        v.attr("wall_top_activated", wall_top_activated, "If true, the wall at y+ moves as the goal says");
        v.attr("wall_back_activated", wall_back_activated, "If true, the wall at z- moves as the goal says");
        v.attr("wall_front_activated", wall_front_activated, "If true, the wall at z+ moves as the goal says");
        v.attr("finalStage", finalStage, "Internal compaction has passed the goal once (finalMaxMultiplier is used from then on)", Attr::hidden);
    }
    void action() override;

    // --- read from Python (py/wrapper/TriaxialWrapper.cpp) ---
    Vector3r stress[6] = {Vector3r::Zero(), Vector3r::Zero(), Vector3r::Zero(), Vector3r::Zero(), Vector3r::Zero(), Vector3r::Zero()};
    Vector3r strain = Vector3r::Zero();
    Real stiffness[6] = {0, 0, 0, 0, 0, 0};
    Real particlesVolume = 0, boxVolume = 0, porosity = 1;
    Vector3r maxVel = Vector3r::Ones(); // max_vel1, max_vel2, max_vel3
    Vector3r strainRate() const;
    int wallId(int w) const;
    bool wallActivated(int w) const;
    Real goal(int axis) const { return axis == 0 ? goal1 : axis == 1 ? goal2 : goal3; }
    static Vector3r normal(int w); // pointing into the sample
    // The dynamic spheres' total volume (particlesVolume).
    static Real solidVolume(const Scene& s);

protected:
    bool initialized = false;
    // A step is measure() (sizes, stiffnesses, stresses and strains when due) then control() (the walls or the radii).
    void measure();
    void control();
    // The walls' ids checked, normals, thickness, reference sizes and particlesVolume (first run).
    void checkAndInit();
    void updateDimensions();
    void updateStiffness();
    void computeStressStrain();
    // Moves the walls of one axis towards a stress goal / a strain rate goal (their velocities).
    void controlExternalStress(int wall, Real goalStress);
    void controlStrainRate(int wall, Real rate);
    // Scales every dynamic sphere's radius, mass and inertia by multiplier.
    void growParticles(Real multiplier);
    void controlInternalStress();
};

} // namespace yade
