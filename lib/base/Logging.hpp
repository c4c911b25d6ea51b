// Warnings from the engine: printed to stderr, or routed to Python's warnings by the module.
#pragma once
#include <functional>
#include <string>

namespace yade {
using WarningSink = std::function<void(const std::string&)>;
void setWarningSink(WarningSink sink);
void logWarning(const std::string& message);
} // namespace yade
