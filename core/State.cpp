#include <core/State.hpp>
#include <cstring>
#include <stdexcept>

namespace yade {

static const char dofLetters[] = "xyzXYZ";

Vector3r State::rot() const {
    AngleAxisr aa(refOri.conjugate() * ori);
    return aa.axis() * aa.angle();
}

std::string State::blockedDOFs() const {
    std::string s;
    for (int i = 0; i < 6; ++i)
        if (blockedDOFsMask & (1 << i)) s += dofLetters[i];
    return s;
}

void State::setBlockedDOFs(const std::string& dofs) {
    int mask = DOF_NONE;
    for (char c : dofs) {
        const char* p = c ? std::strchr(dofLetters, c) : nullptr;
        if (!p) throw std::invalid_argument(std::string("blockedDOFs: invalid letter '") + c + "' (use letters from 'xyzXYZ')");
        mask |= 1 << (p - dofLetters);
    }
    blockedDOFsMask = mask;
}

} // namespace yade
