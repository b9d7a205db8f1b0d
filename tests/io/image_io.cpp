// Tests of io/image_io: the image format table and the PFM writer, checked against the PFM
// layout written out by hand (header, little-endian floats, rows bottom to top); the PNG encoder
// against libpng's reader.
#include <shadetool/io/image_io.h>
#include <shadetool/io/image_png.h>

#include <png.h>

#include <cstring>

#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;

namespace {

float float_at(const std::string& bytes, std::size_t offset) {
  std::uint32_t u = 0;
  for (int k = 3; k >= 0; --k) u = (u << 8) | static_cast<unsigned char>(bytes[offset + std::size_t(k)]);
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

}  // namespace

TEST_CASE("image formats: the table finds its entries by name and extension", "[image_io]") {
  REQUIRE(!image_formats().empty());
  for (const ImageFormatEntry& e : image_formats()) {
    CHECK(find_image_format(e.name) == &e);
    for (const char* ext : e.extensions) CHECK(find_image_format(ext) == &e);
  }
  CHECK(find_image_format("PFM") != nullptr);
  CHECK(find_image_format("obj") == nullptr);
}

TEST_CASE("PFM: header, little-endian floats, bottom row first; 8-bit as c/255; alpha left out with a note", "[image_io]") {
  Image img;
  img.width = 2;
  img.height = 2;
  img.channels = 3;
  img.pixel = Image::Pixel::F32;
  // top row: red, green; bottom row: blue, white (x 0.5)
  img.f32 = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5f, 0.5f, 0.5f};
  ImageWriteInfo info;
  const std::string pfm = encode_image(img, *find_image_format("pfm"), "t.pfm", &info);
  const std::string header = "PF\n2 2\n-1.0\n";
  REQUIRE(pfm.size() == header.size() + 12 * 4);
  CHECK(pfm.substr(0, header.size()) == header);
  const float expected[12] = {0, 0, 1, 0.5f, 0.5f, 0.5f, 1, 0, 0, 0, 1, 0};  // bottom row, then top
  for (int i = 0; i < 12; ++i) CHECK(float_at(pfm, header.size() + 4 * std::size_t(i)) == expected[i]);
  CHECK(info.notes.empty());

  Image rgba;
  rgba.width = 1;
  rgba.height = 1;
  rgba.channels = 4;
  rgba.u8 = {255, 51, 0, 128};
  ImageWriteInfo info2;
  const std::string p2 = encode_image(rgba, *find_image_format("pfm"), "t.pfm", &info2);
  const std::string h2 = "PF\n1 1\n-1.0\n";
  REQUIRE(p2.size() == h2.size() + 12);
  CHECK(float_at(p2, h2.size()) == 1.0f);
  CHECK(float_at(p2, h2.size() + 4) == 51.0f / 255.0f);
  REQUIRE(info2.notes.size() == 1);
  CHECK(info2.notes[0].find("alpha") != std::string::npos);
}

TEST_CASE("image writing refuses malformed images and NaN/Inf pixels; nothing is written", "[image_io]") {
  ScratchDir dir;
  Image img;
  img.width = 1;
  img.height = 1;
  img.pixel = Image::Pixel::F32;
  img.f32 = {0, 0};
  CHECK(error_of([&] { write_image(img, dir / "a.pfm", ""); }).find("holds 2 values, expected 3") != std::string::npos);
  img.f32 = {0, std::numeric_limits<float>::infinity(), 0};
  CHECK(error_of([&] { write_image(img, dir / "a.pfm", ""); }) == dir / "a.pfm" + ": 1 pixel values are NaN or infinite: nothing written");
  CHECK(!fs::exists(dir / "a.pfm"));
  img.f32 = {0, 1, 0};
  CHECK(error_of([&] { write_image(img, dir / "a.xyz", ""); }).find("unknown image format 'xyz'") != std::string::npos);
  write_image(img, dir / "a.pfm", "");
  CHECK(fs::file_size(dir / "a.pfm") == std::string("PF\n1 1\n-1.0\n").size() + 12);
}

// The PNG encoder's compression levels change the file's size and time, never its pixels: every
// level decodes (with libpng's own reader, the reference decoder) to the bytes that went in, on an
// image with flat runs, gradients and noise; a level outside 0..9 is refused.
TEST_CASE("Every PNG compression level decodes to the same pixels", "[io][png]") {
  const int w = 67, h = 41;
  std::vector<std::uint8_t> px(std::size_t(w) * h * 3);
  std::uint32_t state = 12345;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        state = state * 1664525u + 1013904223u;
        const std::size_t i = (std::size_t(y) * w + std::size_t(x)) * 3 + std::size_t(c);
        px[i] = y < 10 ? 40 : y < 25 ? std::uint8_t(x * 3 + c) : std::uint8_t(state >> 24);
      }
  std::size_t stored = 0, fast = 0;
  for (int level = 0; level <= 9; ++level) {
    const std::string png = shadetool::io::encode_png_srgb8(w, h, px, "t.png", level);
    png_image im{};
    im.version = PNG_IMAGE_VERSION;
    REQUIRE(png_image_begin_read_from_memory(&im, png.data(), png.size()));
    im.format = PNG_FORMAT_RGB;
    REQUIRE(im.width == unsigned(w));
    REQUIRE(im.height == unsigned(h));
    std::vector<std::uint8_t> back(PNG_IMAGE_SIZE(im));
    REQUIRE(png_image_finish_read(&im, nullptr, back.data(), 0, nullptr));
    CHECK(back == px);
    if (level == 0) stored = png.size();
    if (level == 1) fast = png.size();
  }
  CHECK(fast < stored);  // level 1 compresses; level 0 stores
  CHECK_THROWS_WITH(shadetool::io::encode_png_srgb8(w, h, px, "t.png", 10),
                    Catch::Contains("t.png: cannot encode PNG: compression level 10 is not in 0..9"));
}
