// Removes the spheres that left a box.
#pragma once
#include <core/PeriodicEngine.hpp>

namespace yade {

class DomainLimiter : public PeriodicEngine {
public:
    static constexpr const char* classDoc =
            "Erases the spheres whose centre is out of the axis-aligned box lo..hi (with their interactions), counting them "
            "(nDeleted) and their mass (mDeleted) and volume (vDeleted); with mask, only spheres whose mask shares a bit with it.";
    Vector3r lo = Vector3r::Zero(), hi = Vector3r::Zero();
    long long nDeleted = 0;
    Real mDeleted = 0, vDeleted = 0;
    int mask = -1;
    template <class V> void visit(V& v) {
        PeriodicEngine::visit(v);
        v.attr("lo", lo, "Lower corner of the box [m]", Attr::finite);
        v.attr("hi", hi, "Upper corner of the box [m]", Attr::finite);
        v.attr("nDeleted", nDeleted, "Number of spheres erased so far");
        v.attr("mDeleted", mDeleted, "Mass of the spheres erased so far [kg]");
        v.attr("vDeleted", vDeleted, "Volume of the spheres erased so far [m³]");
        v.attr("mask", mask, "Only spheres whose mask shares a bit with this (-1: all)");
    }
    void action() override;
};

} // namespace yade
