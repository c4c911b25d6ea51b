// The linear visco-elastic contact law (Pournin et al. 2001): a spring and a dashpot in parallel in the
// normal direction, a spring and a dashpot in parallel in series with a Coulomb slider in the shear
// direction; optional rolling resistance (Zhou et al. 1999).
#pragma once
#include <core/LawDispatcher.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <pkg/dem/ViscElPhys.hpp>

namespace yade {

class Law2_ScGeom_ViscElPhys_Basic : public LawFunctorBatched<Law2_ScGeom_ViscElPhys_Basic, ScGeom, ViscElPhys> {
public:
    static constexpr const char* classDoc =
            "Linear visco-elastic law on ScGeom and ViscElPhys: normal force kn·u + cn·v_n (v_n the approach speed), none while that "
            "sum is not positive (no attraction); shear force: an elastic part updated by -ks·Δus plus the viscous -cs·v_s, the sum "
            "capped at tan(φ)·|Fn| (Coulomb); with ViscElPhys.mR > 0 a rolling-resistance torque against the relative rotation.";
    template <class V> void visit(V& v) { LawFunctor::visit(v); }
    bool go(ScGeom& geom, ViscElPhys& phys, const Contact& c);
};

} // namespace yade
