// O.forces: generalized forces accumulated during one step (1.2.1). Each OpenMP thread adds
// into its own buffer; sync() sums the buffers in thread order, so a run is reproducible.
// With several threads (or permanent forces) sync() moves the buffers' content into the sums and
// zeroes them while their cache lines are at hand, so that reset() has nothing left to clear:
// the sums then accumulate whatever later syncs of the same step gather.
#pragma once
#include <lib/base/Math.hpp>
#include <vector>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace yade {

class ForceContainer {
public:
    ForceContainer() { setThreads(1); }
    void setThreads(int n);
    int threads() const { return (int)force.size(); }
    void resize(size_t nBodies);
    size_t size() const { return summedForce.size(); }
    void addForce(int id, const Vector3r& f) {
        force[thread()][id] += f;
        markUnsynced();
    }
    void addTorque(int id, const Vector3r& t) {
        torque[thread()][id] += t;
        markUnsynced();
    }
    // A contact's force on body 1 (its opposite on body 2) and the torques on both, with one
    // lookup of the calling thread's buffers.
    void addContact(int id1, int id2, const Vector3r& f1, const Vector3r& t1, const Vector3r& t2) {
        const int th = thread();
        std::vector<Vector3r>& F = force[th];
        std::vector<Vector3r>& T = torque[th];
        F[id1] += f1;
        F[id2] -= f1;
        T[id1] += t1;
        T[id2] += t2;
        markUnsynced();
    }
    // Forces that stay from step to step (set from Python with permanent=True).
    void addPermForce(int id, const Vector3r& f);
    void addPermTorque(int id, const Vector3r& t);
    const Vector3r& getForce(int id) { sync(); return forceData()[id]; }
    const Vector3r& getTorque(int id) { sync(); return torqueData()[id]; }
    const Vector3r& getPermForce(int id) const { return permForce[id]; }
    const Vector3r& getPermTorque(int id) const { return permTorque[id]; }
    void sync();
    // sync() in parts: a parallel loop over bodies calls syncRange() on its ranges (each body
    // exactly once) before reading their sums, then gathered() once. Only where gathers().
    bool isSynced() const { return synced; }
    bool gathers() const { return !single(); }
    void syncRange(long begin, long end);
    void gathered() { inSums = clean = synced = true; }
    // The summed arrays (call sync() first), for loops over all bodies.
    // (With one thread and no permanent force the sums are the thread's buffer itself: no copy.)
    const Vector3r* forceData() const { return single() ? force[0].data() : summedForce.data(); }
    const Vector3r* torqueData() const { return single() ? torque[0].data() : summedTorque.data(); }
    void reset(); // zero the per-step forces; permanent ones are kept
    bool hasPermanent() const { return anyPermanent; }

private:
    // Written only when set: threads adding forces in parallel then only read the flag, and its
    // cache line is not passed back and forth between cores.
    void markUnsynced() {
        if (synced) synced = false;
        if (clean) clean = false;
    }
    bool single() const { return force.size() == 1 && !anyPermanent; }
    void zeroBuffers(long begin, long end); // every thread's entries of bodies begin .. end-1
    static int thread() {
#ifdef _OPENMP
        return omp_get_thread_num();
#else
        return 0;
#endif
    }
    std::vector<std::vector<Vector3r>> force, torque; // [thread][body]
    std::vector<Vector3r> summedForce, summedTorque, permForce, permTorque;
    bool synced = true, anyPermanent = false;
    bool inSums = false; // the sums hold what this step's syncs gathered (buffers zeroed since)
    bool clean = false;  // every buffer is zero
};

} // namespace yade
