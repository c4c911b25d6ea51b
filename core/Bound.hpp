// Approximate volume of a body for the first pass of collision detection (1.2.1).
#pragma once
#include <lib/factory/ClassRegistry.hpp>

namespace yade {

class Bound : public Serializable {
public:
    static constexpr const char* classDoc = "Approximate volume of a body (1.2.1), used by the collider for the first, cheap pass of contact detection.";
    Vector3r color = Vector3r(1, 1, 1);
    Vector3r min = Vector3r::Constant(NaN);
    Vector3r max = Vector3r::Constant(NaN);
    long long lastUpdateIter = 0;
    Vector3r refPos = Vector3r::Constant(NaN); // position when the bound was last enlarged (Verlet)
    template <class V> void visit(V& v) {
        Serializable::visit(v);
        v.attr("color", color, "Color for rendering");
        v.attr("min", min, "Lower corner of the box [m]", Attr::readonly);
        v.attr("max", max, "Upper corner of the box [m]", Attr::readonly);
        v.attr("lastUpdateIter", lastUpdateIter, "Iteration when the bound was last updated", Attr::readonly | Attr::noSave);
        v.attr("refPos", refPos, "Body position when the bound was last computed (Verlet stride)", Attr::hidden);
    }
    YADE_INDEXABLE_ROOT(Bound)
};

} // namespace yade
