#include "core/displacement/exr_io.h"

#include <Iex.h>
#include <Imath/half.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <exception>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <system_error>

#include "core/displacement/displacement_validation.h"
#include "core/mesh/input_error.h"

namespace tb::displacement {
namespace {

// Channel names: "Y" for a scalar map (viewers show it as grey), "R", "G", "B" for the x, y, z
// of a vector map (what sculpting tools write for vector displacement).
constexpr std::array<const char*, 3> kVectorChannels = {"R", "G", "B"};
constexpr const char* kScalarChannel = "Y";

std::vector<const char*> channelNames(DisplacementKind kind) {
  if (kind == DisplacementKind::kScalar) return {kScalarChannel};
  return {kVectorChannels.begin(), kVectorChannels.end()};
}

// A library message as one line: OpenEXR's messages may hold newlines.
std::string oneLine(std::string text) {
  std::replace_if(
      text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

// Bounds every header the library parses, so a damaged data window cannot make it allocate
// line-offset tables or buffers of gigabytes.
void limitImageSize() {
  static std::once_flag once;
  std::call_once(once, [] {
    const int side = static_cast<int>(kMaxDisplacementSide);
    Imf::Header::setMaxImageSize(side, side);
    Imf::Header::setMaxTileSize(side, side);
  });
}

// ---- writing ----

void addLayoutAttributes(Imf::Header& header, const DisplacementMap& map) {
  header.insert(kExrLayoutAttribute, Imf::StringAttribute(std::string(layoutName(map.layout))));
  if (map.layout != DisplacementLayout::kTiles) return;
  const auto put = [&](const char* name, std::uint32_t value) {
    header.insert(name, Imf::StringAttribute(std::to_string(value)));
  };
  put(kExrTileSizeAttribute, map.tiles.tile_size);
  put(kExrTileBorderAttribute, map.tiles.border);
  put(kExrTilesPerRowAttribute, map.tiles.tiles_per_row);
  put(kExrTileCountAttribute, map.tiles.tile_count);
}

void writePixels(const std::string& path, const DisplacementMap& map) {
  const int width = static_cast<int>(map.width), height = static_cast<int>(map.height);
  const std::uint32_t channels = channelCount(map.kind);
  const bool half = map.pixel_type == DisplacementPixelType::kHalf;
  const Imf::PixelType type = half ? Imf::HALF : Imf::FLOAT;

  Imf::Header header(width, height, 1.0f, Imath::V2f(0, 0), 1.0f, Imf::INCREASING_Y,
                     Imf::ZIP_COMPRESSION);
  for (const char* name : channelNames(map.kind))
    header.channels().insert(name, Imf::Channel(type));
  addLayoutAttributes(header, map);

  // Half maps convert once into a half buffer; the texels are exact halves (validated).
  std::vector<Imath::half> halves;
  if (half) halves.assign(map.texels.begin(), map.texels.end());
  const char* base = half ? reinterpret_cast<const char*>(halves.data())
                          : reinterpret_cast<const char*>(map.texels.data());
  const std::size_t texel_bytes = half ? sizeof(Imath::half) : sizeof(float);
  const std::size_t x_stride = texel_bytes * channels;
  Imf::FrameBuffer frame;
  const std::vector<const char*> names = channelNames(map.kind);
  for (std::uint32_t c = 0; c < channels; ++c) {
    frame.insert(names[c], Imf::Slice(type, const_cast<char*>(base + c * texel_bytes), x_stride,
                                      x_stride * map.width));
  }
  Imf::OutputFile file(path.c_str(), header);
  file.setFrameBuffer(frame);
  file.writePixels(height);
}

// ---- reading ----

void checkFileStart(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw mesh::InputError(path, "", "cannot open the file (missing or not a regular file)");
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) throw mesh::InputError(path, "", "cannot open the file (unreadable)");
  std::array<char, 4> magic{};
  file.read(magic.data(), magic.size());
  if (file.gcount() == 0) throw mesh::InputError(path, "", "the file is empty");
  // OpenEXR files start with the magic number 20000630 (little-endian 76 2f 31 01).
  constexpr std::array<unsigned char, 4> kMagic = {0x76, 0x2f, 0x31, 0x01};
  if (file.gcount() < 4 ||
      !std::equal(kMagic.begin(), kMagic.end(), magic.begin(),
                  [](unsigned char a, char b) { return a == static_cast<unsigned char>(b); })) {
    throw mesh::InputError(path, "", "not an OpenEXR file (no OpenEXR magic number)");
  }
}

DisplacementKind channelKind(const std::string& path, const Imf::ChannelList& list,
                             Imf::PixelType& type) {
  std::vector<std::string> names;
  for (auto it = list.begin(); it != list.end(); ++it) names.emplace_back(it.name());
  std::string joined;
  for (const std::string& name : names) joined += (joined.empty() ? "" : ",") + name;
  const std::string element = "channels " + (joined.empty() ? std::string("(none)") : joined);
  DisplacementKind kind;
  if (names == std::vector<std::string>{kScalarChannel}) {
    kind = DisplacementKind::kScalar;
  } else if (names == std::vector<std::string>{"B", "G", "R"}) {  // the list is sorted
    kind = DisplacementKind::kVector;
  } else {
    throw mesh::InputError(
        path, element,
        std::to_string(names.size()) + " channels; expected Y (scalar map) or R,G,B (vector map)");
  }
  type = list.begin().channel().type;
  for (auto it = list.begin(); it != list.end(); ++it) {
    const Imf::Channel& channel = it.channel();
    if (channel.type != type || (type != Imf::HALF && type != Imf::FLOAT)) {
      throw mesh::InputError(path, element, "channels must all be half or all be float");
    }
    if (channel.xSampling != 1 || channel.ySampling != 1) {
      throw mesh::InputError(path, element, "subsampled channels are not supported");
    }
  }
  return kind;
}

const std::string* findString(const Imf::Header& header, const char* name) {
  const auto* attribute = header.findTypedAttribute<Imf::StringAttribute>(name);
  return attribute ? &attribute->value() : nullptr;
}

std::uint32_t tileField(const std::string& path, const Imf::Header& header, const char* name) {
  const std::string* text = findString(header, name);
  const std::string element = std::string("header attribute '") + name + "'";
  if (!text) throw mesh::InputError(path, element, "missing (a tiles map needs it, as a string)");
  std::uint32_t value = 0;
  const auto [end, error] = std::from_chars(text->data(), text->data() + text->size(), value);
  if (error != std::errc() || end != text->data() + text->size() || text->empty()) {
    throw mesh::InputError(path, element, "'" + oneLine(*text) + "' is not a whole number");
  }
  return value;
}

void readLayout(const std::string& path, const Imf::Header& header, DisplacementMap& map) {
  const std::string* layout = findString(header, kExrLayoutAttribute);
  const std::string element = std::string("header attribute '") + kExrLayoutAttribute + "'";
  if (!layout) throw mesh::InputError(path, element, "missing (a string: tiles or uv)");
  if (*layout == "uv") {
    map.layout = DisplacementLayout::kUv;
    for (const char* name : {kExrTileSizeAttribute, kExrTileBorderAttribute,
                             kExrTilesPerRowAttribute, kExrTileCountAttribute}) {
      if (header.find(name) != header.end()) {
        throw mesh::InputError(path, std::string("header attribute '") + name + "'",
                               "present on a uv map (only tiles maps have tiles)");
      }
    }
  } else if (*layout == "tiles") {
    map.layout = DisplacementLayout::kTiles;
    map.tiles.tile_size = tileField(path, header, kExrTileSizeAttribute);
    map.tiles.border = tileField(path, header, kExrTileBorderAttribute);
    map.tiles.tiles_per_row = tileField(path, header, kExrTilesPerRowAttribute);
    map.tiles.tile_count = tileField(path, header, kExrTileCountAttribute);
  } else {
    throw mesh::InputError(path, element, "'" + oneLine(*layout) + "', expected tiles or uv");
  }
}

DisplacementMap readPixels(const std::string& path, std::optional<DisplacementKind> expected) {
  Imf::InputFile file(path.c_str());
  const Imf::Header& header = file.header();
  const Imath::Box2i window = header.dataWindow();
  const std::int64_t width = std::int64_t{window.max.x} - window.min.x + 1;
  const std::int64_t height = std::int64_t{window.max.y} - window.min.y + 1;
  if (width < 1 || height < 1 || width > kMaxDisplacementSide || height > kMaxDisplacementSide) {
    throw mesh::InputError(
        path, "resolution " + std::to_string(width) + " x " + std::to_string(height),
        "width and height must be between 1 and " + std::to_string(kMaxDisplacementSide));
  }
  Imf::PixelType type = Imf::FLOAT;
  DisplacementMap map;
  map.kind = channelKind(path, header.channels(), type);
  if (expected && *expected != map.kind) {
    throw mesh::InputError(path, "channels",
                           "a " + std::string(kindName(map.kind)) + " map where a " +
                               std::string(kindName(*expected)) + " map is expected");
  }
  map.pixel_type = type == Imf::HALF ? DisplacementPixelType::kHalf : DisplacementPixelType::kFloat;
  map.width = static_cast<std::uint32_t>(width);
  map.height = static_cast<std::uint32_t>(height);
  readLayout(path, header, map);
  if (!file.isComplete()) throw mesh::InputError(path, "", "truncated (scan lines are missing)");

  const std::uint32_t channels = channelCount(map.kind);
  const std::size_t count = std::size_t{map.width} * map.height * channels;
  const bool half = type == Imf::HALF;
  std::vector<Imath::half> halves(half ? count : 0);
  map.texels.assign(count, 0.0f);
  char* base =
      half ? reinterpret_cast<char*>(halves.data()) : reinterpret_cast<char*>(map.texels.data());
  const std::size_t texel_bytes = half ? sizeof(Imath::half) : sizeof(float);
  const std::size_t x_stride = texel_bytes * channels;
  Imf::FrameBuffer frame;
  const std::vector<const char*> names = channelNames(map.kind);
  for (std::uint32_t c = 0; c < channels; ++c) {
    frame.insert(names[c], Imf::Slice::Make(type, base + c * texel_bytes, window, x_stride,
                                            x_stride * map.width));
  }
  file.setFrameBuffer(frame);
  file.readPixels(window.min.y, window.max.y);
  if (half) std::copy(halves.begin(), halves.end(), map.texels.begin());
  return map;
}

}  // namespace

void writeDisplacementExr(const std::string& path, const DisplacementMap& map) {
  validateDisplacementMap(map, path);
  try {
    writePixels(path, map);
  } catch (const std::exception& error) {  // Iex::BaseExc derives from std::exception
    std::error_code ignored;
    std::filesystem::remove(path, ignored);  // never leave a partial map behind
    throw mesh::InputError(path, "", "cannot write the OpenEXR file: " + oneLine(error.what()));
  }
}

DisplacementMap readDisplacementExr(const std::string& path,
                                    std::optional<DisplacementKind> expected) {
  checkFileStart(path);
  limitImageSize();
  DisplacementMap map;
  try {
    map = readPixels(path, expected);
  } catch (const mesh::InputError&) {
    throw;
  } catch (const std::exception& error) {  // Iex::BaseExc derives from std::exception
    throw mesh::InputError(
        path, "", "unreadable OpenEXR file (damaged or truncated): " + oneLine(error.what()));
  }
  validateDisplacementMap(map, path);
  return map;
}

}  // namespace tb::displacement
