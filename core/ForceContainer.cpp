#include <algorithm>
#include <core/ForceContainer.hpp>
#include <lib/base/ThreadRange.hpp>
#include <cstring>

namespace yade {

void ForceContainer::setThreads(int n) {
    if (n <= 1 && inSums && !anyPermanent) { // one buffer will be the sum: it takes what was gathered
        for (size_t i = 0; i < summedForce.size(); ++i) {
            force[0][i] += summedForce[i];
            torque[0][i] += summedTorque[i];
        }
        inSums = false;
        clean = false;
    }
    force.resize(n > 0 ? n : 1);
    torque.resize(force.size());
    resize(summedForce.size());
}

void ForceContainer::resize(size_t n) {
    if (n == summedForce.size() && force.back().size() == n) return; // (called at every step)
    for (auto* v : {&summedForce, &summedTorque, &permForce, &permTorque}) v->resize(n, Vector3r::Zero());
    for (size_t t = 0; t < force.size(); ++t) {
        force[t].resize(n, Vector3r::Zero());
        torque[t].resize(n, Vector3r::Zero());
    }
    synced = clean = false;
}

void ForceContainer::addPermForce(int id, const Vector3r& f) {
    permForce[id] += f;
    if (inSums) summedForce[id] += f; // (the sums got the permanent forces when this step's first sync made them)
    anyPermanent = true;
    synced = false;
}

void ForceContainer::addPermTorque(int id, const Vector3r& t) {
    permTorque[id] += t;
    if (inSums) summedTorque[id] += t;
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
#pragma omp parallel if (n > 2000)
    {
        const auto range = myThreadRange(n);
        syncRange(range.first, range.second);
    }
    gathered();
}

// each body's sum is done in thread-buffer order, so the result does not depend on the split
void ForceContainer::syncRange(long begin, long end) {
    const int nBuffers = (int)force.size();
    Vector3r* sf = summedForce.data();
    Vector3r* st = summedTorque.data();
    const Vector3r* pf = permForce.data();
    const Vector3r* pt = permTorque.data();
    const bool add = inSums, perm = anyPermanent && !inSums;
    for (long i = begin; i < end; ++i) {
        Vector3r f = force[0][i], t = torque[0][i];
        for (int th = 1; th < nBuffers; ++th) {
            f += force[th][i];
            t += torque[th][i];
        }
        if (add) {
            sf[i] += f;
            st[i] += t;
            continue;
        }
        if (perm) {
            f += pf[i];
            t += pt[i];
        }
        sf[i] = f;
        st[i] = t;
    }
    zeroBuffers(begin, end);
}

void ForceContainer::zeroBuffers(long begin, long end) {
    for (size_t th = 0; th < force.size(); ++th) { // (plain zero bytes: the same as Vector3r::Zero())
        std::memset(static_cast<void*>(force[th].data() + begin), 0, sizeof(Vector3r) * (end - begin));
        std::memset(static_cast<void*>(torque[th].data() + begin), 0, sizeof(Vector3r) * (end - begin));
    }
}

void ForceContainer::reset() {
    inSums = synced = false;
    if (clean) return; // the last sync zeroed the buffers and nothing was added since
    const long n = (long)summedForce.size();
    const long nThreads = (long)force.size();
    // split by bodies as sync() and the integrator: each thread clears the entries it reads next
    // (cache lines stay with one core; clearing whole per-thread buffers moved them between cores)
#pragma omp parallel if (nThreads > 1 && n > 2000)
    {
        const auto range = myThreadRange(n);
        zeroBuffers(range.first, range.second);
    }
    clean = true;
}

} // namespace yade
