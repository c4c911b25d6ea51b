#include <atomic>
#include <lib/base/Logging.hpp>
#include <pkg/common/SnapshotEngine.hpp>
#include <stdexcept>

namespace yade {

void SnapshotEngine::action() {
    // No build has a 3D view yet (gui/README.md): every run is headless.
    const std::string message = "SnapshotEngine: there is no 3D view (no display, -n, or a build without the GUI); no snapshot is saved";
    if (!ignoreErrors) throw std::runtime_error(message + " (SnapshotEngine.ignoreErrors is False)");
    static std::atomic<bool> warned{false};
    if (!warned.exchange(true)) logWarning(message);
}

} // namespace yade
