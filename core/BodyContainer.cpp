#include <core/BodyContainer.hpp>
#include <stdexcept>

namespace yade {

BodyContainer::id_t BodyContainer::insert(const std::shared_ptr<Body>& b) {
    if (!b) throw std::invalid_argument("cannot append None to O.bodies");
    if (b->id >= 0)
        throw std::out_of_range("Body already has id " + std::to_string(b->id) + " set; appending such body (for the second time) is not allowed.");
    b->id = static_cast<id_t>(bodies.size());
    bodies.push_back(b);
    ++changes;
    return b->id;
}

void BodyContainer::erase(id_t id) {
    if (!exists(id)) throw std::out_of_range("Body #" + std::to_string(id) + " does not exist.");
    bodies[id]->id = -1;
    bodies[id].reset();
    ++changes;
}

void BodyContainer::restore(std::vector<std::shared_ptr<Body>> all, long long changeCount) {
    for (size_t i = 0; i < all.size(); ++i)
        if (all[i] && all[i]->id != (id_t)i)
            throw std::invalid_argument("body at position " + std::to_string(i) + " has id " + std::to_string(all[i]->id));
    bodies = std::move(all);
    changes = changeCount;
}

} // namespace yade
