// Saves the 3D view as image files periodically (manual "3d view", making videos): fileBase followed by a
// zero-padded counter and the format's extension. The view belongs to the GUI (yade.qt), which installs the
// taker; without a view (no display, -n) the engine says so once and takes nothing, so that scripts
// written with it run headless unchanged.
#pragma once
#include <core/PeriodicEngine.hpp>
#include <functional>

namespace yade {

class SnapshotEngine : public PeriodicEngine {
public:
    static constexpr const char* classDoc =
        "Periodic engine saving the 3D view as fileBase + a zero-padded counter + the format's extension (PNG frames "
        "for utils.makeVideo). Without a 3D view it warns once and takes nothing.";
    std::string format = "PNG", fileBase, plot;
    int counter = 0, msecSleep = 0;
    bool ignoreErrors = true;
    std::vector<std::string> snapshots;
    Real deadTimeout = 3;
    template <class V> void visit(V& v) {
        PeriodicEngine::visit(v);
        v.attr("format", format, "Image format of the snapshots (PNG, JPEG...)");
        v.attr("fileBase", fileBase, "Start of the file names; a zero-padded counter and the extension follow");
        v.attr("counter", counter, "Number of the next snapshot", Attr::nonNegative);
        v.attr("ignoreErrors", ignoreErrors, "Only warn, rather than stop, when there is no view to save");
        v.attr("snapshots", snapshots, "Files saved so far");
        v.attr("msecSleep", msecSleep, "Milliseconds to wait after each snapshot (slow graphics drivers)", Attr::nonNegative);
        v.attr("deadTimeout", deadTimeout, "Seconds to wait for the view to save a snapshot before giving up", Attr::nonNegative);
        v.attr("plot", plot, "Name of a yade.plot figure whose image is saved with each snapshot ('': none)");
    }
    void action() override;
    // Saves the view into `file`: "" when saved, else why not (noView: there is no view at all).
    using Taker = std::function<std::string(SnapshotEngine&, const std::string& file)>;
    static void setTaker(Taker taker);
    static constexpr const char* noView = "there is no 3D view (no display, or -n)";
    // The name of snapshot number `counter`, as the reference's: fileBase + 5 digits + "." + format in lower case.
    std::string fileName() const;
};

} // namespace yade
