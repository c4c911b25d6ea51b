// Draws boxes in the 3D view.
#pragma once
#include <pkg/common/Box.hpp>
#include <pkg/common/GlFunctors.hpp>

namespace yade {

class Gl1_Box : public GlFunctorOf<GlShapeFunctor, Box> {
public:
    static constexpr const char* classDoc = "Draws boxes in the 3D view (filled unless the body's shape is wire).";
    template <class V> void visit(V& v) { GlShapeFunctor::visit(v); }
    void gather(const Shape& s, const State&, DisplayItem& d) const override { d.size = static_cast<const Box&>(s).extents; }
};

} // namespace yade
