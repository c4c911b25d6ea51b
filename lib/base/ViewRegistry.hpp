// Views handed out over memory the engine owns (the NumPy arrays of O.bodies.arrays() and
// O.interactions.arrays()) that must be told when what they show stops being what the engine
// uses: the owner of the memory calls invalidate() when its content moves or is dropped (bodies
// appended or erased, a contact made or ended, the scene reset). Each client is told once, then
// forgotten. With no client, invalidate() is one atomic load (it is called in the contact loop).
#pragma once
#include <atomic>
#include <mutex>
#include <vector>

namespace yade {

class ViewRegistry {
public:
    class Client {
    public:
        // Called once, from the thread that changed the memory (an engine's, or several of them at
        // once: under the registry's lock), without Python's GIL; it must not call back the registry.
        virtual void stale() = 0;
        virtual ~Client() = default;
    };
    ViewRegistry() = default;
    ViewRegistry(const ViewRegistry&) = delete;
    ViewRegistry& operator=(const ViewRegistry&) = delete;
    void add(Client* c);
    void remove(Client* c); // (nothing if it was told already)
    void invalidate() {
        if (count.load(std::memory_order_acquire) != 0) tellAll();
    }

private:
    std::mutex mutex;
    std::vector<Client*> clients;
    std::atomic<size_t> count{0};
    void tellAll();
};

} // namespace yade
