// Physical properties of a contact (stiffness, forces...), produced by an Ip2 functor (1.2.1).
#pragma once
#include <lib/factory/ClassRegistry.hpp>
#include <string>

namespace yade {

class IPhys : public Serializable {
public:
    static constexpr const char* classDoc = "Physical properties of a contact (stiffnesses, forces; the manual's IPhys), computed by an Ip2 functor.";
    template <class V> void visit(V& v) { Serializable::visit(v); }
    // What in this contact can make a body's spin grow without bound although O.dt is below the
    // critical step of the stiffnesses (3.5.18): a sentence for NewtonIntegrator's message on an
    // unstable run, naming the attributes and what to change; empty (the default) where nothing can.
    virtual std::string diagnoseSpin() const { return std::string(); }
    // The record of a contact this object shows (an object that Python holds while the contact's
    // values live in a ContactPool), or null: its own members. See lib/factory/ClassRegistry.hpp.
    Serializable* viewTarget() const { return target; }
    void setViewTarget(Serializable* t) { target = t; }
    YADE_INDEXABLE_ROOT(IPhys)

private:
    Serializable* target = nullptr;
};

} // namespace yade
