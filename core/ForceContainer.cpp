#include <core/ForceContainer.hpp>

namespace yade {

void ForceContainer::setThreads(int n) {
    force.resize(n > 0 ? n : 1);
    torque.resize(force.size());
    resize(summedForce.size());
}

void ForceContainer::resize(size_t n) {
    for (auto* v : {&summedForce, &summedTorque, &permForce, &permTorque}) v->resize(n, Vector3r::Zero());
    for (size_t t = 0; t < force.size(); ++t) {
        force[t].resize(n, Vector3r::Zero());
        torque[t].resize(n, Vector3r::Zero());
    }
    synced = false;
}

void ForceContainer::addPermForce(int id, const Vector3r& f) {
    permForce[id] += f;
    anyPermanent = true;
    synced = false;
}

void ForceContainer::addPermTorque(int id, const Vector3r& t) {
    permTorque[id] += t;
    anyPermanent = true;
    synced = false;
}

void ForceContainer::sync() {
    if (synced) return;
    if (single()) { // forceData() and torqueData() give the buffer itself
        synced = true;
        return;
    }
    const long n = (long)summedForce.size();
    // each body's sum is done in thread-buffer order, so the result does not depend on the split
#pragma omp parallel for schedule(static) if (n > 2000)
    for (long i = 0; i < n; ++i) {
        Vector3r f = force[0][i], t = torque[0][i];
        for (size_t th = 1; th < force.size(); ++th) {
            f += force[th][i];
            t += torque[th][i];
        }
        if (anyPermanent) {
            f += permForce[i];
            t += permTorque[i];
        }
        summedForce[i] = f;
        summedTorque[i] = t;
    }
    synced = true;
}

void ForceContainer::reset() {
    const long n = (long)summedForce.size();
    const size_t nThreads = force.size();
    // split by bodies as sync() and the integrator: each thread clears the entries it reads next
    // (cache lines stay with one core; clearing whole per-thread buffers moved them between cores)
#pragma omp parallel for schedule(static) if (nThreads > 1 && n > 2000)
    for (long i = 0; i < n; ++i)
        for (size_t th = 0; th < nThreads; ++th) {
            force[th][i] = Vector3r::Zero();
            torque[th][i] = Vector3r::Zero();
        }
    synced = false;
}

} // namespace yade
