// SpheresFactory making spheres in an axis-aligned box.
#pragma once
#include <pkg/dem/SpheresFactory.hpp>

namespace yade {

class BoxFactory : public SpheresFactory {
public:
    static constexpr const char* classDoc = "Box geometry of the SpheresFactory region, given by extents and center: sphere centers are uniform in center ± extents (extents are half-sizes).";
    Vector3r extents = Vector3r::Constant(NaN), center = Vector3r::Constant(NaN);
    template <class V> void visit(V& v) {
        SpheresFactory::visit(v);
        v.attr("extents", extents, "Extents of the region (half-sizes)");
        v.attr("center", center, "Center of the region");
    }

protected:
    Vector3r pickRandomPosition(Real r) override;
    void checkRegion() const override;
    void regionBounds(Vector3r& lo, Vector3r& hi) const override;
};

} // namespace yade
