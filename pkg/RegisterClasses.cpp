// Registers every class listed in the classes.def files (once, at start-up), in the lists' order.
#include <algorithm>
#include <pkg/RegisterClasses.hpp>

namespace yade {

void registerAllClasses() {
    static bool done = false;
    if (done) return;
    done = true;
    std::vector<ClassRegistration> all;
    classRegistrationsPart0(all);
    classRegistrationsPart1(all);
    classRegistrationsPart2(all);
    classRegistrationsPart3(all);
    std::sort(all.begin(), all.end(), [](const ClassRegistration& a, const ClassRegistration& b) { return a.place < b.place; });
    for (const ClassRegistration& r : all) r.add(r.name);
}

} // namespace yade
