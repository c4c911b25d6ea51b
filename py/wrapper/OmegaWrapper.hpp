#pragma once
#include <core/Omega.hpp>
#include <pybind11/pybind11.h>

namespace yade {
Omega& omega(); // the one controller behind Python's O
// Real interactions of a body that is in the current scene.
pybind11::list bodyInteractions(const Body& b);
// Binds Omega (as the object O) and the container proxies O.bodies, O.interactions, ...
void bindOmega(pybind11::module_& m);
// Held while Python adds or removes bodies or interactions: a loop running in the background is
// stopped at the end of its step first (the GIL released meanwhile: a PyRunner may need it) and
// started again afterwards, so that no engine sees the containers change under it. From inside
// the loop (a PyRunner) the change happens at once, between two engines.
class BetweenSteps {
public:
    // yieldToLoop: the 3D view's frames, which give up (held() false) rather than wait for a loop that
    // waits for the GUI (Omega::interrupt).
    explicit BetweenSteps(bool yieldToLoop = false) {
        Omega& o = omega();
        if (o.inLoopThread() || !o.isRunning()) return;
        pybind11::gil_scoped_release nogil;
        resume = o.interrupt(yieldToLoop);
        held_ = !o.isRunning();
    }
    bool held() const { return held_; }
    ~BetweenSteps() {
        if (!resume) return;
        pybind11::gil_scoped_release nogil;
        omega().run(-1); // stopAtIter is kept: a run of n steps still ends where it would have
    }
    BetweenSteps(const BetweenSteps&) = delete;
    BetweenSteps& operator=(const BetweenSteps&) = delete;

private:
    bool resume = false, held_ = true;
};

// Makes labeled engines and functors reachable by name from scripts (builtins namespace).
void injectLabels(const std::vector<std::shared_ptr<Engine>>& engines);
} // namespace yade
