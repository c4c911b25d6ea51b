#include <iostream>
#include <lib/base/Logging.hpp>
#include <mutex>

namespace yade {

static WarningSink& sink() {
    static WarningSink s;
    return s;
}
static std::mutex sinkMutex;

void setWarningSink(WarningSink s) {
    std::lock_guard<std::mutex> lock(sinkMutex);
    sink() = std::move(s);
}

void logWarning(const std::string& message) {
    WarningSink s;
    {
        std::lock_guard<std::mutex> lock(sinkMutex);
        s = sink();
    }
    if (s) s(message); // called unlocked: the Python sink takes the GIL
    else std::cerr << "WARNING: " << message << std::endl;
}

} // namespace yade
