// Integrates the motion of every body from its forces (3.5): leapfrog for positions (3.5.1),
// orientation update (3.5.2: spherical, or one of three schemes for aspherical bodies: AsphericalRotation.hpp),
// adapted Cundall damping (3.5.12).
#pragma once
#include <core/MotionRecord.hpp>
#include <core/Engine.hpp>
#include <core/Body.hpp>
#include <core/State.hpp>
#include <lib/base/ChunkQueue.hpp>
#include <memory>
#include <vector>
#include <stdexcept>
#include <string>

namespace yade {

class Scene;
struct IntegratorStep; // the constants and columns of one step (NewtonIntegrator.cpp)

// Raised when the integrator finds a diverging state; the message names the body, the step and the cause.
struct StabilityError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class NewtonIntegrator : public GlobalEngine {
public:
    static constexpr const char* classDoc = "Engine integrating the motion of every body from its forces (3.5): leapfrog positions (3.5.1), orientation update (3.5.2: spherical, or Euler's equations for aspherical bodies by the scheme rotAlgorithm chooses), Cundall's non-viscous damping (3.5.12) and gravity.";
    Real damping = 0.2;
    Vector3r gravity = Vector3r::Zero();
    bool dampGravity = true;
    Real maxVelocitySq = NaN;
    int mask = -1;
    int stabilityCheckPeriod = 100;
    bool exactAsphericalRot = true, kinSplit = false, warnNoForceReset = true;
    std::string rotAlgorithm = "Fincham1992";
    int normalizeEvery = 1;
    template <class V> void visit(V& v) {
        GlobalEngine::visit(v);
        v.attr("damping", damping, "Numerical damping coefficient λd of (3.5.12), in [0,1)", Attr::nonNegative);
        v.attr("gravity", gravity, "Gravitational acceleration applied to dynamic bodies [m/s²]", Attr::finite);
        v.attr("dampGravity", dampGravity, "Damp the gravity force too (gravity is added before damping)");
        v.attr("maxVelocitySq", maxVelocitySq, "Largest squared velocity in the last step [m²/s²]", Attr::readonly | Attr::noSave);
        v.attr("mask", mask, "Only bodies with (body.mask & mask) != 0 are moved (-1: all)");
        v.attr("stabilityCheckPeriod", stabilityCheckPeriod,
                "Every this many steps (and when O.dt changes, and for bodies with a new contact every step), stop with StabilityError if O.dt exceeds the contacts' critical step (0: only the check for non-finite states, done every step)");
        v.attr("exactAsphericalRot", exactAsphericalRot,
                "Integrate the rotation of aspherical bodies (unequal principal moments of inertia, free rotations) with Euler's equations in their principal frame by the scheme rotAlgorithm chooses (3.5.2); False: the spherical update (3.5.9) for every body");
        v.attr("rotAlgorithm", rotAlgorithm,
                "The scheme that turns aspherical bodies (exactAsphericalRot, 3.5.2): 'Fincham1992' ([Fincham1992], second order, driven by State.angMom: the scheme and the results of the reference 2023.02a, hence the default here), 'delValle2023' (SPIRAL, the manual's default, driven by State.angVel) or 'Omelyan1998' (driven by State.angVel)");
        v.attr("normalizeEvery", normalizeEvery,
                "SPIRAL and Omelyan keep the orientation's norm: it is normalized every this many steps only (1: every step; 0: never). Fincham normalizes every step.",
                Attr::nonNegative);
        v.attr("kinSplit", kinSplit, "Track the kinetic energy as two terms, translational (kinTrans) and rotational (kinRot), instead of kinetic");
        v.attr("warnNoForceReset", warnNoForceReset, "Warn when O.forces were not reset in the current step (no ForceResetter in O.engines before this engine)");
    }
    void action() override;
    void postLoad() override; // (a rotAlgorithm that is not a scheme: ValueError naming the choices)

private:
    Real lastCheckedDt = NaN;
    static constexpr long chunkBodies = 256;
    std::vector<std::unique_ptr<ChunkQueue>> queues; // per thread: its range's chunks (work stealing)
    struct EnergySums {
        Real grav = 0, kin = 0, damp = 0, kinRot = 0; // (kin: all the kinetic energy, or its translational part with kinSplit)
        bool any = false; // a dynamic body was integrated
    };
    std::vector<std::vector<EnergySums>> chunkSums; // per thread range, per chunk
    // per body: its stiffness diagonals (translations, rotations) at the last full stability check, plus the contacts made
    // since (the check of new contacts: pkg/dem/CriticalTimeStep.hpp)
    std::vector<Vector3r> stiffnessTrans, stiffnessRot;
    std::vector<char> spinning; // per body, in a step: whether its orientation is turned by its spin (the second loop)
    struct EnergyTerms {
        int grav = -1, kin = -1, kinRot = -1, damp = -1;
    };
    // What a thread found over its bodies: combined over the threads after the parallel part.
    struct Extremes {
        Real maxV2 = 0;     // the largest squared velocity
        Real maxMoved2 = 0; // the largest squared distance from the skin's reference positions
        long diverged = -1; // the largest id of a body whose new state is not finite (not written)
    };
    long long warnedNoReset = -2; // the step of the last missing-ForceResetter warning
    // The stages of a step, in order (NewtonIntegrator.cpp):
    void gatherForces(Scene& s);
    EnergyTerms energyTerms(Scene& s) const;
    IntegratorStep prepareStep(Scene& s, const MotionRecord::Write& motion);
    void prepareStealing(int threads, long n);
    void integrateShare(const IntegratorStep& st, long n, int threads, const EnergyTerms& ids, Extremes& x);
    void integrateRange(const IntegratorStep& st, long lo, long hi, EnergySums& e, Extremes& x);
    void addChunkEnergies(Scene& s, int threads, const EnergyTerms& ids) const;
    void addEnergy(Scene& s, const EnergySums& e, const EnergyTerms& id) const;
    std::string diagnose(const Scene& s, Body::id_t id, const std::string& what) const;
public:
    // (3.5.12): each component of the acceleration is multiplied by 1 - λd·sign(a·(v + a·dt/2)): reduced
    // when it increases the on-step velocity estimate, increased when it decreases it. The sign is
    // computed without branches (its value is random for bodies in contact: branches mispredict).
    // The x and y components as one pair (a vector of two lanes, the same arithmetic lane by lane):
    // the result is then stored in one piece where the compiler keeps it in memory; stored as two
    // scalars and read back as a pair (as the velocity update reads it), the read waits until the
    // stores are written to the cache (a failed store forwarding: 15 % of the integrator's time).
    static void damp(Vector3r& accel, const Vector3r& vel, Real dt, Real lambda) {
        typedef Real Pair __attribute__((vector_size(2 * sizeof(Real))));
        typedef long long PairMask __attribute__((vector_size(2 * sizeof(Real))));
        static_assert(sizeof(Real) == sizeof(long long), "the sign's lanes as integers of the size of Real");
        const Pair a = {accel[0], accel[1]}, v = {vel[0], vel[1]};
        const Pair p = a * (v + 0.5 * dt * a);
        const PairMask s = (p < 0) - (p > 0); // (comparisons give -1 or 0 per lane; NaN: 0)
        const Pair xy = a * (1 - lambda * __builtin_convertvector(s, Pair));
        const Real pz = accel[2] * (vel[2] + 0.5 * dt * accel[2]);
        const Real z = accel[2] * (1 - lambda * Real(int(pz > 0) - int(pz < 0)));
        accel = Vector3r(xy[0], xy[1], z);
    }
};

} // namespace yade
