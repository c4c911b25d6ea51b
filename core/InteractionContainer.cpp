#include <core/InteractionContainer.hpp>
#include <algorithm>
#include <limits>
#include <stdexcept>

namespace yade {

const InteractionContainer::Ptr InteractionContainer::none;

long InteractionContainer::findIndex(id_t a, id_t b) const {
    if (a < 0 || b < 0 || (size_t)a >= partners.size() || (size_t)b >= partners.size()) return -1;
    const auto& pa = partners[a];
    const auto& pb = partners[b];
    const auto& shorter = pa.size() <= pb.size() ? pa : pb;
    const id_t other = pa.size() <= pb.size() ? b : a;
    for (const Partner& p : shorter)
        if (p.other == other) return (long)p.k;
    return -1;
}

const InteractionContainer::Ptr& InteractionContainer::find(id_t a, id_t b) const {
    const long k = findIndex(a, b);
    return k < 0 ? none : (*this)[(size_t)k];
}

const InteractionContainer::Ptr& InteractionContainer::operator[](size_t k) const {
    Ptr& I = linIntrs[k];
    if (!I) I = std::make_shared<Interaction>(pairIds[2 * k], pairIds[2 * k + 1]);
    return I;
}

InteractionContainer::~InteractionContainer() {
    for (const Ptr& I : linIntrs)
        if (I) I->erased = true;
}

bool InteractionContainer::append(id_t a, id_t b, Ptr I) {
    if (a < 0 || b < 0 || a == b) throw std::invalid_argument("interaction needs two distinct non-negative ids");
    if (I && I->erased) throw std::invalid_argument("this interaction was erased; make a new one");
    if (size() >= std::numeric_limits<uint32_t>::max()) throw std::length_error("too many interactions");
    resizeBodies((size_t)std::max(a, b) + 1);
    if (findIndex(a, b) >= 0) return false;
    const uint32_t k = (uint32_t)size();
    wasReal.push_back(I && I->isReal());
    objects.push_back(I ? Objects{I->geom.get(), I->phys.get()} : Objects{});
    linIntrs.push_back(std::move(I));
    pairIds.push_back(a);
    pairIds.push_back(b);
    partners[a].push_back(Partner{b, k});
    partners[b].push_back(Partner{a, k});
    ++changes;
    return true;
}

bool InteractionContainer::insert(const Ptr& I) {
    if (!I) throw std::invalid_argument("None is not an interaction");
    return append(I->id1, I->id2, I);
}

bool InteractionContainer::insertPotential(id_t a, id_t b) { return append(a, b, nullptr); }

void InteractionContainer::unlinkPartner(id_t from, id_t other) {
    auto& list = partners[from];
    for (size_t i = 0; i < list.size(); ++i)
        if (list[i].other == other) {
            list[i] = list.back();
            list.pop_back();
            return;
        }
}

void InteractionContainer::relinkPartner(id_t from, uint32_t oldK, uint32_t newK) {
    for (Partner& p : partners[from])
        if (p.k == oldK) {
            p.k = newK;
            return;
        }
}

bool InteractionContainer::erase(id_t a, id_t b) {
    const long k = findIndex(a, b);
    if (k < 0) return false;
    eraseAt((size_t)k);
    return true;
}

void InteractionContainer::eraseAt(size_t idx) {
    const id_t a = pairIds[2 * idx], b = pairIds[2 * idx + 1];
    if (linIntrs[idx]) linIntrs[idx]->erased = true;
    unlinkPartner(a, b);
    unlinkPartner(b, a);
    const size_t last = size() - 1;
    if (idx != last) { // the last entry fills the hole, with all its columns
        linIntrs[idx] = std::move(linIntrs[last]);
        pairIds[2 * idx] = pairIds[2 * last];
        pairIds[2 * idx + 1] = pairIds[2 * last + 1];
        wasReal[idx] = wasReal[last];
        objects[idx] = objects[last];
        relinkPartner(pairIds[2 * idx], (uint32_t)last, (uint32_t)idx);
        relinkPartner(pairIds[2 * idx + 1], (uint32_t)last, (uint32_t)idx);
    }
    linIntrs.pop_back();
    pairIds.resize(2 * last);
    wasReal.pop_back();
    objects.pop_back();
    ++changes;
}

void InteractionContainer::reserve(size_t n) {
    if (n <= size()) return;
    linIntrs.reserve(n);
    pairIds.reserve(2 * n);
    wasReal.reserve(n);
    objects.reserve(n);
}

void InteractionContainer::clear() {
    for (const Ptr& I : linIntrs)
        if (I) I->erased = true;
    linIntrs.clear();
    pairIds.clear();
    wasReal.clear();
    objects.clear();
    for (auto& p : partners) p.clear();
    ++changes;
}

void InteractionContainer::endContact(size_t k) {
    Ptr& I = linIntrs[k];
    if (I.use_count() == 1) I.reset(); // (its ids are in the columns)
    else if (I) I->reset();
    objects[k] = Objects();
}

void InteractionContainer::syncObjects() {
    objects.resize(size());
    for (size_t k = 0; k < size(); ++k) {
        const Interaction* I = linIntrs[k].get();
        objects[k] = I ? Objects{I->geom.get(), I->phys.get()} : Objects{};
    }
}

size_t InteractionContainer::countReal() const {
    size_t n = 0;
    for (size_t k = 0; k < size(); ++k) n += isReal(k);
    return n;
}

std::vector<InteractionContainer::Ptr> InteractionContainer::withBody(id_t id) const {
    std::vector<Ptr> r;
    if (id < 0 || (size_t)id >= partners.size()) return r;
    for (const Partner& p : partners[id])
        if (linIntrs[p.k]) r.push_back(linIntrs[p.k]);
    return r;
}

void InteractionContainer::eraseBody(id_t id) {
    if (id < 0 || (size_t)id >= partners.size()) return;
    while (!partners[id].empty()) eraseAt(partners[id].back().k);
}

Interaction& Contact::interaction() const { return I ? *I : *(*owner)[(size_t)k]; }

} // namespace yade
