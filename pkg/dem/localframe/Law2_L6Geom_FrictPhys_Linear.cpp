#include <core/Scene.hpp>
#include <pkg/dem/localframe/Law2_L6Geom_FrictPhys_Linear.hpp>

namespace yade {

bool Law2_L6Geom_FrictPhys_Linear::goLocal(L3Geom& geom, FrictPhys& p, Body::id_t id1, Body::id_t id2) {
    const L6Geom& g = static_cast<const L6Geom&>(geom);
    const Vector3r u = g.u - g.u0, phi = g.phi - g.phi0;
    const Vector3r F(p.kn * u[0], p.ks * u[1], p.ks * u[2]);
    const Vector3r T(p.kn * charLen * phi[0], p.ks * charLen * phi[1], p.ks * charLen * phi[2]);
    applyLocal(g, p, id1, id2, F, &T);
    return true;
}

} // namespace yade
