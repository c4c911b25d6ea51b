// Geometry of a contact between two bodies, produced by an Ig2 functor (1.2.1).
#pragma once
#include <lib/factory/ClassRegistry.hpp>

namespace yade {

class IGeom : public Serializable {
public:
    template <class V> void visit(V& v) { Serializable::visit(v); }
    YADE_INDEXABLE_ROOT(IGeom)
};

} // namespace yade
