// A periodic engine that appends lines to one text file (ForceRecorder, TorqueRecorder...).
#pragma once
#include <core/PeriodicEngine.hpp>
#include <fstream>
#include <memory>
#include <string>

namespace yade {

class Recorder : public PeriodicEngine {
public:
    static constexpr const char* classDoc =
            "Periodic engine that writes lines to one text file (file): opened on its first run, emptied first with truncate; "
            "with addIterNum each run writes to a new file, file-<iteration>.";
    std::string file;
    bool truncate = false, addIterNum = false;
    template <class V> void visit(V& v) {
        PeriodicEngine::visit(v);
        v.attr("file", file, "Name of the file written to");
        v.attr("truncate", truncate, "Empty the file when it is opened (else lines are appended to it)");
        v.attr("addIterNum", addIterNum, "Write each run to its own file, named file-<iteration>");
    }

protected:
    // The stream of this run: (re)opened when the name changed or with addIterNum; throws
    // std::runtime_error naming the file when it cannot be opened.
    std::ostream& out();

private:
    std::shared_ptr<std::ofstream> stream;
    std::string openName;
};

} // namespace yade
