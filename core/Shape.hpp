// Geometry of a particle, independent of its position and orientation (1.2.1).
#pragma once
#include <lib/factory/ClassRegistry.hpp>

namespace yade {

class Clump;

class Shape : public Serializable {
public:
    static constexpr const char* classDoc = "Geometry of a particle (1.2.1), independent of its position and orientation (those are in State).";
    Vector3r color = Vector3r(1, 1, 1);
    bool wire = false;
    bool highlight = false;
    template <class V> void visit(V& v) {
        Serializable::visit(v);
        v.attr("color", color, "Color for rendering (RGB, components in [0,1])");
        v.attr("wire", wire, "Render as wire frame");
        v.attr("highlight", highlight, "Highlight this shape in the 3D view");
    }
    // The shape as a clump's (pkg/common/Clump.hpp), null for the others; members(): a clump's member
    // ids, null for other shapes or when its lists disagree (checks of O.bodies read it).
    virtual const Clump* asClump() const { return nullptr; }
    virtual const std::vector<int>* clumpMembers() const { return nullptr; }
    YADE_INDEXABLE_ROOT(Shape)
};

} // namespace yade
