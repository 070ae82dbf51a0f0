#include "render/GpuScene.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>

#include "core/Footprint.h"
#include "core/Hash.h"
#include "core/Log.h"
#include "gl/State.h"
#include "scene/Pose.h"
#include "shading/ShadingVariant.h"
#include "shaders/shared/Bindings.h"
#include "shaders/shared/MaterialData.h"

namespace specula::render {
namespace {

gl::Filter toGl(scene::Filter f)
{
    return f == scene::Filter::Nearest ? gl::Filter::Nearest : gl::Filter::Linear;
}

gl::Wrap toGl(scene::Wrap w)
{
    switch (w) {
    case scene::Wrap::Repeat: return gl::Wrap::Repeat;
    case scene::Wrap::MirroredRepeat: return gl::Wrap::MirroredRepeat;
    case scene::Wrap::ClampToEdge: return gl::Wrap::ClampToEdge;
    }
    return gl::Wrap::Repeat;
}

/// Image `image`'s alpha is 255 in every texel, or it is missing or undecodable (the draw then
/// binds white): sampled and filtered, it never lowers a factor's alpha.
bool opaqueAlpha(const scene::Scene& scene, int image)
{
    if (image < 0 || size_t(image) >= scene.images.size()) return true;
    const scene::Image& source = scene.images[size_t(image)];
    const size_t texels = size_t(std::max(source.width, 0)) * size_t(std::max(source.height, 0));
    if (texels == 0 || source.pixels.size() < texels * 4) return true;
    for (size_t i = 0; i < texels; ++i)
        if (source.pixels[i * 4 + 3] != 255) return false;
    return true;
}

/// `source` box-filtered down to fit `maxSize` on both sides, keeping its aspect ratio (each
/// output texel averages the source texels its footprint covers, at least one).
scene::Image downscaled(const scene::Image& source, int maxSize)
{
    const double scale = double(maxSize) / double(std::max(source.width, source.height));
    scene::Image out;
    out.name = source.name;
    out.width = std::clamp(int(source.width * scale), 1, maxSize);
    out.height = std::clamp(int(source.height * scale), 1, maxSize);
    out.pixels.resize(size_t(out.width) * size_t(out.height) * 4);
    for (int y = 0; y < out.height; ++y) {
        const auto [y0, y1] = footprint(y, out.height, source.height);
        for (int x = 0; x < out.width; ++x) {
            const auto [x0, x1] = footprint(x, out.width, source.width);
            uint64_t sum[4] = {0, 0, 0, 0};
            for (int sy = y0; sy < y1; ++sy)
                for (int sx = x0; sx < x1; ++sx)
                    for (int c = 0; c < 4; ++c) sum[c] += source.pixels[(size_t(sy) * size_t(source.width) + size_t(sx)) * 4 + size_t(c)];
            const uint64_t n = uint64_t(y1 - y0) * uint64_t(x1 - x0);
            for (int c = 0; c < 4; ++c)
                out.pixels[(size_t(y) * size_t(out.width) + size_t(x)) * 4 + size_t(c)] = uint8_t((sum[c] + n / 2) / n);
        }
    }
    return out;
}

/// Each slot's texture (scene::kMaterialTextures, in slot order): whether it holds sRGB colour,
/// and the record's flag for it.
struct SlotFormat {
    bool srgb;
    uint32_t flag;
};
constexpr std::array<SlotFormat, size_t(TextureSlot::Count)> kSlots{{
    {true, SPECULA_MATERIAL_HAS_BASE_COLOR_TEXTURE},
    {false, SPECULA_MATERIAL_HAS_METALLIC_ROUGHNESS_TEXTURE},
    {false, SPECULA_MATERIAL_HAS_NORMAL_TEXTURE},
    {false, SPECULA_MATERIAL_HAS_OCCLUSION_TEXTURE},
    {true, SPECULA_MATERIAL_HAS_EMISSIVE_TEXTURE},
    // Read only by the CLEARCOAT variant, which samples the first two always (white without
    // one) and the normal map where the record's flag says there is one.
    {false, 0u},
    {false, 0u},
    {false, SPECULA_MATERIAL_HAS_CLEARCOAT_NORMAL_TEXTURE},
    // Read only by the SHEEN variant, which samples both always (white without one).
    {true, 0u},
    {false, 0u},
    // Read only by the ANISOTROPY variant, where anisotropy.w says there is one (linear).
    {false, 0u},
    // Read only by the IRIDESCENCE variant, which samples both always (white without one:
    // factor x 1, and the maximum thickness, as the extension says).
    {false, 0u},
    {false, 0u},
    // Read only by the SPECULAR_TEXTURES variant (A, and sRGB colour), which samples both
    // (white without one).
    {false, 0u},
    {true, 0u},
    // Read only by the TRANSMISSION_TEXTURES variant (R, and G), which samples both (white
    // without one).
    {false, 0u},
    {false, 0u},
    // Read only by the DIFFUSE_TRANSMISSION_TEXTURES variant (A, and sRGB colour), which
    // samples both (white without one).
    {false, 0u},
    {true, 0u},
}};
static_assert(scene::kMaterialTextures.size() == kSlots.size(), "one slot for every texture of scene::Material");

void packTransformRows(shared::GpuMaterial& gpu, int slot, const scene::UvTransform& transform)
{
    // Rows of the 2x3 affine part of KHR_texture_transform's 3x3 matrix.
    const glm::mat3 m = transform.matrix();
    gpu.uvTransform[2 * slot] = glm::vec4(m[0][0], m[1][0], m[2][0], 0.0f);
    gpu.uvTransform[2 * slot + 1] = glm::vec4(m[0][1], m[1][1], m[2][1], 0.0f);
}

void packTransform(shared::GpuMaterial& gpu, int slot, const scene::TextureRef& ref)
{
    packTransformRows(gpu, slot, ref.transform);
    (slot < 16 ? gpu.flags.y : gpu.flags.z) |= uint32_t(ref.texCoord & 3) << (2 * (slot % 16));
}

/// A material's factors in its record (everything a material's numbers set; not the flags,
/// the texture transforms or the classic models' ks): at load, and again for an animated
/// material's animated fields (GpuScene::setAnimatedFields).
void packFactors(const scene::Material& m, shared::GpuMaterial& gpu)
{
    gpu.baseColorFactor = m.baseColorFactor;
    gpu.alpha.x = m.alphaCutoff;
    gpu.emissive = glm::vec4(m.emissiveFactor * m.emissiveStrength, float(m.sectorLight) / 255.0f);
    gpu.params = glm::vec4(m.metallicFactor, m.roughnessFactor, m.normalScale, m.occlusionStrength);
    gpu.specular = glm::vec4(m.specularColorFactor, m.specularFactor);
    // KHR_materials_ior: the shader's dielectric F0 is 0.04 x specular.rgb (x factor).
    if (m.ior) gpu.specular = glm::vec4(m.specularColorFactor * (scene::f0FromIor(*m.ior) / 0.04f), m.specularFactor);
    gpu.transmission = glm::vec4(m.transmissionFactor, m.ior.value_or(1.5f), m.thickness, m.attenuationDistance);
    gpu.attenuation = glm::vec4(m.attenuationColor, m.dispersion);
    gpu.clearcoat = glm::vec4(m.clearcoatFactor, m.clearcoatRoughnessFactor, m.clearcoatNormalScale, 0.0f);
    gpu.sheen = glm::vec4(m.sheenColorFactor, m.sheenRoughnessFactor);
    // The rotation as its cosine and sine: the shader turns the direction with them (w: the
    // texture's flag, set with the textures).
    gpu.anisotropy = glm::vec4(m.anisotropyStrength, std::cos(m.anisotropyRotation), std::sin(m.anisotropyRotation), gpu.anisotropy.w);
    gpu.iridescence = glm::vec4(m.iridescenceFactor, m.iridescenceIor, m.iridescenceThicknessMinimum, m.iridescenceThicknessMaximum);
    gpu.diffuseTransmission = glm::vec4(m.diffuseTransmissionColorFactor, m.diffuseTransmissionFactor);
}

/// The layers' variants a record's factors switch on (MaterialData.h bits, those above 31 the
/// binding's only): a layer of factor 0 is no layer at all — the texture only scales the factor,
/// as each extension says —, so its variant and textures go. One rule for the load, the viewer's
/// edits and the animations' (GpuScene::writeRecord).
constexpr uint64_t kLayerFeatures = SPECULA_MATERIAL_TRANSMISSION | SPECULA_MATERIAL_DISPERSION | SPECULA_MATERIAL_CLEARCOAT |
                                    SPECULA_MATERIAL_SHEEN | SPECULA_MATERIAL_ANISOTROPY | SPECULA_MATERIAL_IRIDESCENCE |
                                    SPECULA_MATERIAL_DIFFUSE_TRANSMISSION;
uint64_t layerFeatures(const shared::GpuMaterial& r)
{
    uint64_t bits = 0;
    if (r.transmission.x > 0.0f) bits |= SPECULA_MATERIAL_TRANSMISSION;
    // Dispersion spreads what a volume refracts: nothing to spread without a thickness.
    if (r.attenuation.w > 0.0f && r.transmission.z > 0.0f) bits |= SPECULA_MATERIAL_DISPERSION;
    if (r.clearcoat.x > 0.0f) bits |= SPECULA_MATERIAL_CLEARCOAT;
    // A black sheen colour is no sheen (the extension's words).
    if (glm::any(glm::greaterThan(glm::vec3(r.sheen), glm::vec3(0.0f)))) bits |= SPECULA_MATERIAL_SHEEN;
    // Strength 0 is the isotropic lobe.
    if (r.anisotropy.x > 0.0f) bits |= SPECULA_MATERIAL_ANISOTROPY;
    if (r.iridescence.x > 0.0f) bits |= SPECULA_MATERIAL_IRIDESCENCE;
    if (r.diffuseTransmission.w > 0.0f) bits |= SPECULA_MATERIAL_DIFFUSE_TRANSMISSION;
    return bits;
}

struct SharedLodChain {
    const scene::Primitive* source = nullptr;
    scene::LodChain chain;
};
using LodChains = std::unordered_multimap<uint64_t, SharedLodChain>;

/// `p`'s levels of detail, from `chains` when a primitive with the same vertices and indices
/// was simplified before (a scene's repeated shapes).
const scene::LodChain& lodChain(LodChains& chains, const scene::Primitive& p)
{
    const auto bytes = [](const auto& v) {
        return std::string_view(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(v[0]));
    };
    const uint64_t key = fnv1a64(bytes(p.vertices)) ^ (fnv1a64(bytes(p.indices)) * 0x9e3779b97f4a7c15ull);
    const auto [begin, end] = chains.equal_range(key);
    for (auto it = begin; it != end; ++it) {
        const scene::Primitive& s = *it->second.source;
        if (bytes(s.vertices) == bytes(p.vertices) && bytes(s.indices) == bytes(p.indices)) return it->second.chain;
    }
    return chains.emplace(key, SharedLodChain{&p, scene::buildLodChain(p)})->second.chain;
}

} // namespace

int textureUnit(TextureSlot slot)
{
    switch (slot) {
    case TextureSlot::Clearcoat: return SPECULA_UNIT_CLEARCOAT;
    case TextureSlot::ClearcoatRoughness: return SPECULA_UNIT_CLEARCOAT_ROUGHNESS;
    case TextureSlot::ClearcoatNormal: return SPECULA_UNIT_CLEARCOAT_NORMAL;
    case TextureSlot::SheenColor: return SPECULA_UNIT_SHEEN_COLOR;
    case TextureSlot::SheenRoughness: return SPECULA_UNIT_SHEEN_ROUGHNESS;
    case TextureSlot::Anisotropy: return SPECULA_UNIT_ANISOTROPY;
    case TextureSlot::Iridescence: return SPECULA_UNIT_IRIDESCENCE;
    case TextureSlot::IridescenceThickness: return SPECULA_UNIT_IRIDESCENCE_THICKNESS;
    case TextureSlot::Specular: return SPECULA_UNIT_SPECULAR;
    case TextureSlot::SpecularColor: return SPECULA_UNIT_SPECULAR_COLOR;
    case TextureSlot::Transmission: return SPECULA_UNIT_TRANSMISSION_FACTOR;
    case TextureSlot::Thickness: return SPECULA_UNIT_THICKNESS;
    case TextureSlot::DiffuseTransmission: return SPECULA_UNIT_DIFFUSE_TRANSMISSION;
    case TextureSlot::DiffuseTransmissionColor: return SPECULA_UNIT_DIFFUSE_TRANSMISSION_COLOR;
    default: return int(slot);
    }
}

void GpuScene::buildLevelsOfDetail()
{
    if (mLevelsOfDetail) return;
    mLevelsOfDetail = true;
    // From the GPU's own copies (the scene need not outlive its upload): each primitive's
    // vertices and indices read back once, simplified, and its index buffer replaced by the
    // chain (level 0 first, the same indices). Identical meshes are simplified once.
    LodChains chains;
    std::vector<scene::Primitive> sources; // kept alive: the cache compares against them
    sources.reserve(mPrimitives.size());
    // A shared geometry gets its chain once; its other primitives take the same levels.
    std::unordered_map<const GpuGeometry*, std::vector<scene::LodLevel>> done;
    for (GpuPrimitive& gpu : mPrimitives) {
        const size_t triangles = gpu.count / 3;
        if (gpu.topology != scene::Topology::Triangles || triangles < scene::kLodMinTriangles) continue;
        GpuGeometry& geometry = *gpu.geometry;
        if (const auto it = done.find(&geometry); it != done.end()) {
            if (it->second.size() < 2) continue;
            gpu.indexed = true;
            gpu.count = it->second[0].count;
            gpu.lods = it->second;
            continue;
        }
        scene::Primitive& p = sources.emplace_back();
        const std::vector<std::byte> vertices = geometry.vertices.read(0, geometry.vertices.size());
        p.vertices.resize(vertices.size() / sizeof(scene::Vertex));
        std::memcpy(p.vertices.data(), vertices.data(), p.vertices.size() * sizeof(scene::Vertex));
        if (gpu.indexed) {
            const std::vector<std::byte> indices = geometry.indices.read(0, size_t(gpu.count) * sizeof(uint32_t));
            p.indices.resize(gpu.count);
            std::memcpy(p.indices.data(), indices.data(), indices.size());
        }
        const scene::LodChain& chain = lodChain(chains, p);
        done.emplace(&geometry, chain.levels);
        if (chain.levels.size() < 2) continue;
        geometry.indices = gl::Buffer(chain.indices.size() * sizeof(uint32_t), chain.indices.data(), gpu.name + " indices (levels of detail)");
        gpu.indexed = true;
        gpu.count = chain.levels[0].count;
        gpu.lods = chain.levels;
        geometry.vertexArray.indexBuffer(geometry.indices);
    }
}

const gl::Sampler* GpuScene::sampler(const scene::Scene&, int index)
{
    if (index < 0 || size_t(index) >= mSamplers.size()) return &mDefaultSampler;
    return &mSamplers[size_t(index)];
}

const gl::Texture* GpuScene::texture(const scene::Scene& scene, int image, bool srgb)
{
    if (image < 0 || size_t(image) >= scene.images.size()) return nullptr;
    const scene::Image& source = scene.images[size_t(image)];
    if (source.width <= 0 || source.height <= 0 || source.pixels.size() < size_t(source.width) * source.height * 4)
        return nullptr; // missing or undecodable: the renderer binds a neutral texture
    gl::Texture& slot = mTextures[size_t(image)][srgb ? 1 : 0];
    if (!slot) {
        // A texture larger than the GL limit is a GL error; shrink it instead, once per image.
        const int maxSize = gl::maxTextureSize();
        std::optional<scene::Image> smaller;
        if (source.width > maxSize || source.height > maxSize) {
            smaller = downscaled(source, maxSize);
            log::warn("{} is {}x{}, larger than this GPU's texture limit of {}; downscaled to {}x{}",
                      source.name.empty() ? "image " + std::to_string(image) : source.name, source.width, source.height,
                      maxSize, smaller->width, smaller->height);
        }
        const scene::Image& pixels = smaller ? *smaller : source;
        gl::TextureDesc desc;
        desc.format = srgb ? gl::Format::SRGB8_ALPHA8 : gl::Format::RGBA8;
        desc.width = pixels.width;
        desc.height = pixels.height;
        desc.levels = 0;
        desc.label = source.name.empty() ? "image " + std::to_string(image) : source.name;
        slot = gl::Texture(desc);
        // Rows go up top row first: GL's t = 0 is then the image's top, which is where glTF's
        // v = 0 is, so uvs need no flip.
        slot.upload(0, 0, 4, gl::PixelType::UnsignedByte, pixels.pixels.data());
        slot.generateMipmaps();
        mTextureBytes += pixels.pixels.size() * 4 / 3;
    }
    return &slot;
}

GpuScene::GpuScene(const scene::Scene& scene)
    : mDefaultSampler(gl::SamplerDesc{}, "default sampler")
{
    mTextures.resize(scene.images.size());
    for (size_t i = 0; i < scene.samplers.size(); ++i) {
        const scene::Sampler& s = scene.samplers[i];
        gl::SamplerDesc desc;
        desc.magFilter = toGl(s.magFilter);
        desc.minFilter = toGl(s.minFilter);
        desc.mipFilter = !s.mipmaps ? gl::MipFilter::None : s.mipLinear ? gl::MipFilter::Linear : gl::MipFilter::Nearest;
        desc.wrapS = toGl(s.wrapS);
        desc.wrapT = toGl(s.wrapT);
        mSamplers.emplace_back(desc, "sampler " + std::to_string(i));
    }

    // Materials, plus the glTF default material at the end.
    std::vector<scene::Material> materials = scene.materials;
    materials.push_back(scene::Material{.name = "default"});
    std::vector<shared::GpuMaterial> gpuMaterials;
    for (const scene::Material& m : materials) {
        shared::GpuMaterial gpu{};
        packFactors(m, gpu);
        // Classic models' specular colour: mid grey, a plastic highlight (Phong 1975's ks).
        gpu.phong = glm::vec4(glm::vec3(0.5f), m.shininess);
        for (int slot = 0; slot < int(TextureSlot::Count); ++slot) gpu.uvTransform[2 * slot] = {1, 0, 0, 0}, gpu.uvTransform[2 * slot + 1] = {0, 1, 0, 0};

        MaterialBinding binding;
        binding.alphaMode = binding.declaredAlphaMode = m.alphaMode;
        binding.doubleSided = m.doubleSided;
        if (m.alphaMode == scene::AlphaMode::Blend && m.baseColorTexture.valid())
            binding.opaqueTexels = opaqueAlpha(scene, m.baseColorTexture.image);
        binding.transmission = m.transmissionFactor;
        uint64_t textureFeatures = 0; // the extension textures' variants (MaterialData.h)
        for (size_t slot = 0; slot < kSlots.size(); ++slot) {
            const scene::TextureRef& ref = m.*scene::kMaterialTextures[slot];
            if (!ref.valid()) continue;
            const gl::Texture* tex = texture(scene, ref.image, kSlots[slot].srgb);
            if (!tex) continue;
            binding.textures[slot] = tex;
            binding.samplers[slot] = sampler(scene, ref.sampler);
            gpu.flags.x |= kSlots[slot].flag;
            packTransform(gpu, int(slot), ref);
            if (TextureSlot(slot) == TextureSlot::Anisotropy) gpu.anisotropy.w = 1.0f;
            if (TextureSlot(slot) == TextureSlot::Specular || TextureSlot(slot) == TextureSlot::SpecularColor)
                textureFeatures |= SPECULA_MATERIAL_SPECULAR_TEXTURES;
            if (TextureSlot(slot) == TextureSlot::Transmission || TextureSlot(slot) == TextureSlot::Thickness)
                textureFeatures |= SPECULA_MATERIAL_TRANSMISSION_TEXTURES;
            if (TextureSlot(slot) == TextureSlot::DiffuseTransmission || TextureSlot(slot) == TextureSlot::DiffuseTransmissionColor)
                textureFeatures |= SPECULA_MATERIAL_DIFFUSE_TRANSMISSION_TEXTURES;
        }
        if (m.doubleSided) gpu.flags.x |= SPECULA_MATERIAL_DOUBLE_SIDED;
        if (m.alphaMode == scene::AlphaMode::Mask) gpu.flags.x |= SPECULA_MATERIAL_ALPHA_MASK;
        if (m.alphaMode == scene::AlphaMode::Blend) gpu.flags.x |= SPECULA_MATERIAL_ALPHA_BLEND;
        if (m.alphaMode == scene::AlphaMode::Blend && m.blendMode == scene::BlendMode::Transparent)
            gpu.flags.x |= SPECULA_MATERIAL_BLEND_TRANSPARENT;
        const uint64_t layers = layerFeatures(gpu);
        gpu.flags.x |= uint32_t(layers); // the bits above 31 are the binding's only
        // The shading model and BRDF terms select the variant too (not read by the shaders).
        binding.features = gpu.flags.x | packShading(m.shading) | textureFeatures | layers;
        gpuMaterials.push_back(gpu);
        mRecordMaterial.push_back(int(mMaterials.size()));
        mMaterials.push_back(binding);
    }
    const int defaultMaterial = int(materials.size() - 1);

    // Primitives, mesh by mesh. Those with the same vertices and indices as one uploaded before
    // share its buffers (candidates by their counts, then compared byte for byte: memcmp stops
    // at the first difference).
    struct Uploaded {
        const scene::Primitive* source;
        std::shared_ptr<GpuGeometry> geometry;
    };
    std::multimap<std::pair<size_t, size_t>, Uploaded> uploaded;
    auto geometryOf = [&](const scene::Primitive& p, const std::string& name, bool shared) {
        const std::pair key(p.vertices.size(), p.indices.size());
        if (shared) {
            const auto [begin, end] = uploaded.equal_range(key);
            for (auto it = begin; it != end; ++it) {
                const scene::Primitive& s = *it->second.source;
                if (std::memcmp(s.vertices.data(), p.vertices.data(), p.vertices.size() * sizeof(scene::Vertex)) == 0 &&
                    std::equal(s.indices.begin(), s.indices.end(), p.indices.begin()))
                    return it->second.geometry;
            }
        }
        auto g = std::make_shared<GpuGeometry>();
        g->vertices = gl::Buffer(p.vertices.size() * sizeof(scene::Vertex), p.vertices.data(), name + " vertices");
        if (!p.indices.empty()) g->indices = gl::Buffer(p.indices.size() * sizeof(uint32_t), p.indices.data(), name + " indices");
        g->vertexArray = gl::VertexArray(name);
        g->vertexArray.vertexBuffer(0, g->vertices, 0, sizeof(scene::Vertex))
            .attribute(SPECULA_ATTRIB_POSITION, 0, 3, gl::AttributeType::Float, offsetof(scene::Vertex, position))
            .attribute(SPECULA_ATTRIB_NORMAL, 0, 3, gl::AttributeType::Float, offsetof(scene::Vertex, normal))
            .attribute(SPECULA_ATTRIB_TANGENT, 0, 4, gl::AttributeType::Float, offsetof(scene::Vertex, tangent))
            .attribute(SPECULA_ATTRIB_UV0, 0, 2, gl::AttributeType::Float, offsetof(scene::Vertex, uv0))
            .attribute(SPECULA_ATTRIB_UV1, 0, 2, gl::AttributeType::Float, offsetof(scene::Vertex, uv1))
            .attribute(SPECULA_ATTRIB_COLOR, 0, 4, gl::AttributeType::Float, offsetof(scene::Vertex, color));
        if (!p.indices.empty()) g->vertexArray.indexBuffer(g->indices);
        if (shared) uploaded.emplace(key, Uploaded{&p, g});
        return g;
    };
    // `shared`: false for a deformed draw's own copy, whose vertices are rewritten per pose.
    auto upload = [&](const scene::Primitive& p, const std::string& name, bool shared = true) {
        GpuPrimitive gpu;
        gpu.name = name;
        gpu.geometry = geometryOf(p, name, shared);
        gpu.indexed = !p.indices.empty();
        gpu.count = uint32_t(gpu.indexed ? p.indices.size() : p.vertices.size());
        gpu.topology = p.topology;
        auto record = [&](int material) { return material >= 0 && material < defaultMaterial ? material : defaultMaterial; };
        gpu.material = gpu.baseMaterial = record(p.material);
        for (const scene::VariantMapping& mapping : p.variants) gpu.variants.push_back({mapping.variant, record(mapping.material)});
        gpu.bounds = p.bounds;
        return gpu;
    };
    std::vector<std::vector<int>> meshPrimitives(scene.meshes.size());
    for (size_t meshIndex = 0; meshIndex < scene.meshes.size(); ++meshIndex) {
        for (const scene::Primitive& p : scene.meshes[meshIndex].primitives) {
            if (p.vertices.empty()) continue;
            meshPrimitives[meshIndex].push_back(int(mPrimitives.size()));
            mPrimitives.push_back(upload(p, scene.meshes[meshIndex].name));
        }
    }
    // A record drawn with a change its material does not make: one copy per material and kind
    // of change (`copies`), the change applied to the copy's GPU record and its binding.
    auto recordCopy = [&](std::map<int, int>& copies, int material, auto change) {
        const auto [found, added] = copies.try_emplace(material, int(gpuMaterials.size()));
        if (!added) return found->second;
        gpuMaterials.push_back(gpuMaterials[size_t(material)]);
        mMaterials.push_back(mMaterials[size_t(material)]);
        mRecordMaterial.push_back(mRecordMaterial[size_t(material)]);
        change(gpuMaterials.back(), mMaterials.back());
        return found->second;
    };
    // Vertex colours multiply base colour (glTF COLOR_0); the flag lives on the material,
    // so primitives with colours draw with a copy of their material's record.
    std::map<int, int> colourCopies;
    auto colourCopy = [&](int material) {
        return recordCopy(colourCopies, material, [](shared::GpuMaterial& record, MaterialBinding& binding) {
            record.flags.x |= SPECULA_MATERIAL_USE_VERTEX_COLOR;
            // The copy's record flags; the shading choice and the texture bits above them stay.
            constexpr uint64_t kRecordFlags = 0xffffffffu & ~uint64_t(kShadingFeatureMask);
            binding.features = record.flags.x | (binding.features & ~kRecordFlags);
        });
    };
    // Lines and points without normals draw unlit (scene::Primitive::unlit): a copy of their
    // material's record (or of its colour copy) with the unlit model.
    std::map<int, int> unlitCopies;
    auto unlitCopy = [&](int material) {
        return recordCopy(unlitCopies, material, [](shared::GpuMaterial&, MaterialBinding& binding) {
            binding.features = (binding.features & ~uint64_t(kShadingFeatureMask)) | packShading({.model = scene::ShadingModel::Unlit});
            binding.unlitCopy = true;
        });
    };
    for (size_t meshIndex = 0, primitiveIndex = 0; meshIndex < scene.meshes.size(); ++meshIndex) {
        for (const scene::Primitive& p : scene.meshes[meshIndex].primitives) {
            if (p.vertices.empty()) continue;
            GpuPrimitive& gpu = mPrimitives[primitiveIndex++];
            if (p.hasColors) {
                gpu.material = gpu.baseMaterial = colourCopy(gpu.baseMaterial);
                for (scene::VariantMapping& mapping : gpu.variants) mapping.material = colourCopy(mapping.material);
            }
            if (p.unlit) {
                gpu.material = gpu.baseMaterial = unlitCopy(gpu.baseMaterial);
                for (scene::VariantMapping& mapping : gpu.variants) mapping.material = unlitCopy(mapping.material);
            }
            if (!p.hasColors) continue;
            const bool opaqueColours =
                std::all_of(p.vertices.begin(), p.vertices.end(), [](const scene::Vertex& v) { return v.color.a >= 1.0f; });
            if (opaqueColours) continue;
            mMaterials[size_t(gpu.baseMaterial)].opaqueTexels = false;
            for (const scene::VariantMapping& mapping : gpu.variants) mMaterials[size_t(mapping.material)].opaqueTexels = false;
        }
    }
    // Each record starts at a multiple of GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT so it can be bound alone.
    const size_t alignment = size_t(std::max(gl::uniformBufferOffsetAlignment(), 16));
    mMaterialStride = (sizeof(shared::GpuMaterial) + alignment - 1) / alignment * alignment;
    std::vector<std::byte> records(gpuMaterials.size() * mMaterialStride);
    for (size_t i = 0; i < gpuMaterials.size(); ++i)
        std::memcpy(records.data() + i * mMaterialStride, &gpuMaterials[i], sizeof(shared::GpuMaterial));
    mMaterialBuffer = gl::Buffer(records.size(), records.data(), "materials");
    mRecords = std::move(gpuMaterials);
    mMaterialCount = int(materials.size());
    for (size_t record = 0; record < mMaterials.size(); ++record) updateCoverage(record);

    // Skins, morph targets and animations make the scene move: keep what posing needs, and
    // give each draw of a deformed primitive a vertex buffer of its own.
    bool moves = !scene.animations.empty();
    for (const scene::MeshInstance& instance : scene.meshInstances())
        for (const scene::Primitive& p : scene.meshes[size_t(instance.mesh)].primitives)
            moves = moves || p.deformable();
    if (moves) {
        mRig.emplace();
        mRig->nodes = scene.nodes;
        mRig->roots = scene.roots;
        mRig->meshes = scene.meshes;
        mRig->skins = scene.skins;
        mRig->animations = scene.animations;
        // KHR_animation_pointer: what posing writes into materials and lights starts from these.
        for (const scene::AnimatedProperty& p : scene::animatedProperties(scene)) {
            if (!scene::isMaterialField(p.field)) continue;
            if (p.index < 0 || size_t(p.index) >= scene.materials.size()) continue; // the importer refuses these
            auto same = std::find_if(mAnimatedMaterials.begin(), mAnimatedMaterials.end(),
                                     [&](const AnimatedMaterial& a) { return a.material == p.index; });
            if (same == mAnimatedMaterials.end()) same = mAnimatedMaterials.insert(mAnimatedMaterials.end(), {p.index, {}});
            same->fields.push_back(p);
        }
        if (!mAnimatedMaterials.empty()) mRig->materials = scene.materials;
        mRig->lights = scene.lights;
    }
    // Hidden nodes' meshes (KHR_node_visibility) are kept where an animation may show them.
    const scene::HiddenNodes hidden = scene.hiddenNodesToKeep(); // Include only with animations, so with mRig
    for (const scene::MeshInstance& instance : scene.meshInstances(hidden)) {
        const auto& sourcePrimitives = scene.meshes[size_t(instance.mesh)].primitives;
        for (size_t k = 0, drawn = 0; k < sourcePrimitives.size(); ++k) {
            const scene::Primitive& source = sourcePrimitives[k];
            if (source.vertices.empty()) continue;
            int primitive = meshPrimitives[size_t(instance.mesh)][drawn++];
            const scene::Node& node = scene.nodes[size_t(instance.node)];
            if (source.deformable()) {
                DeformedDraw deformed;
                deformed.draw = mDraws.size();
                deformed.mesh = instance.mesh;
                deformed.primitive = int(k);
                deformed.skinned = node.skin >= 0 && source.influences > 0;
                mDeformed.push_back(deformed);
                GpuPrimitive own = upload(source, scene.meshes[size_t(instance.mesh)].name + " (deformed)", false);
                own.material = own.baseMaterial = mPrimitives[size_t(primitive)].material;
                own.variants = mPrimitives[size_t(primitive)].variants;
                primitive = int(mPrimitives.size());
                mPrimitives.push_back(std::move(own));
            }
            if (mRig) mDrawNode.push_back(instance.node);
            DrawItem item;
            item.primitive = primitive;
            item.world = instance.world;
            item.normalMatrix = glm::transpose(glm::inverse(glm::mat3(instance.world)));
            item.mirrored = glm::determinant(glm::mat3(instance.world)) < 0.0f;
            item.castShadows = instance.castShadows;
            item.receiveShadows = instance.receiveShadows;
            item.visible = instance.visible;
            mDraws.push_back(item);
            if (item.visible && mPrimitives[size_t(primitive)].topology == scene::Topology::Triangles)
                mTriangles += mPrimitives[size_t(primitive)].count / 3;
        }
    }
    updateBounds();
    // Morph weights and skins change the shape at rest too.
    if (!mDeformed.empty()) setPose(-1, 0.0f);
    log::debug("GPU scene: {} primitives, {} draws, {} materials, {} triangles", mPrimitives.size(), mDraws.size(),
               mMaterials.size(), mTriangles);
}

void GpuScene::updateBounds()
{
    mBounds = {};
    mCasterBounds = {};
    for (const DrawItem& item : mDraws) {
        if (!item.visible) continue;
        const GpuPrimitive& p = mPrimitives[size_t(item.primitive)];
        const scene::Bounds world = p.bounds.transformed(item.world);
        mBounds.extend(world);
        if (item.castShadows && castsShadow(mMaterials[size_t(p.material)])) mCasterBounds.extend(world);
    }
}

bool GpuScene::setVariant(int variant)
{
    bool changed = false;
    for (GpuPrimitive& p : mPrimitives) {
        int material = p.baseMaterial;
        for (const scene::VariantMapping& mapping : p.variants)
            if (mapping.variant == variant) material = mapping.material;
        changed = changed || material != p.material;
        p.material = material;
    }
    if (changed) updateBounds(); // a variant may cast no shadow where the material did
    return changed;
}

size_t GpuScene::setPose(int animation, float seconds)
{
    if (!mRig) return 0;
    const scene::Scene& rig = *mRig;
    const scene::Pose pose = scene::poseAt(rig, animation, seconds);
    // KHR_animation_pointer: the materials and lights as the animation sets them. Every property
    // any animation sets starts from the file's value, so switching animations leaves none behind.
    std::vector<scene::Material> materials = rig.materials;
    mPosedLights = rig.lights;
    scene::applyProperties(pose, materials, mPosedLights);
    for (const AnimatedMaterial& a : mAnimatedMaterials) setAnimatedFields(a.material, materials[size_t(a.material)], a.fields);
    const std::vector<glm::mat4> world = scene::worldMatrices(rig, pose);
    mNodeVisible = scene::nodeVisibility(rig, pose);
    for (size_t d = 0; d < mDraws.size(); ++d) {
        DrawItem& item = mDraws[d];
        item.visible = mNodeVisible[size_t(mDrawNode[d])];
        item.world = world[size_t(mDrawNode[d])];
        item.normalMatrix = glm::transpose(glm::inverse(glm::mat3(item.world)));
        item.mirrored = glm::determinant(glm::mat3(item.world)) < 0.0f;
    }
    size_t uploaded = 0;
    std::vector<glm::mat4> joints;
    for (const DeformedDraw& deformed : mDeformed) {
        DrawItem& item = mDraws[deformed.draw];
        const int node = mDrawNode[deformed.draw];
        const scene::Primitive& rest = rig.meshes[size_t(deformed.mesh)].primitives[size_t(deformed.primitive)];
        joints.clear();
        if (deformed.skinned) {
            joints = scene::jointMatrices(rig.skins[size_t(rig.nodes[size_t(node)].skin)], world);
            // Skinned vertices come out in world space: the mesh node's transform is not applied
            // (glTF 2.0 spec 3.7.3, skins), and the winding is the file's.
            item.world = glm::mat4(1.0f);
            item.normalMatrix = glm::mat3(1.0f);
            item.mirrored = false;
        }
        const std::vector<float> weights = scene::morphWeights(rig, pose, node, rest.targets.size());
        GpuPrimitive& gpu = mPrimitives[size_t(item.primitive)];
        scene::deformPrimitive(rest, joints, weights, mScratch, gpu.bounds);
        gpu.geometry->vertices.update(0, mScratch.size() * sizeof(scene::Vertex), mScratch.data());
        uploaded += mScratch.size() * sizeof(scene::Vertex);
    }
    updateBounds();
    mNodeWorlds = world;
    return uploaded;
}

void GpuScene::updateCoverage(size_t record)
{
    MaterialBinding& binding = mMaterials[record];
    const shared::GpuMaterial& r = mRecords[record];
    const bool opaque =
        binding.declaredAlphaMode == scene::AlphaMode::Blend && binding.opaqueTexels && r.baseColorFactor.a >= 1.0f;
    const scene::AlphaMode mode = opaque ? scene::AlphaMode::Opaque : binding.declaredAlphaMode;
    // The variant key: no blending, or the record's (the declared blend mode: setBlendMode).
    constexpr uint32_t blendBits = SPECULA_MATERIAL_ALPHA_BLEND | SPECULA_MATERIAL_BLEND_TRANSPARENT;
    binding.features = (binding.features & ~uint64_t(blendBits)) | (opaque ? 0u : r.flags.x & blendBits);
    binding.alphaMode = mode;
}

bool castsShadow(const MaterialBinding& material)
{
    // The declared mode: a blended material drawn opaque (alpha 1) still casts none.
    return material.declaredAlphaMode != scene::AlphaMode::Blend &&
           (material.transmission < kTransmissionShadowLimit || transmissionCutout(material));
}

bool transmissionCutout(const MaterialBinding& material)
{
    return material.declaredAlphaMode != scene::AlphaMode::Blend && material.transmission >= kTransmissionShadowLimit &&
           material.textures[size_t(TextureSlot::Transmission)] != nullptr;
}

bool tintsShadow(const MaterialBinding& material)
{
    // A blended material of alpha 1 wherever it is drawn (drawn opaque: MaterialBinding::alphaMode)
    // lets nothing through and casts nothing, as before: files mark lamps so.
    const bool blended = material.declaredAlphaMode == scene::AlphaMode::Blend;
    return (blended && material.alphaMode == scene::AlphaMode::Blend) || material.transmission >= kTransmissionShadowLimit;
}

void GpuScene::setShading(int material, const scene::MaterialShading& shading)
{
    for (size_t record = 0; record < mMaterials.size(); ++record) {
        if (mRecordMaterial[record] != material || mMaterials[record].unlitCopy) continue;
        uint64_t& features = mMaterials[record].features;
        features = (features & ~uint64_t(kShadingFeatureMask)) | packShading(shading);
    }
}

void GpuScene::setBlendMode(int material, scene::BlendMode mode)
{
    for (size_t record = 0; record < mMaterials.size(); ++record) {
        if (mRecordMaterial[record] != material || mMaterials[record].declaredAlphaMode != scene::AlphaMode::Blend) continue;
        // The record holds the declared mode (tools read it); the variant key follows it
        // while the material is drawn blended (updateCoverage).
        uint32_t& flags = mRecords[record].flags.x;
        flags = mode == scene::BlendMode::Transparent ? flags | SPECULA_MATERIAL_BLEND_TRANSPARENT
                                                      : flags & ~uint32_t(SPECULA_MATERIAL_BLEND_TRANSPARENT);
        updateCoverage(record);
        mMaterialBuffer.update(materialOffset(int(record)) + offsetof(shared::GpuMaterial, flags), sizeof(uint32_t),
                               &mRecords[record].flags.x);
    }
}

namespace {

/// The floats of a material's record an animated field is packed into (packFactors): a first
/// float and a count, twice where a field reaches two places (the ior: F0 and refraction).
struct RecordRange {
    size_t offset = 0, size = 0;
};
std::array<RecordRange, 2> recordRanges(const scene::AnimatedProperty& p)
{
    using shared::GpuMaterial;
    using F = scene::AnimatedField;
    constexpr size_t f = sizeof(float);
    const auto at = [](size_t vec4, int first, int count) { return RecordRange{vec4 + size_t(first) * f, size_t(count) * f}; };
    switch (p.field) {
    case F::BaseColor: return {at(offsetof(GpuMaterial, baseColorFactor), 0, 4)};
    case F::Metallic: return {at(offsetof(GpuMaterial, params), 0, 1)};
    case F::Roughness: return {at(offsetof(GpuMaterial, params), 1, 1)};
    case F::Emissive:
    case F::EmissiveStrength: return {at(offsetof(GpuMaterial, emissive), 0, 3)};
    case F::SpecularFactor: return {at(offsetof(GpuMaterial, specular), 3, 1)};
    case F::SpecularColor: return {at(offsetof(GpuMaterial, specular), 0, 3)};
    case F::Ior: return {at(offsetof(GpuMaterial, specular), 0, 3), at(offsetof(GpuMaterial, transmission), 1, 1)};
    case F::ClearcoatFactor: return {at(offsetof(GpuMaterial, clearcoat), 0, 1)};
    case F::ClearcoatRoughness: return {at(offsetof(GpuMaterial, clearcoat), 1, 1)};
    case F::SheenColor: return {at(offsetof(GpuMaterial, sheen), 0, 3)};
    case F::SheenRoughness: return {at(offsetof(GpuMaterial, sheen), 3, 1)};
    case F::AnisotropyStrength: return {at(offsetof(GpuMaterial, anisotropy), 0, 1)};
    case F::AnisotropyRotation: return {at(offsetof(GpuMaterial, anisotropy), 1, 2)};
    case F::IridescenceFactor: return {at(offsetof(GpuMaterial, iridescence), 0, 1)};
    case F::IridescenceIor: return {at(offsetof(GpuMaterial, iridescence), 1, 1)};
    case F::IridescenceThicknessMinimum: return {at(offsetof(GpuMaterial, iridescence), 2, 1)};
    case F::IridescenceThicknessMaximum: return {at(offsetof(GpuMaterial, iridescence), 3, 1)};
    case F::DiffuseTransmission: return {at(offsetof(GpuMaterial, diffuseTransmission), 3, 1)};
    case F::DiffuseTransmissionColor: return {at(offsetof(GpuMaterial, diffuseTransmission), 0, 3)};
    case F::Dispersion: return {at(offsetof(GpuMaterial, attenuation), 3, 1)};
    case F::AlphaCutoff: return {at(offsetof(GpuMaterial, alpha), 0, 1)};
    case F::NormalScale: return {at(offsetof(GpuMaterial, params), 2, 1)};
    case F::OcclusionStrength: return {at(offsetof(GpuMaterial, params), 3, 1)};
    case F::ClearcoatNormalScale: return {at(offsetof(GpuMaterial, clearcoat), 2, 1)};
    case F::Transmission: return {at(offsetof(GpuMaterial, transmission), 0, 1)};
    case F::Thickness: return {at(offsetof(GpuMaterial, transmission), 2, 1)};
    case F::AttenuationDistance: return {at(offsetof(GpuMaterial, transmission), 3, 1)};
    case F::AttenuationColor: return {at(offsetof(GpuMaterial, attenuation), 0, 3)};
    case F::TextureOffset:
    case F::TextureRotation:
    case F::TextureScale: // both rows of the texture's transform
        return {at(offsetof(GpuMaterial, uvTransform) + size_t(std::max(p.texture, 0)) * 2 * 4 * f, 0, 8)};
    default: return {};
    }
}

} // namespace

void GpuScene::setAnimatedFields(int material, const scene::Material& m, const std::vector<scene::AnimatedProperty>& fields)
{
    for (size_t record = 0; record < mRecords.size(); ++record) {
        if (mRecordMaterial[record] != material) continue;
        shared::GpuMaterial next = mRecords[record];
        packFactors(m, next);
        for (size_t slot = 0; slot < scene::kMaterialTextures.size(); ++slot)
            if ((m.*scene::kMaterialTextures[slot]).valid()) packTransformRows(next, int(slot), (m.*scene::kMaterialTextures[slot]).transform);
        // Only the animated fields' floats, and only those that changed: the viewer's edits of
        // the others stay.
        const auto* before = reinterpret_cast<const std::byte*>(&mRecords[record]);
        const auto* after = reinterpret_cast<const std::byte*>(&next);
        for (const scene::AnimatedProperty& p : fields)
            for (const RecordRange& r : recordRanges(p))
                if (r.size > 0 && std::memcmp(before + r.offset, after + r.offset, r.size) != 0)
                    writeRecord(record, r.offset, r.size, after + r.offset);
    }
}

void GpuScene::writeRecord(size_t record, size_t offset, size_t size, const void* data)
{
    // The base colour's alpha decides whether a blended material is drawn opaque.
    constexpr size_t alpha = offsetof(shared::GpuMaterial, baseColorFactor) + 3 * sizeof(float);
    std::memcpy(reinterpret_cast<std::byte*>(&mRecords[record]) + offset, data, size);
    mMaterialBuffer.update(materialOffset(int(record)) + offset, size, data);
    if (offset <= alpha && alpha < offset + size) updateCoverage(record);
    // The layers' variants follow their factors (layerFeatures), and the shadow rule the
    // transmission (castsShadow).
    MaterialBinding& binding = mMaterials[record];
    shared::GpuMaterial& r = mRecords[record];
    binding.transmission = r.transmission.x;
    binding.features = (binding.features & ~kLayerFeatures) | layerFeatures(r);
    const uint32_t flags = (r.flags.x & ~uint32_t(kLayerFeatures)) | uint32_t(binding.features & kLayerFeatures);
    if (flags == r.flags.x) return;
    r.flags.x = flags;
    mMaterialBuffer.update(materialOffset(int(record)) + offsetof(shared::GpuMaterial, flags), sizeof(uint32_t), &r.flags.x);
}

void GpuScene::writeMaterial(int material, size_t offset, size_t size, const void* data)
{
    for (size_t record = 0; record < mRecords.size(); ++record)
        if (mRecordMaterial[record] == material) writeRecord(record, offset, size, data);
}

} // namespace specula::render
