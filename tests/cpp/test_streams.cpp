// Byte sinks and sources: every codec gives back what was written, whatever the sizes of the writes
// and reads; the files are what gzip, bzip2 and zstd write; a damaged stream is a FormatError.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <lib/serialization/Node.hpp>
#include <lib/serialization/Streams.hpp>
#include <random>
#include <string>
#include <system_error>
#include <unistd.h>
#include <vector>
#include <zlib.h>

using namespace yade;

namespace {

const std::string corruptPrefix = "corrupt or truncated compressed file (";
const size_t MiB = size_t(1) << 20;

// Random bytes (incompressible) alternating with runs of doubles that repeat (very compressible).
std::string mixedData(size_t n, unsigned seed = 1) {
    std::mt19937_64 rng(seed);
    std::string s;
    s.reserve(n + 4096);
    while (s.size() < n) {
        for (int i = 0; i < 700; ++i) s.push_back(static_cast<char>(rng()));
        for (int i = 0; i < 300; ++i) {
            double x = 1e-3 * (i % 17) + 0.25;
            s.append(reinterpret_cast<const char*>(&x), sizeof x);
        }
    }
    s.resize(n);
    return s;
}

// Odd-sized pieces, some below and some above the streams' 1 MiB buffers.
const size_t writePieces[] = {1, 7, 4093, 65537, 3, MiB + 3, 13, 2 * MiB + 1};
const size_t readPieces[] = {3, 5001, 1, MiB + 7, 17, 3 * MiB, 262147};

void writeAll(ByteSink& sink, const std::string& data) {
    size_t at = 0, i = 0;
    while (at < data.size()) {
        size_t k = std::min(writePieces[i++ % std::size(writePieces)], data.size() - at);
        sink.write(data.data() + at, k);
        at += k;
    }
    sink.close();
    EXPECT_EQ(sink.bytesIn(), data.size());
}

std::string readAll(ByteSource& source) {
    std::string r;
    for (size_t i = 0;; ++i) {
        size_t want = readPieces[i % std::size(readPieces)];
        size_t at = r.size();
        r.resize(at + want);
        size_t got = source.read(&r[at], want);
        r.resize(at + got);
        if (got < want) break; // short only at the end: every later read gives nothing
    }
    char c;
    EXPECT_EQ(source.read(&c, 1), 0u);
    return r;
}

std::string compress(const std::string& data, Codec c) {
    std::string out;
    writeAll(*stringSink(out, c), data);
    return out;
}

std::string decompress(const std::string& compressed) { return readAll(*stringSource(compressed)); }

// A file in the test's temporary folder, removed at the end.
struct TempFile {
    std::string path;
    int fd = -1;
    TempFile() {
        path = testing::TempDir() + "yade_streams_XXXXXX";
        fd = mkstemp(&path[0]);
        if (fd < 0) throw std::system_error(errno, std::generic_category(), "mkstemp");
    }
    ~TempFile() {
        if (fd >= 0) ::close(fd);
        std::remove(path.c_str());
    }
    void rewind() const { ASSERT_EQ(lseek(fd, 0, SEEK_SET), 0); }
    std::string contents() const {
        std::string s;
        FILE* f = std::fopen(path.c_str(), "rb");
        char buf[65536];
        size_t k;
        while ((k = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, k);
        std::fclose(f);
        return s;
    }
    void setContents(const std::string& s) const {
        FILE* f = std::fopen(path.c_str(), "wb");
        std::fwrite(s.data(), 1, s.size(), f);
        std::fclose(f);
    }
};

// Runs `body`, expecting a FormatError whose message starts with `prefix`; returns the message.
template <class F> std::string formatErrorOf(F body, const std::string& prefix = corruptPrefix) {
    try {
        body();
    } catch (const FormatError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u) << e.what();
        return e.what();
    }
    ADD_FAILURE() << "no FormatError";
    return "";
}

bool haveTool(const char* name) { return std::system((std::string("command -v ") + name + " >/dev/null 2>&1").c_str()) == 0; }

const char* toolOf(Codec c) { return c == Codec::gzip ? "gzip" : c == Codec::bzip2 ? "bzip2" : "zstd"; }

class Streams : public testing::TestWithParam<Codec> {
protected:
    void SetUp() override {
        if (!codecAvailable(GetParam())) {
            GTEST_SKIP() << codecName(GetParam()) << " not in this build";
        }
    }
    Codec codec() const { return GetParam(); }
};
class CompressedStreams : public Streams {};

} // namespace

TEST_P(Streams, RoundTripThroughAString) {
    for (size_t n : {size_t(0), size_t(1), size_t(1000), 5 * MiB}) {
        std::string data = mixedData(n, static_cast<unsigned>(n));
        std::string compressed = compress(data, codec());
        auto source = stringSource(compressed);
        EXPECT_EQ(source->codec(), codec());
        EXPECT_TRUE(readAll(*source) == data) << codecName(codec()) << ", " << n << " bytes";
        if (codec() != Codec::none && n == 5 * MiB) {
            EXPECT_LT(compressed.size(), data.size());
        }
    }
}

TEST_P(Streams, RoundTripThroughAFile) {
    for (size_t n : {size_t(0), size_t(1), size_t(1000), 5 * MiB}) {
        std::string data = mixedData(n, static_cast<unsigned>(n) + 7);
        TempFile file;
        writeAll(*fdSink(file.fd, codec()), data);
        EXPECT_EQ(file.contents(), compress(data, codec())); // the same bytes as a string sink
        file.rewind();
        auto source = fdSource(file.fd);
        EXPECT_TRUE(readAll(*source) == data) << codecName(codec()) << ", " << n << " bytes";
    }
}

TEST_P(Streams, AppendsToTheString) {
    std::string out = "head";
    writeAll(*stringSink(out, codec()), "tail");
    EXPECT_EQ(out.substr(0, 4), "head");
    EXPECT_EQ(decompress(out.substr(4)), "tail");
}

TEST_P(Streams, CloseTwiceIsHarmlessAndWriteAfterCloseIsRefused) {
    std::string out;
    auto sink = stringSink(out, codec());
    sink->write("abc", 3);
    sink->close();
    std::string once = out;
    sink->close();
    EXPECT_EQ(out, once);
    EXPECT_THROW(sink->write("d", 1), std::logic_error);
}

TEST_P(CompressedStreams, TruncatedStreamIsAFormatError) {
    std::string compressed = compress(mixedData(300000), codec());
    for (size_t cut : {size_t(10), compressed.size() / 2, compressed.size() - 1}) {
        std::string part = compressed.substr(0, cut);
        std::string msg = formatErrorOf([&] { decompress(part); });
        EXPECT_NE(msg.find(std::string("(") + codecName(codec()) + ": "), std::string::npos) << msg;
    }
}

TEST_P(CompressedStreams, TruncatedFileIsAFormatError) {
    std::string compressed = compress(mixedData(300000), codec());
    TempFile file;
    file.setContents(compressed.substr(0, compressed.size() - 1));
    formatErrorOf([&] { readAll(*fdSource(file.fd)); });
}

TEST_P(CompressedStreams, FlippedByteIsAFormatError) {
    std::string data = mixedData(300000);
    std::string compressed = compress(data, codec());
    for (size_t at : {compressed.size() / 3, compressed.size() / 2, compressed.size() * 3 / 4}) {
        std::string bad = compressed;
        bad[at] = static_cast<char>(bad[at] ^ 0x55);
        formatErrorOf([&] { decompress(bad); });
    }
}

TEST_P(CompressedStreams, ExtraBytesAfterTheStreamAreAFormatError) {
    std::string compressed = compress(mixedData(5000), codec());
    std::string msg = formatErrorOf([&] { decompress(compressed + "x"); });
    EXPECT_EQ(msg, corruptPrefix + codecName(codec()) + ": extra bytes after the end of the compressed data)");
    formatErrorOf([&] { decompress(compressed + compressed); }); // a second member or frame: not supported
}

TEST_P(CompressedStreams, UnclosedSinkLeavesAnIncompleteStream) {
    std::string out;
    {
        auto sink = stringSink(out, codec());
        std::string data = mixedData(3 * MiB);
        sink->write(data.data(), data.size());
    }
    formatErrorOf([&] { decompress(out); });
}

TEST_P(CompressedStreams, StandardToolReadsOurFileAndWeReadItsFile) {
    const char* tool = toolOf(codec());
    if (!haveTool(tool)) {
        GTEST_SKIP() << tool << " not installed";
    }
    std::string data = mixedData(2 * MiB + 12345);
    TempFile ours, plain;
    writeAll(*fdSink(ours.fd, codec()), data);
    std::string cmd = std::string(tool) + " -dc < " + ours.path + " > " + plain.path;
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    EXPECT_TRUE(plain.contents() == data);

    TempFile theirs;
    cmd = std::string(tool) + " -c < " + plain.path + " > " + theirs.path;
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    EXPECT_TRUE(readAll(*fdSource(theirs.fd)) == data);
}

std::string codecParamName(const testing::TestParamInfo<Codec>& info) { return codecName(info.param); }
INSTANTIATE_TEST_SUITE_P(AllCodecs, Streams, testing::Values(Codec::none, Codec::gzip, Codec::bzip2, Codec::zstd),
                         codecParamName);
INSTANTIATE_TEST_SUITE_P(AllCodecs, CompressedStreams, testing::Values(Codec::gzip, Codec::bzip2, Codec::zstd),
                         codecParamName);

TEST(Streams, GzipOutputIsWhatZlibInflates) {
    std::string data = mixedData(3 * MiB + 5);
    std::string gz = compress(data, Codec::gzip);
    ASSERT_GE(gz.size(), 10u);
    EXPECT_EQ(gz.substr(0, 3), std::string("\x1f\x8b\x08")); // gzip magic, deflate
    std::string plain(data.size() + 1, '\0');
    z_stream z{};
    ASSERT_EQ(inflateInit2(&z, 15 + 16), Z_OK);
    z.next_in = reinterpret_cast<Bytef*>(&gz[0]);
    z.avail_in = static_cast<uInt>(gz.size());
    z.next_out = reinterpret_cast<Bytef*>(&plain[0]);
    z.avail_out = static_cast<uInt>(plain.size());
    EXPECT_EQ(inflate(&z, Z_FINISH), Z_STREAM_END);
    EXPECT_EQ(z.avail_in, 0u);
    plain.resize(plain.size() - z.avail_out);
    inflateEnd(&z);
    EXPECT_TRUE(plain == data);
}

TEST(Streams, UncompressedSourceReturnsTheDataUnchanged) {
    // the first bytes too, also when they begin like a compressed stream's magic
    for (std::string data : {std::string(), std::string("<?xml version=\"1.0\"?><scene/>"), std::string("\x1f", 1),
                             std::string("BZ"), std::string("\x28\xb5\x2f", 3), std::string("\x1f\x8a rest", 7)}) {
        auto source = stringSource(data);
        EXPECT_EQ(source->codec(), Codec::none);
        EXPECT_EQ(readAll(*source), data);
        TempFile file;
        file.setContents(data);
        EXPECT_EQ(readAll(*fdSource(file.fd)), data);
    }
    std::string empty;
    char c;
    EXPECT_EQ(stringSource(empty)->read(&c, 1), 0u);
}

TEST(Streams, GzipCorruptionNamesZlibsReason) {
    std::string gz = compress(mixedData(200000), Codec::gzip);
    std::string bad = gz;
    bad[bad.size() - 3] = static_cast<char>(bad[bad.size() - 3] ^ 1); // the trailer's length (its last 4 bytes)
    EXPECT_EQ(formatErrorOf([&] { decompress(bad); }), corruptPrefix + "gzip: incorrect length check)");
    bad = gz;
    bad[bad.size() - 8] = static_cast<char>(bad[bad.size() - 8] ^ 1); // the trailer's CRC-32 (the 4 before)
    EXPECT_EQ(formatErrorOf([&] { decompress(bad); }), corruptPrefix + "gzip: incorrect data check)");
}

TEST(Streams, Checksum) {
    EXPECT_EQ(checksum(0, "123456789", 9), 0xCBF43926u);
    EXPECT_EQ(checksum(checksum(0, "1234", 4), "56789", 5), 0xCBF43926u);
    EXPECT_EQ(checksum(0, "", 0), 0u);
}

TEST(Streams, CodecNames) {
    EXPECT_EQ(codecForName("a.xml.gz"), Codec::gzip);
    EXPECT_EQ(codecForName("a.bin.bz2"), Codec::bzip2);
    EXPECT_EQ(codecForName("dir.gz/a.zst"), Codec::zstd);
    EXPECT_EQ(codecForName("a.xml"), Codec::none);
    EXPECT_EQ(codecForName("gz"), Codec::none);
    EXPECT_EQ(codecForName(""), Codec::none);
    EXPECT_STREQ(codecName(Codec::none), "none");
    EXPECT_STREQ(codecName(Codec::gzip), "gzip");
    EXPECT_STREQ(codecName(Codec::bzip2), "bzip2");
    EXPECT_STREQ(codecName(Codec::zstd), "zstd");
    EXPECT_TRUE(codecAvailable(Codec::none));
    EXPECT_TRUE(codecAvailable(Codec::gzip));
    EXPECT_TRUE(codecAvailable(Codec::bzip2));
}

TEST(Streams, WithoutZstdSupportZstdIsRefused) {
    if (codecAvailable(Codec::zstd)) {
        GTEST_SKIP() << "this build has zstd";
    }
    std::string out;
    EXPECT_THROW(stringSink(out, Codec::zstd), std::runtime_error);
    std::string zst("\x28\xb5\x2f\xfd\x24\x00", 6);
    std::string msg = formatErrorOf([&] { decompress(zst); }, "");
    EXPECT_NE(msg.find("zstd"), std::string::npos) << msg;
}

TEST(Streams, FileErrorsAreSystemErrors) {
    int readOnly = ::open("/dev/null", O_RDONLY);
    ASSERT_GE(readOnly, 0);
    auto sink = fdSink(readOnly, Codec::gzip);
    sink->write("x", 1);
    try {
        sink->close();
        ADD_FAILURE() << "no system_error";
    } catch (const std::system_error& e) {
        EXPECT_EQ(e.code().value(), EBADF);
        EXPECT_NE(std::string(e.what()).find("writing the file"), std::string::npos) << e.what();
    }
    ::close(readOnly);

    int writeOnly = ::open("/dev/null", O_WRONLY);
    ASSERT_GE(writeOnly, 0);
    try {
        readAll(*fdSource(writeOnly));
        ADD_FAILURE() << "no system_error";
    } catch (const std::system_error& e) {
        EXPECT_EQ(e.code().value(), EBADF);
        EXPECT_NE(std::string(e.what()).find("reading the file"), std::string::npos) << e.what();
    }
    ::close(writeOnly);
}
