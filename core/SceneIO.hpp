// Saving and loading a whole scene (O.save / O.load): every registered object is written
// through its attribute table; shared objects (a material used by many bodies) are written
// once and referenced. See doc/file-format.md.
#pragma once
#include <core/Scene.hpp>
#include <lib/serialization/Node.hpp>

namespace yade {
namespace SceneIO {
    Node toNode(Scene& scene);
    // Builds a new scene; throws FormatError (the current scene is never touched).
    std::shared_ptr<Scene> fromNode(const Node& root);
    std::string save(Scene& scene, bool xml);
    std::shared_ptr<Scene> load(const std::string& data);
} // namespace SceneIO
} // namespace yade
