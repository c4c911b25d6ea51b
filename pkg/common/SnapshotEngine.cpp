#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <lib/base/Logging.hpp>
#include <pkg/common/SnapshotEngine.hpp>
#include <stdexcept>
#include <thread>

namespace yade {

static SnapshotEngine::Taker& taker() {
    static SnapshotEngine::Taker t;
    return t;
}

void SnapshotEngine::setTaker(Taker t) { taker() = std::move(t); }

std::string SnapshotEngine::fileName() const {
    char digits[32];
    std::snprintf(digits, sizeof digits, "%05d", counter);
    std::string ext = format;
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return fileBase + digits + "." + ext;
}

void SnapshotEngine::action() {
    const std::string file = fileName();
    const std::string error = taker() ? taker()(*this, file) : std::string(noView);
    if (error.empty()) {
        snapshots.push_back(file);
        ++counter;
        if (msecSleep > 0) std::this_thread::sleep_for(std::chrono::milliseconds(msecSleep));
        return;
    }
    if (!ignoreErrors) throw std::runtime_error("SnapshotEngine: " + error + " (SnapshotEngine.ignoreErrors is False)");
    if (error == noView) { // headless: said once, and the run goes on
        static std::atomic<bool> warned{false};
        if (!warned.exchange(true)) logWarning(std::string("SnapshotEngine: ") + noView + "; no snapshot is saved");
        return;
    }
    logWarning("SnapshotEngine: " + error + "; the engine stops (dead = True)");
    dead = true; // as the reference does when its view does not answer
}

} // namespace yade
