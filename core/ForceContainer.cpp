#include <algorithm>
#include <core/ForceContainer.hpp>
#include <cstring>
#include <lib/base/ThreadRange.hpp>

namespace yade {

void ForceContainer::setThreads(int n) {
    sync(); // what the lists hold goes into the totals, which stay
    remote.resize(n > 0 ? n : 1);
    setRanges();
}

void ForceContainer::resize(size_t n) {
    if (n == force.size()) return; // (called at every step)
    sync();
    force.resize(n, Vector3r::Zero());
    torque.resize(n, Vector3r::Zero());
    for (auto* v : {&permForce, &permTorque}) v->resize(n, Vector3r::Zero());
    setRanges();
    synced = false;
}

void ForceContainer::setRanges() {
    const long parts = (long)remote.size(), n = (long)force.size();
    rangeStart.resize(parts + 1);
    for (long t = 0; t < parts; ++t) rangeStart[t] = (int)threadRange(n, t, parts).first;
    rangeStart[parts] = (int)n;
}

void ForceContainer::setPermForce(int id, const Vector3r& f) {
    if (permInTotals) force[id] += f - permForce[id]; // (this step's totals got the permanent forces already)
    permForce[id] = f;
    anyPermanent = true;
    synced = clean = false;
}

void ForceContainer::setPermTorque(int id, const Vector3r& t) {
    if (permInTotals) torque[id] += t - permTorque[id];
    permTorque[id] = t;
    anyPermanent = true;
    synced = clean = false;
}

void ForceContainer::clearPermanent() {
    sync(); // (what threads added stays in the totals)
    for (size_t i = 0; i < permForce.size(); ++i) {
        if (permInTotals) {
            force[i] -= permForce[i];
            torque[i] -= permTorque[i];
        }
        permForce[i] = permTorque[i] = Vector3r::Zero();
    }
    anyPermanent = permInTotals = false;
}

// in thread order, each list in the order added: the order of the contributions to a body
// depends only on which thread added which, never on timing
void ForceContainer::sync() {
    if (synced) return;
    ++syncCount;
    const size_t n = force.size();
    for (auto& list : remote) {
        for (const Contribution& c : list.items)
            if ((size_t)c.id < n) addInPlace(c); // (bodies removed since: dropped)
        list.items.clear();
    }
    if (anyPermanent && !permInTotals) {
        for (size_t i = 0; i < n; ++i) {
            force[i] += permForce[i];
            torque[i] += permTorque[i];
        }
        permInTotals = true;
        clean = false;
    }
    synced = true;
}

void ForceContainer::applyCaptured(const std::vector<Captured>& list) {
    const int th = thread();
    for (const Captured& c : list) put(th, c);
}

void ForceContainer::reset() {
    permInTotals = synced = false;
    if (clean) return; // nothing was added since the last reset
    for (auto& list : remote) list.items.clear();
    const long n = (long)force.size();
    const long nThreads = (long)remote.size();
    // each thread clears its own range: the entries it adds to next (their cache lines stay with one core)
#pragma omp parallel if (nThreads > 1 && n > 2000) num_threads(nThreads)
    {
        const auto range = myThreadRange(n);
        std::memset(static_cast<void*>(force.data() + range.first), 0, sizeof(Vector3r) * (range.second - range.first));
        std::memset(static_cast<void*>(torque.data() + range.first), 0, sizeof(Vector3r) * (range.second - range.first));
    }
    clean = true;
}

} // namespace yade
