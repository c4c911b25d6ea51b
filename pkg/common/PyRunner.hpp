// Runs a Python command periodically (PeriodicEngine timing) in the script's namespace.
// The interpreter is reached through a hook that the Python module installs, so the engine
// itself does not depend on Python.
#pragma once
#include <core/PeriodicEngine.hpp>
#include <functional>

namespace yade {

class PyRunner : public PeriodicEngine {
public:
    static constexpr const char* classDoc = "Periodic engine that runs a Python command (command) in the script's namespace, with PeriodicEngine's timing.";
    std::string command;
    template <class V> void visit(V& v) {
        PeriodicEngine::visit(v);
        v.attr("command", command, "Python code to run, in the namespace of the __main__ script");
    }
    void action() override;
    using CommandRunner = std::function<void(const std::string&)>;
    static void setCommandRunner(CommandRunner runner);
    // Runs a Python command in the script's namespace (PyRunner.command, a controller's doneHook);
    // `who` names the caller if there is no interpreter. Python errors propagate as exceptions.
    static void runCommand(const std::string& command, const std::string& who = "PyRunner");
};

} // namespace yade
