// Oracle: the bad-input rules of docs/ARCHITECTURE.md §8 for displacement maps. Each case is a
// crafted file (written with the OpenEXR library directly, or bytes patched or cut from a good
// file) and asserts one InputError line naming the file and the problem; a refused write
// leaves no file.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <random>

#include "tests/displacement/exr_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

using testing::makeMap;
using testing::readError;
using testing::writeError;

// A float EXR written with the library alone: the given channels, every texel `value`, the
// given string attributes.
std::string writeRawExr(const std::filesystem::path& path, const std::vector<const char*>& names,
                        float value, const std::map<std::string, std::string>& attributes,
                        Imf::PixelType first_type = Imf::FLOAT) {
  const int width = 4, height = 3;
  Imf::Header header(width, height);
  for (std::size_t c = 0; c < names.size(); ++c) {
    header.channels().insert(names[c], Imf::Channel(c == 0 ? first_type : Imf::FLOAT));
  }
  for (const auto& [name, text] : attributes) header.insert(name, Imf::StringAttribute(text));
  std::vector<float> floats(width * height * names.size(), value);
  std::vector<Imath::half> halves(floats.begin(), floats.end());
  Imf::FrameBuffer frame;
  for (std::size_t c = 0; c < names.size(); ++c) {
    const bool half = c == 0 && first_type == Imf::HALF;
    char* base =
        half ? reinterpret_cast<char*>(halves.data()) : reinterpret_cast<char*>(floats.data());
    const std::size_t bytes = half ? sizeof(Imath::half) : sizeof(float);
    const std::size_t stride = bytes * names.size();
    frame.insert(names[c], Imf::Slice(first_type == Imf::HALF && c == 0 ? Imf::HALF : Imf::FLOAT,
                                      base + c * bytes, stride, stride * width));
  }
  Imf::OutputFile file(path.c_str(), header);
  file.setFrameBuffer(frame);
  file.writePixels(height);
  return path.string();
}

const std::map<std::string, std::string> kUv = {{displacement::kExrLayoutAttribute, "uv"}};

class ExrBadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::scratchDirectory(
        std::string("exr_bad_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  std::string good(const std::string& name) {
    const std::string path = (dir_ / name).string();
    displacement::writeDisplacementExr(path,
                                       makeMap(displacement::DisplacementKind::kVector,
                                               displacement::DisplacementPixelType::kFloat, 9, 7));
    return path;
  }
  std::filesystem::path dir_;
};

// One line, naming the file and holding the problem.
void expectMessage(const std::string& message, const std::string& path,
                   const std::string& problem) {
  EXPECT_EQ(message.rfind(path, 0), 0u) << message;
  EXPECT_NE(message.find(problem), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST_F(ExrBadInput, MissingFile) {
  const std::string path = (dir_ / "missing.exr").string();
  expectMessage(readError(path), path, "cannot open the file");
}

TEST_F(ExrBadInput, EmptyFile) {
  const std::string path = testing::writeBytes(dir_ / "empty.exr", {});
  expectMessage(readError(path), path, "the file is empty");
}

TEST_F(ExrBadInput, TruncatedFile) {
  const std::string path = good("whole.exr");
  std::vector<char> bytes = testing::fileBytes(path);
  bytes.resize(bytes.size() * 3 / 4);
  const std::string cut = testing::writeBytes(dir_ / "cut.exr", bytes);
  expectMessage(readError(cut), cut, "truncated");
}

TEST_F(ExrBadInput, ObjRenamedIsNotExr) {
  const std::string path = (dir_ / "cube.exr").string();
  std::filesystem::copy_file(testing::assetPath("opensubdiv/catmark_cube.obj"), path);
  expectMessage(readError(path), path, "not an OpenEXR file");
}

TEST_F(ExrBadInput, PngRenamedIsNotExr) {
  const std::string path = testing::writeBytes(
      dir_ / "picture.exr", {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n', 0, 0, 0, 13});
  expectMessage(readError(path), path, "not an OpenEXR file");
}

TEST_F(ExrBadInput, TwoChannels) {
  const std::string path = writeRawExr(dir_ / "two.exr", {"R", "G"}, 0.5f, kUv);
  expectMessage(readError(path), path, "channels G,R: 2 channels; expected Y");
}

TEST_F(ExrBadInput, VectorWhereScalarExpected) {
  const std::string path = good("vector.exr");
  expectMessage(readError(path, displacement::DisplacementKind::kScalar), path,
                "a vector map where a scalar map is expected");
}

TEST_F(ExrBadInput, MixedChannelTypes) {
  const std::string path = writeRawExr(dir_ / "mixed.exr", {"R", "G", "B"}, 0.5f, kUv, Imf::HALF);
  expectMessage(readError(path), path, "all be half or all be float");
}

// OpenEXR cannot write an empty data window, so the file is a good one whose dataWindow
// attribute is patched to xMax = xMin - 1 (a width of 0).
TEST_F(ExrBadInput, ZeroWidthDataWindowOnRead) {
  const std::string path = good("good.exr");
  std::vector<char> bytes = testing::fileBytes(path);
  const std::string key("dataWindow\0box2i\0", 17);
  const auto at = std::search(bytes.begin(), bytes.end(), key.begin(), key.end());
  ASSERT_NE(at, bytes.end());
  const std::size_t box = static_cast<std::size_t>(at - bytes.begin()) + key.size() + 4;
  const std::int32_t x_max = -1;  // xMin is 0
  std::memcpy(bytes.data() + box + 8, &x_max, sizeof x_max);
  const std::string patched = testing::writeBytes(dir_ / "zero_width.exr", bytes);
  expectMessage(readError(patched), patched, "data window");
}

TEST_F(ExrBadInput, ZeroResolutionOnWrite) {
  const std::string path = (dir_ / "zero.exr").string();
  displacement::DisplacementMap map = makeMap(displacement::DisplacementKind::kScalar,
                                              displacement::DisplacementPixelType::kFloat, 0, 4);
  expectMessage(writeError(path, map), path,
                "resolution 0 x 4: width and height must be at least 1");
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST_F(ExrBadInput, NanTexelOnRead) {
  const std::string path =
      writeRawExr(dir_ / "nan.exr", {"Y"}, std::numeric_limits<float>::quiet_NaN(), kUv);
  expectMessage(readError(path), path, "texel (0, 0) channel 0: not finite");
}

TEST_F(ExrBadInput, InfiniteTexelOnRead) {
  const std::string path =
      writeRawExr(dir_ / "inf.exr", {"Y"}, -std::numeric_limits<float>::infinity(), kUv, Imf::HALF);
  expectMessage(readError(path), path, "texel (0, 0) channel 0: not finite");
}

TEST_F(ExrBadInput, NanAndInfiniteTexelsOnWrite) {
  for (const float bad :
       {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    const std::string path = (dir_ / "bad_texel.exr").string();
    displacement::DisplacementMap map = makeMap(displacement::DisplacementKind::kVector,
                                                displacement::DisplacementPixelType::kFloat, 3, 3);
    map.texels[3 * 4 + 2] = bad;  // texel (1, 1), channel 2
    expectMessage(writeError(path, map), path, "texel (1, 1) channel 2: not finite");
    EXPECT_FALSE(std::filesystem::exists(path));
  }
}

TEST_F(ExrBadInput, TexelCountMismatchOnWrite) {
  const std::string path = (dir_ / "count.exr").string();
  displacement::DisplacementMap map = makeMap(displacement::DisplacementKind::kVector,
                                              displacement::DisplacementPixelType::kFloat, 3, 3);
  map.texels.pop_back();
  expectMessage(writeError(path, map), path, "26 values, expected 27");
}

TEST_F(ExrBadInput, MissingLayoutAttribute) {
  const std::string path = writeRawExr(dir_ / "plain.exr", {"Y"}, 0.25f, {});
  expectMessage(readError(path), path, "header attribute 'tessbench.layout': missing");
}

TEST_F(ExrBadInput, UnknownLayout) {
  const std::string path =
      writeRawExr(dir_ / "ptex.exr", {"Y"}, 0.25f, {{displacement::kExrLayoutAttribute, "ptex"}});
  expectMessage(readError(path), path, "'ptex', expected tiles or uv");
}

TEST_F(ExrBadInput, MissingTileAttribute) {
  const std::string path = writeRawExr(dir_ / "no_count.exr", {"Y"}, 0.25f,
                                       {{displacement::kExrLayoutAttribute, "tiles"},
                                        {displacement::kExrTileSizeAttribute, "2"},
                                        {displacement::kExrTileBorderAttribute, "0"},
                                        {displacement::kExrTilesPerRowAttribute, "2"}});
  expectMessage(readError(path), path, "header attribute 'tessbench.tile_count': missing");
}

TEST_F(ExrBadInput, TileAttributeNotANumber) {
  const std::string path = writeRawExr(dir_ / "nan_size.exr", {"Y"}, 0.25f,
                                       {{displacement::kExrLayoutAttribute, "tiles"},
                                        {displacement::kExrTileSizeAttribute, "2x"},
                                        {displacement::kExrTileBorderAttribute, "0"},
                                        {displacement::kExrTilesPerRowAttribute, "2"},
                                        {displacement::kExrTileCountAttribute, "2"}});
  expectMessage(readError(path), path, "'2x' is not a whole number");
}

// The map is 4 x 3: three 2-texel tiles per row need 6 texels.
TEST_F(ExrBadInput, TilesWiderThanMapOnRead) {
  const std::string path = writeRawExr(dir_ / "wide.exr", {"Y"}, 0.25f,
                                       {{displacement::kExrLayoutAttribute, "tiles"},
                                        {displacement::kExrTileSizeAttribute, "2"},
                                        {displacement::kExrTileBorderAttribute, "0"},
                                        {displacement::kExrTilesPerRowAttribute, "3"},
                                        {displacement::kExrTileCountAttribute, "3"}});
  expectMessage(readError(path), path, "the tiles do not fit the 4 x 3 atlas");
}

TEST_F(ExrBadInput, TileAttributeOnUvMap) {
  const std::string path = writeRawExr(
      dir_ / "uv_tiles.exr", {"Y"}, 0.25f,
      {{displacement::kExrLayoutAttribute, "uv"}, {displacement::kExrTileSizeAttribute, "2"}});
  expectMessage(readError(path), path, "present on a uv map");
}

TEST_F(ExrBadInput, InconsistentTilesOnWrite) {
  const std::string path = (dir_ / "tiles.exr").string();
  displacement::DisplacementMap map = testing::makeTilesMap(
      displacement::DisplacementKind::kScalar, displacement::DisplacementPixelType::kFloat);
  map.tiles.tile_count = 7;  // 3 rows of 8 texels in a 16-texel-high atlas
  expectMessage(writeError(path, map), path, "the tiles do not fit the 24 x 16 atlas");
  map.tiles.tile_count = 5;
  map.tiles.border = 4;
  expectMessage(writeError(path, map), path, "2 * border >= tile_size");
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST_F(ExrBadInput, UnwritablePathNamesTheFile) {
  const std::string path = (dir_ / "no_such_folder" / "map.exr").string();
  expectMessage(writeError(path, makeMap(displacement::DisplacementKind::kScalar,
                                         displacement::DisplacementPixelType::kFloat, 2, 2)),
                path, "cannot write the OpenEXR file");
}

// Never a crash and never another exception: every prefix of a good file, random garbage
// behind the magic number, and single-byte corruptions either read or throw InputError.
TEST_F(ExrBadInput, GarbageAndPrefixesNeverCrash) {
  const std::vector<char> whole = testing::fileBytes(good("good.exr"));
  const std::string path = (dir_ / "garbage.exr").string();
  const auto readsOrRefuses = [&](const std::vector<char>& bytes) {
    testing::writeBytes(path, bytes);
    try {
      displacement::readDisplacementExr(path);
    } catch (const mesh::InputError&) {
    }
  };
  for (std::size_t size = 0; size < whole.size(); size += 7) {
    readsOrRefuses(std::vector<char>(whole.begin(), whole.begin() + size));
  }
  std::mt19937 random(20240611);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<char> bytes = {'\x76', '\x2f', '\x31', '\x01'};
    const std::size_t size = random() % 600;
    for (std::size_t i = 0; i < size; ++i) bytes.push_back(static_cast<char>(random()));
    readsOrRefuses(bytes);
    std::vector<char> flipped = whole;
    flipped[random() % flipped.size()] = static_cast<char>(random());
    readsOrRefuses(flipped);
  }
}

}  // namespace
}  // namespace tb
