#include "render/ImageBasedLighting.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>

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
    // irradiance cube can hold folded into it; v6: each source's spread).
    const uint64_t shaders = fnv1a64(gl::loadShaderSource(gl::shaderRoot(), "ibl/equirect_to_cube.comp", {}).text +
                                     gl::loadShaderSource(gl::shaderRoot(), "ibl/prefilter.comp", {}).text +
                                     gl::loadShaderSource(gl::shaderRoot(), "ibl/irradiance.comp", {}).text);
    return fmt::format("v6-c{}-p{}x{}s{}-i{}s{}-{:08x}", cubeSize, prefilterSize, prefilterLevels, prefilterSamples, kIrradianceSize,
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
void writeTextures(std::ofstream& out, const gl::Texture& texture)
{
    const int32_t header[3] = {texture.levels(), texture.desc().type == gl::TextureType::Cube ? 6 : 1, texture.width()};
    out.write(reinterpret_cast<const char*>(header), sizeof header);
    for (int level = 0; level < texture.levels(); ++level) {
        const size_t count = size_t(texture.width(level)) * size_t(texture.height(level)) * size_t(header[1]) * 4;
        std::vector<uint16_t> halfs(count);
        glGetTextureImage(texture.id(), level, GL_RGBA, GL_HALF_FLOAT, GLsizei(count * 2), halfs.data());
        out.write(reinterpret_cast<const char*>(halfs.data()), std::streamsize(count * 2));
    }
}

bool readTexture(std::ifstream& in, gl::Texture& texture, const std::string& label, gl::Format format, int channels)
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
    for (int level = 0; level < header[0]; ++level) {
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

void writeAtomically(const fs::path& file, const std::function<void(std::ofstream&)>& write)
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

void writeBright(std::ofstream& out, const std::vector<IrradianceSource>& bright)
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
    gl::Program toCube, prefilter, irradianceProgram;
    gl::Texture cube, prefiltered, irradiance;
    // With brightSourcesSpecular: the cube less the bright sources, and the prefiltered chain's
    // levels from kResidualFirstLevel on made from it.
    gl::Texture residualCube, residualPrefiltered;
    int specularSources = 0; // the first this many bright sources; 0: none
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

    /// `map` on a cube of `size`² faces (RGBA16F) with box-filtered mips.
    gl::Texture cubeFrom(gl::State& state, const EnvironmentMap& map, int size, const char* label)
    {
        // Source: RGBA32F so values above the half-float range (a real sun) survive until the cube.
        gl::TextureDesc sourceDesc;
        sourceDesc.format = gl::Format::RGBA32F;
        sourceDesc.width = map.width;
        sourceDesc.height = map.height;
        sourceDesc.label = "environment source";
        gl::Texture source(sourceDesc);
        std::vector<float> rgba(map.texels.size() * 4);
        for (size_t i = 0; i < map.texels.size(); ++i) {
            rgba[4 * i] = map.texels[i].x;
            rgba[4 * i + 1] = map.texels[i].y;
            rgba[4 * i + 2] = map.texels[i].z;
            rgba[4 * i + 3] = 1.0f;
        }
        source.upload(0, 0, 4, gl::PixelType::Float, rgba.data());
        glTextureParameteri(source.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);

        gl::TextureDesc cubeDesc;
        cubeDesc.type = gl::TextureType::Cube;
        cubeDesc.format = gl::Format::RGBA16F;
        cubeDesc.width = cubeDesc.height = size;
        cubeDesc.levels = 0;
        cubeDesc.label = label;
        gl::Texture out(cubeDesc);
        state.useProgram(program(toCube, "ibl/equirect_to_cube.comp"));
        state.bindTexture(0, source);
        state.bindSampler(0, nullptr); // the source's own repeat wrap (set above)
        state.bindImage(0, out, 0, gl::ImageAccess::WriteOnly, /*layered*/ true);
        state.dispatchCompute(uint32_t(groups(size)), uint32_t(groups(size)), 6);
        state.memoryBarrier(gl::Barrier::TextureFetch | gl::Barrier::TextureUpdate);
        out.generateMipmaps();
        return out;
    }

    /// Levels firstLevel .. s.prefilterLevels - 1 of the prefiltered chain of `source` into
    /// `target`'s levels 0, 1, ... (roughness = level / (levels - 1) of the whole chain).
    void prefilterLevels(gl::State& state, const gl::Texture& source, gl::Texture& target, int firstLevel, const BakeSettings& s,
                         const std::function<void(const std::string&)>& lap)
    {
        gl::Program& p = program(prefilter, "ibl/prefilter.comp");
        state.useProgram(p);
        state.bindTexture(0, source);
        state.bindSampler(0, nullptr);
        p.set(p.uniformLocation("uSamples"), uint32_t(s.prefilterSamples));
        p.set(p.uniformLocation("uSourceSize"), float(source.width()));
        p.set(p.uniformLocation("uSourceLevels"), float(source.levels()));
        const int roughness = p.uniformLocation("uPerceptualRoughness");
        for (int level = firstLevel; level < s.prefilterLevels; ++level) {
            p.set(roughness, float(level) / float(std::max(s.prefilterLevels - 1, 1)));
            state.bindImage(0, target, level - firstLevel, gl::ImageAccess::WriteOnly, /*layered*/ true);
            const int size = target.width(level - firstLevel);
            state.dispatchCompute(uint32_t(groups(size)), uint32_t(groups(size)), 6);
            lap(fmt::format("prefilter {}²", size));
        }
        state.memoryBarrier(gl::Barrier::TextureFetch | gl::Barrier::TextureUpdate);
    }

    void bake(gl::State& state, const EnvironmentMap& map, const BakeSettings& s)
    {
        gl::DebugGroup group("bake environment");
        // Each stage's time (glFinish after it: a bake waits for its results anyway), logged.
        Stopwatch stage;
        std::string stages;
        const auto lap = [&](const std::string& name) {
            glFinish();
            stages += fmt::format("{}{} {:.0f} ms", stages.empty() ? "" : ", ", name, stage.elapsedMs());
            stage = Stopwatch();
        };
        cube = cubeFrom(state, map, s.cubeSize, "environment cube");
        lap("cube");

        gl::TextureDesc prefilteredDesc = cube.desc();
        prefilteredDesc.width = prefilteredDesc.height = s.prefilterSize;
        prefilteredDesc.levels = s.prefilterLevels;
        prefilteredDesc.label = "prefiltered environment";
        prefiltered = gl::Texture(prefilteredDesc);
        prefilterLevels(state, cube, prefiltered, 0, s, lap);
        sh = projectSh9(map);
        IrradianceSplit split = splitIrradiance(map);
        // The specular lobe's bright sources (ibl/bright_sources.glsl): the first that hold
        // most of the bright sources' flux, where those are a large share of the map's.
        residualCube = gl::Texture();
        residualPrefiltered = gl::Texture();
        specularSources = leadingSourceCount(split.bright);
        if (split.bright.empty() || brightFluxShare(split, specularSources) < kSourcesSpecularShare) specularSources = 0;
        // The diffuse term sums per pixel only the sources the irradiance cube cannot hold.
        const size_t brightCount = split.bright.size();
        const size_t exact = foldSmoothSources(split, size_t(specularSources));
        bakeIrradiance(state, split);
        lap("irradiance");
        log::info("the diffuse term sums {} of the {} bright sources per pixel{}", exact, brightCount,
                  exact < brightCount ? ", the irradiance cube holds the rest" : "");
        if (specularSources > 0) log::info("the specular lobe takes {} of the {} bright sources as lights", specularSources, bright.size());
        if (specularSources > 0 && s.prefilterLevels > kResidualFirstLevel) {
            residualCube = cubeFrom(state, withoutBrightSources(map, split, specularSources), s.cubeSize,
                                    "environment cube less its bright sources");
            lap("residual cube");
            gl::TextureDesc desc = prefilteredDesc;
            desc.width = desc.height = std::max(s.prefilterSize >> kResidualFirstLevel, 1);
            desc.levels = s.prefilterLevels - kResidualFirstLevel;
            desc.label = "prefiltered environment less its bright sources";
            residualPrefiltered = gl::Texture(desc);
            prefilterLevels(state, residualCube, residualPrefiltered, kResidualFirstLevel, s, lap);
        } else {
            specularSources = 0;
        }
        log::info("bake stages: {}", stages);
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
const gl::Texture& ImageBasedLighting::prefiltered() const { return mImpl->prefiltered; }
const gl::Texture& ImageBasedLighting::irradiance() const { return mImpl->irradiance; }
const std::vector<IrradianceSource>& ImageBasedLighting::brightSources() const { return mImpl->bright; }
int ImageBasedLighting::specularSourceCount() const { return mImpl->specularSources; }
const gl::Texture& ImageBasedLighting::residualCube() const { return mImpl->residualCube; }
const gl::Texture& ImageBasedLighting::residualPrefiltered() const { return mImpl->residualPrefiltered; }
void ImageBasedLighting::setLutCacheDirectory(const fs::path& directory) { mImpl->lutCacheDirectory = directory; }

BakeReport ImageBasedLighting::setEnvironment(gl::State& state, const EnvironmentMap& original, const BakeSettings& requested,
                                              const fs::path& cacheDirectory)
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
        if (in && checkMagic(in) && readTexture(in, r.cube, "environment cube", gl::Format::RGBA16F, 4) &&
            readTexture(in, r.prefiltered, "prefiltered environment", gl::Format::RGBA16F, 4) &&
            readTexture(in, r.irradiance, "irradiance", gl::Format::RGBA16F, 4) &&
            in.read(reinterpret_cast<char*>(r.sh.data()), sizeof(Sh9)) && readBright(in, r.bright) && r.readResidual(in)) {
            r.has = true;
            report.fromCache = true;
            report.milliseconds = watch.elapsedMs();
            log::info("environment from the bake cache {} in {:.0f} ms", report.cacheFile.string(), report.milliseconds);
            return report;
        }
    }
    log::info("baking environment ({}x{}, preset {}: cube {}², prefilter {}² x {} levels, {} samples)", map.width, map.height,
              settings.name, settings.cubeSize, settings.prefilterSize, settings.prefilterLevels, settings.prefilterSamples);
    r.bake(state, map, settings);
    r.has = true;
    if (!report.cacheFile.empty()) {
        writeAtomically(report.cacheFile, [&](std::ofstream& out) {
            writeTextures(out, r.cube);
            writeTextures(out, r.prefiltered);
            writeTextures(out, r.irradiance);
            out.write(reinterpret_cast<const char*>(r.sh.data()), sizeof(Sh9));
            writeBright(out, r.bright);
            const int32_t residual = r.specularSources;
            out.write(reinterpret_cast<const char*>(&residual), sizeof residual);
            if (residual) {
                writeTextures(out, r.residualCube);
                writeTextures(out, r.residualPrefiltered);
            }
        });
    }
    glFinish();
    report.milliseconds = watch.elapsedMs();
    log::info("baked environment in {:.0f} ms{}", report.milliseconds,
              report.cacheFile.empty() ? "" : "; cached as " + report.cacheFile.string());
    return report;
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
    if (!file.empty()) writeAtomically(file, [&](std::ofstream& out) { writeTextures(out, lut); });
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
    if (!file.empty()) writeAtomically(file, [&](std::ofstream& out) { writeTextures(out, r.sheenLut); });
    log::info("baked the sheen albedo table ({}², {} samples) in {:.0f} ms (compiling {:.0f} ms)", r.lutSettings.lutSize, samples,
              bakeMs, compileMs);
    return r.sheenLut;
}

} // namespace specula::render
