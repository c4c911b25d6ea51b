// Base of the scene generators (1.1.3): objects whose attributes describe a scene and whose load()
// builds it into O (TriaxialTest).
#pragma once
#include <lib/factory/ClassRegistry.hpp>

namespace yade {

class FileGenerator : public Serializable {
public:
    static constexpr const char* classDoc = "Base of the scene generators: set the attributes, then load() builds the scene into O (replacing the current one).";
    template <class V> void visit(V& v) { Serializable::visit(v); }
};

} // namespace yade
