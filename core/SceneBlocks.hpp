// The block format of saved scenes (doc/file-format.md, "Blocks"): the scene as it lies in memory,
// streamed. Objects (materials, bodies with their states, shapes and bounds, engines...) go out as
// tables, one per class, whose columns are the class's attributes (visit()); each contact pool goes
// out as its records' columns, the pairs as id columns. Every block carries its length and a CRC-32,
// and nothing is held whole in memory: the writer and the reader keep one block (at most 4096 rows).
#pragma once
#include <core/Scene.hpp>
#include <lib/serialization/Streams.hpp>

namespace yade {
namespace SceneBlocks {
    constexpr char magic[] = "YADE-CLONE-BLOCKS\n"; // (18 bytes)
    constexpr size_t magicSize = sizeof magic - 1;
    constexpr int formatVersion = 3; // (3: the periodic cell)
    void write(Scene& scene, ByteSink& out);
    // Reads a scene from `in`, whose first magicSize bytes (the magic) were already read. Builds a new
    // scene: throws FormatError (and the current scene is never touched).
    std::shared_ptr<Scene> read(ByteSource& in);
} // namespace SceneBlocks
} // namespace yade
