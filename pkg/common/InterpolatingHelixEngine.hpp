// A helix whose angular velocity follows a table in time.
#pragma once
#include <pkg/common/HelixEngine.hpp>
#include <vector>

namespace yade {

class InterpolatingHelixEngine : public HelixEngine {
public:
    static constexpr const char* classDoc =
            "HelixEngine whose angularVelocity is interpolated linearly in the table times, angularVelocities at the simulated "
            "time (the first value before the first time, the last after the last; with wrap the table repeats), and whose "
            "linearVelocity is slope·angularVelocity.";
    std::vector<Real> times, angularVelocities;
    bool wrap = false;
    Real slope = 0;
    template <class V> void visit(V& v) {
        HelixEngine::visit(v);
        v.attr("times", times, "Time points of the table, not decreasing [s]");
        v.attr("angularVelocities", angularVelocities, "Angular velocities at those times [rad/s]");
        v.attr("wrap", wrap, "Repeat the table in time");
        v.attr("slope", slope, "Axial displacement per radian turned [m/rad]", Attr::finite);
    }
    void apply(const std::vector<int>& bodyIds) override;
};

} // namespace yade
