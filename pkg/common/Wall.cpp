#include <pkg/common/Wall.hpp>
#include <stdexcept>

namespace yade {

void Wall::postLoad() {
    if (axis < 0 || axis > 2) throw std::invalid_argument("Wall.axis must be 0, 1 or 2 (got " + std::to_string(axis) + ")");
    if (sense < -1 || sense > 1) throw std::invalid_argument("Wall.sense must be -1, 0 or 1 (got " + std::to_string(sense) + ")");
}

} // namespace yade
