#include "render/ImageBasedLighting.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <thread>

#include <unistd.h>

#include <fmt/format.h>

#include "core/Error.h"
#include "core/Hash.h"
#include "core/Log.h"
#include "core/Timer.h"
#include "gl/Debug.h"
#include "gl/Buffer.h"
#include "gl/Program.h"
#include "gl/ShaderSource.h"
#include "gl/State.h"
#include "gl/Texture.h"
#include "shading/VariantKey.h"

namespace specula::render {
namespace fs = std::filesystem;

std::string BakeSettings::key() const
{
    // The bake shaders, as compiled (includes resolved), are part of the key: editing one makes
    // a new cache entry rather than reading a stale one. v2: bump when the CPU side of the bake
    // (the spherical harmonics and irradiance sources of EnvironmentMap) or the file layout
    // changes (v2: the irradiance cube; v3: the bright sources' residual cube and prefiltered
    // levels; v4: with the count of the sources the specular lobe takes; v5: the bright sources the
    // irradiance cube can hold folded into it; v6: each source's spread; v7: the prefiltered
    // chain's level 0 not stored when it is the cube's; v8: the residual chain from level 1; v9:
    // the sky's own cube and chain when it shows what lighting does not, an extracted sun).
    const uint64_t shaders = fnv1a64(gl::loadShaderSource(gl::shaderRoot(), "ibl/equirect_to_cube.comp", {}).text +
                                     gl::loadShaderSource(gl::shaderRoot(), "ibl/downsample.comp", {}).text +
                                     gl::loadShaderSource(gl::shaderRoot(), "ibl/prefilter.comp", {}).text +
                                     gl::loadShaderSource(gl::shaderRoot(), "ibl/irradiance.comp", {}).text);
    return fmt::format("v9-c{}-p{}x{}s{}-i{}s{}-{:08x}", cubeSize, prefilterSize, prefilterLevels, prefilterSamples, kIrradianceSize,
                       kIrradianceSourceWidth, uint32_t(shaders ^ (shaders >> 32)));
}

BakeSettings BakeSettings::resolvedFor(int mapWidth) const
{
    BakeSettings s = *this;
    if (s.cubeSize <= 0) {
        s.cubeSize = 64;
        while (s.cubeSize < 1024 && s.cubeSize * 2 < mapWidth) s.cubeSize *= 2;
    }
    if (s.prefilterSize <= 0) s.prefilterSize = s.cubeSize;
    if (s.prefilterLevels <= 0) {
        s.prefilterLevels = 1;
        for (int size = s.prefilterSize; size > 4; size /= 2) ++s.prefilterLevels;
    }
    return s;
}

std::optional<BakeSettings> bakePreset(std::string_view name)
{
    if (name == "default") return BakeSettings{};
    if (name == "reference") {
        BakeSettings s;
        s.name = "reference";
        s.cubeSize = 512;
        s.prefilterSize = 128;
        s.prefilterLevels = 5;
        s.prefilterSamples = 1024;
        s.lutSize = 512;
        s.lutSamples = 1024;
        return s;
    }
    return std::nullopt;
}

BakeSettings previewSettings(const BakeSettings& full)
{
    BakeSettings p = full;
    p.name = full.name + " preview";
    p.cubeSize = std::min(full.cubeSize, kPreviewCubeSize);
    p.prefilterSize = std::min(full.prefilterSize, p.cubeSize);
    p.prefilterSamples = std::min(full.prefilterSamples, kPreviewSamples);
    if (p.cubeSize == full.cubeSize && p.prefilterSize == full.prefilterSize && p.prefilterSamples == full.prefilterSamples) return full;
    p.prefilterLevels = 0;
    return p.resolvedFor(p.cubeSize * 2);
}

fs::path defaultCacheDirectory()
{
    if (const char* dir = std::getenv("SPECULA_CACHE_DIR"); dir && *dir) return dir;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return fs::path(xdg) / "specula";
    if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".cache" / "specula";
    return fs::temp_directory_path() / "specula-cache";
}

namespace {

constexpr char kMagic[8] = {'S', 'P', 'C', 'L', 'I', 'B', 'L', '1'};

int groups(int size)
{
    return (size + 7) / 8;
}

// Cache files: magic, then per texture (levels, faces, size, RGBA16F texels level by level),
// then optional extra floats. Written to a temporary file and renamed: never half a cache.
// From `firstLevel` on (the levels before it are the reader's to make: readTexture's levelZero).
void writeTextures(std::ostream& out, const gl::Texture& texture, int firstLevel = 0)
{
    const int32_t header[3] = {texture.levels(), texture.desc().type == gl::TextureType::Cube ? 6 : 1, texture.width()};
    out.write(reinterpret_cast<const char*>(header), sizeof header);
    for (int level = firstLevel; level < texture.levels(); ++level) {
        const size_t count = size_t(texture.width(level)) * size_t(texture.height(level)) * size_t(header[1]) * 4;
        std::vector<uint16_t> halfs(count);
        glGetTextureImage(texture.id(), level, GL_RGBA, GL_HALF_FLOAT, GLsizei(count * 2), halfs.data());
        out.write(reinterpret_cast<const char*>(halfs.data()), std::streamsize(count * 2));
    }
}

/// Level 0 of `texture` (a cube) from `cube`'s level 0, which is the same size: a GPU copy.
void copyLevelZero(const gl::Texture& cube, gl::Texture& texture)
{
    glCopyImageSubData(cube.id(), GL_TEXTURE_CUBE_MAP, 0, 0, 0, 0, texture.id(), GL_TEXTURE_CUBE_MAP, 0, 0, 0, 0, cube.width(), cube.width(), 6);
}

/// `levelZero` (not null): the file holds levels 1.. and level 0 is copied from that cube
/// (writeTextures with firstLevel 1).
bool readTexture(std::ifstream& in, gl::Texture& texture, const std::string& label, gl::Format format, int channels,
                 const gl::Texture* levelZero = nullptr)
{
    int32_t header[3] = {};
    if (!in.read(reinterpret_cast<char*>(header), sizeof header)) return false;
    if (header[0] < 1 || header[0] > 16 || (header[1] != 1 && header[1] != 6) || header[2] < 1 || header[2] > 8192) return false;
    gl::TextureDesc desc;
    desc.type = header[1] == 6 ? gl::TextureType::Cube : gl::TextureType::Texture2D;
    desc.format = format;
    desc.width = desc.height = header[2];
    desc.levels = header[0];
    desc.label = label;
    gl::Texture t(desc);
    if (levelZero) {
        if (desc.type != gl::TextureType::Cube || !*levelZero || levelZero->width() != desc.width || levelZero->desc().format != format)
            return false;
        copyLevelZero(*levelZero, t);
    }
    for (int level = levelZero ? 1 : 0; level < header[0]; ++level) {
        const size_t texels = size_t(t.width(level)) * size_t(t.height(level));
        std::vector<uint16_t> halfs(texels * size_t(header[1]) * 4);
        if (!in.read(reinterpret_cast<char*>(halfs.data()), std::streamsize(halfs.size() * 2))) return false;
        for (int face = 0; face < header[1]; ++face) {
            const uint16_t* data = halfs.data() + size_t(face) * texels * 4;
            if (channels == 4) {
                t.upload(level, face, 4, gl::PixelType::HalfFloat, data);
            } else {
                std::vector<uint16_t> packed(texels * size_t(channels));
                for (size_t i = 0; i < texels; ++i)
                    for (int c = 0; c < channels; ++c) packed[i * size_t(channels) + size_t(c)] = data[i * 4 + size_t(c)];
                t.upload(level, face, channels, gl::PixelType::HalfFloat, packed.data());
            }
        }
    }
    texture = std::move(t);
    return true;
}

/// A cube and its prefiltered chain: the cube, a flag, then the chain, from level 1 when its
/// level 0 is the cube's (the same size: the bake copies it) and the flag 1.
void writeCubeAndChain(std::ostream& out, const gl::Texture& cube, const gl::Texture& chain)
{
    writeTextures(out, cube);
    const int32_t levelZeroFromCube = chain.width() == cube.width() ? 1 : 0;
    out.write(reinterpret_cast<const char*>(&levelZeroFromCube), sizeof levelZeroFromCube);
    writeTextures(out, chain, levelZeroFromCube);
}

bool readCubeAndChain(std::ifstream& in, gl::Texture& cube, gl::Texture& chain, const std::string& cubeLabel, const std::string& chainLabel)
{
    int32_t levelZeroFromCube = -1;
    return readTexture(in, cube, cubeLabel, gl::Format::RGBA16F, 4) &&
           in.read(reinterpret_cast<char*>(&levelZeroFromCube), sizeof levelZeroFromCube) &&
           (levelZeroFromCube == 0 || levelZeroFromCube == 1) &&
           readTexture(in, chain, chainLabel, gl::Format::RGBA16F, 4, levelZeroFromCube ? &cube : nullptr);
}

void writeAtomically(const fs::path& file, const std::function<void(std::ostream&)>& write)
{
    std::error_code ec;
    fs::create_directories(file.parent_path(), ec);
    const fs::path temp = file.string() + ".tmp" + std::to_string(::getpid());
    {
        std::ofstream out(temp, std::ios::binary);
        if (!out) {
            log::warn("cannot write the bake cache {}: not writable; continuing without it", file.string());
            return;
        }
        out.write(kMagic, sizeof kMagic);
        write(out);
        if (!out) {
            out.close();
            fs::remove(temp, ec);
            log::warn("cannot write the bake cache {}; continuing without it", file.string());
            return;
        }
    }
    fs::rename(temp, file, ec);
    if (ec) fs::remove(temp, ec);
}

void writeBright(std::ostream& out, const std::vector<IrradianceSource>& bright)
{
    const int32_t count = int32_t(bright.size());
    out.write(reinterpret_cast<const char*>(&count), sizeof count);
    out.write(reinterpret_cast<const char*>(bright.data()), std::streamsize(bright.size() * sizeof(IrradianceSource)));
}

bool readBright(std::ifstream& in, std::vector<IrradianceSource>& bright)
{
    int32_t count = 0;
    if (!in.read(reinterpret_cast<char*>(&count), sizeof count) || count < 0 || count > kIrradianceBrightSources) return false;
    bright.resize(size_t(count));
    return bool(in.read(reinterpret_cast<char*>(bright.data()), std::streamsize(bright.size() * sizeof(IrradianceSource))));
}

bool checkMagic(std::ifstream& in)
{
    char magic[8] = {};
    return in.read(magic, sizeof magic) && std::memcmp(magic, kMagic, sizeof magic) == 0;
}

int dfgKey(const ResolvedShading& variant)
{
    return (int(variant.distribution) * 8 + int(variant.geometry)) * 8 + int(variant.fresnel);
}

/// "ggx smith-ggx schlick": the variant's D, G and F by their scene-file names.
std::string dfgName(const ResolvedShading& variant)
{
    return fmt::format("{} {} {}", scene::brdfDistributionName(variant.distribution), scene::brdfGeometryName(variant.geometry),
                       scene::brdfFresnelName(variant.fresnel));
}

/// `map` as an RGBA32F texture, repeating across the seam: values above the half-float range (a
/// real sun) survive until the cube.
gl::Texture equirectSource(const EnvironmentMap& map)
{
    gl::TextureDesc desc;
    desc.format = gl::Format::RGBA32F;
    desc.width = map.width;
    desc.height = map.height;
    desc.label = "environment source";
    gl::Texture source(desc);
    std::vector<float> rgba(map.texels.size() * 4);
    for (size_t i = 0; i < map.texels.size(); ++i) {
        rgba[4 * i] = map.texels[i].x;
        rgba[4 * i + 1] = map.texels[i].y;
        rgba[4 * i + 2] = map.texels[i].z;
        rgba[4 * i + 3] = 1.0f;
    }
    source.upload(0, 0, 4, gl::PixelType::Float, rgba.data());
    glTextureParameteri(source.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    return source;
}

/// One dispatch of a bake: rows [y, y + rows) of faces [face, face + faces) of a level.
struct BakeStep {
    enum class Op { ToCube, Mipmaps, CopyLevelZero, Prefilter };
    Op op = Op::ToCube;
    int slot = 0;            ///< 0: the map, 1: the residual (less the specular lobe's sources), 2: the sky
    int level = 0;           ///< Prefilter: the target's level
    float roughness = 0.0f;  ///< Prefilter: perceptual roughness
    int face = 0, faces = 6; ///< faces [face, face + faces)
    int y = 0, rows = 0;     ///< rows [y, y + rows)
    double reads = 0.0;      ///< its texture reads: its share of the bake (progress)
    std::string stage;       ///< the log's stage it belongs to
};

/// A bake's textures while it runs: slot 0 the map's, slot 1 the residual's, slot 2 the sky's
/// (a cube and chain as the map's, for the sharp and the blurred sky). Slots 1 and 2 are empty
/// when not needed.
using BakeSources = std::array<std::shared_ptr<const gl::Texture>, 3>;
struct BakeJob {
    BakeSettings s;
    /// The equirect sources, shared by a progressive bake's preview and full jobs.
    BakeSources source;
    std::array<gl::Texture, 3> cube, prefiltered;
    std::vector<BakeStep> steps;
    size_t next = 0;
    double total = 0.0, done = 0.0; ///< texture reads
    std::vector<std::pair<std::string, double>> stages; ///< milliseconds by stage, in order
    fs::path cacheFile;
    Stopwatch watch; ///< since the bake began (its preview included)
    int frames = 0;  ///< advanceBake calls it took
};

} // namespace

ResolvedShading dfgVariant(const ResolvedShading& shading)
{
    ResolvedShading v;
    v.distribution = shading.distribution;
    v.geometry = shading.geometry;
    v.fresnel = shading.fresnel == scene::BrdfFresnel::None ? scene::BrdfFresnel::Schlick : shading.fresnel;
    return v;
}

struct ImageBasedLighting::Impl {
    gl::Program toCube, downsample, prefilter, irradianceProgram;
    gl::Texture cube, prefiltered, irradiance;
    // With brightSourcesSpecular: the cube less the bright sources, and the prefiltered chain's
    // levels from kResidualFirstLevel on made from it.
    gl::Texture residualCube, residualPrefiltered;
    // The sky's cube and chain where it shows what lighting does not (EnvironmentMap::skyOnly).
    gl::Texture skyCube, skyPrefiltered;
    int specularSources = 0; // the first this many bright sources; 0: none
    int analysedSpecularSources = 0; // what analyse found: specularSources once a bake has a residual
    /// The full bake still running after a preview (BakeMode::Progressive).
    std::unique_ptr<BakeJob> pending;
    std::thread cacheWriter; ///< writing a progressive bake's cache file
    /// DFG tables by dfgKey of their variant, made on first use; the compute program is
    /// compiled only to bake (a table read from the disk cache needs none) and not kept.
    std::map<int, gl::Texture> luts;
    gl::Texture sheenLut; ///< KHR_materials_sheen's E table, made on first use
    Sh9 sh{};
    std::vector<IrradianceSource> bright; // summed per pixel beside the irradiance cube
    bool has = false;
    fs::path lutCacheDirectory;
    BakeSettings lutSettings;

    gl::Program& program(gl::Program& p, const char* path)
    {
        if (!p) p = gl::Program({.compute = path, .label = path});
        return p;
    }

    /// The CPU half of a bake and the irradiance cube: the SH, the bright sources, the
    /// irradiance cube and how many sources the specular lobe takes (analysedSpecularSources).
    /// Returns the map less those sources (for the residual cube), or nothing when none.
    std::optional<EnvironmentMap> analyse(gl::State& state, const EnvironmentMap& map)
    {
        sh = projectSh9(map);
        IrradianceSplit split = splitIrradiance(map);
        // The specular lobe's bright sources (ibl/bright_sources.glsl): the first that hold
        // most of the bright sources' flux, where those are a large share of the map's.
        analysedSpecularSources = leadingSourceCount(split.bright);
        if (split.bright.empty() || brightFluxShare(split, analysedSpecularSources) < kSourcesSpecularShare) analysedSpecularSources = 0;
        // The diffuse term sums per pixel only the sources the irradiance cube cannot hold.
        const size_t brightCount = split.bright.size();
        const size_t exact = foldSmoothSources(split, size_t(analysedSpecularSources));
        bakeIrradiance(state, split);
        log::info("the diffuse term sums {} of the {} bright sources per pixel{}", exact, brightCount,
                  exact < brightCount ? ", the irradiance cube holds the rest" : "");
        if (analysedSpecularSources > 0)
            log::info("the specular lobe takes {} of the {} bright sources as lights", analysedSpecularSources, bright.size());
        if (analysedSpecularSources == 0) return std::nullopt;
        return withoutBrightSources(map, split, analysedSpecularSources);
    }

    /// A bake's GPU work on the map (and on its residual, sources[1], and the sky's, sources[2],
    /// when not null): the cubes, then their prefiltered chains, as steps run in order
    /// (runStep). maxReads 0: one step per level, the bake at once; else steps of a band of rows
    /// of one face, each about that many texture reads, for a bake spread over frames.
    std::unique_ptr<BakeJob> makeJob(const BakeSources& sources, const BakeSettings& s, double maxReads)
    {
        auto job = std::make_unique<BakeJob>();
        job->s = s;
        const bool withResidual = sources[1] && s.prefilterLevels > kResidualFirstLevel;
        static constexpr const char* kCubeLabels[3] = {"environment cube", "environment cube less its bright sources", "sky cube"};
        static constexpr const char* kChainLabels[3] = {"prefiltered environment", "prefiltered environment less its bright sources",
                                                        "prefiltered sky"};
        static constexpr const char* kStagePrefixes[3] = {"", "residual ", "sky "};
        for (int slot = 0; slot < 3; ++slot) {
            if (!sources[size_t(slot)] || (slot == 1 && !withResidual)) continue;
            job->source[size_t(slot)] = sources[size_t(slot)];
            gl::TextureDesc cubeDesc;
            cubeDesc.type = gl::TextureType::Cube;
            cubeDesc.format = gl::Format::RGBA16F;
            cubeDesc.width = cubeDesc.height = s.cubeSize;
            cubeDesc.levels = 0;
            cubeDesc.label = kCubeLabels[slot];
            job->cube[size_t(slot)] = gl::Texture(cubeDesc);
            // Level 0 of the residual chain is the whole chain's kResidualFirstLevel.
            const int first = slot == 1 ? kResidualFirstLevel : 0;
            gl::TextureDesc desc = cubeDesc;
            desc.width = desc.height = std::max(s.prefilterSize >> first, 1);
            desc.levels = s.prefilterLevels - first;
            desc.label = kChainLabels[slot];
            job->prefiltered[size_t(slot)] = gl::Texture(desc);

            const std::string prefix = kStagePrefixes[slot];
            BakeStep toCube{.op = BakeStep::Op::ToCube, .slot = slot, .stage = prefix + "cube"};
            addBands(*job, toCube, s.cubeSize, 1.0, maxReads);
            // The box-filtered mips: one step (every level, ibl/downsample.comp).
            job->steps.push_back({.op = BakeStep::Op::Mipmaps, .slot = slot, .reads = double(s.cubeSize) * s.cubeSize * 6 * 0.5,
                                  .stage = prefix + "cube"});
            job->total += job->steps.back().reads;
            for (int level = first; level < s.prefilterLevels; ++level) {
                BakeStep step{.op = BakeStep::Op::Prefilter, .slot = slot, .level = level - first,
                              .roughness = float(level) / float(std::max(s.prefilterLevels - 1, 1))};
                const int size = job->prefiltered[size_t(slot)].width(level - first);
                step.stage = fmt::format("{}prefilter {}²", prefix, size);
                if (level == 0 && size == s.cubeSize) {
                    // The mirror at the cube's own size is the cube: copied, and not stored twice
                    // in the cache (finish, setEnvironment).
                    step.op = BakeStep::Op::CopyLevelZero;
                    step.reads = double(size) * size * 6;
                    job->total += step.reads;
                    job->steps.push_back(step);
                    continue;
                }
                addBands(*job, step, size, step.roughness > 0.0f ? double(s.prefilterSamples) : 1.0, maxReads);
            }
        }
        return job;
    }

    /// Adds `step` over the faces of a level of `size`² texels, `readsPerTexel` texture reads
    /// each: one step (maxReads 0, or all of it fits), else bands of rows of one face, whole
    /// work groups, of about maxReads reads.
    static void addBands(BakeJob& job, BakeStep step, int size, double readsPerTexel, double maxReads)
    {
        const double faceReads = double(size) * double(size) * readsPerTexel;
        if (maxReads <= 0.0 || 6.0 * faceReads <= maxReads) {
            step.rows = size;
            step.reads = 6.0 * faceReads;
            job.total += step.reads;
            job.steps.push_back(step);
            return;
        }
        const int rows = std::clamp(int(maxReads / (double(size) * readsPerTexel)) / 8 * 8, std::min(8, size), size);
        step.faces = 1;
        for (int face = 0; face < 6; ++face) {
            for (int y = 0; y < size; y += rows) {
                step.face = face;
                step.y = y;
                step.rows = std::min(rows, size - y);
                step.reads = double(size) * step.rows * readsPerTexel;
                job.total += step.reads;
                job.steps.push_back(step);
            }
        }
    }

    void runStep(gl::State& state, BakeJob& job, const BakeStep& step)
    {
        const size_t slot = size_t(step.slot);
        gl::Texture& cube = job.cube[slot];
        switch (step.op) {
        case BakeStep::Op::ToCube: {
            gl::Program& p = program(toCube, "ibl/equirect_to_cube.comp");
            state.useProgram(p);
            state.bindTexture(0, *job.source[slot]);
            state.bindSampler(0, nullptr); // the source's own repeat wrap (equirectSource)
            p.set(p.uniformLocation("uOffset"), glm::ivec3(0, step.y, step.face));
            state.bindImage(0, cube, 0, gl::ImageAccess::WriteOnly, /*layered*/ true);
            state.dispatchCompute(uint32_t(groups(cube.width())), uint32_t(groups(step.rows)), uint32_t(step.faces));
            break;
        }
        case BakeStep::Op::Mipmaps:
            if ((cube.width() & (cube.width() - 1)) == 0) {
                // Power-of-two faces: 2 x 2 box means, level by level (ibl/downsample.comp).
                gl::Program& p = program(downsample, "ibl/downsample.comp");
                state.useProgram(p);
                for (int level = 1; level < cube.levels(); ++level) {
                    state.memoryBarrier(gl::Barrier::Image);
                    state.bindImage(0, cube, level - 1, gl::ImageAccess::ReadOnly, /*layered*/ true);
                    state.bindImage(1, cube, level, gl::ImageAccess::WriteOnly, /*layered*/ true);
                    state.dispatchCompute(uint32_t(groups(cube.width(level))), uint32_t(groups(cube.width(level))), 6);
                }
            } else {
                cube.generateMipmaps();
            }
            // The equirect stays until the job ends: a viewer's GL objects then do not depend
            // on how far a bake has come (CliViewer.LoadingAModelAndAnEnvironmentAgain…).
            break;
        case BakeStep::Op::CopyLevelZero:
            copyLevelZero(cube, job.prefiltered[slot]);
            break;
        case BakeStep::Op::Prefilter: {
            gl::Program& p = program(prefilter, "ibl/prefilter.comp");
            state.useProgram(p);
            state.bindTexture(0, cube);
            state.bindSampler(0, nullptr);
            p.set(p.uniformLocation("uSamples"), uint32_t(job.s.prefilterSamples));
            p.set(p.uniformLocation("uSourceSize"), float(cube.width()));
            p.set(p.uniformLocation("uSourceLevels"), float(cube.levels()));
            p.set(p.uniformLocation("uPerceptualRoughness"), step.roughness);
            p.set(p.uniformLocation("uOffset"), glm::ivec3(0, step.y, step.face));
            gl::Texture& target = job.prefiltered[slot];
            state.bindImage(0, target, step.level, gl::ImageAccess::WriteOnly, /*layered*/ true);
            state.dispatchCompute(uint32_t(groups(target.width(step.level))), uint32_t(groups(step.rows)), uint32_t(step.faces));
            break;
        }
        }
        state.memoryBarrier(gl::Barrier::TextureFetch | gl::Barrier::TextureUpdate);
        ++job.next;
        job.done += step.reads;
    }

    /// Runs `job`'s next step and waits for it; its time goes to its stage's.
    void runTimedStep(gl::State& state, BakeJob& job)
    {
        const BakeStep& step = job.steps[job.next];
        Stopwatch watch;
        runStep(state, job, step);
        glFinish(); // the step's time, not its submission's (a bake waits for its results anyway)
        const double ms = watch.elapsedMs();
        auto it = std::find_if(job.stages.begin(), job.stages.end(), [&](const auto& s) { return s.first == step.stage; });
        if (it == job.stages.end()) job.stages.emplace_back(step.stage, ms);
        else it->second += ms;
    }

    /// Makes `job`'s textures the environment's, logs its stages and writes the cache file
    /// (`inBackground`: read back now, written to the disk by a thread, so that a viewer's frame
    /// does not wait for it).
    void finish(std::unique_ptr<BakeJob> job, const fs::path& cacheFile, bool inBackground = false)
    {
        std::string stages;
        for (const auto& [name, ms] : job->stages) stages += fmt::format("{}{} {:.0f} ms", stages.empty() ? "" : ", ", name, ms);
        log::info("bake stages: {}", stages);
        cube = std::move(job->cube[0]);
        prefiltered = std::move(job->prefiltered[0]);
        residualCube = std::move(job->cube[1]);
        residualPrefiltered = std::move(job->prefiltered[1]);
        skyCube = std::move(job->cube[2]);
        skyPrefiltered = std::move(job->prefiltered[2]);
        specularSources = residualCube ? analysedSpecularSources : 0;
        has = true;
        if (cacheFile.empty()) return;
        const auto write = [&](std::ostream& out) {
            writeCubeAndChain(out, cube, prefiltered);
            writeTextures(out, irradiance);
            out.write(reinterpret_cast<const char*>(sh.data()), sizeof(Sh9));
            writeBright(out, bright);
            const int32_t residual = specularSources;
            out.write(reinterpret_cast<const char*>(&residual), sizeof residual);
            if (residual) {
                writeTextures(out, residualCube);
                writeTextures(out, residualPrefiltered);
            }
            const int32_t sky = skyCube ? 1 : 0;
            out.write(reinterpret_cast<const char*>(&sky), sizeof sky);
            if (sky) writeCubeAndChain(out, skyCube, skyPrefiltered);
        };
        if (!inBackground) {
            writeAtomically(cacheFile, write);
            return;
        }
        std::ostringstream bytes;
        write(bytes);
        if (cacheWriter.joinable()) cacheWriter.join();
        cacheWriter = std::thread([file = cacheFile, data = std::move(bytes).str()] {
            writeAtomically(file, [&](std::ostream& out) { out.write(data.data(), std::streamsize(data.size())); });
        });
    }

    ~Impl()
    {
        if (cacheWriter.joinable()) cacheWriter.join();
    }

    /// The cache's residual textures (after the bright sources): the specular sources' count,
    /// then both textures unless it is 0.
    bool readResidual(std::ifstream& in)
    {
        int32_t flag = -1;
        residualCube = gl::Texture();
        residualPrefiltered = gl::Texture();
        if (!in.read(reinterpret_cast<char*>(&flag), sizeof flag) || flag < 0 || flag > int32_t(bright.size())) return false;
        specularSources = flag;
        return specularSources == 0 || (readTexture(in, residualCube, "environment cube less its bright sources", gl::Format::RGBA16F, 4) &&
                                    readTexture(in, residualPrefiltered, "prefiltered environment less its bright sources",
                                                gl::Format::RGBA16F, 4));
    }

    /// The cache's sky (after the residual textures): a flag, then its cube and chain when it is 1.
    bool readSky(std::ifstream& in)
    {
        int32_t flag = -1;
        skyCube = gl::Texture();
        skyPrefiltered = gl::Texture();
        if (!in.read(reinterpret_cast<char*>(&flag), sizeof flag) || (flag != 0 && flag != 1)) return false;
        return flag == 0 || readCubeAndChain(in, skyCube, skyPrefiltered, "sky cube", "prefiltered sky");
    }

    /// The irradiance cube: the map reduced on the CPU (32-bit float), convolved on the GPU.
    void bakeIrradiance(gl::State& state, const IrradianceSplit& split)
    {
        bright = split.bright;
        const std::vector<IrradianceSource>& sources = split.cube;
        std::vector<glm::vec4> packed;
        packed.reserve(sources.size() * 2);
        for (const IrradianceSource& s : sources) {
            packed.emplace_back(s.direction, s.spread);
            packed.emplace_back(s.flux, 0.0f);
        }
        const gl::Buffer buffer(packed.size() * sizeof(glm::vec4), packed.data(), "irradiance sources");
        gl::TextureDesc desc;
        desc.type = gl::TextureType::Cube;
        desc.format = gl::Format::RGBA16F;
        desc.width = desc.height = kIrradianceSize;
        desc.label = "irradiance";
        irradiance = gl::Texture(desc);
        state.useProgram(program(irradianceProgram, "ibl/irradiance.comp"));
        gl::bindStorageBuffer(0, buffer);
        state.bindImage(0, irradiance, 0, gl::ImageAccess::WriteOnly, /*layered*/ true);
        state.dispatchCompute(uint32_t(groups(kIrradianceSize)), uint32_t(groups(kIrradianceSize)), 6);
        state.memoryBarrier(gl::Barrier::TextureFetch | gl::Barrier::TextureUpdate);
    }

    /// Returns the milliseconds spent compiling the program (the rest of a bake is the dispatch).
    double bakeLut(gl::State& state, gl::Texture& lut, const std::vector<std::string>& defines, const std::string& label,
                   const char* shader = "ibl/dfg.comp", int samples = 0)
    {
        gl::DebugGroup group("bake " + label);
        gl::TextureDesc desc;
        desc.format = gl::Format::RG16F;
        desc.width = desc.height = lutSettings.lutSize;
        desc.label = label;
        lut = gl::Texture(desc);
        Stopwatch compile;
        gl::Program p({.compute = shader, .defines = defines, .label = label});
        const double compileMs = compile.elapsedMs();
        state.useProgram(p);
        p.set(p.uniformLocation("uSamples"), uint32_t(samples > 0 ? samples : lutSettings.lutSamples));
        state.bindImage(0, lut, 0, gl::ImageAccess::WriteOnly);
        state.dispatchCompute(uint32_t(groups(lutSettings.lutSize)), uint32_t(groups(lutSettings.lutSize)), 1);
        state.memoryBarrier(gl::Barrier::TextureFetch | gl::Barrier::TextureUpdate);
        return compileMs;
    }
};

ImageBasedLighting::ImageBasedLighting() : mImpl(std::make_unique<Impl>()) {}
ImageBasedLighting::~ImageBasedLighting() = default;
ImageBasedLighting::ImageBasedLighting(ImageBasedLighting&&) noexcept = default;
ImageBasedLighting& ImageBasedLighting::operator=(ImageBasedLighting&&) noexcept = default;

bool ImageBasedLighting::hasEnvironment() const { return mImpl->has; }
const Sh9& ImageBasedLighting::sh() const { return mImpl->sh; }
const gl::Texture& ImageBasedLighting::cube() const { return mImpl->cube; }
const gl::Texture& ImageBasedLighting::sky() const { return mImpl->skyCube ? mImpl->skyCube : mImpl->cube; }
const gl::Texture& ImageBasedLighting::skyPrefiltered() const { return mImpl->skyCube ? mImpl->skyPrefiltered : mImpl->prefiltered; }
const gl::Texture& ImageBasedLighting::prefiltered() const { return mImpl->prefiltered; }
const gl::Texture& ImageBasedLighting::irradiance() const { return mImpl->irradiance; }
const std::vector<IrradianceSource>& ImageBasedLighting::brightSources() const { return mImpl->bright; }
int ImageBasedLighting::specularSourceCount() const { return mImpl->specularSources; }
const gl::Texture& ImageBasedLighting::residualCube() const { return mImpl->residualCube; }
const gl::Texture& ImageBasedLighting::residualPrefiltered() const { return mImpl->residualPrefiltered; }
void ImageBasedLighting::setLutCacheDirectory(const fs::path& directory) { mImpl->lutCacheDirectory = directory; }

BakeReport ImageBasedLighting::setEnvironment(gl::State& state, const EnvironmentMap& original, const BakeSettings& requested,
                                              const fs::path& cacheDirectory, BakeMode mode)
{
    // The bake uploads the map as one 2D texture: wider or taller than the GL limit, it is
    // downscaled first (a GL error otherwise).
    const int maxSize = gl::maxTextureSize();
    const EnvironmentMap fitted = original.width > maxSize || original.height > maxSize ? downscaledToFit(original, maxSize) : EnvironmentMap{};
    const EnvironmentMap& map = fitted.width > 0 ? fitted : original;
    if (&map == &fitted)
        log::warn("the environment is {}x{}, larger than this GPU's texture limit of {}; downscaled to {}x{}", original.width,
                  original.height, maxSize, map.width, map.height);
    const BakeSettings settings = requested.resolvedFor(map.width);
    Impl& r = *mImpl;
    r.pending.reset(); // a new environment ends the last one's bake
    Stopwatch watch;
    BakeReport report;
    // Tables of other sizes or sample counts are other tables.
    if (settings.lutSize != r.lutSettings.lutSize || settings.lutSamples != r.lutSettings.lutSamples) {
        r.luts.clear();
        r.sheenLut = gl::Texture();
    }
    r.lutSettings = settings;
    if (!cacheDirectory.empty()) {
        report.cacheFile = cacheDirectory / fmt::format("env-{}-{}.bin", map.key, settings.key());
        std::ifstream in(report.cacheFile, std::ios::binary);
        if (in && checkMagic(in) && readCubeAndChain(in, r.cube, r.prefiltered, "environment cube", "prefiltered environment") &&
            readTexture(in, r.irradiance, "irradiance", gl::Format::RGBA16F, 4) &&
            in.read(reinterpret_cast<char*>(r.sh.data()), sizeof(Sh9)) && readBright(in, r.bright) && r.readResidual(in) &&
            r.readSky(in)) {
            r.has = true;
            report.fromCache = true;
            report.milliseconds = watch.elapsedMs();
            log::info("environment from the bake cache {} in {:.0f} ms", report.cacheFile.string(), report.milliseconds);
            return report;
        }
    }
    const BakeSettings preview = previewSettings(settings);
    const bool progressive = mode == BakeMode::Progressive && (preview.cubeSize != settings.cubeSize ||
                                                                 preview.prefilterSamples != settings.prefilterSamples);
    log::info("baking environment ({}x{}, preset {}: cube {}², prefilter {}² x {} levels, {} samples{})", map.width, map.height,
              settings.name, settings.cubeSize, settings.prefilterSize, settings.prefilterLevels, settings.prefilterSamples,
              progressive ? fmt::format("; a preview of a {}² cube with {} samples first", preview.cubeSize, preview.prefilterSamples) : "");
    {
        gl::DebugGroup group("bake environment");
        Stopwatch analysis;
        const std::optional<EnvironmentMap> residual = r.analyse(state, map);
        glFinish();
        const double analysisMs = analysis.elapsedMs();
        BakeSources sources;
        sources[0] = std::make_shared<const gl::Texture>(equirectSource(map));
        if (residual) sources[1] = std::make_shared<const gl::Texture>(equirectSource(*residual));
        if (!map.skyOnly.empty()) sources[2] = std::make_shared<const gl::Texture>(equirectSource(skyOf(map)));
        // A progressive bake's steps: a band of rows of a face, about 2M texture reads each
        // (10-20 ms on llvmpipe, well under one on a GPU).
        constexpr double kReadsPerStep = 2.0e6;
        std::unique_ptr<BakeJob> job = r.makeJob(sources, progressive ? preview : settings, 0.0);
        job->stages.emplace_back("irradiance", analysisMs);
        if (progressive) r.pending = r.makeJob(sources, settings, kReadsPerStep);
        while (job->next < job->steps.size()) r.runTimedStep(state, *job);
        r.finish(std::move(job), progressive ? fs::path() : report.cacheFile);
    }
    glFinish();
    report.milliseconds = watch.elapsedMs();
    if (progressive) {
        report.progressive = true;
        r.pending->cacheFile = report.cacheFile;
        r.pending->watch = watch;
        log::info("baked the environment's preview in {:.0f} ms; the full bake follows over the frames ({} steps)", report.milliseconds,
                  r.pending->steps.size());
    } else {
        log::info("baked environment in {:.0f} ms{}", report.milliseconds,
                  report.cacheFile.empty() ? "" : "; cached as " + report.cacheFile.string());
    }
    return report;
}

BakeProgress ImageBasedLighting::advanceBake(gl::State& state, double budgetMs)
{
    Impl& r = *mImpl;
    BakeProgress progress;
    if (!r.pending) return progress;
    BakeJob& job = *r.pending;
    gl::DebugGroup group("bake environment");
    Stopwatch watch;
    ++job.frames;
    do {
        r.runTimedStep(state, job);
    } while (job.next < job.steps.size() && watch.elapsedMs() < budgetMs);
    progress.fraction = job.total > 0.0 ? job.done / job.total : 1.0;
    if (job.next < job.steps.size()) {
        progress.pending = true;
        return progress;
    }
    progress.finished = true;
    const double ms = job.watch.elapsedMs();
    const int frames = job.frames;
    const fs::path file = job.cacheFile;
    Stopwatch finishing;
    r.finish(std::move(r.pending), file, /*inBackground*/ true);
    log::info("baked environment over {} frames, {:.1f} s after it began{} ({:.0f} ms)", frames, ms / 1000.0,
              file.empty() ? "" : "; cached as " + file.string(), finishing.elapsedMs());
    return progress;
}

void ImageBasedLighting::waitForCacheWrite()
{
    if (mImpl->cacheWriter.joinable()) mImpl->cacheWriter.join();
}

bool ImageBasedLighting::hasDfg(const ResolvedShading& shading) const
{
    const auto it = mImpl->luts.find(dfgKey(dfgVariant(shading)));
    return it != mImpl->luts.end() && it->second;
}

const gl::Texture& ImageBasedLighting::dfg(gl::State& state, const ResolvedShading& shading)
{
    Impl& r = *mImpl;
    const ResolvedShading variant = dfgVariant(shading);
    gl::Texture& lut = r.luts[dfgKey(variant)];
    if (lut) return lut;
    // The defines are the forward pass's for this D, G and F (one table, shading/VariantKey).
    const std::vector<std::string> defines = ForwardVariant::make(0, variant, DebugView::None, IblVariant::None, false, false, false).defines();
    const std::string name = dfgName(variant);
    const std::string label = "dfg " + name;
    fs::path file;
    if (!r.lutCacheDirectory.empty()) {
        // The key holds what the table depends on: the variant, its size and samples, and the
        // shader source as compiled (includes and defines), so an edited BRDF term or bake
        // shader is a new entry rather than a stale one.
        const uint64_t source = fnv1a64(gl::loadShaderSource(gl::shaderRoot(), "ibl/dfg.comp", defines).text);
        std::string fileName = fmt::format("dfg-{}-{}x{}-{:016x}.bin", name, r.lutSettings.lutSize, r.lutSettings.lutSamples, source);
        std::replace(fileName.begin(), fileName.end(), ' ', '-');
        file = r.lutCacheDirectory / fileName;
        std::ifstream in(file, std::ios::binary);
        if (in && checkMagic(in) && readTexture(in, lut, label, gl::Format::RG16F, 2) && lut.width() == r.lutSettings.lutSize)
            return lut;
    }
    Stopwatch watch;
    const double compileMs = r.bakeLut(state, lut, defines, label);
    glFinish(); // the time of the bake, not of its submission
    const double bakeMs = watch.elapsedMs();
    if (!file.empty()) writeAtomically(file, [&](std::ostream& out) { writeTextures(out, lut); });
    log::info("baked the DFG table of {} ({}², {} samples) in {:.0f} ms (compiling {:.0f} ms)", name, r.lutSettings.lutSize,
              r.lutSettings.lutSamples, bakeMs, compileMs);
    return lut;
}

const gl::Texture& ImageBasedLighting::sheenAlbedo(gl::State& state)
{
    Impl& r = *mImpl;
    if (r.sheenLut) return r.sheenLut;
    const int samples = r.lutSettings.lutSamples * kSheenAlbedoSampleFactor;
    const std::string label = "sheen albedo";
    fs::path file;
    if (!r.lutCacheDirectory.empty()) {
        // As the DFG tables': size, samples and the compiled source name the entry.
        const uint64_t source = fnv1a64(gl::loadShaderSource(gl::shaderRoot(), "ibl/sheen_albedo.comp", {}).text);
        file = r.lutCacheDirectory / fmt::format("sheen-albedo-{}x{}-{:016x}.bin", r.lutSettings.lutSize, samples, source);
        std::ifstream in(file, std::ios::binary);
        if (in && checkMagic(in) && readTexture(in, r.sheenLut, label, gl::Format::RG16F, 2) && r.sheenLut.width() == r.lutSettings.lutSize)
            return r.sheenLut;
    }
    Stopwatch watch;
    const double compileMs = r.bakeLut(state, r.sheenLut, {}, label, "ibl/sheen_albedo.comp", samples);
    glFinish(); // the time of the bake, not of its submission
    const double bakeMs = watch.elapsedMs();
    if (!file.empty()) writeAtomically(file, [&](std::ostream& out) { writeTextures(out, r.sheenLut); });
    log::info("baked the sheen albedo table ({}², {} samples) in {:.0f} ms (compiling {:.0f} ms)", r.lutSettings.lutSize, samples,
              bakeMs, compileMs);
    return r.sheenLut;
}

} // namespace specula::render
