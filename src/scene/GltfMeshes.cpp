// glTF import: accessors and primitives (vertex attributes, indices, flat normals, tangents).
#include <algorithm>
#include <cassert>
#include <cstring>
#include <limits>

#include "scene/GltfInternal.h"
#include "scene/Tangents.h"

namespace specula::scene::gltf_detail {

// ---------------------------------------------------------------------------------------------
// Accessors

int componentCount(int type)
{
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    default: return 0; // matrices: no vertex attribute we read uses them
    }
}

namespace {

// An accessor without a bufferView (all zeros, maybe sparse) has no data bounding its count;
// this keeps a hostile count from turning into a multi-gigabyte allocation. Accessors with a
// bufferView are bounded by the file's size.
constexpr size_t kMaxUnbackedAccessorCount = size_t(1) << 24;

/// Byte size of a glTF accessor component type, or 0 for types glTF does not allow.
size_t componentSize(int componentType)
{
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
    }
}

template <typename T>
T load(const unsigned char* p)
{
    T value;
    std::memcpy(&value, p, sizeof(T)); // accessors need not be aligned for T in memory
    return value;
}

/// One component as a double; normalized integers map to [0, 1] or [-1, 1] with the glTF 2.0
/// spec's decoding equations (signed ones clamped so that -128 and -32768 give -1).
double readComponent(const unsigned char* p, int componentType, bool normalized)
{
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const double v = load<int8_t>(p);
        return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
        const double v = load<uint8_t>(p);
        return normalized ? v / 255.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        const double v = load<int16_t>(p);
        return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        const double v = load<uint16_t>(p);
        return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        const double v = load<uint32_t>(p);
        return normalized ? v / 4294967295.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return load<float>(p);
    default: return 0.0;
    }
}

/// A primitive's index list as a triangle list, whatever its (triangle) mode.
std::vector<uint32_t> triangulate(const std::vector<uint32_t>& in, int mode)
{
    std::vector<uint32_t> out;
    const size_t n = in.size();
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        out.assign(in.begin(), in.begin() + std::ptrdiff_t(n - n % 3));
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        // The glTF 2.0 spec (Meshes, topology types): triangle i is (i, i + 1 + i % 2,
        // i + 2 - i % 2), which keeps every triangle counter-clockwise.
        for (size_t i = 0; i + 2 < n; ++i) {
            const uint32_t a = in[i], b = in[i + 1 + i % 2], c = in[i + 2 - i % 2];
            // Repeated indices are how strips are stitched together; they draw nothing.
            if (a != b && b != c && a != c) out.insert(out.end(), {a, b, c});
        }
    } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        // The glTF 2.0 spec (Meshes, topology types): triangle i is (i + 1, i + 2, 0).
        for (size_t i = 0; i + 2 < n; ++i) out.insert(out.end(), {in[i + 1], in[i + 2], in[0]});
    }
    return out;
}

/// A primitive's index list as a line list, whatever its (line) mode.
std::vector<uint32_t> lineList(const std::vector<uint32_t>& in, int mode)
{
    std::vector<uint32_t> out;
    const size_t n = in.size();
    if (mode == TINYGLTF_MODE_LINE) {
        out.assign(in.begin(), in.begin() + std::ptrdiff_t(n - n % 2));
    } else {
        // The glTF 2.0 spec (Meshes, topology types): strip segment i is (i, i + 1); a loop
        // adds (n - 1, 0).
        for (size_t i = 0; i + 1 < n; ++i) out.insert(out.end(), {in[i], in[i + 1]});
        if (mode == TINYGLTF_MODE_LINE_LOOP && n > 2) out.insert(out.end(), {in[n - 1], in[0]});
    }
    return out;
}

const char* modeName(int mode)
{
    switch (mode) {
    case TINYGLTF_MODE_POINTS: return "points";
    case TINYGLTF_MODE_LINE: return "lines";
    case TINYGLTF_MODE_LINE_LOOP: return "line loops";
    case TINYGLTF_MODE_LINE_STRIP: return "line strips";
    case TINYGLTF_MODE_TRIANGLE_STRIP: return "triangle strips";
    case TINYGLTF_MODE_TRIANGLE_FAN: return "triangle fans";
    case TINYGLTF_MODE_TRIANGLES: return "triangles";
    default: return "an unknown mode";
    }
}

} // namespace

// ---------------------------------------------------------------------------------------------
// The conversion from tinygltf's model to our scene: accessors and meshes

/// Start of `count` elements of `elementSize` bytes, `stride` apart, at `byteOffset` in a
/// bufferView; an error unless they all lie inside it.
const unsigned char* Importer::elements(int viewIndex, size_t byteOffset, size_t count, size_t elementSize,
                                        size_t stride, std::string_view where) const
{
    assert(stride >= elementSize && elementSize > 0);
    const tinygltf::BufferView& view = at(mModel.bufferViews, viewIndex, "bufferView", where);
    if (count > 0) {
        const size_t length = view.byteLength;
        // Written to avoid overflow: offset + (count - 1) * stride + elementSize <= length.
        if (byteOffset > length || elementSize > length - byteOffset ||
            count - 1 > (length - byteOffset - elementSize) / stride)
            fail(
                "{} reads past the end of bufferView {} ({} elements of {} bytes every {} from offset {}; the view "
                "has {} bytes)",
                where, viewIndex, count, elementSize, stride, byteOffset, length);
    }
    return mModel.buffers[size_t(view.buffer)].data.data() + view.byteOffset + byteOffset;
}

/// Reads accessor `index`, converting each component with readComponent, sparse values applied.
template <typename T>
AccessorData<T> Importer::read(int index, std::string_view where) const
{
    const tinygltf::Accessor& accessor = at(mModel.accessors, index, "accessor", where);
    const auto name = fmt::format("accessor {}", index);
    AccessorData<T> out;
    out.components = componentCount(accessor.type);
    const size_t size = componentSize(accessor.componentType);
    if (out.components == 0) fail("{} is a matrix; {} needs a scalar or a vector", name, where);
    if (size == 0) fail("{} has the invalid componentType {}", name, accessor.componentType);
    out.count = accessor.count;
    const size_t elementSize = size * size_t(out.components);

    // Without a bufferView the accessor is all zeros (glTF 2.0 spec, Sparse Accessors).
    const unsigned char* data = nullptr;
    size_t stride = elementSize;
    if (accessor.bufferView >= 0) {
        const tinygltf::BufferView& view = at(mModel.bufferViews, accessor.bufferView, "bufferView", name);
        if (view.byteStride != 0) stride = view.byteStride;
        if (stride < elementSize)
            fail("{} has elements of {} bytes but bufferView {} has a byteStride of {}", name, elementSize,
                 accessor.bufferView, stride);
        data = elements(accessor.bufferView, accessor.byteOffset, out.count, elementSize, stride, name);
    } else if (out.count > kMaxUnbackedAccessorCount) {
        fail("{} has no bufferView and an implausible count ({})", name, out.count);
    }

    out.values.assign(out.count * size_t(out.components), T(0));
    auto readElement = [&](const unsigned char* p, size_t element) {
        for (int c = 0; c < out.components; ++c)
            out.values[element * size_t(out.components) + size_t(c)] =
                T(readComponent(p + size_t(c) * size, accessor.componentType, accessor.normalized));
    };
    if (data)
        for (size_t i = 0; i < out.count; ++i) readElement(data + i * stride, i);

    if (accessor.sparse.isSparse) {
        const auto& sparse = accessor.sparse;
        const auto sparseName = fmt::format("the sparse part of {}", name);
        const int indexType = sparse.indices.componentType;
        if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
            indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            fail("{} has indices of the invalid componentType {}", sparseName, indexType);
        if (sparse.count < 0 || size_t(sparse.count) > out.count || sparse.indices.byteOffset < 0 ||
            sparse.values.byteOffset < 0)
            fail("{} has an invalid count or byteOffset", sparseName);
        const size_t count = size_t(sparse.count);
        const size_t indexSize = componentSize(indexType);
        const unsigned char* indices = elements(sparse.indices.bufferView, size_t(sparse.indices.byteOffset), count,
                                                indexSize, indexSize, sparseName);
        const unsigned char* values = elements(sparse.values.bufferView, size_t(sparse.values.byteOffset), count,
                                               elementSize, elementSize, sparseName);
        for (size_t k = 0; k < count; ++k) {
            const auto target = size_t(readComponent(indices + k * indexSize, indexType, false));
            if (target >= out.count)
                fail("{} replaces element {}, but the accessor has {}", sparseName, target, out.count);
            readElement(values + k * elementSize, target);
        }
    }
    return out;
}

// -- meshes ----------------------------------------------------------------------------------

std::optional<Primitive> Importer::convertPrimitive(const tinygltf::Primitive& source, const int indicesAccessor,
                                                    const std::string& where)
{
    // tinygltf reads an absent mode as TRIANGLES.
    const int mode = source.mode;
    Topology topology = Topology::Triangles;
    if (mode == TINYGLTF_MODE_LINE || mode == TINYGLTF_MODE_LINE_STRIP || mode == TINYGLTF_MODE_LINE_LOOP)
        topology = Topology::Lines;
    else if (mode == TINYGLTF_MODE_POINTS)
        topology = Topology::Points;
    else if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        warn("{} draws {} (mode {}), which are not supported; it is skipped", where, modeName(mode), mode);
        return std::nullopt;
    }
    if (topology != Topology::Triangles && gltf_detail::extension(source.extensions, "KHR_draco_mesh_compression")) {
        warn("{} draws {} with KHR_draco_mesh_compression, which Specula decodes for triangles only; it is skipped", where,
             modeName(mode));
        return std::nullopt;
    }
    auto attribute = [&](const char* name) {
        const auto it = source.attributes.find(name);
        return it == source.attributes.end() ? -1 : it->second;
    };
    const int positionAccessor = attribute("POSITION");
    if (positionAccessor < 0) {
        // The glTF 2.0 spec (Meshes): without positions a primitive is not rendered.
        warn("{} has no POSITION; it is skipped", where);
        return std::nullopt;
    }

    // KHR_draco_mesh_compression: the attributes it names and the indices come from its data,
    // any others from their accessors as usual.
    std::optional<DracoPrimitive> draco;
    if (const tinygltf::Value* extension = gltf_detail::extension(source.extensions, "KHR_draco_mesh_compression"))
        draco = decodeDraco(source, indicesAccessor, *extension, where);
    auto readAttribute = [&](const char* name, int index, const std::string& attributeWhere) {
        if (draco) {
            const auto it = draco->attributes.find(name);
            if (it != draco->attributes.end()) return std::move(it->second);
        }
        return read<float>(index, attributeWhere);
    };

    const auto positions = readAttribute("POSITION", positionAccessor, where + " POSITION");
    if (positions.components != 3) fail("{} POSITION must be VEC3", where);
    const size_t vertexCount = positions.count;
    if (vertexCount > std::numeric_limits<uint32_t>::max()) fail("{} has too many vertices", where);

    // Reads an optional attribute; its count must match POSITION's.
    auto optional = [&](const char* name, int minComponents, int maxComponents) {
        std::optional<AccessorData<float>> data;
        const int index = attribute(name);
        if (index < 0) return data;
        const auto attributeWhere = fmt::format("{} {}", where, name);
        data = readAttribute(name, index, attributeWhere);
        if (data->components < minComponents || data->components > maxComponents)
            fail("{} has {} components per element, which glTF does not allow", attributeWhere, data->components);
        if (data->count != vertexCount)
            fail("{} has {} elements but POSITION has {}", attributeWhere, data->count, vertexCount);
        return data;
    };
    const auto normals = optional("NORMAL", 3, 3);
    const auto tangents = optional("TANGENT", 4, 4);
    const auto uv0 = optional("TEXCOORD_0", 2, 2);
    const auto uv1 = optional("TEXCOORD_1", 2, 2);
    const auto colors = optional("COLOR_0", 3, 4);

    Primitive primitive;
    primitive.topology = topology;
    // Strips, fans and loops become lists; lists stay as they are.
    const auto assemble = [&](const std::vector<uint32_t>& in) {
        return topology == Topology::Triangles ? triangulate(in, mode) : topology == Topology::Lines ? lineList(in, mode) : in;
    };
    primitive.vertices.resize(vertexCount);
    for (size_t i = 0; i < vertexCount; ++i) {
        Vertex& v = primitive.vertices[i];
        v.position = {positions.at(i, 0), positions.at(i, 1), positions.at(i, 2)};
        if (normals) v.normal = {normals->at(i, 0), normals->at(i, 1), normals->at(i, 2)};
        if (tangents) {
            // glTF requires w = ±1; take only its sign, so a stray 0 cannot flatten the bitangent.
            v.tangent = {tangents->at(i, 0), tangents->at(i, 1), tangents->at(i, 2),
                         tangents->at(i, 3) < 0.0f ? -1.0f : 1.0f};
        }
        if (uv0) v.uv0 = {uv0->at(i, 0), uv0->at(i, 1)};
        if (uv1) v.uv1 = {uv1->at(i, 0), uv1->at(i, 1)};
        if (colors) {
            v.color = {colors->at(i, 0), colors->at(i, 1), colors->at(i, 2),
                       colors->components == 4 ? colors->at(i, 3) : 1.0f};
        }
        primitive.bounds.extend(v.position);
    }
    primitive.hasTangents = tangents.has_value();
    primitive.hasColors = colors.has_value();
    readDeformation(source, vertexCount, primitive, where, draco ? &*draco : nullptr);

    if (draco) {
        // decodeDraco has checked them against the vertex count.
        primitive.indices = mode == TINYGLTF_MODE_TRIANGLES ? std::move(draco->indices) : triangulate(draco->indices, mode);
    } else if (indicesAccessor >= 0) {
        const auto indexWhere = where + " indices";
        const auto& accessor = at(mModel.accessors, indicesAccessor, "accessor", indexWhere);
        if (accessor.type != TINYGLTF_TYPE_SCALAR ||
            (accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
             accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
             accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
            fail("{}: accessor {} must hold unsigned byte, short or int scalars", indexWhere, indicesAccessor);
        auto indices = read<uint32_t>(indicesAccessor, indexWhere);
        for (uint32_t index : indices.values)
            if (index >= vertexCount)
                fail("{} refer to vertex {}, but there are {} vertices", indexWhere, index, vertexCount);
        primitive.indices = assemble(indices.values);
    } else if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_LINE && mode != TINYGLTF_MODE_POINTS) {
        std::vector<uint32_t> sequence(vertexCount);
        for (size_t i = 0; i < vertexCount; ++i) sequence[i] = uint32_t(i);
        primitive.indices = assemble(sequence);
    }

    if (source.material >= 0) {
        at(mModel.materials, source.material, "material", where);
        primitive.material = source.material;
    }
    readVariantMappings(source, primitive, where);

    if (!normals && topology != Topology::Triangles) {
        // A line or a point has no face to take a normal from: drawn unlit (Primitive::unlit).
        primitive.unlit = true;
        primitive.hasTangents = false;
        return primitive;
    }
    if (topology != Topology::Triangles) return primitive; // lit by its normals; no normal map without faces
    if (!normals) {
        // The glTF 2.0 spec (Meshes): without normals, flat normals, and tangents are ignored.
        generateFlatNormals(primitive);
        primitive.hasTangents = false;
    }
    // A normal map needs the tangent frame: the material's, or a variant's (the clearcoat
    // layer's normal map too), and so does anisotropy (its direction is in it):
    // KHR_materials_anisotropy asks for a normalTexture then, but without one the anisotropy
    // texture's, or the first, uv set gives the tangents.
    std::vector<int> materials = {primitive.material};
    for (const VariantMapping& mapping : primitive.variants) materials.push_back(mapping.material);
    for (int index : materials) {
        if (primitive.hasTangents || index < 0) continue;
        const Material& material = mScene.materials[size_t(index)];
        const TextureRef& normalTexture = material.normalTexture.valid() ? material.normalTexture : material.clearcoatNormalTexture;
        if (normalTexture.valid()) generateTangents(primitive, normalTexture.texCoord);
        else if (material.anisotropyStrength > 0.0f)
            generateTangents(primitive, material.anisotropyTexture.valid() ? material.anisotropyTexture.texCoord : 0);
    }
    return primitive;
}

void Importer::convertMeshes()
{
    for (size_t m = 0; m < mModel.meshes.size(); ++m) {
        const tinygltf::Mesh& source = mModel.meshes[m];
        Mesh mesh;
        mesh.name = source.name;
        for (double w : source.weights) mesh.weights.push_back(float(w));
        for (size_t p = 0; p < source.primitives.size(); ++p) {
            const auto draco = mDracoIndices.find({m, p});
            const int indices = draco != mDracoIndices.end() ? draco->second : source.primitives[p].indices;
            auto primitive = convertPrimitive(source.primitives[p], indices, fmt::format("mesh {} primitive {}", m, p));
            if (primitive) mesh.primitives.push_back(std::move(*primitive));
        }
        // glTF 2.0 spec (Morph targets): every primitive of a mesh has the same number of
        // targets, and the mesh's default weights (if any) one per target.
        const size_t targets = source.primitives.empty() ? 0 : source.primitives[0].targets.size();
        for (size_t p = 1; p < source.primitives.size(); ++p)
            if (source.primitives[p].targets.size() != targets)
                fail("mesh {}: primitive {} has {} morph targets but primitive 0 has {} (they must match)", m, p,
                     source.primitives[p].targets.size(), targets);
        if (!mesh.weights.empty() && mesh.weights.size() != targets)
            fail("mesh {} has {} weights but {} morph targets", m, mesh.weights.size(), targets);
        mScene.meshes.push_back(std::move(mesh));
    }
}

// GltfAnimation.cpp reads skins' and animations' accessors through the same reader.
template AccessorData<float> Importer::read<float>(int, std::string_view) const;

} // namespace specula::scene::gltf_detail
