// Draws walls in the 3D view as a grid (class-wide settings, as in the reference).
#pragma once
#include <pkg/common/GlFunctors.hpp>
#include <pkg/common/Wall.hpp>

namespace yade {

class Gl1_Wall : public GlFunctorOf<GlShapeFunctor, Wall> {
public:
    static constexpr const char* classDoc = "Draws walls in the 3D view as a square grid around the wall's position.";
    inline static int div = 20;
    template <class V> void visit(V& v) {
        GlShapeFunctor::visit(v);
        v.attr("div", div, "Number of grid lines along each side", Attr::classWide | Attr::positive);
    }
    void gather(const Shape& s, const State&, DisplayItem& d) const override {
        const Wall& w = static_cast<const Wall&>(s);
        d.size = Vector3r(w.axis, w.sense, 0);
    }
};

} // namespace yade
