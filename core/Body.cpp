#include <core/Body.hpp>
#include <stdexcept>

namespace yade {

void Body::postLoad() {
    if (!state) throw std::invalid_argument("Body.state cannot be None (give a State())");
    if (!store) return;
    if (state->boundStore() != store.get() || state->boundSlot() != id) {
        if (auto old = boundState.lock(); old && old != state) old->unbind();
        state->bind(store, id, mask);
        boundState = state;
    }
    store->mask[(size_t)id] = mask;
}

} // namespace yade
