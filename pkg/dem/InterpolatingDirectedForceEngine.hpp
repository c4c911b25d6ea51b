// A force of constant direction whose magnitude follows a table in time.
#pragma once
#include <pkg/dem/ForceEngine.hpp>
#include <vector>

namespace yade {

class InterpolatingDirectedForceEngine : public ForceEngine {
public:
    static constexpr const char* classDoc =
            "ForceEngine whose force is direction (normalized) times a magnitude interpolated linearly in the table times, "
            "magnitudes at the simulated time: the first magnitude before the first time, the last after the last; with wrap "
            "the table repeats (time taken modulo its span).";
    std::vector<Real> times, magnitudes;
    Vector3r direction = Vector3r::UnitX();
    bool wrap = false;
    template <class V> void visit(V& v) {
        ForceEngine::visit(v);
        v.attr("times", times, "Time points of the table, not decreasing [s]");
        v.attr("magnitudes", magnitudes, "Force magnitudes at those times [N]");
        v.attr("direction", direction, "Direction of the force (normalized when used)", Attr::finite);
        v.attr("wrap", wrap, "Repeat the table in time");
    }
    void action() override;
};

} // namespace yade
