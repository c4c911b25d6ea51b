// Geometry of the bond of two grid nodes: ScGeom6D (the nodes are the spheres) and the
// GridConnection that made it.
#pragma once
#include <core/Body.hpp>
#include <pkg/dem/cohesive/ScGeom6D.hpp>

namespace yade {

class GridNodeGeom6D : public ScGeom6D {
public:
    static constexpr const char* classDoc =
            "Geometry of the bond of two GridNodes: ScGeom6D of the two node spheres (so penetrationDepth is 2r minus the node distance, "
            "negative for a grid) and the GridConnection body that made it.";
    std::shared_ptr<Body> connectionBody;
    template <class V> void visit(V& v) {
        ScGeom6D::visit(v);
        v.attr("connectionBody", connectionBody, "The GridConnection body linking the two nodes (set by yade.gridpfacet.gridConnection; not saved with the scene)",
                Attr::noSave);
    }
    YADE_INDEXABLE(GridNodeGeom6D)
};

} // namespace yade
