// Physics of a linear visco-elastic contact (Law2_ScGeom_ViscElPhys_Basic): stiffnesses kn, ks,
// viscous constants cn, cs, the elastic and viscous parts of the normal force, rolling resistance.
#pragma once
#include <pkg/dem/FrictPhys.hpp>

namespace yade {

class ViscElPhys : public FrictPhys {
public:
    static constexpr const char* classDoc =
            "Contact physics of the linear visco-elastic law (Law2_ScGeom_ViscElPhys_Basic), made from two ViscElMat by "
            "Ip2_ViscElMat_ViscElMat_ViscElPhys.";
    Real cn = NaN, cs = NaN;
    Real Fn = 0, Fv = 0;
    Real mR = 0;
    int mRtype = 1;
    template <class V> void visit(V& v) {
        FrictPhys::visit(v);
        v.attr("cn", cn, "Normal viscous constant [N·s/m]");
        v.attr("cs", cs, "Shear viscous constant [N·s/m]");
        v.attr("Fn", Fn, "Elastic part of the normal force, kn·u [N]");
        v.attr("Fv", Fv, "Viscous part of the normal force, cn·(approach speed) [N]");
        v.attr("mR", mR, "Rolling resistance coefficient");
        v.attr("mRtype", mRtype, "Rolling resistance type (ViscElMat.mRtype)");
    }
    // The rolling resistance (mR > 0): its torque grows with the relative spin.
    std::string diagnoseSpin() const override;
    YADE_INDEXABLE(ViscElPhys)
};

} // namespace yade
