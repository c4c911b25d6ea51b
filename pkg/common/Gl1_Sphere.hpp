// Draws spheres in the 3D view; its settings are class-wide (Gl1_Sphere.quality = 2), as in the reference.
#pragma once
#include <pkg/common/GlFunctors.hpp>
#include <pkg/common/Sphere.hpp>

namespace yade {

class Gl1_Sphere : public GlFunctorOf<GlShapeFunctor, Sphere> {
public:
    static constexpr const char* classDoc = "Draws spheres in the 3D view (settings shared by all spheres: Gl1_Sphere.quality = 2).";
    inline static Real quality = 1, circleRelThickness = 0.2;
    inline static bool wire = false, stripes = false, localSpecView = true, circleView = false;
    inline static int glutSlices = 12, glutStacks = 6;
    inline static std::string circleAllowedRotationAxis = "z";
    template <class V> void visit(V& v) {
        GlShapeFunctor::visit(v);
        v.attr("quality", quality, "Resolution of the sphere's mesh relative to the default (glutSlices, glutStacks)", Attr::classWide | Attr::positive);
        v.attr("wire", wire, "Draw spheres as wire frame", Attr::classWide);
        v.attr("stripes", stripes, "Draw stripes that show the spheres' rotation", Attr::classWide);
        v.attr("localSpecView", localSpecView, "Place the specular highlight as seen by the viewer", Attr::classWide);
        v.attr("glutSlices", glutSlices, "Slices of the sphere's mesh at quality 1", Attr::classWide | Attr::positive);
        v.attr("glutStacks", glutStacks, "Stacks of the sphere's mesh at quality 1", Attr::classWide | Attr::positive);
        v.attr("circleView", circleView, "Draw spheres as circles facing the viewer (2D simulations)", Attr::classWide);
        v.attr("circleRelThickness", circleRelThickness, "Thickness of the circles of circleView, relative to the radius", Attr::classWide | Attr::positive);
        v.attr("circleAllowedRotationAxis", circleAllowedRotationAxis, "Axis ('x', 'y' or 'z') about which circleView's circles turn", Attr::classWide);
    }
    void gather(const Shape& s, const State&, DisplayItem& d) const override { d.size[0] = static_cast<const Sphere&>(s).radius; }
};

} // namespace yade
