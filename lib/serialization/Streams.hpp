// Byte streams for saved scenes: sinks that compress as they are written and sources that
// decompress as they are read (gzip, bzip2, zstd or none), with about 1 MiB buffered each way,
// so that a scene of any size is never held whole in memory.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace yade {

enum class Codec { none, gzip, bzip2, zstd };

Codec codecForName(const std::string& fileName); // by suffix: ".gz" gzip, ".bz2" bzip2, ".zst" zstd, else none
const char* codecName(Codec c);                   // "none", "gzip", "bzip2", "zstd"
bool codecAvailable(Codec c);                     // zstd only when built with libzstd (YADE_HAVE_ZSTD)

// Bytes written out in order; buffered (about 1 MiB) and compressed as they come.
class ByteSink {
public:
    virtual ~ByteSink() = default;
    virtual void write(const void* data, size_t n) = 0;
    // Ends the compressed stream and flushes everything; must be called for a complete file
    // (the destructor does not throw and does not finish the stream). Later calls do nothing.
    virtual void close() = 0;
    uint64_t bytesIn() const { return bytesIn_; } // uncompressed bytes written so far

protected:
    uint64_t bytesIn_ = 0;
};

// Bytes read in order, decompressed as they are read. A corrupt or truncated compressed stream
// throws FormatError (lib/serialization/Node.hpp), at the latest from the read that reaches its end.
class ByteSource {
public:
    virtual ~ByteSource() = default;
    // Fills `n` bytes unless the data ends first; returns how many were read (less than n only at the end).
    virtual size_t read(void* data, size_t n) = 0;
    Codec codec() const { return codec_; }

protected:
    Codec codec_ = Codec::none; // set by the source from the first bytes
};

// Writes to an open file descriptor (not closed); write(2) errors throw std::system_error.
// A codec this build lacks (zstd without libzstd) throws std::runtime_error.
std::unique_ptr<ByteSink> fdSink(int fd, Codec c);
std::unique_ptr<ByteSink> stringSink(std::string& out, Codec c); // appends to `out`

// Sources detect the codec from the first bytes: 1f 8b gzip, "BZh" bzip2, 28 b5 2f fd zstd, anything
// else uncompressed (returned as is, the first bytes included).
std::unique_ptr<ByteSource> fdSource(int fd);                      // read(2) errors: std::system_error
std::unique_ptr<ByteSource> stringSource(const std::string& data); // keeps a reference to data (the caller keeps it alive); no copy

uint32_t checksum(uint32_t crc, const void* data, size_t n); // CRC-32 (zlib's crc32), crc starts at 0

} // namespace yade
