// Acceleration of constant magnitude directed towards one body (CentralGravityEngine in older scripts).
#pragma once
#include <pkg/dem/FieldApplier.hpp>

namespace yade {

class CentralConstantAccelerationEngine : public FieldApplier {
public:
    static constexpr const char* classDoc = "Adds to every body other than centralBody the force m·accel directed towards centralBody, whatever the distance; with reciprocal, centralBody receives the opposite of their sum.";
    int centralBody = -1;
    Real accel = 0;
    bool reciprocal = false;
    int mask = 0;
    template <class V> void visit(V& v) {
        FieldApplier::visit(v);
        v.attr("centralBody", centralBody, "Id of the body towards which the others are attracted");
        v.attr("accel", accel, "Magnitude of the acceleration [m/s²]", Attr::finite);
        v.attr("reciprocal", reciprocal, "If True, centralBody receives the opposite of the sum of the forces applied");
        v.attr("mask", mask, "Applies only to bodies with (body.mask & mask) != 0 (0: all)");
    }
    void action() override;
};

} // namespace yade
