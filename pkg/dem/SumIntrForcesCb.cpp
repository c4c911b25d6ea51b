#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/SumIntrForcesCb.hpp>
#include <iostream>
#include <stdexcept>
#include <string>

namespace yade {

void SumIntrForcesCb::stepInit(Scene&) {
    std::cerr << "(" << sum << "," << count << ")" << std::flush; // (the reference's output: default stream format, no newline)
    sum = 0;
    count = 0;
}

void SumIntrForcesCb::go(Body::id_t id1, Body::id_t id2, const IPhys& phys) {
    const auto* p = dynamic_cast<const NormShearPhys*>(&phys);
    if (!p)
        throw std::invalid_argument("SumIntrForcesCb: the physics of interaction (" + std::to_string(id1) + "," + std::to_string(id2) + ") is a "
                + phys.getClassName() + ", not a NormShearPhys");
    sum += (p->normalForce + p->shearForce).norm();
    ++count;
}

} // namespace yade
