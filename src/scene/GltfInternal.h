#pragma once
// Private to the glTF importer, which is split by concern: GltfImporter.cpp (loading the file,
// the checks, cameras, lights, nodes and the scene), GltfMeshes.cpp (accessors and primitives)
// and GltfMaterials.cpp (images, samplers, textures and materials). Not for use elsewhere.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <tiny_gltf.h>

#include "core/Error.h"
#include "core/Log.h"
#include "scene/LoadOptions.h"
#include "scene/Scene.h"

namespace specula::scene::gltf_detail {

/// Why each image that failed to decode failed, by image index.
using ImageFailures = std::map<int, std::string>;

/// Decoding a model's images, shared by tinygltf's image callback (external and data-URI
/// images) and the importer (bufferView images): what failed, and what the images may cost.
struct ImageDecoding {
    ImageFailures failures;
    /// What a decoder got past in an image it did decode (libjpeg's corrupt-data warnings).
    ImageFailures warnings;
    LoadLimits limits;
    uint64_t textureBytes = 0; ///< decoded so far, RGBA8
    /// The first image over a limit, as the end of a message naming the file: the load fails with it.
    std::string refusal;
};

// tinygltf's image callback (GltfMaterials.cpp); `user` is an ImageDecoding.
bool loadImageData(tinygltf::Image* image, const int imageIndex, std::string* /*err*/, std::string* /*warn*/,
                   int /*reqWidth*/, int /*reqHeight*/, const unsigned char* bytes, int size, void* user);

// tinygltf::Value helpers (GltfImporter.cpp)
const tinygltf::Value* member(const tinygltf::Value& object, const char* key);
const tinygltf::Value* extension(const tinygltf::ExtensionMap& extensions, const char* name);
std::optional<double> number(const tinygltf::Value& object, const char* key);
std::optional<int> integer(const tinygltf::Value& object, const char* key);
std::optional<glm::vec2> vec2(const tinygltf::Value& object, const char* key);

/// Accessor contents as `components` values per element (GltfMeshes.cpp reads them from
/// buffers, GltfCompression.cpp from Draco data).
template <typename T>
struct AccessorData {
    size_t count = 0;
    int components = 0;
    std::vector<T> values;
    T at(size_t element, int component) const { return values[element * size_t(components) + size_t(component)]; }
};

/// A primitive's KHR_draco_mesh_compression data, decoded (GltfCompression.cpp): the attributes
/// the extension names, by glTF attribute name, and the triangle list.
struct DracoPrimitive {
    std::map<std::string, AccessorData<float>> attributes;
    std::vector<uint32_t> indices;
};

/// Number of components of an accessor type (1 to 4; 0 for matrices), GltfMeshes.cpp.
int componentCount(int type);

// ---------------------------------------------------------------------------------------------
// The conversion from tinygltf's model to our scene

class Importer {
public:
    /// `dracoIndices`: the indices accessor of each Draco primitive, by mesh and primitive
    /// index, taken out of the JSON before tinygltf parsed it (see prepareForTinygltf).
    Importer(std::string file, std::string name, tinygltf::Model& model, ImageDecoding& images,
             std::map<std::pair<size_t, size_t>, int> dracoIndices = {})
        : mFile(std::move(file)), mModel(model), mImages(images), mDracoIndices(std::move(dracoIndices))
    {
        mScene.name = std::move(name);
    }

    Scene run()
    {
        checkVersion();
        checkRequiredExtensions();
        warnIgnoredExtensions();
        decodeMeshoptBufferViews();
        checkBufferViews();
        convertImages();
        convertSamplers();
        convertMaterials();
        convertVariants();
        convertMeshes();
        convertCameras();
        convertLights();
        convertNodes();
        convertSkins();
        convertAnimations();
        chooseRoots();
        return std::move(mScene);
    }

private:
    template <typename... Args>
    [[noreturn]] void fail(fmt::format_string<Args...> format, Args&&... args) const
    {
        throw Error("{}: {}", mFile, fmt::format(format, std::forward<Args>(args)...));
    }

    template <typename... Args>
    void warn(fmt::format_string<Args...> format, Args&&... args)
    {
        std::string message = fmt::format("{}: {}", mFile, fmt::format(format, std::forward<Args>(args)...));
        log::warn("{}", message);
        mScene.warnings.push_back(std::move(message));
    }

    /// `items[index]`, or an error naming `where` the index came from.
    template <typename T>
    const T& at(const std::vector<T>& items, int index, std::string_view kind, std::string_view where) const
    {
        if (index < 0 || size_t(index) >= items.size())
            fail("{} refers to {} {}, which is out of range (the file has {})", where, kind, index, items.size());
        return items[size_t(index)];
    }

    template <int N>
    glm::vec<N, float> factor(const std::vector<double>& values, glm::vec<N, float> fallback, std::string_view where,
                              std::string_view what) const
    {
        if (values.empty()) return fallback;
        if (values.size() != size_t(N)) fail("{}: {} has {} numbers instead of {}", where, what, values.size(), N);
        glm::vec<N, float> out;
        for (int i = 0; i < N; ++i) out[i] = float(values[size_t(i)]);
        return out;
    }

    // -- checks (GltfImporter.cpp) -------------------------------------------------------------

    void checkVersion() const;
    void checkRequiredExtensions() const;
    /// One warning per optional extension the file uses that we ignore (not one per use).
    void warnIgnoredExtensions();
    void checkBufferViews() const;

    // -- compressed data (GltfCompression.cpp) -------------------------------------------------

    /// EXT_meshopt_compression: every compressed bufferView decoded into a buffer of its own, the
    /// view pointed at it, so that accessors read it as any other.
    void decodeMeshoptBufferViews();
    /// KHR_draco_mesh_compression: the primitive's compressed attributes and indices.
    DracoPrimitive decodeDraco(const tinygltf::Primitive& source, int indicesAccessor, const tinygltf::Value& draco,
                               const std::string& where) const;

    // -- accessors (GltfMeshes.cpp) ------------------------------------------------------------

    const unsigned char* elements(int viewIndex, size_t byteOffset, size_t count, size_t elementSize, size_t stride,
                                  std::string_view where) const;
    template <typename T>
    AccessorData<T> read(int index, std::string_view where) const;

    // -- images, samplers, materials (GltfMaterials.cpp) ---------------------------------------

    /// The image a texture samples: EXT_texture_webp's if it has one, else `source` (-1: none).
    static int textureSource(const tinygltf::Texture& texture);
    void convertImages();
    static Wrap wrap(int mode);
    void convertSamplers();
    /// The textureInfo `name` of a material extension's JSON object (none when absent).
    TextureRef extensionTexture(const tinygltf::Value& extension, const char* name, std::string_view where);
    TextureRef textureRef(int textureIndex, int texCoord, const tinygltf::ExtensionMap& extensions,
                          std::string_view where);

    void convertMaterials();
    /// KHR_materials_pbrSpecularGlossiness (archived) as a metal-rough material with
    /// KHR_materials_specular's colour and ior 0.
    void convertSpecularGlossiness(const tinygltf::Value& sg, Material& material, const std::string& where);
    /// KHR_materials_variants: the variants' names (the root extension); each primitive's
    /// mappings are read with it (readVariantMappings).
    void convertVariants();
    void readVariantMappings(const tinygltf::Primitive& source, Primitive& primitive, const std::string& where) const;

    // -- meshes (GltfMeshes.cpp) ---------------------------------------------------------------

    std::optional<Primitive> convertPrimitive(const tinygltf::Primitive& source, int indicesAccessor, const std::string& where);
    void convertMeshes();

    // -- skins, morph targets, animations (GltfAnimation.cpp) ----------------------------------

    /// JOINTS_n / WEIGHTS_n and the morph targets of a primitive whose POSITION has `vertexCount` elements.
    /// `draco`: the primitive's decoded KHR_draco_mesh_compression attributes (JOINTS_n and
    /// WEIGHTS_n may be among them), or null.
    void readDeformation(const tinygltf::Primitive& source, size_t vertexCount, Primitive& primitive,
                         const std::string& where, DracoPrimitive* draco);
    /// Skins, after the nodes: their joints, inverse bind matrices, and the joint indices of
    /// the meshes the nodes they skin draw.
    void convertSkins();
    void convertAnimations();

    // -- cameras, lights, nodes (GltfImporter.cpp) ---------------------------------------------

    void convertCameras();
    void convertLights();
    void convertNodes();
    /// EXT_mesh_gpu_instancing on `node`: one node per instance (its TRS, the node's mesh).
    std::vector<Node> meshInstances(const tinygltf::Value& instancing, const Node& node, std::string_view where);
    void chooseRoots();

    std::string mFile; ///< the path as the user gave it, for messages
    tinygltf::Model& mModel;
    ImageDecoding& mImages;
    /// Roughness images made from a specular-glossiness texture's alpha, by (image, glossinessFactor).
    std::map<std::pair<int, float>, int> mRoughnessImages;
    uint64_t mInstanceCount = 0; ///< EXT_mesh_gpu_instancing's instances so far (LoadLimits::maxInstances)
    Scene mScene;
    std::vector<int> mParent; ///< per node, -1 for roots
    std::map<std::pair<size_t, size_t>, int> mDracoIndices;
};

} // namespace specula::scene::gltf_detail
