#include <lib/base/ViewRegistry.hpp>
#include <algorithm>

namespace yade {

void ViewRegistry::add(Client* c) {
    std::lock_guard<std::mutex> lock(mutex);
    clients.push_back(c);
    count.store(clients.size(), std::memory_order_release);
}

void ViewRegistry::remove(Client* c) {
    std::lock_guard<std::mutex> lock(mutex);
    const auto it = std::find(clients.begin(), clients.end(), c);
    if (it == clients.end()) return;
    *it = clients.back();
    clients.pop_back();
    count.store(clients.size(), std::memory_order_release);
}

void ViewRegistry::tellAll() {
    std::lock_guard<std::mutex> lock(mutex);
    for (Client* c : clients) c->stale();
    clients.clear();
    count.store(0, std::memory_order_release);
}

} // namespace yade
