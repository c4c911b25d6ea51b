// Whole-scene measurements used from Python (utils): time steps, energies, forces.
#pragma once
#include <core/Scene.hpp>

namespace yade {
namespace Shop {
    // (3.5.22): min over spheres of r / sqrt(E/ρ), ρ = mass/volume; throws if no sphere has an elastic material.
    Real PWaveTimeStep(const Scene& scene);
    // Mean (or maximum) resultant force on dynamic bodies, gravity of the NewtonIntegrator
    // included, divided by the mean contact force; tends to 0 at static equilibrium.
    Real unbalancedForce(Scene& scene, bool useMaxForce);
    // Sum of ½mv² + ½ω·Iω over dynamic bodies (v: in a periodic cell, relative to the homogeneous field).
    // maxId (if given): the id of the body with the largest kinetic energy (-1: none)
    Real kineticEnergy(const Scene& scene, long* maxId = nullptr);
    // Box around all spheres (surfaces, or centers only).
    std::pair<Vector3r, Vector3r> aabbExtremaOfSpheres(const Scene& scene, bool centers);
    // Total volume of the spheres whose mask shares a bit with `mask` (0 or -1: all).
    Real spheresVolume(const Scene& scene, int mask);
    // Number of real interactions of each body whose position is inside [lo, hi].
    std::vector<int> coordinations(const Scene& scene, const Vector3r& lo, const Vector3r& hi);
    // The spheres whose mask shares a bit with `mask` (-1: all), in id order: id, center, radius and
    // the index of their material in O.materials (-1 if none); for yade.export.
    struct SphereColumns {
        std::vector<int> ids, matIds;
        std::vector<Vector3r> pos;
        std::vector<Real> radius;
    };
    SphereColumns sphereColumns(const Scene& scene, int mask);
    // Total mass of the spheres whose mask shares a bit with `mask` (0 or -1: all).
    Real spheresMass(const Scene& scene, int mask);
} // namespace Shop
} // namespace yade
