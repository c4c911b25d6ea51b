// A sinusoidal force on a set of bodies (the force counterpart of HarmonicMotionEngine).
#pragma once
#include <core/Engine.hpp>

namespace yade {

class HarmonicForceEngine : public PartialEngine {
public:
    static constexpr const char* classDoc =
            "Adds the harmonic force A·sin(2π·f·t + fi) (componentwise, t the simulated time) to each body in ids every step; "
            "HarmonicMotionEngine with a force amplitude instead of a motion.";
    Vector3r A = Vector3r::Zero(), f = Vector3r::Zero(), fi = Vector3r::Zero();
    template <class V> void visit(V& v) {
        PartialEngine::visit(v);
        v.attr("A", A, "Amplitude of the force [N]", Attr::finite);
        v.attr("f", f, "Frequency [Hz]", Attr::finite);
        v.attr("fi", fi, "Phase [rad]", Attr::finite);
    }
    void action() override;
};

} // namespace yade
