// Physics of a Cundall-Strack contact with normal viscous damping
// (Law2_ScGeom_FrictViscoPhys_CundallStrackVisco): FrictPhys with the viscous constant cn, the
// critical one cn_crit and the viscous part of the normal force.
#pragma once
#include <pkg/dem/FrictPhys.hpp>

namespace yade {

class FrictViscoPhys : public FrictPhys {
public:
    static constexpr const char* classDoc =
            "Contact physics of the FrictViscoPM type (Law2_ScGeom_FrictViscoPhys_CundallStrackVisco): FrictPhys with a normal viscous "
            "constant cn = betan·cn_crit; normalForce includes the viscous part, -normalViscous.";
    Real cn_crit = NaN, cn = NaN;
    Vector3r normalViscous = Vector3r::Zero();
    template <class V> void visit(V& v) {
        FrictPhys::visit(v);
        v.attr("cn_crit", cn_crit, "Critical normal viscous constant, 2·sqrt(m*·kn) with m* the effective mass [N·s/m] (NaN when betan is 0)");
        v.attr("cn", cn, "Normal viscous constant, betan·cn_crit [N·s/m]");
        v.attr("normalViscous", normalViscous, "Normal viscous force, cn·v_n·n with v_n the normal relative velocity (negative while the "
                                               "bodies approach); normalForce = kn·u·n - normalViscous [N]");
    }
    YADE_INDEXABLE(FrictViscoPhys)
};

} // namespace yade
