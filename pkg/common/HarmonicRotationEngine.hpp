// Harmonic oscillation of the rotation angle: angularVelocity = -A·ω·sin(ω·t + fi), ω = 2π·f.
#pragma once
#include <pkg/common/RotationEngine.hpp>

namespace yade {

class HarmonicRotationEngine : public RotationEngine {
public:
    static constexpr const char* classDoc = "RotationEngine whose angularVelocity is set every step to -A·ω·sin(ω·t + fi), ω = 2π·f: the angle oscillates as A·(cos(ω·t + fi) - cos(fi)).";
    Real A = 0;
    Real f = 0;
    Real fi = M_PI / 2;
    template <class V> void visit(V& v) {
        RotationEngine::visit(v);
        v.attr("A", A, "Amplitude of the angle [rad]", Attr::finite);
        v.attr("f", f, "Frequency [Hz]", Attr::finite);
        v.attr("fi", fi, "Initial phase [rad]", Attr::finite);
    }
    void apply(const std::vector<int>& bodyIds) override;
};

} // namespace yade
