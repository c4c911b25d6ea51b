#include <core/State.hpp>
#include <cstring>
#include <stdexcept>

namespace yade {

static const char dofLetters[] = "xyzXYZ";

Vector3r State::rot() const {
    AngleAxisr aa(refOri.conjugate() * ori());
    return aa.axis() * aa.angle();
}

std::string State::blockedDOFs() const {
    std::string s;
    for (int i = 0; i < 6; ++i)
        if (blockedDOFsMask() & (1 << i)) s += dofLetters[i];
    return s;
}

void State::setBlockedDOFs(const std::string& dofs) {
    int mask = DOF_NONE;
    for (char c : dofs) {
        const char* p = c ? std::strchr(dofLetters, c) : nullptr;
        if (!p) throw std::invalid_argument(std::string("blockedDOFs: invalid letter '") + c + "' (use letters from 'xyzXYZ')");
        mask |= 1 << (p - dofLetters);
    }
    blockedDOFsMask() = mask | (blockedDOFsMask() & clumpedBit);
}

void State::bind(const std::shared_ptr<BodyStore>& s, long id, int bodyMask) {
    if (slot >= 0) unbind();
    if ((size_t)id >= s->size()) s->resize((size_t)id + 1);
    BodyHot r = *local;
    r.mask = bodyMask;
    r.exists = true;
    s->set((size_t)id, r);
    store = s;
    slot = id;
    local.reset();
}

void State::unbind() {
    if (slot < 0) return;
    local = std::make_unique<BodyHot>(store->get((size_t)slot));
    local->exists = false;
    store->exists[(size_t)slot] = false;
    slot = -1;
}

} // namespace yade
