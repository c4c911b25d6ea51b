#include <pkg/common/Sphere.hpp>
#include <pkg/common/Wall.hpp>
#include <pkg/dem/localframe/Ig2_Wall_Sphere_L3Geom.hpp>

namespace yade {

bool Ig2_Wall_Sphere_L3Geom::goContact(const Shape& s1, const Shape& s2, const Kinematics& k1, const Kinematics& k2, bool force, Contact& c) {
    const Wall& wall = static_cast<const Wall&>(s1);
    const Real radius = static_cast<const Sphere&>(s2).radius;
    const int ax = wall.axis;
    const Real dist = k2.pos[ax] - k1.pos[ax]; // signed distance of the centre from the wall
    if (!c.geom && !force && std::abs(dist) > radius) return false;
    Vector3r normal = Vector3r::Zero();
    normal[ax] = wall.sense == 0 ? (dist > 0 ? 1 : -1) : wall.sense;
    Vector3r contPt = k2.pos;
    contPt[ax] = k1.pos[ax];
    handleSpheresLikeContact(c, k1, k2, normal, contPt, std::abs(dist) - radius, 0, radius);
    return true;
}

} // namespace yade
