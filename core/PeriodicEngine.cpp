#include <chrono>
#include <core/PeriodicEngine.hpp>
#include <core/Scene.hpp>

namespace yade {

Real PeriodicEngine::wallClock() {
    using namespace std::chrono;
    return duration<Real>(system_clock::now().time_since_epoch()).count();
}

PeriodicEngine::PeriodicEngine() : realLast(wallClock()) {}

bool PeriodicEngine::isActivated() {
    const Real virtNow = scene->time, realNow = wallClock();
    const long long iterNow = scene->iter;
    const bool first = !reachedOnce;
    reachedOnce = true;
    if (iterNow < firstIterRun || (nDo >= 0 && nDone >= nDo)) return false;
    const bool due = (first && initRun) || (virtPeriod > 0 && virtNow - virtLast >= virtPeriod)
            || (realPeriod > 0 && realNow - realLast >= realPeriod) || (iterPeriod > 0 && iterNow - iterLast >= iterPeriod);
    if (!due) return false;
    virtLast = virtNow;
    realLast = realNow;
    iterLast = iterNow;
    ++nDone;
    return true;
}

} // namespace yade
