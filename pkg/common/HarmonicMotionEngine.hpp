// Harmonic oscillation of position, each component separately: v = -A·ω·sin(ω·t + fi), ω = 2π·f,
// so that x = x0 + A·(cos(ω·t + fi) - cos(fi)).
#pragma once
#include <pkg/common/KinematicEngine.hpp>

namespace yade {

class HarmonicMotionEngine : public KinematicEngine {
public:
    static constexpr const char* classDoc = "Kinematic engine oscillating the bodies in ids, each component separately: velocity -A·ω·sin(ω·t + fi) with ω = 2π·f, i.e. position x0 + A·(cos(ω·t + fi) - cos(fi)); the default fi = π/2 oscillates around the initial position.";
    Vector3r A = Vector3r::Zero();
    Vector3r f = Vector3r::Zero();
    Vector3r fi = Vector3r::Constant(M_PI / 2);
    template <class V> void visit(V& v) {
        KinematicEngine::visit(v);
        v.attr("A", A, "Amplitude of each component [m]", Attr::finite);
        v.attr("f", f, "Frequency of each component [Hz]", Attr::finite);
        v.attr("fi", fi, "Initial phase of each component [rad]", Attr::finite);
    }
    void apply(const std::vector<int>& bodyIds) override;
};

} // namespace yade
