#include <core/InteractionContainer.hpp>
#include <algorithm>

namespace yade {

const InteractionContainer::Ptr InteractionContainer::none;

const InteractionContainer::Ptr& InteractionContainer::find(id_t a, id_t b) const {
    if (a < 0 || b < 0 || (size_t)a >= partners.size() || (size_t)b >= partners.size()) return none;
    const auto& pa = partners[a];
    const auto& pb = partners[b];
    const auto& shorter = pa.size() <= pb.size() ? pa : pb;
    const id_t other = pa.size() <= pb.size() ? b : a;
    for (const auto& p : shorter)
        if (p.first == other) return linIntrs[p.second->linIndex];
    return none;
}

bool InteractionContainer::insert(const Ptr& I) {
    const id_t a = I->id1, b = I->id2;
    if (a < 0 || b < 0 || a == b) throw std::invalid_argument("interaction needs two distinct non-negative ids");
    resizeBodies((size_t)std::max(a, b) + 1);
    if (find(a, b)) return false;
    I->linIndex = linIntrs.size();
    linIntrs.push_back(I);
    pairIds.push_back(a);
    pairIds.push_back(b);
    wasReal.push_back(I->isReal());
    objects.push_back(Objects{I->geom.get(), I->phys.get()});
    partners[a].emplace_back(b, I.get());
    partners[b].emplace_back(a, I.get());
    ++changes;
    return true;
}

void InteractionContainer::unlinkPartner(id_t from, id_t other) {
    auto& list = partners[from];
    for (size_t i = 0; i < list.size(); ++i)
        if (list[i].first == other) {
            list[i] = list.back();
            list.pop_back();
            return;
        }
}

bool InteractionContainer::erase(id_t a, id_t b) {
    const Ptr& I = find(a, b);
    if (!I) return false;
    const size_t idx = I->linIndex;
    unlinkPartner(a, b);
    unlinkPartner(b, a);
    const size_t last = linIntrs.size() - 1;
    if (idx != last) {
        linIntrs[idx] = std::move(linIntrs.back());
        linIntrs[idx]->linIndex = idx;
        pairIds[2 * idx] = pairIds[2 * last];
        pairIds[2 * idx + 1] = pairIds[2 * last + 1];
        wasReal[idx] = wasReal[last];
        objects[idx] = objects[last];
    }
    linIntrs.pop_back();
    pairIds.resize(2 * last);
    wasReal.pop_back();
    objects.pop_back();
    ++changes;
    return true;
}

void InteractionContainer::clear() {
    linIntrs.clear();
    pairIds.clear();
    wasReal.clear();
    objects.clear();
    for (auto& p : partners) p.clear();
    ++changes;
}

void InteractionContainer::syncObjects() {
    objects.resize(linIntrs.size());
    for (size_t k = 0; k < linIntrs.size(); ++k) objects[k] = Objects{linIntrs[k]->geom.get(), linIntrs[k]->phys.get()};
}

size_t InteractionContainer::countReal() const {
    return std::count_if(linIntrs.begin(), linIntrs.end(), [](const Ptr& I) { return I->isReal(); });
}

std::vector<InteractionContainer::Ptr> InteractionContainer::withBody(id_t id) const {
    std::vector<Ptr> r;
    if (id < 0 || (size_t)id >= partners.size()) return r;
    for (const auto& p : partners[id]) r.push_back(linIntrs[p.second->linIndex]);
    return r;
}

void InteractionContainer::eraseBody(id_t id) {
    if (id < 0 || (size_t)id >= partners.size()) return;
    while (!partners[id].empty()) erase(id, partners[id].back().first);
}

} // namespace yade
