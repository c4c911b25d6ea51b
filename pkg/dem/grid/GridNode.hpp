// A node of a grid (Effeindzourou et al. 2016): a sphere that carries the mass of the grid and is
// linked to other nodes by GridConnections; the connections it belongs to are listed here.
#pragma once
#include <memory>
#include <pkg/common/Sphere.hpp>
#include <vector>

namespace yade {

class Body;

class GridNode : public Sphere {
public:
    static constexpr const char* classDoc =
            "Node of a grid (Effeindzourou et al. 2016, Bourrier et al. 2013): a sphere that carries the mass of the GridConnections it "
            "belongs to. Nodes are linked by the cohesive contact their GridConnection makes; spheres touch the connections, not the "
            "nodes. Make them with yade.gridpfacet.gridNode.";
    // the GridConnection bodies this node belongs to (weak: a connection points to its nodes, not back)
    std::vector<std::weak_ptr<Body>> ConnList;
    template <class V> void visit(V& v) { Sphere::visit(v); }
    YADE_INDEXABLE(GridNode)
};

} // namespace yade
