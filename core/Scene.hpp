// The whole simulation: bodies, interactions, forces, materials, engines and time (1.2.1).
#pragma once
#include <core/BodyContainer.hpp>
#include <core/EnergyTracker.hpp>
#include <core/Engine.hpp>
#include <core/ForceContainer.hpp>
#include <core/InteractionContainer.hpp>
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
    long long iter = 0;
    long long stopAtIter = 0;
    Real time = 0;
    Real dt = 1e-8;
    bool isPeriodic = false;
    bool trackEnergy = false;
    // O.timingEnabled: engines accumulate execTime/execCount (one clock read per engine run).
    static bool timingEnabled;
    std::map<std::string, std::string> tags;
    // Bodies that got a new contact during the current step (filled by InteractionLoop, read by
    // the integrator's stability guard), cleared at the start of each step.
    std::vector<Body::id_t> newContactBodies;

    Scene();
    // Runs every engine once and advances iter and time.
    void moveToNextTimeStep();

    // The engine list, or the one assigned during the current step (in effect at its end).
    const std::vector<std::shared_ptr<Engine>>& getEngines() const { return hasNextEngines ? nextEngines : engines; }
    // Takes effect at once, or at the end of the current step if the loop is inside a step.
    void setEngines(const std::vector<std::shared_ptr<Engine>>& e);
    void setDt(Real value); // throws std::invalid_argument unless finite and positive

    Body::id_t appendBody(const std::shared_ptr<Body>& b);
    void eraseBody(Body::id_t id); // removes the body's interactions too
    int appendMaterial(const std::shared_ptr<Material>& m);
    void setThreads(int n);
    int threads() const { return forces.threads(); }

private:
    std::vector<std::shared_ptr<Engine>> engines, nextEngines;
    bool hasNextEngines = false, inStep = false;
    std::mutex enginesMutex;
};

} // namespace yade
