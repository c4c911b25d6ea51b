#include <core/Dispatcher.hpp>
#include <stdexcept>

namespace yade {

int familyIndexOf(const std::string& family, const std::string& name) {
    const ClassInfo* c = ClassRegistry::instance().find(name);
    if (!c || c->family != family) throw std::invalid_argument("'" + name + "' is not a " + family + " class");
    return c->classIndex;
}

std::vector<int> classChain(const std::string& family, int index) {
    std::vector<int> chain;
    for (int c = index; c >= 0; c = ClassRegistry::instance().parentIndex(family, c)) chain.push_back(c);
    return chain;
}

} // namespace yade
