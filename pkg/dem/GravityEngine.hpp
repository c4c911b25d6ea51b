// Adds the weight m·g to every dynamic body (an alternative to NewtonIntegrator.gravity).
#pragma once
#include <core/Engine.hpp>

namespace yade {

class GravityEngine : public GlobalEngine {
public:
    static constexpr const char* classDoc = "Engine adding the weight m·g to every dynamic body (an alternative to NewtonIntegrator.gravity).";
    Vector3r gravity = Vector3r::Zero();
    int mask = 0;
    template <class V> void visit(V& v) {
        GlobalEngine::visit(v);
        v.attr("gravity", gravity, "Gravitational acceleration [m/s²]", Attr::finite);
        v.attr("mask", mask, "Applies only to bodies with (body.mask & mask) != 0 (0: all)");
    }
    void action() override;
};

} // namespace yade
