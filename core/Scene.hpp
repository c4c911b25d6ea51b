// The whole simulation: bodies, interactions, forces, materials, engines and time (1.2.1).
#pragma once
#include <core/BodyContainer.hpp>
#include <core/Cell.hpp>
#include <core/EnergyTracker.hpp>
#include <core/Engine.hpp>
#include <core/ForceContainer.hpp>
#include <core/InteractionContainer.hpp>
#include <core/MotionRecord.hpp>
#include <map>
#include <mutex>

namespace yade {

class Scene {
public:
    BodyContainer bodies;
    InteractionContainer interactions;
    ForceContainer forces;
    EnergyTracker energy;
    std::vector<std::shared_ptr<Material>> materials;
    std::vector<std::shared_ptr<Serializable>> miscParams; // O.miscParams: objects saved with the scene
    long long iter = 0;
    long long stopAtIter = 0;
    Real stopAtTime = 0; // O.stopAtTime: when positive, the loop stops at the end of the step where time reaches it
    Real time = 0;
    Real dt = 1e-8;
    bool isPeriodic = false;
    // O.cell (kept while not periodic, as the reference keeps it; Python sees None then). Each step
    // deforms it first (beginStep) while isPeriodic.
    std::shared_ptr<Cell> cell = std::make_shared<Cell>();
    // O.periodic: periodic from the next step on (the pairs there are get cellDist zero; the collider
    // sees the change and starts afresh).
    void setPeriodic(bool periodic);
    // Cell flipping (3.6.2, utils.flipCell): the same periodic space with the cell's edges hSize·(I + flip),
    // flip integer with I + flip unimodular (zero: the flip that makes the edges least skewed); the pairs'
    // cellDist follow, so that every image stays where it is. Returns the flip applied; throws
    // std::invalid_argument for a flip that is not integer or does not keep the volume.
    Matrix3r flipCell(Matrix3r flip);
    bool trackEnergy = false;
    // O.timingEnabled: engines accumulate execTime/execCount (one clock read per engine run).
    static bool timingEnabled;
    // Unique per Scene object: engines that keep data between steps rebuild it when they find
    // themselves in another scene (engine objects can be reused after O.reset()).
    const long long serial;
    std::map<std::string, std::string> tags;
    // The contacts made during the current step, as entries of O.interactions (filled by
    // InteractionLoop, read by the integrator's stability guard), cleared at the start of each step.
    std::vector<size_t> newContacts;
    // The skin protocol: whether the positions are as the integrator left them and how far bodies
    // moved, for the collider and the interaction loop (who writes, who reads, what invalidates
    // it: core/MotionRecord.hpp).
    MotionRecord motion{*this};

    Scene();
    // O drops this scene (O.reset(), O.load()): the NumPy views of its bodies and contacts, which
    // may keep it, refuse writes from now on.
    void dropViews() {
        bodies.hot().views.invalidate();
        interactions.views->invalidate();
    }
    // Runs every engine once and advances iter and time (the rest of the step if sub-steps began it).
    void moveToNextTimeStep();
    // O.subStepping: a step in parts, one per call; subStep is the part to run next: -1 the step's
    // start, k the k-th engine, the number of engines the step's end (iter and time advance).
    bool subStepping = false;
    int subStep = -1;
    void moveToNextSubStep();

    // The engine list, or the one assigned during the current step (in effect at its end).
    const std::vector<std::shared_ptr<Engine>>& getEngines() const { return hasNextEngines ? nextEngines : engines; }
    // The list the current step runs, and the one assigned during it (empty if none), for O._currEngines / O._nextEngines.
    const std::vector<std::shared_ptr<Engine>>& currentEngines() const { return engines; }
    const std::vector<std::shared_ptr<Engine>>& pendingEngines() const { return nextEngines; }
    // Takes effect at once, or at the end of the current step if the loop is inside a step.
    void setEngines(const std::vector<std::shared_ptr<Engine>>& e);
    void setDt(Real value); // throws std::invalid_argument unless finite and >= 0

    Body::id_t appendBody(const std::shared_ptr<Body>& b);
    void eraseBody(Body::id_t id); // removes the body's interactions too
    int appendMaterial(const std::shared_ptr<Material>& m);
    void setThreads(int n);
    int threads() const { return forces.threads(); }
    // The engine whose action threw last, as "Class labeled 'label'" (empty if none has thrown):
    // the loop names it when an error stops a run.
    std::string failedEngine;
    // Runs e unless dead or not activated; if it throws, records failedEngine (the innermost engine
    // that threw, when one engine runs others: ParallelEngine) and rethrows.
    void runEngine(Engine& e);

private:
    std::vector<std::shared_ptr<Engine>> engines, nextEngines;
    bool hasNextEngines = false, inStep = false;
    std::mutex enginesMutex;
    void beginStep();
    void runEngineAction(Engine& e); // (timed while timingEnabled)
    void leaveStep(); // inStep off; an O.engines assigned during the step takes effect
};

} // namespace yade
