#include "harness/pictures/png_writer.h"

#include <png.h>

#include <csetjmp>
#include <stdexcept>
#include <vector>

namespace tb::pictures {
namespace {

// libpng reports errors by longjmp to the encoder's setjmp; a C++ exception must not cross
// its C frames, so the callbacks only record what went wrong.
struct WriteState {
  std::string* out = nullptr;
  bool out_of_memory = false;
  std::string error;
};

void appendBytes(png_structp png, png_bytep data, size_t length) {
  auto* state = static_cast<WriteState*>(png_get_io_ptr(png));
  bool failed = false;
  try {
    state->out->append(reinterpret_cast<const char*>(data), length);
  } catch (const std::bad_alloc&) {
    failed = true;
  }
  if (failed) {
    state->out_of_memory = true;
    png_error(png, "out of memory while writing the PNG");
  }
}

void flushNothing(png_structp) {}

void recordError(png_structp png, png_const_charp message) {
  auto* state = static_cast<WriteState*>(png_get_error_ptr(png));
  state->error = message;
  png_longjmp(png, 1);
}

void ignoreWarning(png_structp, png_const_charp) {}

}  // namespace

std::string encodePng(const RgbImage& image) {
  if (image.width_px == 0 || image.height_px == 0 ||
      image.rgb.size() != size_t(image.width_px) * image.height_px * 3) {
    throw std::invalid_argument("encodePng: the image is empty or its pixels do not fit its size");
  }
  std::string out;
  WriteState state;
  state.out = &out;
  std::vector<png_bytep> rows(image.height_px);
  for (uint32_t y = 0; y < image.height_px; ++y) {
    rows[y] = const_cast<png_bytep>(&image.rgb[size_t(y) * image.width_px * 3]);
  }
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, &state, recordError, ignoreWarning);
  if (png == nullptr) throw std::runtime_error("encodePng: cannot create the libpng writer");
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png)) != 0) {
    png_destroy_write_struct(&png, info == nullptr ? nullptr : &info);
    throw std::runtime_error("encodePng: libpng: " +
                             (state.error.empty() ? std::string("no info struct") : state.error));
  }
  png_set_write_fn(png, &state, appendBytes, flushNothing);
  png_set_compression_level(png, kPngCompressionLevel);
  png_set_IHDR(png, info, image.width_px, image.height_px, 8, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

}  // namespace tb::pictures
