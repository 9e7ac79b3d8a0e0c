#include "core/mesh/gltf_accessor.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>

#include "core/mesh/input_error.h"

namespace tb::mesh {
namespace {

[[noreturn]] void refuse(const GltfPlace& place, const std::string& rule) {
  throw InputError(place.file, place.element, rule);
}

// Bytes of one component, 0 for a type glTF 2.0 does not have.
size_t componentBytes(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

template <class T>
T readAs(const uint8_t* bytes) {
  T value;
  std::memcpy(&value, bytes, sizeof(T));
  return value;
}

// One component as the specification reads it (§3.11: normalised signed values map
// max(c / (2^(b-1) - 1), -1), unsigned c / (2^b - 1)).
double component(int type, bool normalized, const uint8_t* bytes) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const double c = readAs<int8_t>(bytes);
      return normalized ? std::max(c / 127.0, -1.0) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      const double c = readAs<uint8_t>(bytes);
      return normalized ? c / 255.0 : c;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      const double c = readAs<int16_t>(bytes);
      return normalized ? std::max(c / 32767.0, -1.0) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      const double c = readAs<uint16_t>(bytes);
      return normalized ? c / 65535.0 : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return double(readAs<uint32_t>(bytes));
    default:
      return double(readAs<float>(bytes));
  }
}

// The bytes of buffer view `index`, checked against its buffer.
struct ViewBytes {
  const uint8_t* data = nullptr;
  size_t size = 0;
  size_t stride = 0;  // 0: tightly packed
};

ViewBytes viewBytes(const tinygltf::Model& model, int index, const std::string& who,
                    const GltfPlace& place) {
  if (index < 0 || size_t(index) >= model.bufferViews.size()) {
    refuse(place, who + ": buffer view " + std::to_string(index) + " does not exist");
  }
  const tinygltf::BufferView& view = model.bufferViews[size_t(index)];
  if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size()) {
    refuse(place, who + ": buffer view " + std::to_string(index) + " names buffer " +
                      std::to_string(view.buffer) + ", which does not exist");
  }
  const std::vector<unsigned char>& data = model.buffers[size_t(view.buffer)].data;
  if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset) {
    refuse(place, who + ": buffer view " + std::to_string(index) + " (bytes " +
                      std::to_string(view.byteOffset) + " + " + std::to_string(view.byteLength) +
                      ") runs past buffer " + std::to_string(view.buffer) + " of " +
                      std::to_string(data.size()) + " bytes (missing or short buffer)");
  }
  return {data.data() + view.byteOffset, view.byteLength, view.byteStride};
}

// Checks that `count` elements of `element` bytes, `stride` apart from `offset`, lie in
// `size` bytes.
void requireInside(size_t offset, size_t count, size_t element, size_t stride, size_t size,
                   const std::string& who, const GltfPlace& place) {
  if (count == 0) return;
  const bool fits = offset <= size && element <= size - offset &&
                    (count - 1) <= (size - offset - element) / std::max<size_t>(stride, 1);
  if (!fits) {
    refuse(place, who + ": " + std::to_string(count) + " elements of " + std::to_string(element) +
                      " bytes from byte " + std::to_string(offset) + " run past its buffer view (" +
                      std::to_string(size) + " bytes)");
  }
}

int typeWidth(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
    case TINYGLTF_TYPE_VEC3:
    case TINYGLTF_TYPE_VEC4:
      return type;
    default:
      return 0;
  }
}

// Overwrites the elements a sparse accessor names (§3.6.2.3).
void applySparse(const tinygltf::Model& model, const tinygltf::Accessor& accessor, int width,
                 const std::string& who, const GltfPlace& place, std::vector<double>* values) {
  const auto& sparse = accessor.sparse;
  if (sparse.count <= 0 || size_t(sparse.count) > accessor.count) {
    refuse(place, who + ": sparse count " + std::to_string(sparse.count) + " is not in 1.." +
                      std::to_string(accessor.count));
  }
  const size_t count = size_t(sparse.count);
  const int index_type = sparse.indices.componentType;
  const size_t index_bytes = componentBytes(index_type);
  if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
    refuse(place, who + ": sparse indices of component type " + std::to_string(index_type) +
                      " (unsigned byte, short or int expected)");
  }
  const ViewBytes iv = viewBytes(model, sparse.indices.bufferView, who + " sparse indices", place);
  const ViewBytes vv = viewBytes(model, sparse.values.bufferView, who + " sparse values", place);
  const size_t element = componentBytes(accessor.componentType) * size_t(width);
  requireInside(size_t(std::max(sparse.indices.byteOffset, 0)), count, index_bytes, index_bytes,
                iv.size, who + " sparse indices", place);
  requireInside(size_t(std::max(sparse.values.byteOffset, 0)), count, element, element, vv.size,
                who + " sparse values", place);
  const uint8_t* indices = iv.data + std::max(sparse.indices.byteOffset, 0);
  const uint8_t* data = vv.data + std::max(sparse.values.byteOffset, 0);
  const size_t bytes = componentBytes(accessor.componentType);
  for (size_t s = 0; s < count; ++s) {
    const double target = component(index_type, false, indices + s * index_bytes);
    if (target >= double(accessor.count)) {
      refuse(place, who + ": sparse index " + std::to_string(size_t(target)) + " is past its " +
                        std::to_string(accessor.count) + " elements");
    }
    for (int c = 0; c < width; ++c) {
      (*values)[size_t(target) * size_t(width) + size_t(c)] = component(
          accessor.componentType, accessor.normalized, data + s * element + size_t(c) * bytes);
    }
  }
}

}  // namespace

std::vector<double> readGltfAccessor(const tinygltf::Model& model, int index, int width,
                                     const char* what, const GltfPlace& place) {
  const std::string who = std::string(what) + " accessor " + std::to_string(index);
  if (index < 0 || size_t(index) >= model.accessors.size()) {
    refuse(place, who + " does not exist (the file has " + std::to_string(model.accessors.size()) +
                      " accessors)");
  }
  const tinygltf::Accessor& accessor = model.accessors[size_t(index)];
  const size_t bytes = componentBytes(accessor.componentType);
  if (bytes == 0) {
    refuse(place, who + ": component type " + std::to_string(accessor.componentType) +
                      " is not a glTF 2.0 component type");
  }
  if (typeWidth(accessor.type) != width) {
    refuse(place, who + " has " + std::to_string(typeWidth(accessor.type)) + " components, " +
                      std::to_string(width) + " expected");
  }
  // A count no buffer could hold is refused before anything is allocated.
  if (accessor.count > (size_t(1) << 28)) {
    refuse(place, who + ": count " + std::to_string(accessor.count) + " is above 2^28");
  }
  std::vector<double> values(accessor.count * size_t(width), 0.0);
  const size_t element = bytes * size_t(width);
  if (accessor.bufferView >= 0) {
    const ViewBytes view = viewBytes(model, accessor.bufferView, who, place);
    const size_t stride = view.stride == 0 ? element : view.stride;
    if (stride < element) {
      refuse(place, who + ": byte stride " + std::to_string(stride) + " is below its element's " +
                        std::to_string(element) + " bytes");
    }
    requireInside(accessor.byteOffset, accessor.count, element, stride, view.size, who, place);
    for (size_t i = 0; i < accessor.count; ++i) {
      const uint8_t* at = view.data + accessor.byteOffset + i * stride;
      for (int c = 0; c < width; ++c) {
        values[i * size_t(width) + size_t(c)] =
            component(accessor.componentType, accessor.normalized, at + size_t(c) * bytes);
      }
    }
  }
  if (accessor.sparse.isSparse) applySparse(model, accessor, width, who, place, &values);
  return values;
}

std::vector<uint32_t> readGltfIndices(const tinygltf::Model& model, int index,
                                      const GltfPlace& place) {
  if (index >= 0 && size_t(index) < model.accessors.size()) {
    const tinygltf::Accessor& accessor = model.accessors[size_t(index)];
    const int type = accessor.componentType;
    if ((type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
         type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
         type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) ||
        accessor.normalized) {
      refuse(place, "indices accessor " + std::to_string(index) + ": component type " +
                        std::to_string(type) +
                        " (unsigned byte, short or int, not normalised, expected)");
    }
  }
  const std::vector<double> values = readGltfAccessor(model, index, 1, "indices", place);
  std::vector<uint32_t> indices(values.size());
  std::transform(values.begin(), values.end(), indices.begin(),
                 [](double v) { return uint32_t(v); });
  return indices;
}

}  // namespace tb::mesh
