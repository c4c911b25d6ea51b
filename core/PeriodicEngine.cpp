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
    if (iterNow < firstIterRun) return false;
    auto fire = [&] {
        virtLast = virtNow;
        realLast = realNow;
        iterLast = iterNow;
        ++nDone;
    };
    const bool due = (virtPeriod > 0 && virtNow - virtLast >= virtPeriod) || (realPeriod > 0 && realNow - realLast >= realPeriod)
            || (iterPeriod > 0 && iterNow - iterLast >= iterPeriod) || (firstIterRun > 0 && iterNow == firstIterRun);
    if ((nDo < 0 || nDone < nDo) && due) {
        fire();
        return true;
    }
    if (nDone == 0) { // first time reached: periods count from now (the call counts in nDone, as in Yade)
        fire();
        return initRun;
    }
    return false;
}

} // namespace yade
