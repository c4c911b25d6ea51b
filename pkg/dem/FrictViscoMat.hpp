// Material of the Cundall-Strack contact with viscous damping in the normal direction
// (Law2_ScGeom_FrictViscoPhys_CundallStrackVisco): a FrictMat with the damping ratio betan.
#pragma once
#include <pkg/common/FrictMat.hpp>

namespace yade {

class FrictViscoMat : public FrictMat {
public:
    static constexpr const char* classDoc =
            "Material for use with the FrictViscoPM classes: FrictMat with betan, the normal viscous damping as a fraction of the critical "
            "damping, cn = betan·cn_crit, cn_crit = 2·sqrt(m*·kn) (Ip2_FrictViscoMat_FrictViscoMat_FrictViscoPhys, "
            "Ip2_FrictMat_FrictViscoMat_FrictViscoPhys, Law2_ScGeom_FrictViscoPhys_CundallStrackVisco).";
    Real betan = 0;
    template <class V> void visit(V& v) {
        FrictMat::visit(v);
        v.attr("betan", betan, "Fraction of the critical viscous damping in the normal direction, cn/cn_crit [-] (not checked: as in the "
                               "reference, a negative value gives a negative damping)");
    }
    YADE_INDEXABLE(FrictViscoMat)
};

} // namespace yade
