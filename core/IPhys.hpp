// Physical properties of a contact (stiffness, forces...), produced by an Ip2 functor (1.2.1).
#pragma once
#include <lib/factory/ClassRegistry.hpp>

namespace yade {

class IPhys : public Serializable {
public:
    template <class V> void visit(V& v) { Serializable::visit(v); }
    YADE_INDEXABLE_ROOT(IPhys)
};

} // namespace yade
