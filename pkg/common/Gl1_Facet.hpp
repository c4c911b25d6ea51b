// Draws facets in the 3D view (class-wide settings, as in the reference).
#pragma once
#include <pkg/common/Facet.hpp>
#include <pkg/common/GlFunctors.hpp>

namespace yade {

class Gl1_Facet : public GlFunctorOf<GlShapeFunctor, Facet> {
public:
    static constexpr const char* classDoc = "Draws facets in the 3D view: their edges, filled unless wire.";
    inline static bool normals = false;
    template <class V> void visit(V& v) {
        GlShapeFunctor::visit(v);
        v.attr("normals", normals, "Also draw each facet's normal and its edges' normals", Attr::classWide);
    }
    void gather(const Shape& s, const State& st, DisplayItem& d) const override {
        const Matrix3r R = st.ori().toRotationMatrix();
        for (const Vector3r& v : static_cast<const Facet&>(s).vertices) d.triangles->push_back(st.pos() + R * v);
    }
};

} // namespace yade
