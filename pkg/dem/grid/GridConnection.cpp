#include <core/Scene.hpp>
#include <pkg/dem/grid/GridConnection.hpp>
#include <stdexcept>

namespace yade {

void GridConnection::nodePositions(const Scene& scene, Vector3r& p1, Vector3r& p2) const {
    if (!node1 || !node2) throw std::runtime_error("GridConnection: node1 and node2 must both be set (use yade.gridpfacet.gridConnection)");
    const auto body = [&](const std::shared_ptr<Body>& n) -> const Body& {
        // the scene's body of that id (a node read back from a file is a copy of it)
        if (!scene.bodies.exists(n->id)) throw std::runtime_error("GridConnection: its node #" + std::to_string(n->id) + " is not in O.bodies");
        return *scene.bodies[n->id];
    };
    p1 = body(node1).state->pos();
    p2 = body(node2).state->pos();
    if (periodic) p2 += scene.cell->hSize * cellDist.cast<Real>();
}

Real GridConnection::getLength(const Scene& scene) const {
    Vector3r p1, p2;
    nodePositions(scene, p1, p2);
    return (p2 - p1).norm();
}

} // namespace yade
