// Geometry of a contact of a polyhedron with a polyhedron, a wall or a facet: the volume of their overlap.
#pragma once
#include <core/IGeom.hpp>

namespace yade {

class PolyhedraGeom : public IGeom {
public:
    static constexpr const char* classDoc = "Geometry of the contact of two Polyhedra (or of a Polyhedra and a Wall or Facet): the volume of their overlap, its centroid, the normal and the shear increment.";
    Real penetrationVolume = NaN;
    Real equivalentCrossSection = NaN;
    Real equivalentPenetrationDepth = NaN;
    Vector3r contactPoint = Vector3r::Zero();
    Vector3r shearInc = Vector3r::Zero();
    Vector3r normal = Vector3r::Zero();
    Vector3r twist_axis = Vector3r::Zero();
    Vector3r orthonormal_axis = Vector3r::Zero();
    template <class V> void visit(V& v) {
        IGeom::visit(v);
        v.attr("penetrationVolume", penetrationVolume, "Volume of overlap [m³]");
        v.attr("equivalentCrossSection", equivalentCrossSection, "Cross-section of the overlap, penetrationVolume^(2/3) as in the reference [m²] (not used by the law)");
        v.attr("equivalentPenetrationDepth", equivalentPenetrationDepth, "penetrationVolume / equivalentCrossSection [m] (not used by the law)");
        v.attr("contactPoint", contactPoint, "Contact point (global coordinates): the centroid of the overlap [m]");
        v.attr("shearInc", shearInc, "Shear displacement increment in the last step [m]");
        v.attr("normal", normal, "Normal direction of the interaction, from body 1 to body 2");
        v.attr("twist_axis", twist_axis, "Turn of the contact plane about the normal in the last step (half the sum of the spins along the normal, times dt)");
        v.attr("orthonormal_axis", orthonormal_axis, "Turn of the normal in the last step: previous normal × normal");
    }
    YADE_INDEXABLE(PolyhedraGeom)
};

} // namespace yade
