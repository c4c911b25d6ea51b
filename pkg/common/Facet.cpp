#include <pkg/common/Facet.hpp>
#include <stdexcept>

namespace yade {

void Facet::postLoad() {
    if (vertices.size() != 3) throw std::invalid_argument("Facet needs exactly 3 vertices, got " + std::to_string(vertices.size()));
    if (!(isFinite(vertices[0]) && isFinite(vertices[1]) && isFinite(vertices[2]))) return; // not set yet
    const Vector3r e[3] = {vertices[1] - vertices[0], vertices[2] - vertices[1], vertices[0] - vertices[2]};
    const Vector3r n = e[0].cross(e[1]);
    if (!(n.norm() > 0)) throw std::invalid_argument("Facet vertices are degenerate (coincident or collinear): zero area");
    area = 0.5 * n.norm();
    normal = n / (2 * area);
    for (int i = 0; i < 3; ++i) {
        ne[i] = e[i].cross(normal).normalized();
        vl[i] = vertices[i].norm();
        vu[i] = vertices[i] / vl[i];
    }
    const Real perimeter = e[0].norm() + e[1].norm() + e[2].norm();
    icr = e[0].norm() * ne[0].dot(e[2]) / perimeter; // base × height / perimeter = 2·area/perimeter
}

} // namespace yade
