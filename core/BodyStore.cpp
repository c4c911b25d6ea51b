#include <core/BodyStore.hpp>
#include <algorithm>
#include <stdexcept>

namespace yade {

void BodyStore::resize(size_t n) {
    const size_t most = std::min({rows.maxSize(), ori.maxSize(), radius.maxSize()});
    if (n > most) throw std::length_error("more than " + std::to_string(most) + " bodies (the address space reserved for them)");
    rows.resize(n); // (holes: exists is false)
    ori.resize(n, Quaternionr::Identity());
}

BodyHot BodyStore::get(size_t id) const {
    const BodyRow& w = rows[id];
    BodyHot r;
    r.pos = w.pos;
    r.vel = w.vel;
    r.angVel = w.angVel;
    r.ori = ori[id];
    r.inertia = w.inertia;
    r.mass = w.mass;
    r.blockedDOFsMask = w.blockedDOFsMask;
    r.mask = w.mask;
    r.isDamped = w.isDamped;
    r.exists = w.exists;
    return r;
}

void BodyStore::set(size_t id, const BodyHot& r) {
    BodyRow& w = rows[id];
    w.pos = r.pos;
    w.vel = r.vel;
    w.angVel = r.angVel;
    ori[id] = r.ori;
    w.inertia = r.inertia;
    w.mass = r.mass;
    w.blockedDOFsMask = r.blockedDOFsMask;
    w.mask = r.mask;
    w.isDamped = r.isDamped;
    w.exists = r.exists;
}

void* BodyStore::fieldAddress(std::ptrdiff_t offset, size_t id) {
    static const BodyHot proto;
    const char* base = reinterpret_cast<const char*>(&proto);
    auto at = [&](const void* member) { return reinterpret_cast<const char*>(member) - base; };
    BodyRow& w = rows[id];
    if (offset == at(&proto.pos)) return &w.pos;
    if (offset == at(&proto.vel)) return &w.vel;
    if (offset == at(&proto.angVel)) return &w.angVel;
    if (offset == at(&proto.ori)) return &ori[id];
    if (offset == at(&proto.inertia)) return &w.inertia;
    if (offset == at(&proto.mass)) return &w.mass;
    if (offset == at(&proto.blockedDOFsMask)) return &w.blockedDOFsMask;
    if (offset == at(&proto.mask)) return &w.mask;
    if (offset == at(&proto.isDamped)) return &w.isDamped;
    if (offset == at(&proto.exists)) return &w.exists;
    throw std::logic_error("BodyStore::fieldAddress: no column at offset " + std::to_string(offset));
}

} // namespace yade
