// The classic triaxial test as a scene generator: a random cloud of spheres in six walls, with a
// TriaxialCompressionEngine (compaction, then axial loading) and a TriaxialStateRecorder. The
// attributes are here; load() (py/yade/_triaxial.py) builds the scene from them.
#pragma once
#include <pkg/dem/triaxial/FileGenerator.hpp>

namespace yade {

class TriaxialTest : public FileGenerator {
public:
    static constexpr const char* classDoc =
            "Generator of the classic triaxial test: numberOfGrains spheres (mean radius radiusMean, relative spread radiusStdDev; radiusMean<=0: "
            "sized for a loose cloud) at random (seed) in the box lowerCorner-upperCorner, six walls (ids 0-5: bottom, top, left, right, back, front), "
            "ForceResetter, InsertionSortCollider, InteractionLoop (Cundall-Strack), GlobalStiffnessTimeStepper, a TriaxialCompressionEngine "
            "(isotropic compaction to sigmaIsoCompaction, then loading at strainRate under sigmaLateralConfinement), a TriaxialStateRecorder "
            "(unless noFiles) and NewtonIntegrator. TriaxialTest(...).load() builds it into O. The random packing is SpherePack.makeCloud(lowerCorner, upperCorner, rMean=radiusMean or -1 with porosity 0.8, rRelFuzz=radiusStdDev, num=numberOfGrains, seed=seed).";
    std::string Key, WallStressRecordFile = "./WallStresses", fixedBoxDims, importFilename;
    Real StabilityCriterion = 0.01;
    bool autoCompressionActivation = true, autoStopSimulation = false, autoUnload = true, facetWalls = false, internalCompaction = false, noFiles = false,
         wallWalls = false;
    Real boxFrictionDeg = 0, boxKsDivKn = 0.5, boxYoungModulus = 15e6, compactionFrictionDeg = 18, dampingForce = 0.2, dampingMomentum = 0.2, defaultDt = -1,
         density = 2600, finalMaxMultiplier = 1.001, maxMultiplier = 1.01, maxWallVelocity = 10, radiusMean = -1, radiusStdDev = 0.3,
         sigmaIsoCompaction = -50000, sigmaLateralConfinement = -50000, sphereFrictionDeg = 18, sphereKsDivKn = 0.5, sphereYoungModulus = 15e6,
         strainRate = 0.1, thickness = 0.001, wallOversizeFactor = 1.3;
    Vector3r lowerCorner = Vector3r::Zero(), upperCorner = Vector3r::Ones();
    int numberOfGrains = 400, radiusControlInterval = 10, recordIntervalIter = 20, seed = 0, timeStepUpdateInterval = 50, wallStiffnessUpdateInterval = 10;

    template <class V> void visit(V& v) {
        FileGenerator::visit(v);
        v.attr("Key", Key, "A string appended to the names of the files written (the recorder's)");
        v.attr("StabilityCriterion", StabilityCriterion, "TriaxialCompressionEngine.StabilityCriterion: the unbalanced force below which the packing is stable", Attr::nonNegative);
        v.attr("WallStressRecordFile", WallStressRecordFile, "File of the TriaxialStateRecorder (Key is appended)");
        v.attr("autoCompressionActivation", autoCompressionActivation, "TriaxialCompressionEngine.autoCompressionActivation");
        v.attr("autoStopSimulation", autoStopSimulation, "TriaxialCompressionEngine.autoStopSimulation");
        v.attr("autoUnload", autoUnload, "TriaxialCompressionEngine.autoUnload");
        v.attr("boxFrictionDeg", boxFrictionDeg, "Friction angle of the walls [deg]", Attr::nonNegative);
        v.attr("boxKsDivKn", boxKsDivKn, "Ratio of shear to normal stiffness of the walls (their material's poisson)", Attr::nonNegative);
        v.attr("boxYoungModulus", boxYoungModulus, "Young modulus of the walls [Pa]", Attr::positive);
        v.attr("compactionFrictionDeg", compactionFrictionDeg, "Friction angle of the spheres during the compaction [deg]", Attr::nonNegative);
        v.attr("dampingForce", dampingForce, "NewtonIntegrator.damping", Attr::nonNegative);
        v.attr("dampingMomentum", dampingMomentum, "Damping of the rotations (NewtonIntegrator has one damping: dampingForce is used)", Attr::nonNegative);
        v.attr("defaultDt", defaultDt, "Time step (non-positive: utils.PWaveTimeStep of the generated packing) [s]");
        v.attr("density", density, "Density of the spheres [kg/m³]", Attr::positive);
        v.attr("facetWalls", facetWalls, "Walls made of facets instead of boxes (not supported here: True is refused)");
        v.attr("finalMaxMultiplier", finalMaxMultiplier, "TriaxialStressController.finalMaxMultiplier", Attr::positive);
        v.attr("fixedBoxDims", fixedBoxDims, "Axes (letters among 'xyz') along which the box is not scaled to the packing (not supported here: non-empty is refused)");
        v.attr("importFilename", importFilename, "File of spheres (x y z r per line) to use instead of a random cloud");
        v.attr("internalCompaction", internalCompaction, "Compaction by growing the spheres instead of moving the walls");
        v.attr("lowerCorner", lowerCorner, "Lower corner of the box [m]", Attr::finite);
        v.attr("maxMultiplier", maxMultiplier, "TriaxialStressController.maxMultiplier", Attr::positive);
        v.attr("maxWallVelocity", maxWallVelocity, "TriaxialStressController.max_vel [m/s]", Attr::nonNegative);
        v.attr("noFiles", noFiles, "No TriaxialStateRecorder (no file written)");
        v.attr("numberOfGrains", numberOfGrains, "Number of spheres of the random cloud", Attr::positive);
        v.attr("radiusControlInterval", radiusControlInterval, "TriaxialStressController.radiusControlInterval", Attr::positive);
        v.attr("radiusMean", radiusMean, "Mean radius of the spheres (non-positive: the one that gives the cloud a porosity of 0.8) [m]");
        v.attr("radiusStdDev", radiusStdDev, "Relative spread of the radii: uniform in radiusMean·(1 ± radiusStdDev)", Attr::nonNegative);
        v.attr("recordIntervalIter", recordIntervalIter, "TriaxialStateRecorder.iterPeriod", Attr::positive);
        v.attr("seed", seed, "Seed of the random cloud");
        v.attr("sigmaIsoCompaction", sigmaIsoCompaction, "TriaxialCompressionEngine.sigmaIsoCompaction [Pa]", Attr::finite);
        v.attr("sigmaLateralConfinement", sigmaLateralConfinement, "TriaxialCompressionEngine.sigmaLateralConfinement [Pa]", Attr::finite);
        v.attr("sphereFrictionDeg", sphereFrictionDeg, "Friction angle of the spheres during the loading (TriaxialCompressionEngine.frictionAngleDegree) [deg]", Attr::nonNegative);
        v.attr("sphereKsDivKn", sphereKsDivKn, "Ratio of shear to normal stiffness of the spheres (their material's poisson)", Attr::nonNegative);
        v.attr("sphereYoungModulus", sphereYoungModulus, "Young modulus of the spheres [Pa]", Attr::positive);
        v.attr("strainRate", strainRate, "TriaxialCompressionEngine.strainRate [1/s]", Attr::finite);
        v.attr("thickness", thickness, "Thickness of the walls [m]", Attr::positive);
        v.attr("timeStepUpdateInterval", timeStepUpdateInterval, "GlobalStiffnessTimeStepper.timeStepUpdateInterval", Attr::positive);
        v.attr("upperCorner", upperCorner, "Upper corner of the box [m]", Attr::finite);
        v.attr("wallOversizeFactor", wallOversizeFactor, "The walls are this many times larger than the box", Attr::positive);
        v.attr("wallStiffnessUpdateInterval", wallStiffnessUpdateInterval, "TriaxialStressController.stiffnessUpdateInterval", Attr::positive);
        v.attr("wallWalls", wallWalls, "Walls made of Wall instead of boxes (not supported here: True is refused)");
    }
};

} // namespace yade
