// image_io.h: images out of a subcommand (a renderer's frame, a baked map), and the image formats
// that write them, one table entry each (as files/format_table.h does for meshes).
//
// Image: width x height pixels, rows top to bottom, `channels` interleaved values per pixel
// (3 = RGB, 4 = RGBA), either 8-bit (u8, display-encoded as the producer chose) or 32-bit float
// (f32, linear, unclamped). Exactly one of u8 / f32 holds width*height*channels values.
//
// Image formats (image_formats(), the first entry is the default where none is named):
//   pfm  Portable Float Map: "PF" (RGB), little-endian float rows bottom to top (scale -1).
//        8-bit images are written as c/255; alpha is left out (a note says so). A NaN or infinite
//        pixel is refused (Error): no writer writes Inf or NaN.
// A PNG writer (8-bit RGB/RGBA through libpng) is one more entry in image_io.cpp's table.
//
// encode_image   Image -> the bytes of a file in `format`; notes for what the format left out.
//                Errors (shadetool::Error `NAME: what`): a malformed image, a value the format
//                cannot hold.
// write_image    encode_image, then io/atomic_write.h: all or nothing, "-" is stdout.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct Image {
  enum class Pixel { U8, F32 };
  std::size_t width = 0, height = 0;
  int channels = 3;  // 3 RGB, 4 RGBA
  Pixel pixel = Pixel::U8;
  std::vector<std::uint8_t> u8;  // Pixel::U8: width * height * channels
  std::vector<float> f32;        // Pixel::F32: width * height * channels
  int png_compression = 1;       // PNG only: 0..9, io/image_png.h (1: fast, the default; 9: smallest)

  bool empty() const { return width == 0 || height == 0; }
};

struct ImageWriteInfo {
  std::vector<std::string> notes;  // what the format could not carry (one line each)
};

struct ImageFormatEntry {
  const char* name;                     // lower case: "pfm"
  std::vector<const char*> extensions;  // lower case, no dot; the first names written files
  std::string (*encode)(const Image& image, const std::string& name, ImageWriteInfo& info);
};

const std::vector<ImageFormatEntry>& image_formats();
// By name or extension, any case, no dot; nullptr if none.
const ImageFormatEntry* find_image_format(std::string_view name_or_extension);
std::vector<std::string> image_format_names();

// `name` is used in messages (the output path).
std::string encode_image(const Image& image, const ImageFormatEntry& format, const std::string& name,
                         ImageWriteInfo* info = nullptr);
// The format named `format_name` if not empty, else the one of `path`'s extension; Error otherwise.
const ImageFormatEntry& image_format_for(const std::string& path, const std::string& format_name);
// Format from `format_name` if not empty, else from the extension of `path` ("-" needs a name).
void write_image(const Image& image, const std::string& path, const std::string& format_name,
                 ImageWriteInfo* info = nullptr);

}  // namespace shadetool
#pragma GCC visibility pop
