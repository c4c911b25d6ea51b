// Sinks buffer what is written and hand it to the codec 1 MiB at a time; sources decompress into a
// 1 MiB buffer. Compressed bytes go to and come from a RawOut / RawIn (a file descriptor or a string).
#include <lib/serialization/Node.hpp>
#include <lib/serialization/Streams.hpp>

#include <algorithm>
#include <bzlib.h>
#include <cerrno>
#include <cstring>
#include <new>
#include <stdexcept>
#include <system_error>
#include <unistd.h>
#include <zlib.h>
#ifdef YADE_HAVE_ZSTD
#include <zstd.h>
#endif

namespace yade {

Codec codecForName(const std::string& fileName) {
    auto endsWith = [&](const char* suffix) {
        size_t n = std::strlen(suffix);
        return fileName.size() >= n && fileName.compare(fileName.size() - n, n, suffix) == 0;
    };
    if (endsWith(".gz")) return Codec::gzip;
    if (endsWith(".bz2")) return Codec::bzip2;
    if (endsWith(".zst")) return Codec::zstd;
    return Codec::none;
}

const char* codecName(Codec c) {
    switch (c) {
        case Codec::none: return "none";
        case Codec::gzip: return "gzip";
        case Codec::bzip2: return "bzip2";
        case Codec::zstd: return "zstd";
    }
    return "unknown";
}

bool codecAvailable(Codec c) {
#ifdef YADE_HAVE_ZSTD
    (void)c;
    return true;
#else
    return c != Codec::zstd;
#endif
}

uint32_t checksum(uint32_t crc, const void* data, size_t n) {
    auto p = static_cast<const Bytef*>(data);
    while (n > 0) { // crc32() takes a uInt length
        uInt k = static_cast<uInt>(std::min<size_t>(n, 1u << 30));
        crc = static_cast<uint32_t>(crc32(crc, p, k));
        p += k;
        n -= k;
    }
    return crc;
}

namespace {

constexpr size_t bufferSize = size_t(1) << 20;
const char* const noZstd = "this build has no zstd support: install libzstd-dev and rebuild";

std::unique_ptr<char[]> newBuffer() { return std::unique_ptr<char[]>(new char[bufferSize]); }

// ------------------------------------------------------------------ where compressed bytes go

class RawOut {
public:
    virtual ~RawOut() = default;
    virtual void put(const char* p, size_t n) = 0;
};

class FdOut : public RawOut {
public:
    explicit FdOut(int fd) : fd_(fd) {}
    void put(const char* p, size_t n) override {
        while (n > 0) { // write(2) may write less than asked, or be interrupted by a signal
            ssize_t k = ::write(fd_, p, n);
            if (k < 0) {
                if (errno == EINTR) continue;
                throw std::system_error(errno, std::generic_category(), "writing the file");
            }
            p += k;
            n -= static_cast<size_t>(k);
        }
    }

private:
    int fd_;
};

class StringOut : public RawOut {
public:
    explicit StringOut(std::string& s) : s_(s) {}
    void put(const char* p, size_t n) override { s_.append(p, n); }

private:
    std::string& s_;
};

// ------------------------------------------------------------------ sinks

// Collects writes into 1 MiB and hands each full buffer to encode(); large writes skip the copy.
class BufferedSink : public ByteSink {
public:
    void write(const void* data, size_t n) final {
        if (closed_) throw std::logic_error("ByteSink::write after close()");
        bytesIn_ += n;
        auto p = static_cast<const char*>(data);
        while (n > 0) {
            if (used_ == 0 && n >= bufferSize) {
                encode(p, bufferSize, false);
                p += bufferSize;
                n -= bufferSize;
                continue;
            }
            size_t k = std::min(n, bufferSize - used_);
            std::memcpy(in_.get() + used_, p, k);
            used_ += k;
            p += k;
            n -= k;
            if (used_ == bufferSize) {
                encode(in_.get(), used_, false);
                used_ = 0;
            }
        }
    }
    void close() final {
        if (closed_) return;
        closed_ = true; // also when encoding fails: a second close() must not append to a broken stream
        encode(in_.get(), used_, true);
        used_ = 0;
    }

protected:
    explicit BufferedSink(std::unique_ptr<RawOut> out) : out_(std::move(out)), in_(newBuffer()) {}
    // Compresses all `n` bytes and emits what the codec gives back; `finish` ends the stream.
    virtual void encode(const char* in, size_t n, bool finish) = 0;
    void emit(const char* p, size_t n) {
        if (n > 0) out_->put(p, n);
    }

private:
    std::unique_ptr<RawOut> out_;
    std::unique_ptr<char[]> in_;
    size_t used_ = 0;
    bool closed_ = false;
};

class PlainSink : public BufferedSink {
public:
    explicit PlainSink(std::unique_ptr<RawOut> out) : BufferedSink(std::move(out)) {}

protected:
    void encode(const char* in, size_t n, bool) override { emit(in, n); }
};

class GzipSink : public BufferedSink {
public:
    explicit GzipSink(std::unique_ptr<RawOut> out) : BufferedSink(std::move(out)), out_(newBuffer()) {
        // windowBits 15 + 16: a gzip header and trailer, as gzip(1) writes
        int r = deflateInit2(&z_, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY);
        if (r == Z_MEM_ERROR) throw std::bad_alloc();
        if (r != Z_OK) throw std::runtime_error(std::string("gzip: deflateInit2 failed: ") + zError(r));
    }
    ~GzipSink() override { deflateEnd(&z_); }

protected:
    void encode(const char* in, size_t n, bool finish) override {
        z_.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in));
        z_.avail_in = static_cast<uInt>(n); // n <= bufferSize
        for (;;) {
            z_.next_out = reinterpret_cast<Bytef*>(out_.get());
            z_.avail_out = static_cast<uInt>(bufferSize);
            int r = deflate(&z_, finish ? Z_FINISH : Z_NO_FLUSH);
            if (r == Z_STREAM_ERROR) throw std::runtime_error("gzip: deflate failed (inconsistent stream state)");
            emit(out_.get(), bufferSize - z_.avail_out);
            // without finish: done once the input is taken and the output had room to spare
            if (finish ? r == Z_STREAM_END : (z_.avail_in == 0 && z_.avail_out > 0)) break;
        }
    }

private:
    z_stream z_{};
    std::unique_ptr<char[]> out_;
};

class Bzip2Sink : public BufferedSink {
public:
    explicit Bzip2Sink(std::unique_ptr<RawOut> out) : BufferedSink(std::move(out)), out_(newBuffer()) {
        int r = BZ2_bzCompressInit(&b_, 9, 0, 0);
        if (r == BZ_MEM_ERROR) throw std::bad_alloc();
        if (r != BZ_OK) throw std::runtime_error("bzip2: BZ2_bzCompressInit failed (" + std::to_string(r) + ")");
    }
    ~Bzip2Sink() override { BZ2_bzCompressEnd(&b_); }

protected:
    void encode(const char* in, size_t n, bool finish) override {
        b_.next_in = const_cast<char*>(in);
        b_.avail_in = static_cast<unsigned>(n);
        for (;;) {
            b_.next_out = out_.get();
            b_.avail_out = static_cast<unsigned>(bufferSize);
            int r = BZ2_bzCompress(&b_, finish ? BZ_FINISH : BZ_RUN);
            if (r != BZ_RUN_OK && r != BZ_FINISH_OK && r != BZ_STREAM_END)
                throw std::runtime_error("bzip2: BZ2_bzCompress failed (" + std::to_string(r) + ")");
            emit(out_.get(), bufferSize - b_.avail_out);
            if (finish ? r == BZ_STREAM_END : b_.avail_in == 0) break;
        }
    }

private:
    bz_stream b_{};
    std::unique_ptr<char[]> out_;
};

#ifdef YADE_HAVE_ZSTD
class ZstdSink : public BufferedSink {
public:
    explicit ZstdSink(std::unique_ptr<RawOut> out) : BufferedSink(std::move(out)), out_(newBuffer()) {
        c_ = ZSTD_createCCtx();
        if (!c_) throw std::bad_alloc();
        check(ZSTD_CCtx_setParameter(c_, ZSTD_c_compressionLevel, 3));
        check(ZSTD_CCtx_setParameter(c_, ZSTD_c_checksumFlag, 1)); // corruption found when read back
    }
    ~ZstdSink() override { ZSTD_freeCCtx(c_); }

protected:
    void encode(const char* in, size_t n, bool finish) override {
        ZSTD_inBuffer input{in, n, 0};
        for (;;) {
            ZSTD_outBuffer output{out_.get(), bufferSize, 0};
            size_t left = check(ZSTD_compressStream2(c_, &output, &input, finish ? ZSTD_e_end : ZSTD_e_continue));
            emit(out_.get(), output.pos);
            // ZSTD_e_end returns how much is still to flush; ZSTD_e_continue is done once it took the input
            if (finish ? left == 0 : input.pos == input.size) break;
        }
    }

private:
    static size_t check(size_t r) {
        if (ZSTD_isError(r)) throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(r));
        return r;
    }
    ZSTD_CCtx* c_ = nullptr;
    std::unique_ptr<char[]> out_;
};
#endif

std::unique_ptr<ByteSink> makeSink(std::unique_ptr<RawOut> out, Codec c) {
    switch (c) {
        case Codec::none: return std::make_unique<PlainSink>(std::move(out));
        case Codec::gzip: return std::make_unique<GzipSink>(std::move(out));
        case Codec::bzip2: return std::make_unique<Bzip2Sink>(std::move(out));
        case Codec::zstd:
#ifdef YADE_HAVE_ZSTD
            return std::make_unique<ZstdSink>(std::move(out));
#else
            throw std::runtime_error(noZstd);
#endif
    }
    throw std::invalid_argument("unknown Codec");
}

// ------------------------------------------------------------------ where compressed bytes come from

// The bytes that arrived and are not used yet: the window [pos, end), which refill() replaces once
// it is used up. A string is one window (no copy); a file is read 1 MiB at a time.
class RawIn {
public:
    virtual ~RawIn() = default;
    size_t available() const { return static_cast<size_t>(end - pos); }
    // The next window, when the current one is used up; false at the end of the data.
    virtual bool refill() = 0;
    const char* pos = nullptr;
    const char* end = nullptr;
};

class StringIn : public RawIn {
public:
    explicit StringIn(const std::string& s) {
        pos = s.data();
        end = pos + s.size();
    }
    bool refill() override { return false; }
};

class FdIn : public RawIn {
public:
    explicit FdIn(int fd) : fd_(fd), buf_(newBuffer()) {
        // at least the 4 bytes that tell the codec, even from a pipe that delivers fewer at a time
        size_t n = 0;
        while (n < 4) {
            size_t k = readSome(buf_.get() + n, bufferSize - n);
            if (k == 0) break;
            n += k;
        }
        pos = buf_.get();
        end = pos + n;
    }
    bool refill() override {
        if (eof_) return false;
        size_t k = readSome(buf_.get(), bufferSize);
        pos = buf_.get();
        end = pos + k;
        return k > 0;
    }

private:
    size_t readSome(char* p, size_t n) {
        for (;;) {
            ssize_t k = ::read(fd_, p, n);
            if (k >= 0) {
                if (k == 0) eof_ = true;
                return static_cast<size_t>(k);
            }
            if (errno != EINTR) throw std::system_error(errno, std::generic_category(), "reading the file");
        }
    }
    int fd_;
    std::unique_ptr<char[]> buf_;
    bool eof_ = false;
};

// ------------------------------------------------------------------ sources

// Serves reads from a 1 MiB buffer that decode() fills; reads of 1 MiB or more skip the copy.
class DecodingSource : public ByteSource {
public:
    size_t read(void* data, size_t n) final {
        auto p = static_cast<char*>(data);
        size_t got = 0;
        while (got < n) {
            if (pos_ == end_) {
                if (finished_) break;
                if (n - got >= bufferSize) {
                    got += decode(p + got, bufferSize);
                    continue;
                }
                pos_ = 0;
                end_ = decode(buf_.get(), bufferSize);
                continue;
            }
            size_t k = std::min(n - got, end_ - pos_);
            std::memcpy(p + got, buf_.get() + pos_, k);
            pos_ += k;
            got += k;
        }
        return got;
    }

protected:
    DecodingSource(std::unique_ptr<RawIn> in, Codec c) : in_(std::move(in)), buf_(newBuffer()) { codec_ = c; }
    // Fills `cap` bytes (at most bufferSize) of `out`; fewer only at the end of the stream, after
    // setting finished_ (the end marker and checksum checked, nothing after it).
    virtual size_t decode(char* out, size_t cap) = 0;

    RawIn& in() { return *in_; }
    // Input left to give the codec: false once the data has ended.
    bool haveInput() { return in_->available() > 0 || in_->refill(); }
    // How much of the window to offer the codec at once (its lengths are 32-bit).
    size_t chunk() const { return std::min<size_t>(in_->available(), 1u << 30); }
    [[noreturn]] void corrupt(const std::string& reason) const {
        throw FormatError(std::string("corrupt or truncated compressed file (") + codecName(codec()) + ": " + reason +
                          ")");
    }
    [[noreturn]] void truncated() const { corrupt("unexpected end of data, the compressed stream is incomplete"); }
    // The codec's end marker was met: the data must end there too.
    void finish() {
        finished_ = true;
        if (haveInput()) corrupt("extra bytes after the end of the compressed data");
    }
    bool finished_ = false;

private:
    std::unique_ptr<RawIn> in_;
    std::unique_ptr<char[]> buf_;
    size_t pos_ = 0, end_ = 0;
};

class PlainSource : public DecodingSource {
public:
    explicit PlainSource(std::unique_ptr<RawIn> in) : DecodingSource(std::move(in), Codec::none) {}

protected:
    size_t decode(char* out, size_t cap) override {
        size_t got = 0;
        while (got < cap) {
            if (!haveInput()) {
                finished_ = true;
                break;
            }
            size_t k = std::min(cap - got, in().available());
            std::memcpy(out + got, in().pos, k);
            in().pos += k;
            got += k;
        }
        return got;
    }
};

class GzipSource : public DecodingSource {
public:
    explicit GzipSource(std::unique_ptr<RawIn> in) : DecodingSource(std::move(in), Codec::gzip) {
        int r = inflateInit2(&z_, 15 + 16); // gzip only: the magic bytes said so
        if (r == Z_MEM_ERROR) throw std::bad_alloc();
        if (r != Z_OK) throw std::runtime_error(std::string("gzip: inflateInit2 failed: ") + zError(r));
    }
    ~GzipSource() override { inflateEnd(&z_); }

protected:
    size_t decode(char* out, size_t cap) override {
        z_.next_out = reinterpret_cast<Bytef*>(out);
        z_.avail_out = static_cast<uInt>(cap);
        while (z_.avail_out > 0) {
            bool atEnd = !haveInput();
            uInt before = z_.avail_out;
            z_.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in().pos));
            z_.avail_in = static_cast<uInt>(chunk());
            int r = inflate(&z_, Z_NO_FLUSH);
            in().pos = reinterpret_cast<const char*>(z_.next_in);
            if (r == Z_STREAM_END) {
                finish();
                break;
            }
            if (r == Z_MEM_ERROR) throw std::bad_alloc();
            if (r == Z_NEED_DICT) corrupt("needs a preset dictionary");
            if (r != Z_OK && r != Z_BUF_ERROR) corrupt(z_.msg ? z_.msg : zError(r));
            if (atEnd && z_.avail_out == before) truncated(); // no input left and nothing came out
        }
        return cap - z_.avail_out;
    }

private:
    z_stream z_{};
};

class Bzip2Source : public DecodingSource {
public:
    explicit Bzip2Source(std::unique_ptr<RawIn> in) : DecodingSource(std::move(in), Codec::bzip2) {
        int r = BZ2_bzDecompressInit(&b_, 0, 0);
        if (r == BZ_MEM_ERROR) throw std::bad_alloc();
        if (r != BZ_OK) throw std::runtime_error("bzip2: BZ2_bzDecompressInit failed (" + std::to_string(r) + ")");
    }
    ~Bzip2Source() override { BZ2_bzDecompressEnd(&b_); }

protected:
    size_t decode(char* out, size_t cap) override {
        b_.next_out = out;
        b_.avail_out = static_cast<unsigned>(cap);
        while (b_.avail_out > 0) {
            bool atEnd = !haveInput();
            unsigned before = b_.avail_out;
            b_.next_in = const_cast<char*>(in().pos);
            b_.avail_in = static_cast<unsigned>(chunk());
            int r = BZ2_bzDecompress(&b_);
            in().pos = b_.next_in;
            if (r == BZ_STREAM_END) {
                finish();
                break;
            }
            // libbz2 has no messages of its own for a stream (BZ2_bzerror is for its FILE interface)
            if (r == BZ_DATA_ERROR) corrupt("BZ_DATA_ERROR, data integrity error (a bad block or a CRC mismatch)");
            if (r == BZ_DATA_ERROR_MAGIC) corrupt("BZ_DATA_ERROR_MAGIC, a block or stream header is wrong");
            if (r == BZ_MEM_ERROR) throw std::bad_alloc();
            if (r != BZ_OK) throw std::runtime_error("bzip2: BZ2_bzDecompress failed (" + std::to_string(r) + ")");
            if (atEnd && b_.avail_out == before) truncated();
        }
        return cap - b_.avail_out;
    }

private:
    bz_stream b_{};
};

#ifdef YADE_HAVE_ZSTD
class ZstdSource : public DecodingSource {
public:
    explicit ZstdSource(std::unique_ptr<RawIn> in) : DecodingSource(std::move(in), Codec::zstd) {
        d_ = ZSTD_createDCtx();
        if (!d_) throw std::bad_alloc();
    }
    ~ZstdSource() override { ZSTD_freeDCtx(d_); }

protected:
    size_t decode(char* out, size_t cap) override {
        ZSTD_outBuffer output{out, cap, 0};
        while (output.pos < cap) {
            bool atEnd = !haveInput();
            size_t before = output.pos;
            ZSTD_inBuffer input{in().pos, chunk(), 0};
            size_t r = ZSTD_decompressStream(d_, &output, &input);
            in().pos += input.pos;
            if (ZSTD_isError(r)) corrupt(ZSTD_getErrorName(r));
            if (r == 0) { // the frame is complete and all of it flushed
                finish();
                break;
            }
            if (atEnd && output.pos == before) truncated(); // non-zero at the end of input: frame incomplete
        }
        return output.pos;
    }

private:
    ZSTD_DCtx* d_ = nullptr;
};
#endif

std::unique_ptr<ByteSource> makeSource(std::unique_ptr<RawIn> in) {
    auto starts = [&](const char* magic, size_t n) {
        return in->available() >= n && std::memcmp(in->pos, magic, n) == 0;
    };
    if (starts("\x1f\x8b", 2)) return std::make_unique<GzipSource>(std::move(in));
    if (starts("BZh", 3)) return std::make_unique<Bzip2Source>(std::move(in));
    if (starts("\x28\xb5\x2f\xfd", 4)) {
#ifdef YADE_HAVE_ZSTD
        return std::make_unique<ZstdSource>(std::move(in));
#else
        throw FormatError("the file is zstd-compressed and this build has no zstd support: install libzstd-dev and "
                          "rebuild");
#endif
    }
    return std::make_unique<PlainSource>(std::move(in));
}

} // namespace

std::unique_ptr<ByteSink> fdSink(int fd, Codec c) { return makeSink(std::make_unique<FdOut>(fd), c); }
std::unique_ptr<ByteSink> stringSink(std::string& out, Codec c) { return makeSink(std::make_unique<StringOut>(out), c); }
std::unique_ptr<ByteSource> fdSource(int fd) { return makeSource(std::make_unique<FdIn>(fd)); }
std::unique_ptr<ByteSource> stringSource(const std::string& data) { return makeSource(std::make_unique<StringIn>(data)); }

} // namespace yade
