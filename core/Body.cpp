#include <core/Body.hpp>
#include <atomic>
#include <stdexcept>

namespace yade {

static std::atomic<long> standIns{0};

long Body::standInsAlive() { return standIns.load(); }

void Body::postLoad() {
    if (!state) {
        if (!stateStandIn) {
            ++standIns;
            stateStandIn = std::shared_ptr<State>(new State(), [](State* s) {
                delete s;
                --standIns;
            });
        }
        state = stateStandIn;
    }
    if (!store) return;
    if (state->boundStore() != store.get() || state->boundSlot() != id) {
        if (auto old = boundState.lock(); old && old != state) old->unbind();
        state->bind(store, id, mask);
        boundState = state;
    }
    store->mask[(size_t)id] = mask;
}

} // namespace yade
