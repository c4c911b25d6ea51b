// Geometry of a contact between two bodies, produced by an Ig2 functor (1.2.1).
#pragma once
#include <lib/factory/ClassRegistry.hpp>

namespace yade {

class IGeom : public Serializable {
public:
    static constexpr const char* classDoc = "Geometry of a contact between two bodies (the manual's IGeom), computed by an Ig2 functor.";
    template <class V> void visit(V& v) { Serializable::visit(v); }
    // The record of a contact this object shows (an object that Python holds while the contact's
    // values live in a ContactPool), or null: its own members. See lib/factory/ClassRegistry.hpp.
    Serializable* viewTarget() const { return target; }
    void setViewTarget(Serializable* t) { target = t; }
    YADE_INDEXABLE_ROOT(IGeom)

private:
    Serializable* target = nullptr;
};

} // namespace yade
