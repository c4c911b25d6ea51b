#include <atomic>
#include <lib/base/ExternalWrites.hpp>

namespace yade {

static std::atomic<long long> count{0};

long long externalWrites() { return count.load(std::memory_order_acquire); }

void noteExternalWrite() { count.fetch_add(1, std::memory_order_acq_rel); }

} // namespace yade
