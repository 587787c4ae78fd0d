#include "scene/gltf_accessor.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/common.hpp>
#include <tiny_gltf.h>

#include "util/error.h"

namespace rad {
namespace {

std::string describe(const AccessorRequest& request) {
    return "accessor " + std::to_string(request.accessor) + " (" + request.purpose + ")";
}

[[noreturn]] void fail(const AccessorRequest& request, const std::string& problem) {
    throw InputError(describe(request) + ": " + problem);
}

int componentSize(int componentType) {
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

int componentCount(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return 1;
        case TINYGLTF_TYPE_VEC2: return 2;
        case TINYGLTF_TYPE_VEC3: return 3;
        case TINYGLTF_TYPE_VEC4: return 4;
        case TINYGLTF_TYPE_MAT2: return 4;
        case TINYGLTF_TYPE_MAT3: return 9;
        case TINYGLTF_TYPE_MAT4: return 16;
        default: return 0;
    }
}

// A validated window onto a buffer view: `count` elements of `elementSize` bytes, `stride`
// bytes apart, starting at `data`.
struct ElementRange {
    const unsigned char* data = nullptr;
    std::size_t stride = 0;
};

// Checks that `count` elements of `elementSize` bytes at `byteOffset` in buffer view `viewIndex`
// (with the view's stride, or `packedStride` when it has none) lie inside the view and the
// view inside its buffer.
ElementRange elementRange(const tinygltf::Model& model, const AccessorRequest& request, int viewIndex,
                          std::size_t byteOffset, std::size_t count, std::size_t elementSize,
                          std::size_t alignment) {
    if (viewIndex < 0 || static_cast<std::size_t>(viewIndex) >= model.bufferViews.size())
        fail(request, "buffer view " + std::to_string(viewIndex) + " does not exist");
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(viewIndex)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
        fail(request, "buffer view " + std::to_string(viewIndex) + " names buffer " +
                          std::to_string(view.buffer) + ", which does not exist");
    const tinygltf::Buffer& buffer = model.buffers[static_cast<std::size_t>(view.buffer)];
    if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset)
        fail(request, "buffer view " + std::to_string(viewIndex) + " (bytes " + std::to_string(view.byteOffset) +
                          " to " + std::to_string(view.byteOffset + view.byteLength) + ") reaches past the end of buffer " +
                          std::to_string(view.buffer) + " (" + std::to_string(buffer.data.size()) + " bytes)");
    std::size_t stride = view.byteStride != 0 ? view.byteStride : elementSize;
    if (stride < elementSize)
        fail(request, "byte stride " + std::to_string(stride) + " is smaller than one element (" +
                          std::to_string(elementSize) + " bytes)");
    if (byteOffset % alignment != 0 || stride % alignment != 0)
        fail(request, "byte offset or stride is not a multiple of the component size");
    if (count > 0) {
        // Last byte read: byteOffset + stride * (count - 1) + elementSize, without overflow.
        const std::size_t limit = view.byteLength;
        if (byteOffset > limit || elementSize > limit - byteOffset ||
            (count - 1) > (limit - byteOffset - elementSize) / stride)
            fail(request, std::to_string(count) + " elements of " + std::to_string(elementSize) +
                              " bytes from offset " + std::to_string(byteOffset) + " read past the end of buffer view " +
                              std::to_string(viewIndex) + " (" + std::to_string(limit) + " bytes)");
    }
    return {buffer.data.data() + view.byteOffset + byteOffset, stride};
}

double readComponent(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float v;
            std::memcpy(&v, p, 4);
            return v;
        }
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            std::int8_t v;
            std::memcpy(&v, p, 1);
            return normalized ? std::max(v / 127.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
            std::uint8_t v;
            std::memcpy(&v, p, 1);
            return normalized ? v / 255.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            std::int16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? std::max(v / 32767.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? v / 65535.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            std::uint32_t v;
            std::memcpy(&v, p, 4);
            return normalized ? v / 4294967295.0 : v;
        }
        default: return 0.0;
    }
}

// Reads the accessor as `components` doubles per element, applying sparse substitution.
std::vector<double> readComponents(const tinygltf::Model& model, const AccessorRequest& request,
                                   int expectedType, int components) {
    if (request.accessor < 0 || static_cast<std::size_t>(request.accessor) >= model.accessors.size())
        fail(request, "does not exist (the file has " + std::to_string(model.accessors.size()) + " accessors)");
    const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(request.accessor)];
    if (accessor.type != expectedType)
        fail(request, "has type " + std::to_string(accessor.type) + " where " +
                          std::to_string(componentCount(expectedType)) + " components are needed");
    const int size = componentSize(accessor.componentType);
    if (size == 0) fail(request, "unknown component type " + std::to_string(accessor.componentType));
    const std::size_t elementSize = static_cast<std::size_t>(size) * static_cast<std::size_t>(components);
    // A count this large cannot be backed by any real buffer; refuse before allocating.
    if (accessor.count > (std::size_t{1} << 28))
        fail(request, "count " + std::to_string(accessor.count) + " is absurdly large");
    if (accessor.bufferView < 0 && !accessor.sparse.isSparse)
        fail(request, "has neither a buffer view nor sparse values");
    // Without a buffer view nothing backs the count but the file's word: a sparse accessor of
    // zeros is bounded by what its sparse values could plausibly address.
    if (accessor.bufferView < 0 && accessor.count > (std::size_t{1} << 24) &&
        accessor.count > 64 * static_cast<std::size_t>(std::max(accessor.sparse.count, 0)))
        fail(request, "count " + std::to_string(accessor.count) + " has no buffer view behind it and only " +
                          std::to_string(accessor.sparse.count) + " sparse values: absurdly large");

    ElementRange range;
    if (accessor.bufferView >= 0)
        range = elementRange(model, request, accessor.bufferView, accessor.byteOffset, accessor.count, elementSize,
                             static_cast<std::size_t>(size));
    std::vector<double> values(accessor.count * static_cast<std::size_t>(components), 0.0);
    if (range.data != nullptr) {
        for (std::size_t i = 0; i < accessor.count; ++i)
            for (int c = 0; c < components; ++c)
                values[i * components + c] = readComponent(range.data + i * range.stride + c * size,
                                                           accessor.componentType, accessor.normalized);
    }

    if (accessor.sparse.isSparse) {
        const auto count = static_cast<std::size_t>(std::max(accessor.sparse.count, 0));
        if (accessor.sparse.count < 1 || count > accessor.count)
            fail(request, "sparse count " + std::to_string(accessor.sparse.count) + " is outside 1.." +
                              std::to_string(accessor.count));
        const int indexType = accessor.sparse.indices.componentType;
        const int indexSize = componentSize(indexType);
        if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            fail(request, "sparse indices must be unsigned byte, short or int");
        const ElementRange indices =
            elementRange(model, request, accessor.sparse.indices.bufferView,
                         static_cast<std::size_t>(std::max(accessor.sparse.indices.byteOffset, 0)), count,
                         static_cast<std::size_t>(indexSize), static_cast<std::size_t>(indexSize));
        const ElementRange substitutes =
            elementRange(model, request, accessor.sparse.values.bufferView,
                         static_cast<std::size_t>(std::max(accessor.sparse.values.byteOffset, 0)), count, elementSize,
                         static_cast<std::size_t>(size));
        for (std::size_t k = 0; k < count; ++k) {
            const auto target = static_cast<std::size_t>(readComponent(indices.data + k * indices.stride, indexType, false));
            if (target >= accessor.count)
                fail(request, "sparse index " + std::to_string(target) + " is out of range (count " +
                                  std::to_string(accessor.count) + ")");
            for (int c = 0; c < components; ++c)
                values[target * components + c] = readComponent(substitutes.data + k * substitutes.stride + c * size,
                                                                 accessor.componentType, accessor.normalized);
        }
    }
    return values;
}

}  // namespace

std::vector<glm::dvec3> readPositions(const tinygltf::Model& model, const AccessorRequest& request) {
    if (request.accessor >= 0 && static_cast<std::size_t>(request.accessor) < model.accessors.size()) {
        const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(request.accessor)];
        if (accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            fail(request, "positions cannot have component type UNSIGNED_INT (5125)");
    }
    const std::vector<double> values = readComponents(model, request, TINYGLTF_TYPE_VEC3, 3);
    std::vector<glm::dvec3> positions(values.size() / 3);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        positions[i] = {values[3 * i], values[3 * i + 1], values[3 * i + 2]};
        if (!std::isfinite(values[3 * i]) || !std::isfinite(values[3 * i + 1]) || !std::isfinite(values[3 * i + 2]))
            fail(request, "position " + std::to_string(i) + " is not finite (NaN or infinity)");
    }
    return positions;
}

namespace {

// Directions (NORMAL, TANGENT): float, or (KHR_mesh_quantization) normalized signed byte or short.
void requireDirectionComponents(const tinygltf::Model& model, const AccessorRequest& request, const char* what) {
    if (request.accessor < 0 || static_cast<std::size_t>(request.accessor) >= model.accessors.size()) return;
    const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(request.accessor)];
    const int type = accessor.componentType;
    const bool quantized =
        (type == TINYGLTF_COMPONENT_TYPE_BYTE || type == TINYGLTF_COMPONENT_TYPE_SHORT) && accessor.normalized;
    if (type != TINYGLTF_COMPONENT_TYPE_FLOAT && !quantized)
        fail(request, std::string(what) + " must be float, or normalized signed byte or short (component type " +
                          std::to_string(type) + ")");
}

// Values in [0, 1] (COLOR_0, WEIGHTS_n): float, or normalized unsigned byte or short, as glTF
// allows. The accessor exists.
void requireUnitComponents(const tinygltf::Model& model, const AccessorRequest& request, const char* what) {
    const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(request.accessor)];
    const int component = accessor.componentType;
    const bool quantized =
        (component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) &&
        accessor.normalized;
    if (component != TINYGLTF_COMPONENT_TYPE_FLOAT && !quantized)
        fail(request, std::string(what) + " must be float, or normalized unsigned byte or short (component type " +
                          std::to_string(component) + ")");
}

}  // namespace

std::vector<glm::dvec3> readNormals(const tinygltf::Model& model, const AccessorRequest& request) {
    requireDirectionComponents(model, request, "normals");
    const std::vector<double> values = readComponents(model, request, TINYGLTF_TYPE_VEC3, 3);
    std::vector<glm::dvec3> normals(values.size() / 3);
    for (std::size_t i = 0; i < normals.size(); ++i) {
        normals[i] = {values[3 * i], values[3 * i + 1], values[3 * i + 2]};
        if (!std::isfinite(values[3 * i]) || !std::isfinite(values[3 * i + 1]) || !std::isfinite(values[3 * i + 2]))
            fail(request, "normal " + std::to_string(i) + " is not finite (NaN or infinity)");
    }
    return normals;
}

std::vector<glm::dvec4> readTangents(const tinygltf::Model& model, const AccessorRequest& request) {
    requireDirectionComponents(model, request, "tangents");
    const std::vector<double> values = readComponents(model, request, TINYGLTF_TYPE_VEC4, 4);
    std::vector<glm::dvec4> tangents(values.size() / 4);
    for (std::size_t i = 0; i < tangents.size(); ++i) {
        tangents[i] = {values[4 * i], values[4 * i + 1], values[4 * i + 2], values[4 * i + 3]};
        for (int c = 0; c < 4; ++c)
            if (!std::isfinite(values[4 * i + static_cast<std::size_t>(c)]))
                fail(request, "tangent " + std::to_string(i) + " is not finite (NaN or infinity)");
    }
    return tangents;
}

std::vector<glm::dvec2> readTexCoords(const tinygltf::Model& model, const AccessorRequest& request) {
    if (request.accessor >= 0 && static_cast<std::size_t>(request.accessor) < model.accessors.size()) {
        const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(request.accessor)];
        const int type = accessor.componentType;
        // glTF: float, normalized unsigned byte or short; KHR_mesh_quantization adds signed and
        // non-normalized byte and short.
        if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            fail(request, "texture coordinates cannot have component type UNSIGNED_INT (5125)");
    }
    const std::vector<double> values = readComponents(model, request, TINYGLTF_TYPE_VEC2, 2);
    std::vector<glm::dvec2> uv(values.size() / 2);
    for (std::size_t i = 0; i < uv.size(); ++i) {
        uv[i] = {values[2 * i], values[2 * i + 1]};
        if (!std::isfinite(uv[i].x) || !std::isfinite(uv[i].y) || std::fabs(uv[i].x) > 1e6 || std::fabs(uv[i].y) > 1e6)
            fail(request, "texture coordinate " + std::to_string(i) + " is not a finite number within 1e6");
    }
    return uv;
}

std::vector<glm::dvec3> readColors(const tinygltf::Model& model, const AccessorRequest& request) {
    int type = TINYGLTF_TYPE_VEC3;
    if (request.accessor >= 0 && static_cast<std::size_t>(request.accessor) < model.accessors.size()) {
        requireUnitComponents(model, request, "colours");
        if (model.accessors[static_cast<std::size_t>(request.accessor)].type == TINYGLTF_TYPE_VEC4)
            type = TINYGLTF_TYPE_VEC4;
    }
    const int components = type == TINYGLTF_TYPE_VEC4 ? 4 : 3;
    const std::vector<double> values = readComponents(model, request, type, components);
    std::vector<glm::dvec3> colors(values.size() / static_cast<std::size_t>(components));
    for (std::size_t i = 0; i < colors.size(); ++i) {
        const double* c = &values[i * static_cast<std::size_t>(components)];
        if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2]))
            fail(request, "colour " + std::to_string(i) + " is not finite (NaN or infinity)");
        colors[i] = glm::clamp(glm::dvec3(c[0], c[1], c[2]), 0.0, 1.0);
    }
    return colors;
}

std::vector<std::array<std::uint32_t, 4>> readJoints(const tinygltf::Model& model, const AccessorRequest& request) {
    if (request.accessor >= 0 && static_cast<std::size_t>(request.accessor) < model.accessors.size()) {
        const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(request.accessor)];
        const int type = accessor.componentType;
        if ((type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) ||
            accessor.normalized)
            fail(request, "joints must be unsigned byte or short, not normalized (component type " +
                              std::to_string(type) + ")");
    }
    const std::vector<double> values = readComponents(model, request, TINYGLTF_TYPE_VEC4, 4);
    std::vector<std::array<std::uint32_t, 4>> joints(values.size() / 4);
    for (std::size_t i = 0; i < joints.size(); ++i)
        for (std::size_t c = 0; c < 4; ++c) joints[i][c] = static_cast<std::uint32_t>(values[4 * i + c]);
    return joints;
}

std::vector<glm::dvec4> readWeights(const tinygltf::Model& model, const AccessorRequest& request) {
    if (request.accessor >= 0 && static_cast<std::size_t>(request.accessor) < model.accessors.size())
        requireUnitComponents(model, request, "weights");
    const std::vector<double> values = readComponents(model, request, TINYGLTF_TYPE_VEC4, 4);
    std::vector<glm::dvec4> weights(values.size() / 4);
    for (std::size_t i = 0; i < weights.size(); ++i)
        for (int c = 0; c < 4; ++c) {
            const double w = values[4 * i + static_cast<std::size_t>(c)];
            if (!std::isfinite(w) || w < -1e-6)
                fail(request, "weight " + std::to_string(i) + " is " + (std::isfinite(w) ? "negative" : "not finite"));
            weights[i][c] = std::max(w, 0.0);
        }
    return weights;
}

std::vector<glm::dmat4> readMatrices(const tinygltf::Model& model, const AccessorRequest& request) {
    if (request.accessor >= 0 && static_cast<std::size_t>(request.accessor) < model.accessors.size() &&
        model.accessors[static_cast<std::size_t>(request.accessor)].componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
        fail(request, "matrices must be float");
    const std::vector<double> values = readComponents(model, request, TINYGLTF_TYPE_MAT4, 16);
    std::vector<glm::dmat4> matrices(values.size() / 16);
    for (std::size_t i = 0; i < matrices.size(); ++i)
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) {
                const double v = values[16 * i + static_cast<std::size_t>(4 * c + r)];
                if (!std::isfinite(v)) fail(request, "matrix " + std::to_string(i) + " is not finite");
                matrices[i][c][r] = v;
            }
    return matrices;
}

std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, const AccessorRequest& request) {
    if (request.accessor >= 0 && static_cast<std::size_t>(request.accessor) < model.accessors.size()) {
        const int type = model.accessors[static_cast<std::size_t>(request.accessor)].componentType;
        if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            fail(request, "indices must be unsigned byte, short or int (component type " + std::to_string(type) + ")");
        if (model.accessors[static_cast<std::size_t>(request.accessor)].normalized)
            fail(request, "indices cannot be normalized");
    }
    const std::vector<double> values = readComponents(model, request, TINYGLTF_TYPE_SCALAR, 1);
    std::vector<std::uint32_t> indices(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) indices[i] = static_cast<std::uint32_t>(values[i]);
    return indices;
}

}  // namespace rad
