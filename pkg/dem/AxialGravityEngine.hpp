// Acceleration of constant magnitude directed towards an axis (perpendicular to it).
#pragma once
#include <pkg/dem/FieldApplier.hpp>

namespace yade {

class AxialGravityEngine : public FieldApplier {
public:
    static constexpr const char* classDoc = "Adds to every body the force m·acceleration directed perpendicularly towards the axis through axisPoint along axisDirection, whatever the distance (bodies on the axis get none).";
    Vector3r axisPoint = Vector3r::Zero();
    Vector3r axisDirection = Vector3r::UnitX();
    Real acceleration = 0;
    int mask = 0;
    template <class V> void visit(V& v) {
        FieldApplier::visit(v);
        v.attr("axisPoint", axisPoint, "A point of the axis [m]", Attr::finite);
        v.attr("axisDirection", axisDirection, "Direction of the axis (normalized when used)", Attr::finite);
        v.attr("acceleration", acceleration, "Magnitude of the acceleration [m/s²]", Attr::finite);
        v.attr("mask", mask, "Applies only to bodies with (body.mask & mask) != 0 (0: all)");
    }
    void action() override;
};

} // namespace yade
