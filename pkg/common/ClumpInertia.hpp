// The mass, centroid and inertia of a clump from its members (3.5.3): summed over the members (their
// overlaps counted twice, as the reference does by default), or integrated over the union of member
// spheres on a regular grid (appendClumped(..., discretization=N)).
#pragma once
#include <lib/base/Math.hpp>
#include <vector>

namespace yade {

// One member as the sums need it.
struct ClumpPart {
    Vector3r pos;
    Quaternionr ori;
    Real mass;
    Vector3r inertia; // principal moments, in the member's frame
    Real radius;      // a sphere's radius (NaN: not a sphere)
    Real density;     // of its material (NaN: none)
};

struct MassProperties {
    Real mass = 0;
    Vector3r centroid = Vector3r::Zero();
    Matrix3r inertia = Matrix3r::Zero(); // about the centroid, in global axes
};

// Each member's mass, and its inertia moved to the clump's centroid (parallel axes).
MassProperties summedMassProperties(const std::vector<ClumpPart>& parts);

// Cells of size min(extent of the members' box)/n, centred at min + (k + 1/2)·size, inside any member
// sphere; each of mass density·size³ with its own inertia (a cube's, mass·size²/6). The density is
// the first member's (as the reference). Every member must be a sphere (std::invalid_argument).
MassProperties gridMassProperties(const std::vector<ClumpPart>& parts, int n);

// The principal moments (ascending) and the rotation from the principal frame to the global one
// (right-handed) of a symmetric inertia tensor.
struct PrincipalAxes {
    Vector3r moments;
    Quaternionr ori;
};
PrincipalAxes principalAxes(const Matrix3r& inertia);

} // namespace yade
