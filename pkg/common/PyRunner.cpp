#include <pkg/common/PyRunner.hpp>
#include <stdexcept>

namespace yade {

static PyRunner::CommandRunner& runner() {
    static PyRunner::CommandRunner r;
    return r;
}

void PyRunner::setCommandRunner(CommandRunner r) { runner() = std::move(r); }

void PyRunner::runCommand(const std::string& command, const std::string& who) {
    if (!runner()) throw std::runtime_error(who + ": no Python interpreter to run '" + command + "'");
    const std::string cmd = command; // the command may replace itself (checker.command = ...)
    runner()(cmd);
}

void PyRunner::action() {
    if (command.empty()) return;
    runCommand(command);
}

} // namespace yade
