#include <core/MotionRecord.hpp>
#include <core/Scene.hpp>
#include <lib/base/ExternalWrites.hpp>

namespace yade {

bool MotionRecord::current() const {
    const BodyContainer& bodies = scene.bodies;
    return changes == bodies.changes && count == bodies.size() && (iter == scene.iter || iter + 1 == scene.iter)
            && writes == externalWrites() && bodies.hot().writableViews == 0;
}

MotionRecord::Write MotionRecord::beginWrite(size_t n) {
    Write w;
    writesBefore = externalWrites(); // (a write from Python during the pass makes the result stale)
    w.continues = current() && iter + 1 == scene.iter;
    count = n;
    w.reference = reference && reference->size() == n ? reference->data() : nullptr;
    return w;
}

void MotionRecord::publish(const Write& w, Real maxV2, Real dt, Real moved2) {
    iter = scene.iter;
    writes = writesBefore;
    changes = scene.bodies.changes;
    maxStepLen = w.continues ? std::sqrt(maxV2) * dt : Inf; // (pos + vel·dt: each body moved |vel|·dt)
    maxMoved2 = moved2;
    maxMovedTag = w.reference ? referenceTag : -1;
}

const Vector3r* MotionRecord::positions() const { return scene.bodies.hot().pos.data(); }

void MotionRecord::setReference(std::shared_ptr<const std::vector<Vector3r>> ref, long long tag) {
    reference = std::move(ref);
    referenceTag = tag;
}

Real MotionRecord::maxMovedSince(long long tag) const { return maxMovedTag == tag && referenceTag == tag ? maxMoved2 : NaN; }

} // namespace yade
