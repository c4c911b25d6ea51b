// Contact physics with rotational stiffnesses: FrictPhys with a rolling (kr) and a twisting (ktw)
// stiffness, the base of CohFrictPhys.
#pragma once
#include <pkg/dem/FrictPhys.hpp>

namespace yade {

class RotStiffFrictPhys : public FrictPhys {
public:
    static constexpr const char* classDoc = "FrictPhys with a rolling stiffness kr and a twisting stiffness ktw, for laws with contact moments.";
    Real kr = 0, ktw = 0;
    template <class V> void visit(V& v) {
        FrictPhys::visit(v);
        v.attr("kr", kr, "Rolling (bending) stiffness [N·m/rad]");
        v.attr("ktw", ktw, "Twisting stiffness [N·m/rad]");
    }
    YADE_INDEXABLE(RotStiffFrictPhys)
};

} // namespace yade
