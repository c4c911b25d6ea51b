// Prescribed translation: vel += velocity·translationAxis for every body in ids.
#pragma once
#include <pkg/common/KinematicEngine.hpp>

namespace yade {

class TranslationEngine : public KinematicEngine {
public:
    static constexpr const char* classDoc = "Kinematic engine translating the bodies in ids: their velocity is velocity·translationAxis (the axis is normalized).";
    Real velocity = 0;
    Vector3r translationAxis = Vector3r::Zero();
    template <class V> void visit(V& v) {
        KinematicEngine::visit(v);
        v.attr("velocity", velocity, "Magnitude of the imposed velocity [m/s]; the velocity vector is velocity·translationAxis", Attr::finite);
        v.attr("translationAxis", translationAxis, "Direction of the translation (normalized when set)", Attr::finite);
    }
    void postLoad() override;
    void apply(const std::vector<int>& bodyIds) override;
};

} // namespace yade
