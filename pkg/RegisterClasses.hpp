#pragma once
namespace yade {
// Fills the ClassRegistry from core/classes.def and pkg/*/classes.def; safe to call twice.
void registerAllClasses();
} // namespace yade
