// Quadratic drag of a medium on spheres (the drag equation).
#pragma once
#include <core/Engine.hpp>

namespace yade {

class DragEngine : public PartialEngine {
public:
    static constexpr const char* classDoc =
            "Drag of a medium on the spheres of ids, added to their force every step: F = -v/|v|·(1/2·Rho·|v|²·Cd·A), A = pi·r² "
            "(bodies that are not spheres, or at rest, get nothing).";
    Real Rho = 1.225, Cd = 0.47;
    template <class V> void visit(V& v) {
        PartialEngine::visit(v);
        v.attr("Rho", Rho, "Density of the medium [kg/m³]", Attr::finite);
        v.attr("Cd", Cd, "Drag coefficient", Attr::finite);
    }
    void action() override;
};

} // namespace yade
