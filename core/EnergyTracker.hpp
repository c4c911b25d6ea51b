// O.energy: named energy terms. Engines add to them only when O.trackEnergy is on. A term is
// either cumulative (work, dissipation: summed over the run) or instantaneous (kinetic, elastic:
// zeroed at the start of every step). Threads add into their own slots; sync() sums them in order.
#pragma once
#include <lib/base/Math.hpp>
#include <map>
#include <string>
#include <vector>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace yade {

class EnergyTracker {
public:
    // Index of a term, creating it if needed; call outside parallel regions.
    int term(const std::string& name, bool cumulative);
    void add(int id, Real value) {
#ifdef _OPENMP
        const int t = omp_get_thread_num();
#else
        const int t = 0;
#endif
        if (captureTo[t].into) return captureTo[t].into->push_back({id, value});
        perThread[t][id] += value;
        touchedThread[t][id] = 1;
    }
    // Work stealing (as ForceContainer::capture): the calling thread's adds go, in order, to
    // `into` until capture(nullptr); applyCaptured() adds such a list as the calling thread's own.
    struct Captured {
        int id;
        Real value;
    };
    void capture(std::vector<Captured>* into);
    void applyCaptured(const std::vector<Captured>& list);
    void setThreads(int n);
    void sync();             // adds the per-thread parts into the totals
    void resetInstantaneous(); // at the start of a step
    void clear();
    Real total();
    // Terms that something has added to (as in Yade, a term appears once it is first used).
    std::vector<std::string> names();
    std::vector<Real> values();
    std::vector<bool> cumulativeFlags();
    // Restores a saved term.
    void set(const std::string& name, Real value, bool isCumulative);

private:
    std::vector<std::string> termNames;
    std::vector<Real> termValues;
    std::vector<char> cumulative, touched;
    std::map<std::string, int> index;
    std::vector<std::vector<Real>> perThread = std::vector<std::vector<Real>>(1);
    std::vector<std::vector<char>> touchedThread = std::vector<std::vector<char>>(1);
    struct alignas(64) CaptureSlot {
        std::vector<Captured>* into = nullptr;
    };
    std::vector<CaptureSlot> captureTo = std::vector<CaptureSlot>(1); // [thread]
};

} // namespace yade
