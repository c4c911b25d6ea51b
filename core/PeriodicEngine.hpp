// An engine that runs only every iterPeriod steps, virtPeriod of simulated time or realPeriod
// seconds of wall time (whichever comes first), at most nDo times.
#pragma once
#include <core/Engine.hpp>

namespace yade {

class PeriodicEngine : public GlobalEngine {
public:
    static constexpr const char* classDoc = "Engine that runs only every iterPeriod steps, virtPeriod of simulated time or realPeriod seconds of wall time (whichever comes first), at most nDo times.";
    Real virtPeriod = 0, realPeriod = 0;
    long long iterPeriod = 0, nDo = -1, nDone = 0, iterLast = 0, firstIterRun = 0;
    bool initRun = false;
    Real virtLast = 0, realLast = 0;
    template <class V> void visit(V& v) {
        GlobalEngine::visit(v);
        v.attr("virtPeriod", virtPeriod, "Period of simulated time between runs (0: not used) [s]", Attr::nonNegative);
        v.attr("realPeriod", realPeriod, "Period of wall-clock time between runs (0: not used) [s]", Attr::nonNegative);
        v.attr("iterPeriod", iterPeriod, "Number of iterations between runs (0: not used)");
        v.attr("nDo", nDo, "Run at most this many times (-1: no limit)");
        v.attr("initRun", initRun, "Run also the first time the engine is reached");
        v.attr("firstIterRun", firstIterRun, "Do not run before this iteration");
        v.attr("nDone", nDone, "How many times the engine has run");
        v.attr("virtLast", virtLast, "Simulated time of the last run");
        v.attr("realLast", realLast, "Wall-clock time of the last run", Attr::noSave);
        v.attr("iterLast", iterLast, "Iteration of the last run");
    }
    PeriodicEngine();
    bool isActivated() override;
    static Real wallClock();
};

} // namespace yade
