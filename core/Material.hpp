// Mechanical properties shared by bodies (1.2.1); held in O.materials.
#pragma once
#include <core/State.hpp>
#include <lib/factory/ClassRegistry.hpp>
#include <memory>

namespace yade {

class Material : public Serializable {
public:
    static constexpr const char* classDoc = "Mechanical properties shared by bodies (1.2.1): density and a label; held in O.materials.";
    int id = -1; // index in O.materials, -1 while not appended
    std::string label;
    Real density = 1000;
    template <class V> void visit(V& v) {
        Serializable::visit(v);
        v.attr("id", id, "Index in O.materials (-1 if not there); set by O.materials.append", Attr::readonly);
        v.attr("label", label, "Textual name; O.materials['label'] finds it");
        v.attr("density", density, "Density [kg/m³] (0: massless bodies, e.g. fixed walls, as in Yade)", Attr::nonNegative);
    }
    // A new State for a body of this material (a material whose bodies need more state returns its subclass;
    // utils.sphere etc. call it).
    virtual std::shared_ptr<State> newAssocState() const { return std::make_shared<State>(); }
    YADE_INDEXABLE_ROOT(Material)
};

} // namespace yade
