// O.forces: generalized forces accumulated during one step (1.2.1), one force and one torque per
// body. With several OpenMP threads the bodies are split in the consecutive ranges of
// ThreadRange.hpp (the split the integrator sums and integrates by): a thread adds in place to
// the bodies of its own range, and appends what it adds to other bodies to its list of remote
// contributions. sync() adds the lists to the totals in thread order, each in the order added,
// so that a run is reproducible for a given thread count; only the few remote contributions
// (contacts across two ranges) cross between cores, and a range's entries stay with the core
// that adds to them, integrates them and zeroes them.
#pragma once
#include <core/BodyStore.hpp>
#include <lib/base/Math.hpp>
#include <atomic>
#include <vector>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace yade {

class ForceContainer {
public:
    ForceContainer() { setThreads(1); }
    void setThreads(int n);
    int threads() const { return (int)remote.size(); }
    void resize(size_t nBodies);
    size_t size() const { return force.size(); }
    void addForce(int id, const Vector3r& f) { put(thread(), {id, Contribution::force, f, Vector3r::Zero()}); }
    void addTorque(int id, const Vector3r& t) { put(thread(), {id, Contribution::torque, Vector3r::Zero(), t}); }
    // A contact's force on body 1 (its opposite on body 2) and the torques on both.
    void addContact(int id1, int id2, const Vector3r& f1, const Vector3r& t1, const Vector3r& t2) {
        const int th = thread();
        if (!remote[th].capture && owns(th, id1) && owns(th, id2)) { // the common case: both in place (as addInPlace)
            force[id1] += f1;
            torque[id1] += t1;
            force[id2] -= f1;
            torque[id2] += t2;
            markUnsynced();
            return;
        }
        put(th, {id1, Contribution::both, f1, t1});
        put(th, {id2, Contribution::both, -f1, t2});
    }
    // With one thread and nothing captured every add goes in place: a contact loop may then take
    // the totals once and add to them itself (calling markAdded() once); null otherwise (use addContact).
    Vector3r* inPlaceForces() { return remote.size() == 1 && !remote[0].capture ? force.data() : nullptr; }
    Vector3r* inPlaceTorques() { return remote.size() == 1 && !remote[0].capture ? torque.data() : nullptr; }
    void markAdded() { markUnsynced(); }
    // Forces that stay from step to step (O.forces.setPermF / setPermT): each call replaces the body's.
    void setPermForce(int id, const Vector3r& f);
    void setPermTorque(int id, const Vector3r& t);
    void clearPermanent(); // no permanent force or torque left (O.forces.reset(resetAll=True))
    const Vector3r& getForce(int id) { sync(); return force[id]; }
    const Vector3r& getTorque(int id) { sync(); return torque[id]; }
    const Vector3r& getPermForce(int id) const { return permForce[id]; }
    const Vector3r& getPermTorque(int id) const { return permTorque[id]; }
    // Adds the remote contributions (and, once per step, the permanent forces) to the totals.
    void sync();
    long long syncCount = 0; // O.forceSyncCount: syncs that had something to add (for profiling)
    // The totals (call sync() first), for loops over all bodies.
    const Vector3r* forceData() const { return force.data(); }
    const Vector3r* torqueData() const { return torque.data(); }
    // The totals to change in place after sync(), before the integrator reads them (a clump's
    // members' forces summed into the clump's: pkg/common/Clump.cpp).
    Vector3r* forceTotals() { return force.data(); }
    Vector3r* torqueTotals() { return torque.data(); }
    void reset(); // zero the per-step forces; permanent ones are kept
    long long lastReset = -1; // the step in which ForceResetter last ran (NewtonIntegrator.warnNoForceReset)
    bool hasPermanent() const { return anyPermanent; }
    // One body's share of an add: a force, a torque or both.
    struct Contribution {
        int id;
        enum Kind : char { both, force, torque } kind;
        Vector3r f, t;
    };
    // Work stealing (ChunkQueue.hpp): what the calling thread adds goes, in order, to `into`
    // until capture(nullptr); applyCaptured() then adds such a list as if the calling thread
    // added it now (so a chunk computed by another thread gives the same sums).
    using Captured = Contribution;
    void capture(std::vector<Captured>* into) { remote[thread()].capture = into; }
    void applyCaptured(const std::vector<Captured>& list);

private:
    // Written only when set: threads adding forces in parallel then only read the flag, and its
    // cache line is not passed back and forth between cores. Relaxed atomic accesses (plain loads
    // and stores on x86-64): with plain bools one thread's store and another's load were a data race.
    void markUnsynced() {
        if (synced.load(std::memory_order_relaxed)) synced.store(false, std::memory_order_relaxed);
        if (clean.load(std::memory_order_relaxed)) clean.store(false, std::memory_order_relaxed);
    }
    // whether body id is in thread th's range (with one thread: every body)
    bool owns(int th, int id) const { return id >= rangeStart[th] && id < rangeStart[th + 1]; }
    // One contribution of thread th: captured, in place (its own range) or to its remote list.
    void put(int th, const Contribution& c) {
        RemoteList& mine = remote[th];
        if (mine.capture) mine.capture->push_back(c);
        else if (!owns(th, c.id)) mine.items.push_back(c);
        else addInPlace(c);
        markUnsynced();
    }
    void addInPlace(const Contribution& c) {
        if (c.kind != Contribution::torque) force[c.id] += c.f;
        if (c.kind != Contribution::force) torque[c.id] += c.t;
    }
    void setRanges();
    int thread() const { // (with one thread, no library call)
#ifdef _OPENMP
        return remote.size() == 1 ? 0 : omp_get_thread_num();
#else
        return 0;
#endif
    }
    // [body]; the totals never move (NumPy views of them stay valid, see BodyArrays)
    StableArray<Vector3r> force{BodyStore::maxBodies}, torque{BodyStore::maxBodies};
    std::vector<Vector3r> permForce, permTorque;
    struct alignas(64) RemoteList { // (a cache line each: the threads append to their own lists at the same time)
        std::vector<Contribution> items; // to other ranges, in the order added
        std::vector<Captured>* capture = nullptr;
    };
    std::vector<RemoteList> remote; // [thread]
    std::vector<int> rangeStart; // thread t's range: rangeStart[t] .. rangeStart[t + 1] - 1
    std::atomic<bool> synced{true}; // (set by any thread adding forces: markUnsynced)
    bool anyPermanent = false;
    bool permInTotals = false;     // this step's totals include the permanent forces
    std::atomic<bool> clean{true}; // every total is zero and no list holds anything (as synced)
};

} // namespace yade
