// Physical properties of a contact (stiffness, forces...), produced by an Ip2 functor (1.2.1).
#pragma once
#include <lib/factory/ClassRegistry.hpp>

namespace yade {

class IPhys : public Serializable {
public:
    static constexpr const char* classDoc = "Physical properties of a contact (stiffnesses, forces; the manual's IPhys), computed by an Ip2 functor.";
    template <class V> void visit(V& v) { Serializable::visit(v); }
    // The record of a contact this object shows (an object that Python holds while the contact's
    // values live in a ContactPool), or null: its own members. See lib/factory/ClassRegistry.hpp.
    Serializable* viewTarget() const { return target; }
    void setViewTarget(Serializable* t) { target = t; }
    YADE_INDEXABLE_ROOT(IPhys)

private:
    Serializable* target = nullptr;
};

} // namespace yade
