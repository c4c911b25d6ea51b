// Draws force chains in the 3D view: each contact's normal force as a cylinder between the two
// centres whose radius grows with the force (OpenGLRenderer.intrPhys). Class-wide settings, as in the reference.
#pragma once
#include <limits>
#include <pkg/common/GlFunctors.hpp>
#include <pkg/dem/FrictPhys.hpp>

namespace yade {

class Gl1_NormPhys : public GlFunctorOf<GlIPhysFunctor, NormPhys> {
public:
    static constexpr const char* classDoc =
        "Draws each contact's normal force as a cylinder between the centres, of radius maxRadius·|Fn|/maxFn (force chains).";
    inline static Real maxFn = 0, refRadius = std::numeric_limits<Real>::infinity(), maxRadius = -1;
    inline static Real maxWeakFn = std::numeric_limits<Real>::quiet_NaN(), weakScale = 1;
    inline static int signFilter = 0, slices = 6, stacks = 1, weakFilter = 0;
    template <class V> void visit(V& v) {
        GlIPhysFunctor::visit(v);
        v.attr("maxFn", maxFn, "Largest normal force seen, which gets radius maxRadius (updated while drawing)", Attr::classWide);
        v.attr("signFilter", signFilter, "Draw only compressive (-1) or tensile (+1) forces; 0: both", Attr::classWide);
        v.attr("refRadius", refRadius, "Reference radius: the smallest body radius seen (updated while drawing)", Attr::classWide);
        v.attr("maxRadius", maxRadius, "Radius of the cylinder of the largest force; negative: refRadius/2", Attr::classWide);
        v.attr("slices", slices, "Slices of each cylinder (negative: a line of width ∝ the force)", Attr::classWide);
        v.attr("stacks", stacks, "Stacks of each cylinder", Attr::classWide);
        v.attr("maxWeakFn", maxWeakFn, "Forces below this are 'weak' (weakFilter); NaN: set from the mean force while drawing", Attr::classWide);
        v.attr("weakFilter", weakFilter, "Draw only the strong (1) or the weak (-1) contacts; 0: both", Attr::classWide);
        v.attr("weakScale", weakScale, "Scale of the weak contacts' radius", Attr::classWide);
    }
};

} // namespace yade
