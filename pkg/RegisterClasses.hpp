#pragma once
#include <vector>

namespace yade {
// Fills the ClassRegistry from core/classes.def and pkg/*/classes.def; safe to call twice.
void registerAllClasses();

// The registration is compiled in parts (pkg/RegisterClassesPart.ipp, included by RegisterClassesPart0-3.cpp):
// each part instantiates the registry's templates for every fourth class of the lists, so that several
// compilers share that heavy code (one translation unit took 16 minutes in the sanitizer builds).
// registerAllClasses() then runs the four parts' registrations in the lists' order (bases first).
struct ClassRegistration {
    int place;        // in the lists
    const char* name;
    void (*add)(const char* name);
};
constexpr int classRegistrationParts = 4;
void classRegistrationsPart0(std::vector<ClassRegistration>& out);
void classRegistrationsPart1(std::vector<ClassRegistration>& out);
void classRegistrationsPart2(std::vector<ClassRegistration>& out);
void classRegistrationsPart3(std::vector<ClassRegistration>& out);
} // namespace yade
