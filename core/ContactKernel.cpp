#include <core/ContactKernel.hpp>
#include <map>
#include <utility>

namespace yade {

namespace {
// (filled at start-up by registerAllClasses, before any thread runs; read-only afterwards)
std::map<std::pair<std::type_index, std::type_index>, KernelPasses::Pass>& passes() {
    static std::map<std::pair<std::type_index, std::type_index>, KernelPasses::Pass> table;
    return table;
}
} // namespace

bool KernelPasses::add(std::type_index geom, std::type_index law, Pass pass) {
    passes()[{geom, law}] = pass;
    return true;
}

KernelPasses::Pass KernelPasses::find(const IGeomFunctor& geom, const LawFunctor& law) {
    const auto it = passes().find({std::type_index(typeid(geom)), std::type_index(typeid(law))});
    return it == passes().end() ? nullptr : it->second;
}

} // namespace yade
