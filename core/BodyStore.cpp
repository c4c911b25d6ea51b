#include <core/BodyStore.hpp>
#include <algorithm>
#include <stdexcept>

namespace yade {

void BodyStore::resize(size_t n) {
    size_t most = pos.maxSize();
    for (size_t m : {vel.maxSize(), angVel.maxSize(), inertia.maxSize(), ori.maxSize(), mass.maxSize(), blockedDOFsMask.maxSize(),
                 mask.maxSize(), isDamped.maxSize(), exists.maxSize(), radius.maxSize()})
        most = std::min(most, m);
    if (n > most) throw std::length_error("more than " + std::to_string(most) + " bodies (the address space reserved for them)");
    const BodyHot hole;
    pos.resize(n, hole.pos);
    vel.resize(n, hole.vel);
    angVel.resize(n, hole.angVel);
    inertia.resize(n, hole.inertia);
    ori.resize(n, hole.ori);
    mass.resize(n, hole.mass);
    blockedDOFsMask.resize(n, hole.blockedDOFsMask);
    mask.resize(n, hole.mask);
    isDamped.resize(n, hole.isDamped);
    exists.resize(n, false);
}

BodyHot BodyStore::get(size_t id) const {
    BodyHot r;
    r.pos = pos[id];
    r.vel = vel[id];
    r.angVel = angVel[id];
    r.ori = ori[id];
    r.inertia = inertia[id];
    r.mass = mass[id];
    r.blockedDOFsMask = blockedDOFsMask[id];
    r.mask = mask[id];
    r.isDamped = isDamped[id];
    r.exists = exists[id];
    return r;
}

void BodyStore::set(size_t id, const BodyHot& r) {
    pos[id] = r.pos;
    vel[id] = r.vel;
    angVel[id] = r.angVel;
    ori[id] = r.ori;
    inertia[id] = r.inertia;
    mass[id] = r.mass;
    blockedDOFsMask[id] = r.blockedDOFsMask;
    mask[id] = r.mask;
    isDamped[id] = r.isDamped;
    exists[id] = r.exists;
}

void* BodyStore::fieldAddress(std::ptrdiff_t offset, size_t id) {
    static const BodyHot proto;
    const char* base = reinterpret_cast<const char*>(&proto);
    auto at = [&](const void* member) { return reinterpret_cast<const char*>(member) - base; };
    if (offset == at(&proto.pos)) return &pos[id];
    if (offset == at(&proto.vel)) return &vel[id];
    if (offset == at(&proto.angVel)) return &angVel[id];
    if (offset == at(&proto.ori)) return &ori[id];
    if (offset == at(&proto.inertia)) return &inertia[id];
    if (offset == at(&proto.mass)) return &mass[id];
    if (offset == at(&proto.blockedDOFsMask)) return &blockedDOFsMask[id];
    if (offset == at(&proto.mask)) return &mask[id];
    if (offset == at(&proto.isDamped)) return &isDamped[id];
    if (offset == at(&proto.exists)) return &exists[id];
    throw std::logic_error("BodyStore::fieldAddress: no column at offset " + std::to_string(offset));
}

} // namespace yade
