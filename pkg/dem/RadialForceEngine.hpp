// A force of given magnitude pushing bodies away from an axis.
#pragma once
#include <core/Engine.hpp>

namespace yade {

class RadialForceEngine : public PartialEngine {
public:
    static constexpr const char* classDoc =
            "Adds the force fNorm directed away from the axis through axisPt along axisDir (perpendicular to it) to each body "
            "in ids every step (none to a body on the axis).";
    Vector3r axisPt = Vector3r::Zero(), axisDir = Vector3r::UnitX();
    Real fNorm = 0;
    template <class V> void visit(V& v) {
        PartialEngine::visit(v);
        v.attr("axisPt", axisPt, "A point of the axis [m]", Attr::finite);
        v.attr("axisDir", axisDir, "Direction of the axis (normalized when used)", Attr::finite);
        v.attr("fNorm", fNorm, "Magnitude of the force (negative: towards the axis) [N]", Attr::finite);
    }
    void action() override;
};

} // namespace yade
