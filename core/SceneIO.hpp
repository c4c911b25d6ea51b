// Saving and loading a whole scene (O.save / O.load): every registered object is written
// through its attribute table; shared objects (a material used by many bodies) are written
// once and referenced. Binary files are the block format (core/SceneBlocks.hpp); XML files and
// the binary files of format version 1 are a tree of nodes (lib/serialization/Node.hpp).
// See doc/file-format.md.
#pragma once
#include <core/Scene.hpp>
#include <lib/serialization/Node.hpp>
#include <lib/serialization/Streams.hpp>

namespace yade {
namespace SceneIO {
    // Builds a new scene from a tree; throws FormatError (the current scene is never touched).
    std::shared_ptr<Scene> fromNode(const Node& root);
    // Writes the scene to `out` (closed at the end): the block format, or XML.
    void save(Scene& scene, ByteSink& out, bool xml);
    // Reads a scene in any of the formats, detected from its first bytes. Throws FormatError for
    // what the data holds, std::system_error for failures of reading it.
    std::shared_ptr<Scene> load(ByteSource& in);
    // The same into and from memory (uncompressed when saved; any compression when loaded).
    std::string save(Scene& scene, bool xml);
    std::shared_ptr<Scene> load(const std::string& data);
} // namespace SceneIO
} // namespace yade
