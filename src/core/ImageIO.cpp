#include "core/ImageIO.h"

#include <algorithm>
#include <cassert>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

#include <OpenEXR/Iex.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfRgbaFile.h>
#include "core/StbImage.h"

#include "core/Error.h"

namespace specula {

namespace {

namespace fs = std::filesystem;

// The largest finite half float.
constexpr float kHalfMax = 65504.0f;
// Refuse images beyond 2^27 pixels (16384 x 8192, 2 GiB as RGBA floats): a forged or corrupt
// header must not make us allocate without bound.
constexpr uint64_t kMaxPixels = uint64_t(1) << 27;

std::string errnoText(int error) { return std::generic_category().message(error); }

// Library messages may span lines; errors reaching the user are one line.
std::string oneLine(std::string text)
{
    std::replace(text.begin(), text.end(), '\n', ' ');
    while (!text.empty() && (text.back() == ' ' || text.back() == '.')) text.pop_back();
    return text;
}

enum class Format { Png, Hdr, Exr };

std::optional<Format> formatOf(const fs::path& path)
{
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".png") return Format::Png;
    if (ext == ".hdr") return Format::Hdr;
    if (ext == ".exr") return Format::Exr;
    return std::nullopt;
}

const char* extensionOf(Format format)
{
    switch (format) {
    case Format::Png: return ".png";
    case Format::Hdr: return ".hdr";
    case Format::Exr: return ".exr";
    }
    return "";
}

[[noreturn]] void writeFailed(const fs::path& path, const std::string& reason)
{
    throw Error("cannot write {}: {}", path.string(), reason);
}

[[noreturn]] void readFailed(const fs::path& path, const std::string& reason)
{
    throw Error("cannot read {}: {}", path.string(), reason);
}

// A writer given a name whose extension says another format would produce a file that other
// tools misread, so the name must match what is written.
void checkExtension(const fs::path& path, Format format)
{
    const auto named = formatOf(path);
    if (!named) writeFailed(path, "unknown image format (use .png, .hdr or .exr)");
    if (*named != format) writeFailed(path, fmt::format("this writer writes {} files", extensionOf(format)));
}

template <typename Image>
void checkWritable(const fs::path& path, const Image& image)
{
    if (image.width <= 0 || image.height <= 0)
        writeFailed(path, fmt::format("the image is empty ({}x{})", image.width, image.height));
    assert(image.pixels.size() == size_t(image.width) * size_t(image.height) * 4);
}

/// A new file next to the destination. commit() renames it over the destination; until then the
/// destination is untouched, and a file never committed is removed. Where the file system allows
/// it (O_TMPFILE: ext4, xfs, btrfs, tmpfs) the file has no name until commit(), so even a writer
/// killed by SIGKILL or a power cut leaves nothing behind (tests/cli/test_cli_limits.cpp kills
/// one mid-write); elsewhere a hidden, uniquely named file stands in, which a killed writer
/// leaves.
class AtomicFile {
public:
    explicit AtomicFile(fs::path destination) : mDestination(std::move(destination))
    {
        const fs::path directory = mDestination.parent_path().empty() ? fs::path(".") : mDestination.parent_path();
        // 0666 and the umask give the permissions any new file would have.
        mFd = ::open(directory.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
        if (mFd >= 0) {
            mAnonymous = true;
            return;
        }
        if (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL) writeFailed(mDestination, errnoText(errno));
        createNamed();
        if (mFd < 0) writeFailed(mDestination, errnoText(errno));
    }
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;
    ~AtomicFile()
    {
        if (mFd >= 0) ::close(mFd);
        if (!mCommitted && !mTemp.empty()) ::unlink(mTemp.c_str());
    }

    /// Records the first error instead of throwing: stb calls this through C code, which
    /// exceptions must not cross.
    /// Writes at the current position, which seek() moves (OpenEXR goes back to fill in its
    /// table of scanline offsets).
    void write(const void* data, size_t size) noexcept
    {
        const char* bytes = static_cast<const char*>(data);
        while (size > 0 && mError == 0) {
            const ssize_t n = ::pwrite(mFd, bytes, size, off_t(mPosition));
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                mError = n < 0 ? errno : EIO;
                break;
            }
            bytes += n;
            size -= size_t(n);
            mPosition += uint64_t(n);
        }
    }
    uint64_t position() const { return mPosition; }
    void seek(uint64_t position) { mPosition = position; }
    bool failed() const { return mError != 0; }

    /// Throws for an earlier write error; `library` explains a failure the writer reported
    /// without an errno.
    void commit(const char* library = nullptr)
    {
        if (mError != 0) writeFailed(mDestination, errnoText(mError));
        if (library) writeFailed(mDestination, library);
        // No fsync: this guards against a failed or killed writer, not against power loss, and a
        // flush per image would slow down rendering sequences.
        if (mAnonymous) {
            // An unnamed file gets a name (linkat cannot replace one), which rename() then moves
            // over the destination in one step.
            const std::string self = fmt::format("/proc/self/fd/{}", mFd);
            for (int attempt = 0; attempt < 16; ++attempt) {
                mTemp = tempName();
                if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, mTemp.c_str(), AT_SYMLINK_FOLLOW) == 0) break;
                const int error = errno;
                mTemp.clear();
                if (error != EEXIST) writeFailed(mDestination, errnoText(error));
            }
            if (mTemp.empty()) writeFailed(mDestination, errnoText(EEXIST));
        }
        const int fd = mFd;
        mFd = -1;
        if (::close(fd) != 0) writeFailed(mDestination, errnoText(errno));
        if (::rename(mTemp.c_str(), mDestination.c_str()) != 0) writeFailed(mDestination, errnoText(errno));
        mCommitted = true;
    }

private:
    /// Hidden and uniquely named so that concurrent writers of the same file never collide.
    fs::path tempName() const
    {
        static thread_local std::random_device random;
        const uint64_t tag = (uint64_t(random()) << 32) ^ random();
        return mDestination.parent_path() / fmt::format(".{}.{:016x}.tmp", mDestination.filename().string(), tag);
    }
    void createNamed()
    {
        for (int attempt = 0; attempt < 16; ++attempt) {
            mTemp = tempName();
            mFd = ::open(mTemp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
            if (mFd >= 0) return;
            mTemp.clear();
            if (errno != EEXIST) return;
        }
    }

    fs::path mDestination;
    fs::path mTemp;
    int mFd = -1;
    bool mAnonymous = false; ///< O_TMPFILE: no name until commit()
    uint64_t mPosition = 0;
    int mError = 0;
    bool mCommitted = false;
};

void stbWrite(void* context, void* data, int size)
{
    static_cast<AtomicFile*>(context)->write(data, size_t(size));
}

/// OpenEXR writes through this so that its output lands in the AtomicFile.
class ExrOutput : public Imf::OStream {
public:
    ExrOutput(AtomicFile& file, const fs::path& path) : Imf::OStream(path.c_str()), mFile(file) {}
    void write(const char c[], int n) override
    {
        mFile.write(c, size_t(n));
        // Stops OpenEXR early; the error itself is reported by AtomicFile::commit, because
        // OpenEXR swallows exceptions thrown while it finishes the file in its destructor.
        if (mFile.failed()) throw Iex::IoExc("write failed");
    }
    uint64_t tellp() override { return mFile.position(); }
    void seekp(uint64_t pos) override { mFile.seek(pos); }

private:
    AtomicFile& mFile;
};

/// OpenEXR reads the file from memory through this; we read it ourselves for uniform errors.
class ExrInput : public Imf::IStream {
public:
    ExrInput(const std::vector<char>& data, const fs::path& path) : Imf::IStream(path.c_str()), mData(data) {}
    bool read(char c[], int n) override
    {
        // The exception type OpenEXR's own file stream throws, which it knows how to handle.
        if (n < 0 || mPosition > mData.size() || size_t(n) > mData.size() - mPosition)
            throw Iex::InputExc("the file is truncated");
        std::memcpy(c, mData.data() + mPosition, size_t(n));
        mPosition += size_t(n);
        return mPosition < mData.size();
    }
    uint64_t tellg() override { return mPosition; }
    void seekg(uint64_t pos) override { mPosition = pos; }
    void clear() override {}

private:
    const std::vector<char>& mData;
    uint64_t mPosition = 0;
};

std::vector<char> readFile(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) readFailed(path, errnoText(errno));
    std::error_code ec;
    if (fs::is_directory(path, ec)) readFailed(path, "is a directory");
    std::vector<char> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) readFailed(path, errnoText(errno));
    return data;
}

/// stb_image reads through this so that a decoder asking for bytes past the end is noticed:
/// stb_image pads missing bytes with zeros, so a truncated .hdr would decode without error.
struct StbInput {
    const std::vector<char>& data;
    size_t position = 0;
    bool overran = false;

    static int read(void* user, char* out, int size)
    {
        auto& self = *static_cast<StbInput*>(user);
        const size_t n = std::min(size_t(size), self.data.size() - self.position);
        if (size > 0 && n == 0) self.overran = true;
        // memcpy's pointers must be valid even for zero bytes; an empty vector's data() is null
        // (UBSan, from the unit tests).
        if (n > 0) std::memcpy(out, self.data.data() + self.position, n);
        self.position += n;
        return int(n);
    }
    static void skip(void* user, int n)
    {
        auto& self = *static_cast<StbInput*>(user);
        if (n < 0) {
            self.position -= std::min(self.position, size_t(-n));
        } else if (size_t(n) > self.data.size() - self.position) {
            self.overran = true;
            self.position = self.data.size();
        } else {
            self.position += size_t(n);
        }
    }
    static int eof(void* user)
    {
        auto& self = *static_cast<StbInput*>(user);
        return self.position >= self.data.size();
    }
    static constexpr stbi_io_callbacks kCallbacks{&StbInput::read, &StbInput::skip, &StbInput::eof};
};

struct StbFree {
    void operator()(void* p) const { stbi_image_free(p); }
};

// The renderer filters and integrates these values; one NaN or negative texel would spread
// through every mip level and prefiltered environment map.
float sanitize(float v)
{
    if (!(v > 0.0f)) return 0.0f; // negative or NaN
    return std::min(v, kHalfMax);
}

bool isExr(const std::vector<char>& data)
{
    static constexpr unsigned char kMagic[4] = {0x76, 0x2f, 0x31, 0x01};
    return data.size() >= 4 && std::memcmp(data.data(), kMagic, 4) == 0;
}

/// Walks the header(s) of an OpenEXR file before OpenEXR reads it: OpenEXR allocates each
/// attribute's declared size, and the tables of chunk offsets from the data window, before it
/// checks either against the file, so a forged size of 2 GiB in a 100-byte file is an
/// out-of-memory kill (found by an earlier fuzzing attempt on issue 16; the reproducer is
/// tests/unit/test_image_io.cpp, ExrAttributeSizeBeyondTheFileIsAnError). Returns the problem found, or nothing; the
/// rest (a bad type, bad compression) is left to OpenEXR, which reports it.
std::optional<std::string> checkExrHeader(const std::vector<char>& data)
{
    const size_t size = data.size();
    if (size < 8) return std::string("the file is truncated");
    const auto u32 = [&](size_t at) {
        uint32_t v = 0;
        std::memcpy(&v, data.data() + at, 4); // little endian, as are our targets
        return v;
    };
    const uint32_t flags = u32(4) >> 8;
    const bool longNames = flags & 0x4, multiPart = flags & 0x10;
    const size_t maxName = longNames ? 255 : 31;
    size_t pos = 8;
    // A null-terminated name of at most maxName characters, or nothing.
    const auto name = [&]() -> std::optional<std::string> {
        const size_t limit = std::min(size - pos, maxName + 1);
        const void* end = std::memchr(data.data() + pos, '\0', limit);
        if (!end) return std::nullopt;
        std::string text(data.data() + pos, static_cast<const char*>(end));
        pos += text.size() + 1;
        return text;
    };
    for (int part = 0;; ++part) {
        if (pos >= size) return std::string("the file is truncated");
        if (data[pos] == '\0') {
            ++pos; // the end of the headers (multi-part), or an empty header
            if (part == 0) return std::string("the header is empty");
            break;
        }
        for (;;) {
            if (pos >= size) return std::string("the file is truncated");
            if (data[pos] == '\0') {
                ++pos;
                break;
            }
            // A name without its terminator is a truncated file when the file ends first.
            const auto attribute = name();
            if (!attribute && size - pos <= maxName) return std::string("the file is truncated");
            if (!attribute) return std::string("an attribute name is too long or unterminated");
            const auto type = name();
            if (!type && size - pos <= maxName) return std::string("the file is truncated");
            if (!type) return fmt::format("attribute {}: its type name is too long or unterminated", *attribute);
            if (size - pos < 4) return std::string("the file is truncated");
            const int32_t length = int32_t(u32(pos));
            pos += 4;
            if (length < 0 || size_t(length) > size - pos)
                return fmt::format("attribute {} declares {} bytes, more than the file holds", *attribute, length);
            if (*attribute == "dataWindow" && *type == "box2i" && length == 16) {
                const int64_t xMin = int32_t(u32(pos)), yMin = int32_t(u32(pos + 4));
                const int64_t xMax = int32_t(u32(pos + 8)), yMax = int32_t(u32(pos + 12));
                const int64_t width = xMax - xMin + 1, height = yMax - yMin + 1;
                if (width <= 0 || height <= 0 || uint64_t(width) * uint64_t(height) > kMaxPixels)
                    return fmt::format("unsupported image size {}x{}", width, height);
            }
            pos += size_t(length);
        }
        if (!multiPart) break;
    }
    return std::nullopt;
}

ImageFloat readExr(const fs::path& path, const std::vector<char>& data)
{
    if (const auto problem = checkExrHeader(data)) readFailed(path, *problem);
    try {
        ExrInput stream(data, path);
        Imf::RgbaInputFile file(stream);
        const Imath::Box2i window = file.dataWindow();
        const int64_t width = int64_t(window.max.x) - window.min.x + 1;
        const int64_t height = int64_t(window.max.y) - window.min.y + 1;
        if (width <= 0 || height <= 0 || uint64_t(width) * uint64_t(height) > kMaxPixels)
            readFailed(path, fmt::format("unsupported image size {}x{}", width, height));
        if (!file.isComplete()) readFailed(path, "the file is truncated");

        std::vector<Imf::Rgba> pixels(size_t(width * height));
        // OpenEXR addresses pixel (x, y) at base + x + y * width. Imf::ComputeBasePointer forms
        // that base by pointer arithmetic, which overflows for a data window far from the
        // origin (undefined behaviour: fuzz_exr, a window at 3.7e8; UBSan "pointer index
        // expression overflowed"). Formed as an integer here, where wrapping is defined; every
        // address OpenEXR then computes from it lies inside `pixels`.
        const uint64_t origin = uint64_t(window.min.x + int64_t(window.min.y) * width) * sizeof(Imf::Rgba);
        auto* base = reinterpret_cast<Imf::Rgba*>(reinterpret_cast<uintptr_t>(pixels.data()) - uintptr_t(origin));
        file.setFrameBuffer(base, 1, size_t(width));
        file.readPixels(window.min.y, window.max.y);

        ImageFloat image;
        image.width = int(width);
        image.height = int(height);
        image.pixels.resize(pixels.size() * 4);
        for (size_t i = 0; i < pixels.size(); ++i) {
            image.pixels[i * 4 + 0] = sanitize(pixels[i].r);
            image.pixels[i * 4 + 1] = sanitize(pixels[i].g);
            image.pixels[i * 4 + 2] = sanitize(pixels[i].b);
            image.pixels[i * 4 + 3] = sanitize(pixels[i].a);
        }
        return image;
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        // OpenEXR prefixes what it was doing and the quoted file name, which we already give.
        std::string message = oneLine(e.what());
        const std::string quotedName = "\"" + path.string() + "\". ";
        if (const size_t at = message.find(quotedName); at != std::string::npos) message.erase(0, at + quotedName.size());
        readFailed(path, message);
    }
}

/// Walks the pixel data of a Radiance file as stb_image will decode it, without decoding. The
/// stb_image in Debian 12 loops forever on a zero run length, which a truncated or corrupt file
/// can contain, and returns a truncated file as if it were complete. Returns the problem found;
/// problems stb_image itself reports (a bad header, a wrong scanline length) are left to it.
std::optional<std::string> checkRadianceData(const std::vector<char>& data)
{
    const auto* bytes = reinterpret_cast<const uint8_t*>(data.data());
    const size_t size = data.size();
    size_t pos = 0;
    const auto nextLine = [&]() -> std::optional<std::string> {
        const void* newline = std::memchr(bytes + pos, '\n', size - pos);
        if (!newline) return std::nullopt;
        const size_t end = size_t(static_cast<const uint8_t*>(newline) - bytes);
        std::string line(data.data() + pos, end - pos);
        pos = end + 1;
        return line;
    };
    const std::string truncated = "the file is truncated";

    // Header lines end with an empty one; the resolution line follows. stb_image reads each line
    // as a C string: a line that starts with a NUL is empty to it (fuzz_hdr found a header that
    // ended so, and the walk below must start where stb_image's decoding does).
    for (;;) {
        const auto line = nextLine();
        if (!line) return truncated;
        if (line->empty() || (*line)[0] == '\0') break;
    }
    const auto resolution = nextLine();
    if (!resolution) return truncated;
    // Parsed as stb_image parses it ("-Y H +X W", strtol), up to the line's first NUL.
    const char* token = resolution->c_str();
    if (std::strncmp(token, "-Y ", 3) != 0) return std::nullopt;
    char* end = nullptr;
    const int height = int(std::strtol(token + 3, &end, 10)); // stb_image's (int) conversion too
    token = end;
    while (*token == ' ') ++token;
    if (std::strncmp(token, "+X ", 3) != 0) return std::nullopt;
    const int width = int(std::strtol(token + 3, nullptr, 10));
    if (width <= 0 || height <= 0 || width > (1 << 24) || height > (1 << 24)) return std::nullopt; // it refuses those
    const uint64_t flatSize = uint64_t(width) * uint64_t(height) * 4;
    // Outside these widths the format has no run-length encoding.
    if (width < 8 || width >= 32768) return size - pos >= flatSize ? std::nullopt : std::optional(truncated);

    for (int y = 0; y < height; ++y) {
        if (size - pos < 4) return truncated;
        if (bytes[pos] != 2 || bytes[pos + 1] != 2 || (bytes[pos + 2] & 0x80)) {
            // An old-style flat scanline: stb_image decodes the whole image flat from here.
            return size - pos >= flatSize ? std::nullopt : std::optional(truncated);
        }
        if (((bytes[pos + 2] << 8) | bytes[pos + 3]) != width) return std::nullopt;
        pos += 4;
        // Each of R, G, B, E separately: runs (count > 128, one byte repeated) and dumps.
        for (int channel = 0; channel < 4; ++channel) {
            for (int x = 0; x < width;) {
                if (pos >= size) return truncated;
                int count = bytes[pos++];
                size_t payload = 1;
                if (count > 128) {
                    count -= 128;
                } else {
                    if (count == 0) return std::string("corrupt run-length data");
                    payload = size_t(count);
                }
                if (count > width - x) return std::nullopt;
                if (size - pos < payload) return truncated;
                pos += payload;
                x += count;
            }
        }
    }
    return std::nullopt;
}

ImageFloat readHdr(const fs::path& path, const std::vector<char>& data)
{
    if (const auto problem = checkRadianceData(data)) readFailed(path, *problem);
    StbInput input{data};
    int width = 0, height = 0, channels = 0;
    std::unique_ptr<float, StbFree> pixels(
        stbi_loadf_from_callbacks(&StbInput::kCallbacks, &input, &width, &height, &channels, 4));
    if (!pixels) readFailed(path, fmt::format("not a valid Radiance image ({})", stbi_failure_reason()));
    if (input.overran) readFailed(path, "the file is truncated");
    ImageFloat image;
    image.width = width;
    image.height = height;
    image.pixels.assign(pixels.get(), pixels.get() + size_t(width) * size_t(height) * 4);
    for (float& v : image.pixels) v = sanitize(v);
    return image;
}

} // namespace

void writePng(const fs::path& path, const ImageRGBA8& image)
{
    checkExtension(path, Format::Png);
    checkWritable(path, image);
    AtomicFile file(path);
    const int ok = stbi_write_png_to_func(stbWrite, &file, image.width, image.height, 4, image.pixels.data(),
                                          image.width * 4);
    file.commit(ok ? nullptr : "the PNG encoder failed");
}

void writeHdr(const fs::path& path, const ImageFloat& image)
{
    checkExtension(path, Format::Hdr);
    checkWritable(path, image);
    // RGBE shares one exponent between three non-negative mantissas: a negative or NaN component
    // would wrap around to a bright garbage value.
    std::vector<float> rgb(size_t(image.width) * size_t(image.height) * 3);
    for (size_t i = 0, n = rgb.size() / 3; i < n; ++i)
        for (size_t c = 0; c < 3; ++c) {
            const float v = image.pixels[i * 4 + c];
            rgb[i * 3 + c] = v > 0.0f ? v : 0.0f;
        }
    AtomicFile file(path);
    const int ok = stbi_write_hdr_to_func(stbWrite, &file, image.width, image.height, 3, rgb.data());
    file.commit(ok ? nullptr : "the Radiance encoder failed");
}

void writeExr(const fs::path& path, const ImageFloat& image)
{
    checkExtension(path, Format::Exr);
    checkWritable(path, image);
    // Beyond ±65504 a half is infinite, and infinities break every reader's filtering.
    const auto toHalf = [](float v) { return half(std::clamp(v, -kHalfMax, kHalfMax)); };
    std::vector<Imf::Rgba> pixels(size_t(image.width) * size_t(image.height));
    for (size_t i = 0; i < pixels.size(); ++i) {
        const float* p = &image.pixels[i * 4];
        pixels[i] = Imf::Rgba(toHalf(p[0]), toHalf(p[1]), toHalf(p[2]), toHalf(p[3]));
    }

    AtomicFile file(path);
    std::string failure;
    try {
        ExrOutput stream(file, path);
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        Imf::RgbaOutputFile out(stream, header, Imf::WRITE_RGBA);
        out.setFrameBuffer(pixels.data(), 1, size_t(image.width));
        out.writePixels(image.height);
    } catch (const std::exception& e) {
        failure = oneLine(e.what());
    }
    // An errno recorded by the file explains a failure better than OpenEXR's message does.
    file.commit(failure.empty() ? nullptr : failure.c_str());
}

ImageRGBA8 readPng(const fs::path& path)
{
    const std::vector<char> data = readFile(path);
    if (!isPngOrJpeg(data.data(), data.size())) readFailed(path, "not a readable image (not a PNG or JPEG file)");
    if (const std::optional<EncodedImageSize> size = encodedImageSize(data.data(), data.size());
        size && uint64_t(size->width) * uint64_t(size->height) > kMaxPixels)
        readFailed(path, fmt::format("unsupported image size {}x{}", size->width, size->height));
    DecodedImage decoded = decodePngOrJpeg(data.data(), data.size());
    if (decoded.error == "the file is truncated") readFailed(path, decoded.error);
    if (!decoded.error.empty()) readFailed(path, fmt::format("not a readable image ({})", decoded.error));
    return std::move(decoded.image);
}

ImageFloat readFloatImage(const fs::path& path)
{
    return decodeFloatImage(readFile(path), path);
}

ImageFloat decodeFloatImage(const std::vector<char>& data, const fs::path& path)
{
    if (isExr(data)) return readExr(path, data);
    // Checked first because stbi_loadf would also accept an 8-bit image, silently linearising it
    // with an assumed gamma of 2.2.
    // The signature is in the first 11 bytes; passing fewer keeps the int length from overflowing.
    const int head = int(std::min<size_t>(data.size(), 64));
    if (!stbi_is_hdr_from_memory(reinterpret_cast<const stbi_uc*>(data.data()), head))
        readFailed(path, "not a Radiance .hdr or OpenEXR image");
    return readHdr(path, data);
}

void checkOutputPath(const fs::path& path)
{
    if (!path.has_filename()) writeFailed(path, "not a file name");
    if (!formatOf(path)) writeFailed(path, "unknown image format (use .png, .hdr or .exr)");
    std::error_code ec;
    if (fs::is_directory(path, ec)) writeFailed(path, "is a directory");
    const fs::path directory = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    if (!fs::exists(directory, ec)) writeFailed(path, fmt::format("directory {} does not exist", directory.string()));
    if (!fs::is_directory(directory, ec)) writeFailed(path, fmt::format("{} is not a directory", directory.string()));
    // Creating a file is the only reliable test: permission bits do not tell about read-only
    // mounts, ACLs or root.
    AtomicFile probe(path);
}

} // namespace specula
