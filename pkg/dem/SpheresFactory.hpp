// Makes spheres in a region at a given mass flow rate (base of BoxFactory and CircularFactory).
#pragma once
#include <core/Engine.hpp>
#include <random>
#include <string>
#include <vector>

namespace yade {

class Body;

class SpheresFactory : public GlobalEngine {
public:
    static constexpr const char* classDoc =
            "Engine for spitting spheres based on mass flow rate, particle size distribution etc. Each step goalMass grows by "
            "massFlowRate*dt and spheres are made at random positions of the region, not overlapping any sphere of the scene (nor "
            "the bound of another body), until totalMass reaches goalMass (or maxParticles / maxMass is reached). Radii are uniform in "
            "[rMin, rMax], or follow the table PSDsizes/PSDcum (diameters; the class whose share lags most behind its target is "
            "made next). The speed is drawn uniformly in [vMin, vMax] once per step, the direction is normalVel if set, else normal "
            "(as in the reference, vAngle does not tilt it). The region is defined by a derived engine (BoxFactory, CircularFactory).";
    Real massFlowRate = NaN, rMin = NaN, rMax = NaN, vMin = NaN, vMax = NaN, vAngle = NaN;
    Vector3r normal = Vector3r::Constant(NaN), normalVel = Vector3r::Constant(NaN);
    int materialId = -1, mask = -1;
    Vector3r color = Vector3r(-1, -1, -1);
    std::vector<int> ids;
    Real totalMass = 0, totalVolume = 0, goalMass = 0;
    int maxParticles = 100;
    Real maxMass = -1;
    int numParticles = 0;
    int maxAttempt = 5000;
    bool silent = false;
    std::string blockedDOFs;
    std::vector<Real> PSDsizes, PSDcum;
    bool PSDcalculateMass = true, stopIfFailed = true, exactDiam = true;
    int seed = -1;
    template <class V> void visit(V& v) {
        GlobalEngine::visit(v);
        v.attr("massFlowRate", massFlowRate, "Mass flow rate [kg/s]");
        v.attr("rMin", rMin, "Minimum radius of generated spheres (uniform distribution)");
        v.attr("rMax", rMax, "Maximum radius of generated spheres (uniform distribution)");
        v.attr("vMin", vMin, "Minimum velocity norm of generated spheres (uniform distribution)");
        v.attr("vMax", vMax, "Maximum velocity norm of generated spheres (uniform distribution)");
        v.attr("vAngle", vAngle, "Maximum angle by which the initial sphere velocity deviates from the normal (as in the reference, the velocity follows the normal exactly)");
        v.attr("normal", normal, "Orientation of the region's geometry, direction of particle's velocites if normalVel is not set.");
        v.attr("normalVel", normalVel, "Direction of particle's velocites.");
        v.attr("materialId", materialId, "Shared material id to use for newly created spheres (can be negative to count from the end)");
        v.attr("mask", mask, "groupMask to apply for newly created spheres (not positive: the body's default mask)");
        v.attr("color", color, "Use the color for newly created particles, if specified (components >= 0)");
        v.attr("ids", ids, "ids of created bodies");
        v.attr("totalMass", totalMass, "Mass of spheres that was produced so far.");
        v.attr("totalVolume", totalVolume, "Volume of spheres that was produced so far.");
        v.attr("goalMass", goalMass, "Total mass that should be attained at the end of the current step.");
        v.attr("maxParticles", maxParticles, "The number of particles at which to stop generating new ones regardless of massFlowRate. if maxParticles=-1 - this parameter is ignored .");
        v.attr("maxMass", maxMass, "Maximal mass at which to stop generating new particles regardless of massFlowRate. if maxMass=-1 - this parameter is ignored.");
        v.attr("numParticles", numParticles, "Cummulative number of particles produces so far");
        v.attr("maxAttempt", maxAttempt, "Maximum number of attempts to position a new sphere randomly.");
        v.attr("silent", silent, "If true no complain about excessing maxAttempt.");
        v.attr("blockedDOFs", blockedDOFs, "Blocked degress of freedom");
        v.attr("PSDsizes", PSDsizes, "PSD-dispersion, sizes of cells, Diameter [m]");
        v.attr("PSDcum", PSDcum, "PSD-dispersion, cumulative procent meanings [-]");
        v.attr("PSDcalculateMass", PSDcalculateMass, "PSD-Input is in mass (true), otherwise the number of particles will be considered.");
        v.attr("stopIfFailed", stopIfFailed, "If true, the SpheresFactory stops (sets massFlowRate=0), when maximal number of attempts to insert particle exceed.");
        v.attr("exactDiam", exactDiam, "If true, the particles only with the defined in PSDsizes diameters will be created. Otherwise the diameter will be randomly chosen in the range [PSDsizes[i-1]:PSDsizes[i]], in this case the length of PSDsizes should be  more on 1, than the length of PSDcum.");
        v.attr("seed", seed, "Seed of the engine's random generator (mt19937); negative: a random seed (not in the reference). Setting it restarts the sequence.");
    }
    void action() override;

protected:
    // A random position for the center of a sphere of radius r in the region (derived engines).
    virtual Vector3r pickRandomPosition(Real r);
    // Throws std::invalid_argument naming the attribute when the region is not defined.
    virtual void checkRegion() const;
    // Axis-aligned box holding every position pickRandomPosition can return.
    virtual void regionBounds(Vector3r& lo, Vector3r& hi) const;
    Real uniform01() { return std::uniform_real_distribution<Real>(0, 1)(rng); }
    std::mt19937 rng;

private:
    bool rngSeeded = false;
    int seededWith = -1;
    // Per PSD class: number and mass of the spheres made (which class is made next).
    std::vector<long long> psdCount;
    std::vector<Real> psdMass;
    void seedRng();
    void checkInput(bool psd) const;
    int pickPsdClass();
};

} // namespace yade
