// A cylinder between two grid nodes, with rounded ends (the Minkowski sum of the segment and a
// sphere): the shape that other bodies touch; its nodes carry its mass and its motion.
#pragma once
#include <core/Body.hpp>
#include <pkg/common/Sphere.hpp>

namespace yade {

class Scene;

class GridConnection : public Sphere {
public:
    static constexpr const char* classDoc =
            "Cylinder linking two GridNodes (Effeindzourou et al. 2016, Bourrier et al. 2013): the segment node1-node2 swept by a "
            "sphere of the given radius. It does not move by itself: it follows its nodes, and the forces of its contacts go to them. "
            "Make it with yade.gridpfacet.gridConnection.";
    std::shared_ptr<Body> node1, node2;
    bool periodic = false;
    Vector3i cellDist = Vector3i::Zero();
    template <class V> void visit(V& v) {
        Sphere::visit(v);
        v.attr("node1", node1, "First GridNode body of the connection");
        v.attr("node2", node2, "Second GridNode body of the connection");
        v.attr("periodic", periodic, "Whether the connection crosses the periodic cell (node2 seen in the cell cellDist away)");
        v.attr("cellDist", cellDist, "For a periodic connection, the cell of node2's image, in cell sizes");
    }
    // The nodes' positions now (the scene's bodies of node1's and node2's ids); throws without nodes.
    void nodePositions(const Scene& scene, Vector3r& p1, Vector3r& p2) const;
    Real getLength(const Scene& scene) const;
    YADE_INDEXABLE(GridConnection)
};

} // namespace yade
