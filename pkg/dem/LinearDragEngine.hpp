// Linear (Stokes) drag of a viscous medium on spheres.
#pragma once
#include <core/Engine.hpp>

namespace yade {

class LinearDragEngine : public PartialEngine {
public:
    static constexpr const char* classDoc =
            "Viscous (Stokes) drag on the spheres of ids, added to their force every step: F = -b·v, b = 6·pi·nu·r "
            "(bodies that are not spheres get nothing).";
    Real nu = 0.001;
    template <class V> void visit(V& v) {
        PartialEngine::visit(v);
        v.attr("nu", nu, "Dynamic viscosity of the medium [Pa·s]", Attr::finite);
    }
    void action() override;
};

} // namespace yade
