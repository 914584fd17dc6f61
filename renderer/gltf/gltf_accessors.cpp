#include "gltf/gltf_accessors.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace pt::gltf {
namespace {

size_t componentSize(int type) {
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
    }
}

const char* componentTypeName(int type) {
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    default: return "an unknown component type";
    }
}

int componentsOf(int type) {
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

// A value of type T at p, which need not be aligned.
template <typename T>
T load(const uint8_t* p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// One component at p, converted to float.
float component(const uint8_t* p, int type, bool normalized) {
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return load<float>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.0f : float(p[0]);
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        int8_t v = load<int8_t>(p);
        return normalized ? std::max(v / 127.0f, -1.0f) : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t v = load<uint16_t>(p);
        return normalized ? v / 65535.0f : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        int16_t v = load<int16_t>(p);
        return normalized ? std::max(v / 32767.0f, -1.0f) : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return float(load<uint32_t>(p));
    default: return 0.0f;
    }
}

uint32_t unsignedComponent(const uint8_t* p, int type) {
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return p[0];
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load<uint16_t>(p);
    default: return load<uint32_t>(p);
    }
}

// Where `count` elements of `elementSize` bytes lie in a buffer view, checked against the view
// and the view against its buffer. Returns the first element and sets the stride.
const uint8_t* locate(const tinygltf::Model& model, int viewIndex, size_t byteOffset, size_t count, size_t elementSize,
                      bool strided, size_t& stride, const std::string& name) {
    if (viewIndex < 0 || size_t(viewIndex) >= model.bufferViews.size())
        throw LoadError(name + ": bufferView " + std::to_string(viewIndex) + " does not exist (the file has " +
                        std::to_string(model.bufferViews.size()) + ")");
    const tinygltf::BufferView& view = model.bufferViews[size_t(viewIndex)];
    std::string viewName = name + ", bufferView " + std::to_string(viewIndex);
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
        throw LoadError(viewName + ": buffer " + std::to_string(view.buffer) + " does not exist");
    const std::vector<unsigned char>& data = model.buffers[size_t(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        throw LoadError(viewName + ": bytes " + std::to_string(view.byteOffset) + " to " +
                        std::to_string(view.byteOffset + view.byteLength) + " pass the end of buffer " +
                        std::to_string(view.buffer) + " (" + std::to_string(data.size()) + " bytes)");
    stride = strided && view.byteStride != 0 ? view.byteStride : elementSize;
    if (stride < elementSize)
        throw LoadError(viewName + ": byteStride " + std::to_string(stride) + " is below the element size " +
                        std::to_string(elementSize));
    if (count > 0) {
        // byteOffset + stride * (count - 1) + elementSize <= byteLength, without overflow.
        size_t room = view.byteLength;
        bool fits = byteOffset <= room && elementSize <= room - byteOffset &&
                    (count - 1) <= (room - byteOffset - elementSize) / stride;
        if (!fits)
            throw LoadError(name + ": " + std::to_string(count) + " elements from byte " + std::to_string(byteOffset) +
                            " pass the end of bufferView " + std::to_string(viewIndex) + " (" +
                            std::to_string(view.byteLength) + " bytes)");
    }
    return data.data() + view.byteOffset + byteOffset;
}

const tinygltf::Accessor& accessorAt(const tinygltf::Model& model, int index, const std::string& what) {
    if (index < 0 || size_t(index) >= model.accessors.size())
        throw LoadError(what + ": accessor " + std::to_string(index) + " does not exist (the file has " +
                        std::to_string(model.accessors.size()) + ")");
    return model.accessors[size_t(index)];
}

} // namespace

std::vector<unsigned char> bufferViewBytes(const tinygltf::Model& model, int view, const std::string& what) {
    size_t length = view >= 0 && size_t(view) < model.bufferViews.size() ? model.bufferViews[size_t(view)].byteLength : 0;
    size_t stride;
    const uint8_t* p = locate(model, view, 0, 1, length, false, stride, what);
    return std::vector<unsigned char>(p, p + length);
}

std::string accessorName(int accessor, const std::string& what) {
    return what + ", accessor " + std::to_string(accessor);
}

std::vector<float> readFloats(const tinygltf::Model& model, int index, int components, std::initializer_list<int> types,
                              const std::string& what) {
    const tinygltf::Accessor& a = accessorAt(model, index, what);
    std::string name = accessorName(index, what);
    if (componentsOf(a.type) != components)
        throw LoadError(name + ": has " + std::to_string(componentsOf(a.type)) + " components per element; expected " +
                        std::to_string(components));
    if (std::find(types.begin(), types.end(), a.componentType) == types.end())
        throw LoadError(name + ": component type " + componentTypeName(a.componentType) + " is not allowed here");
    size_t size = componentSize(a.componentType), elementSize = size * size_t(components);
    std::vector<float> out;
    if (a.bufferView >= 0) {
        size_t stride;
        const uint8_t* p = locate(model, a.bufferView, a.byteOffset, a.count, elementSize, true, stride, name);
        out.resize(a.count * size_t(components)); // bounded now: the elements lie in the buffer
        for (size_t i = 0; i < a.count; ++i)
            for (int c = 0; c < components; ++c)
                out[i * size_t(components) + size_t(c)] = component(p + i * stride + size_t(c) * size, a.componentType, a.normalized);
    } else if (!a.sparse.isSparse) {
        throw LoadError(name + ": has neither a bufferView nor sparse values");
    } else if (a.count > (size_t(1) << 24)) {
        // Zeros with a few sparse values: bytes the file does not hold, so bounded apart.
        throw LoadError(name + ": a count of " + std::to_string(a.count) + " with no buffer behind it (at most 2^24)");
    } else {
        out.resize(a.count * size_t(components)); // zeros under the sparse values
    }
    if (a.sparse.isSparse) {
        const auto& s = a.sparse;
        if (s.count < 0 || size_t(s.count) > a.count)
            throw LoadError(name + ": sparse count " + std::to_string(s.count) + " exceeds the accessor's count " +
                            std::to_string(a.count));
        int indexType = s.indices.componentType;
        if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            throw LoadError(name + ": sparse indices of type " + componentTypeName(indexType));
        if (s.indices.byteOffset < 0 || s.values.byteOffset < 0) throw LoadError(name + ": negative sparse byteOffset");
        size_t indexStride, valueStride;
        const uint8_t* ip = locate(model, s.indices.bufferView, size_t(s.indices.byteOffset), size_t(s.count),
                                   componentSize(indexType), false, indexStride, name + " sparse indices");
        const uint8_t* vp = locate(model, s.values.bufferView, size_t(s.values.byteOffset), size_t(s.count), elementSize,
                                   false, valueStride, name + " sparse values");
        for (size_t k = 0; k < size_t(s.count); ++k) {
            uint32_t target = unsignedComponent(ip + k * indexStride, indexType);
            if (target >= a.count)
                throw LoadError(name + ": sparse index " + std::to_string(target) + " is past the count " +
                                std::to_string(a.count));
            if (k > 0 && target <= unsignedComponent(ip + (k - 1) * indexStride, indexType))
                throw LoadError(name + ": sparse index " + std::to_string(k) + " is " + std::to_string(target) +
                                ", not above the one before it (they must strictly increase)");
            for (int c = 0; c < components; ++c)
                out[size_t(target) * size_t(components) + size_t(c)] =
                    component(vp + k * valueStride + size_t(c) * size, a.componentType, a.normalized);
        }
    }
    for (size_t i = 0; i < out.size(); ++i)
        if (!std::isfinite(out[i]))
            throw LoadError(name + ": element " + std::to_string(i / size_t(components)) + " component " +
                            std::to_string(i % size_t(components)) + " is not a finite number");
    return out;
}

std::vector<uint32_t> readIndices(const tinygltf::Model& model, int index, size_t vertexCount, const std::string& what) {
    const tinygltf::Accessor& a = accessorAt(model, index, what);
    std::string name = accessorName(index, what);
    if (a.type != TINYGLTF_TYPE_SCALAR) throw LoadError(name + ": indices must be SCALAR");
    int t = a.componentType;
    if (t != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && t != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        t != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        throw LoadError(name + ": indices of type " + componentTypeName(t) + "; expected an unsigned integer type");
    if (a.sparse.isSparse) throw LoadError(name + ": sparse index accessors are not supported");
    if (a.bufferView < 0) throw LoadError(name + ": indices need a bufferView");
    if (size_t(a.bufferView) < model.bufferViews.size() && model.bufferViews[size_t(a.bufferView)].byteStride != 0)
        throw LoadError(name + ": bufferView " + std::to_string(a.bufferView) + " of indices has a byteStride; index views are packed");
    size_t stride;
    const uint8_t* p = locate(model, a.bufferView, a.byteOffset, a.count, componentSize(t), false, stride, name);
    std::vector<uint32_t> out(a.count);
    for (size_t i = 0; i < a.count; ++i) {
        out[i] = unsignedComponent(p + i * stride, t);
        if (out[i] >= vertexCount)
            throw LoadError(name + ": index " + std::to_string(i) + " is " + std::to_string(out[i]) +
                            ", past the primitive's " + std::to_string(vertexCount) + " vertices");
    }
    return out;
}

} // namespace pt::gltf
