// SpheresFactory making spheres on a disc or in a cylinder.
#pragma once
#include <pkg/dem/SpheresFactory.hpp>

namespace yade {

class CircularFactory : public SpheresFactory {
public:
    static constexpr const char* classDoc =
            "Circular geometry of the SpheresFactory region. It can be disk (given by radius and center), or cylinder (given by "
            "radius, length and center); its axis is normal. As in the reference, a center is at a uniform angle and at a distance "
            "from the axis uniform in [0, radius - r] (r: the sphere's radius), and uniform in [-length/2, length/2] along the axis.";
    Real radius = NaN, length = 0;
    Vector3r center = Vector3r::Constant(NaN);
    template <class V> void visit(V& v) {
        SpheresFactory::visit(v);
        v.attr("radius", radius, "Radius of the region");
        v.attr("length", length, "Length of the cylindrical region (0 by default)");
        v.attr("center", center, "Center of the region");
    }

protected:
    Vector3r pickRandomPosition(Real r) override;
    void checkRegion() const override;
    void regionBounds(Vector3r& lo, Vector3r& hi) const override;
};

} // namespace yade
