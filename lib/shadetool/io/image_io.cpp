// image_io.cpp: the image format table and the PFM writer (see image_io.h).
#include <shadetool/io/image_io.h>
#include <shadetool/io/image_png.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>

#include <shadetool/core/error.h>
#include <shadetool/io/atomic_write.h>

namespace shadetool {

namespace {

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

void check_shape(const Image& image, const std::string& name) {
  if (image.empty()) fail(name, 0, "the image is empty (0 pixels)");
  if (image.channels != 3 && image.channels != 4)
    fail(name, 0, "an image has 3 (RGB) or 4 (RGBA) channels, not " + std::to_string(image.channels));
  const std::size_t n = image.width * image.height * std::size_t(image.channels);
  const std::size_t have = image.pixel == Image::Pixel::U8 ? image.u8.size() : image.f32.size();
  if (have != n) fail(name, 0, "the image holds " + std::to_string(have) + " values, expected " + std::to_string(n));
}

// Portable Float Map (Debevec's PFM as read by pfstools, OpenImageIO, Blender): header
// "PF\nW H\n-1.0\n", then float RGB rows from the bottom row up; scale < 0 means little-endian.
std::string encode_pfm(const Image& image, const std::string& name, ImageWriteInfo& info) {
  if (image.channels == 4) info.notes.push_back("alpha not written: PFM holds RGB only");
  std::string out = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
  out.reserve(out.size() + image.width * image.height * 12);
  const std::size_t ch = std::size_t(image.channels);
  std::size_t nonfinite = 0;
  for (std::size_t row = image.height; row-- > 0;)
    for (std::size_t x = 0; x < image.width; ++x)
      for (std::size_t k = 0; k < 3; ++k) {
        const std::size_t i = (row * image.width + x) * ch + k;
        const float v = image.pixel == Image::Pixel::F32 ? image.f32[i] : float(image.u8[i]) / 255.0f;
        nonfinite += !std::isfinite(v);
        std::uint32_t u;
        std::memcpy(&u, &v, 4);
        const char b[4] = {char(u & 0xff), char((u >> 8) & 0xff), char((u >> 16) & 0xff), char((u >> 24) & 0xff)};
        out.append(b, 4);
      }
  if (nonfinite > 0) fail(name, 0, std::to_string(nonfinite) + " pixel values are NaN or infinite: nothing written");
  return out;
}

// PNG (io/image_png.h, libpng): 8-bit RGB marked sRGB; the caller has encoded the pixels (a float
// image has no 8-bit meaning without a transfer curve and quantisation, which are the caller's).
std::string encode_png(const Image& image, const std::string& name, ImageWriteInfo& info) {
  if (image.pixel != Image::Pixel::U8) fail(name, 0, "PNG holds 8-bit pixels: encode the float image first (or write PFM)");
  if (image.channels == 4) {
    info.notes.push_back("alpha not written: the PNG writer holds RGB only");
    std::vector<std::uint8_t> rgb(image.width * image.height * 3);
    for (std::size_t i = 0; i < image.width * image.height; ++i)
      for (int k = 0; k < 3; ++k) rgb[3 * i + k] = image.u8[4 * i + k];
    return io::encode_png_srgb8(int(image.width), int(image.height), rgb, name, image.png_compression);
  }
  return io::encode_png_srgb8(int(image.width), int(image.height), image.u8, name, image.png_compression);
}

}  // namespace

const std::vector<ImageFormatEntry>& image_formats() {
  // The first entry is the default image format.
  static const std::vector<ImageFormatEntry> table = {
      {"png", {"png"}, encode_png},
      {"pfm", {"pfm"}, encode_pfm},
  };
  return table;
}

const ImageFormatEntry* find_image_format(std::string_view name) {
  for (const ImageFormatEntry& e : image_formats()) {
    if (equal_ignoring_case(name, e.name)) return &e;
    for (const char* ext : e.extensions)
      if (equal_ignoring_case(name, ext)) return &e;
  }
  return nullptr;
}

std::vector<std::string> image_format_names() {
  std::vector<std::string> names;
  for (const ImageFormatEntry& e : image_formats()) names.emplace_back(e.name);
  return names;
}

std::string encode_image(const Image& image, const ImageFormatEntry& format, const std::string& name,
                         ImageWriteInfo* info) {
  ImageWriteInfo local;
  check_shape(image, name);
  return format.encode(image, name, info ? *info : local);
}

const ImageFormatEntry& image_format_for(const std::string& path, const std::string& format_name) {
  std::string name = format_name;
  if (name.empty()) {
    if (path == "-") fail("stdout", 0, "writing stdout needs a format (--format)");
    const std::size_t slash = path.find_last_of('/'), dot = path.find_last_of('.');
    if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) name = path.substr(dot + 1);
  }
  std::string known;
  for (const auto& n : image_format_names()) known += (known.empty() ? "" : ", ") + n;
  const ImageFormatEntry* format = find_image_format(name);
  if (!format) fail(path, 0, "unknown image format '" + name + "' (expected " + known + ")");
  return *format;
}

void write_image(const Image& image, const std::string& path, const std::string& format_name, ImageWriteInfo* info) {
  io::write_file_atomically(path, encode_image(image, image_format_for(path, format_name), path, info));
}

}  // namespace shadetool
