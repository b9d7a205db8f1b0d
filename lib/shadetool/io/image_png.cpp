// image_png.cpp: see image_png.h.
#include <shadetool/io/image_png.h>

#include <csetjmp>

#include <png.h>
#include <zlib.h>

#include <shadetool/core/error.h>

namespace shadetool::io {

namespace {

struct PngSink {
  std::string bytes;
  std::string error;
};

void append_bytes(png_structp png, png_bytep data, png_size_t length) {
  auto* sink = static_cast<PngSink*>(png_get_io_ptr(png));
  sink->bytes.append(reinterpret_cast<const char*>(data), length);
}
void flush_nothing(png_structp) {}
void on_error(png_structp png, png_const_charp message) {
  auto* sink = static_cast<PngSink*>(png_get_error_ptr(png));
  sink->error = message ? message : "unknown libpng error";
  png_longjmp(png, 1);
}
void on_warning(png_structp, png_const_charp) {}

}  // namespace

std::string encode_png_srgb8(int width, int height, const std::vector<std::uint8_t>& srgb8, const std::string& name,
                             int level) {
  if (level < 0 || level > 9) fail(name, 0, "cannot encode PNG: compression level " + std::to_string(level) + " is not in 0..9");
  if (width <= 0 || height <= 0 || srgb8.size() != std::size_t(width) * std::size_t(height) * 3)
    fail(name, 0, "cannot encode PNG: the pixel buffer does not match " + std::to_string(width) + "x" +
                      std::to_string(height) + " RGB");
  PngSink sink;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, on_error, on_warning);
  if (!png) fail(name, 0, "cannot encode PNG: out of memory");
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    fail(name, 0, "cannot encode PNG: out of memory");
  }
  // libpng reports errors by longjmp: nothing with a destructor is created below this point.
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    fail(name, 0, "cannot encode PNG: " + sink.error);
  }
  png_set_write_fn(png, &sink, append_bytes, flush_nothing);
  png_set_compression_level(png, level);
  if (level <= 1) {  // stored, or the fast default (see image_png.h): Up on every row, run-length coding
    png_set_filter(png, PNG_FILTER_TYPE_BASE, level == 0 ? PNG_FILTER_NONE : PNG_FILTER_UP);
    if (level == 1) png_set_compression_strategy(png, Z_RLE);
  }
  png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_write_info(png, info);
  const std::size_t stride = std::size_t(width) * 3;
  for (int y = 0; y < height; ++y)
    png_write_row(png, const_cast<png_bytep>(srgb8.data() + std::size_t(y) * stride));
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return std::move(sink.bytes);
}

}  // namespace shadetool::io
