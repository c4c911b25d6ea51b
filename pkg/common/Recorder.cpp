#include <core/Scene.hpp>
#include <pkg/common/Recorder.hpp>
#include <stdexcept>

namespace yade {

std::ostream& Recorder::out() {
    const std::string name = addIterNum ? file + "-" + std::to_string(scene->iter) : file;
    if (name.empty()) throw std::invalid_argument(getClassName() + ".file is empty: give the name of the file to write to");
    if (!stream || name != openName || !stream->is_open()) {
        stream = std::make_shared<std::ofstream>(name, truncate ? std::ios::trunc : std::ios::app);
        if (!stream->is_open()) {
            stream.reset();
            throw std::runtime_error(getClassName() + ": cannot open " + name + " for writing");
        }
        openName = name;
    }
    return *stream;
}

} // namespace yade
