// glTF import: compressed geometry. KHR_draco_mesh_compression (Debian's libdraco) decodes a
// primitive's attributes and indices; EXT_meshopt_compression (Debian's meshoptimizer) decodes
// bufferViews, which accessors then read like any other. KHR_mesh_quantization needs nothing
// here: the accessor reader takes every component type (GltfMeshes.cpp).
//
// Both decoders meet data from anywhere, so the limits of LoadOptions hold for what they
// produce as for plain buffers: a decoded bufferView is a buffer (--max-buffer-bytes), decoded
// vertices and indices are accessor elements (--max-accessor-count). Malformed data is a
// one-line error naming the primitive or bufferView.
#include <cstring>
#include <limits>

#include <draco/compression/decode.h>
#include <draco/compression/point_cloud/point_cloud_decoder.h>
#include <meshoptimizer.h>

#include "scene/GltfInternal.h"

namespace specula::scene::gltf_detail {

namespace {

/// Draco's variable-length integers (draco/core/varint_decoding.h): 7 bits a byte, low first.
bool readVarint(draco::DecoderBuffer& buffer, uint64_t& value)
{
    value = 0;
    for (int shift = 0; shift < 64; shift += 7) {
        uint8_t byte = 0;
        if (!buffer.Decode(&byte)) return false;
        value |= uint64_t(byte & 0x7F) << shift;
        if (!(byte & 0x80)) return true;
    }
    return false;
}

/// The face count a Draco mesh declares before its connectivity, read without decoding it: the
/// decoder allocates its tables from this count before it reads the faces, so a few forged bytes
/// could otherwise cost gigabytes. Read for version 2.2 bitstreams without metadata (what every
/// current encoder writes); nothing for others, which then have only Draco's own checks.
std::optional<uint64_t> declaredDracoFaces(const unsigned char* bytes, size_t size)
{
    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(bytes), size);
    draco::DracoHeader header;
    if (!draco::PointCloudDecoder::DecodeHeader(&buffer, &header).ok()) return std::nullopt;
    if (header.version_major != 2 || header.version_minor != 2 || (header.flags & METADATA_FLAG_MASK))
        return std::nullopt;
    if (header.encoder_type != draco::TRIANGULAR_MESH) return std::nullopt;
    uint64_t faces = 0, vertices = 0;
    if (header.encoder_method == draco::MESH_SEQUENTIAL_ENCODING) {
        // MeshSequentialDecoder::DecodeConnectivity: faces, then points.
        if (!readVarint(buffer, faces)) return std::nullopt;
    } else if (header.encoder_method == draco::MESH_EDGEBREAKER_ENCODING) {
        // MeshEdgebreakerDecoder::InitializeDecoder reads the traversal type, then
        // MeshEdgebreakerDecoderImpl::DecodeConnectivity the vertex and face counts.
        uint8_t traversal = 0;
        if (!buffer.Decode(&traversal) || !readVarint(buffer, vertices) || !readVarint(buffer, faces))
            return std::nullopt;
    } else {
        return std::nullopt;
    }
    return faces;
}

const char* dracoAttributeType(draco::DataType type)
{
    switch (type) {
    case draco::DT_INT8: return "int8";
    case draco::DT_UINT8: return "uint8";
    case draco::DT_INT16: return "int16";
    case draco::DT_UINT16: return "uint16";
    case draco::DT_INT32: return "int32";
    case draco::DT_UINT32: return "uint32";
    case draco::DT_FLOAT32: return "float32";
    default: return "an unsupported type";
    }
}

} // namespace

// ---------------------------------------------------------------------------------------------
// KHR_draco_mesh_compression

DracoPrimitive Importer::decodeDraco(const tinygltf::Primitive& source, int indicesAccessor,
                                     const tinygltf::Value& draco, const std::string& where) const
{
    const auto name = where + " KHR_draco_mesh_compression";
    const auto viewIndex = integer(draco, "bufferView");
    const tinygltf::Value* attributes = member(draco, "attributes");
    if (!viewIndex || !attributes || !attributes->IsObject()) fail("{} needs a bufferView and attributes", name);
    // checkBufferViews has made sure the view lies inside its buffer.
    const tinygltf::BufferView& view = at(mModel.bufferViews, *viewIndex, "bufferView", name);
    const unsigned char* bytes = mModel.buffers[size_t(view.buffer)].data.data() + view.byteOffset;
    const LoadLimits& limits = mImages.limits;

    // The glTF spec for the extension: the primitive's accessors keep their count, and the
    // decoded data must have it. Both are bounded before anything is decoded.
    const auto declaredCount = [&](int accessor) -> uint64_t {
        return accessor >= 0 && size_t(accessor) < mModel.accessors.size() ? mModel.accessors[size_t(accessor)].count : 0;
    };
    if (const auto faces = declaredDracoFaces(bytes, view.byteLength)) {
        if (*faces * 3 > limits.maxAccessorCount)
            fail("{} declares {} triangles ({} indices), over the limit of {} (--max-accessor-count)", name, *faces,
                 *faces * 3, limits.maxAccessorCount);
        if (indicesAccessor >= 0 && *faces * 3 != declaredCount(indicesAccessor))
            fail("{} holds {} triangles but its indices accessor {} has {} elements", name, *faces, indicesAccessor,
                 declaredCount(indicesAccessor));
    }

    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(bytes), view.byteLength);
    const auto type = draco::Decoder::GetEncodedGeometryType(&buffer);
    if (!type.ok()) fail("{}: the Draco data is malformed ({})", name, type.status().error_msg_string());
    if (type.value() != draco::TRIANGULAR_MESH) fail("{}: the Draco data is a point cloud, not a triangle mesh", name);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok()) fail("{}: the Draco data is malformed ({})", name, decoded.status().error_msg_string());
    const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
    const uint64_t points = mesh->num_points(), faces = mesh->num_faces();
    if (points > limits.maxAccessorCount || faces * 3 > limits.maxAccessorCount)
        fail("{} decodes to {} vertices and {} indices, over the limit of {} (--max-accessor-count)", name, points,
             faces * 3, limits.maxAccessorCount);

    DracoPrimitive out;
    if (indicesAccessor >= 0 && faces * 3 != declaredCount(indicesAccessor))
        fail("{} decodes to {} indices but its indices accessor {} has {}", name, faces * 3, indicesAccessor,
             declaredCount(indicesAccessor));
    out.indices.resize(size_t(faces) * 3);
    for (uint32_t f = 0; f < faces; ++f) {
        const auto& face = mesh->face(draco::FaceIndex(f));
        for (int k = 0; k < 3; ++k) {
            const uint32_t index = face[k].value();
            if (index >= points) fail("{}: triangle {} refers to vertex {} of {}", name, f, index, points);
            out.indices[size_t(f) * 3 + size_t(k)] = index;
        }
    }

    for (const std::string& key : attributes->Keys()) {
        const auto id = integer(*attributes, key.c_str());
        if (!id || *id < 0) fail("{}: attribute {} has no Draco id", name, key);
        const auto it = source.attributes.find(key);
        if (it == source.attributes.end()) fail("{} compresses {}, which the primitive does not have", name, key);
        const tinygltf::Accessor& accessor = at(mModel.accessors, it->second, "accessor", fmt::format("{} {}", where, key));
        if (accessor.count != points)
            fail("{}: accessor {} ({}) has {} elements but the Draco data decodes to {} vertices", name, it->second, key,
                 accessor.count, points);
        const draco::PointAttribute* attribute = mesh->GetAttributeByUniqueId(uint32_t(*id));
        if (!attribute) fail("{}: attribute {} names Draco attribute {}, which the data does not have", name, key, *id);
        AccessorData<float> data;
        data.count = size_t(points);
        data.components = componentCount(accessor.type);
        if (data.components == 0 || attribute->num_components() < 1)
            fail("{}: attribute {} has an unusable type", name, key);
        data.values.resize(data.count * size_t(data.components));
        // Integers come out normalized when Draco marks them so (glTF's normalized accessors);
        // components the data lacks are 0.
        for (uint32_t p = 0; p < points; ++p) {
            if (!attribute->ConvertValue<float>(attribute->mapped_index(draco::PointIndex(p)), int8_t(data.components),
                                                data.values.data() + size_t(p) * size_t(data.components)))
                fail("{}: attribute {} holds {} values that cannot be read as numbers", name, key,
                     dracoAttributeType(attribute->data_type()));
        }
        out.attributes.emplace(key, std::move(data));
    }
    return out;
}

// ---------------------------------------------------------------------------------------------
// EXT_meshopt_compression

void Importer::decodeMeshoptBufferViews()
{
    const LoadLimits& limits = mImages.limits;
    for (size_t i = 0; i < mModel.bufferViews.size(); ++i) {
        tinygltf::BufferView& view = mModel.bufferViews[i];
        const tinygltf::Value* meshopt = extension(view.extensions, "EXT_meshopt_compression");
        if (!meshopt) continue;
        const auto where = fmt::format("bufferView {} EXT_meshopt_compression", i);
        const auto bufferIndex = integer(*meshopt, "buffer");
        const auto offset = number(*meshopt, "byteOffset").value_or(0.0);
        const auto length = number(*meshopt, "byteLength");
        const auto stride = integer(*meshopt, "byteStride");
        const auto count = number(*meshopt, "count");
        const tinygltf::Value* modeValue = member(*meshopt, "mode");
        const tinygltf::Value* filterValue = member(*meshopt, "filter");
        const std::string mode = modeValue && modeValue->IsString() ? modeValue->Get<std::string>() : "";
        const std::string filter = filterValue && filterValue->IsString() ? filterValue->Get<std::string>() : "NONE";
        if (!bufferIndex || !length || !stride || !count || mode.empty())
            fail("{} needs buffer, byteLength, byteStride, count and mode", where);
        const std::vector<unsigned char>& data = at(mModel.buffers, *bufferIndex, "buffer", where).data;
        if (!(offset >= 0.0 && *length >= 0.0 && *count >= 0.0) || offset > double(data.size()) ||
            *length > double(data.size()) - offset)
            fail("{} (offset {}, length {}) reaches past the end of buffer {} ({} bytes)", where, offset, *length,
                 *bufferIndex, data.size());
        if (*count > double(limits.maxAccessorCount))
            fail("{} declares {} elements, over the limit of {} (--max-accessor-count)", where, *count,
                 limits.maxAccessorCount);
        const size_t elements = size_t(*count), size = size_t(std::max(*stride, 0));
        // The extension's limits (and meshoptimizer's): vertices are 4 to 256 bytes, a multiple of
        // 4; indices 2 or 4; triangles come in threes.
        if (mode == "ATTRIBUTES") {
            if (size == 0 || size > 256 || size % 4 != 0)
                fail("{}: byteStride {} is not a multiple of 4 from 4 to 256", where, *stride);
        } else if (mode == "TRIANGLES" || mode == "INDICES") {
            if (size != 2 && size != 4) fail("{}: byteStride {} of {} is neither 2 nor 4", where, *stride, mode);
            if (mode == "TRIANGLES" && elements % 3 != 0) fail("{}: count {} is not a multiple of 3", where, elements);
        } else {
            fail("{} has the unknown mode '{}'", where, mode);
        }
        const uint64_t bytes = uint64_t(elements) * size;
        if (bytes > limits.maxBufferBytes)
            fail("{} decodes to {} bytes, over the limit of {} (--max-buffer-bytes)", where, bytes, limits.maxBufferBytes);
        if (view.byteLength > bytes)
            fail("{}: the bufferView has {} bytes but decodes to {} ({} elements of {})", where, view.byteLength, bytes,
                 elements, size);

        tinygltf::Buffer decoded;
        decoded.name = where;
        decoded.data.resize(size_t(bytes));
        const unsigned char* source = data.data() + size_t(offset);
        const size_t sourceSize = size_t(*length);
        int result = 0;
        if (mode == "ATTRIBUTES") {
            result = meshopt_decodeVertexBuffer(decoded.data.data(), elements, size, source, sourceSize);
        } else if (mode == "TRIANGLES") {
            result = meshopt_decodeIndexBuffer(decoded.data.data(), elements, size, source, sourceSize);
        } else {
            result = meshopt_decodeIndexSequence(decoded.data.data(), elements, size, source, sourceSize);
        }
        if (result != 0) fail("{}: the {} data is malformed (meshoptimizer error {})", where, mode, result);
        // Filters undo what the encoder did to attributes before compressing them (the
        // extension's "Filters" section); each works on whole elements of given sizes.
        if (filter == "OCTAHEDRAL") {
            if (mode != "ATTRIBUTES" || (size != 4 && size != 8)) fail("{}: the OCTAHEDRAL filter needs 4 or 8 byte attributes", where);
            meshopt_decodeFilterOct(decoded.data.data(), elements, size);
        } else if (filter == "QUATERNION") {
            if (mode != "ATTRIBUTES" || size != 8) fail("{}: the QUATERNION filter needs 8 byte attributes", where);
            meshopt_decodeFilterQuat(decoded.data.data(), elements, size);
        } else if (filter == "EXPONENTIAL") {
            if (mode != "ATTRIBUTES") fail("{}: the EXPONENTIAL filter needs attributes", where);
            meshopt_decodeFilterExp(decoded.data.data(), elements, size);
        } else if (filter != "NONE") {
            fail("{} has the unknown filter '{}'", where, filter);
        }

        // The view now reads the decoded bytes (the file's fallback buffer may hold none).
        mModel.buffers.push_back(std::move(decoded));
        view.buffer = int(mModel.buffers.size() - 1);
        view.byteOffset = 0;
        if (view.byteLength == 0) view.byteLength = size_t(bytes);
    }
}

} // namespace specula::scene::gltf_detail
