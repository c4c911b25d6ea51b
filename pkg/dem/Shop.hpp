// Whole-scene measurements used from Python (utils): time steps, energies, forces.
#pragma once
#include <core/Scene.hpp>

namespace yade {
namespace Shop {
    // (3.5.22): min over spheres of r / sqrt(E/ρ), ρ = mass/volume; throws if no sphere has an elastic material.
    Real PWaveTimeStep(const Scene& scene);
} // namespace Shop
} // namespace yade
