// png_encode.cpp: how long io/image_png.h's encoder takes on rendered frames at each compression
// level, against libpng's own default settings (zlib 6, adaptive filters) in the same run.
// Usage: bench_png_encode ROUNDS FRAME.png...   (frames made by bench/render/png_encode.sh)
// Prints per frame and level: median ms, bytes, and the median of the per-round ratios
// (libpng default time / this level's time), rounds interleaved so drift hits both alike.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <png.h>

#include <shadetool/io/image_png.h>

namespace {

void append(png_structp png, png_bytep data, png_size_t n) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), n);
}
void flush(png_structp) {}

// The reference: libpng with every setting at its default.
std::string libpng_default(int w, int h, const std::vector<std::uint8_t>& px) {
  std::string out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_set_write_fn(png, &out, append, flush);
  png_set_IHDR(png, info, png_uint_32(w), png_uint_32(h), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < h; ++y) png_write_row(png, const_cast<png_bytep>(px.data() + std::size_t(y) * std::size_t(w) * 3));
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return out;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: bench_png_encode ROUNDS FRAME.png...\n");
    return 2;
  }
  const int rounds = std::atoi(argv[1]);
  std::printf("| frame | level | median ms | bytes | libpng default / level (median of rounds) |\n|---|---|---|---|---|\n");
  for (int a = 2; a < argc; ++a) {
    png_image im{};
    im.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&im, argv[a])) return 1;
    im.format = PNG_FORMAT_RGB;
    std::vector<std::uint8_t> px(PNG_IMAGE_SIZE(im));
    if (!png_image_finish_read(&im, nullptr, px.data(), 0, nullptr)) return 1;
    const int w = int(im.width), h = int(im.height);
    const std::vector<int> levels = {0, 1, 2, 3, 6, 9};
    std::vector<std::vector<double>> ms(levels.size() + 1), ratio(levels.size());
    std::vector<std::size_t> bytes(levels.size() + 1);
    for (int r = 0; r < rounds; ++r) {
      auto t0 = std::chrono::steady_clock::now();
      bytes.back() = libpng_default(w, h, px).size();
      const double ref = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      ms.back().push_back(ref);
      for (std::size_t k = 0; k < levels.size(); ++k) {
        t0 = std::chrono::steady_clock::now();
        bytes[k] = shadetool::io::encode_png_srgb8(w, h, px, "bench", levels[k]).size();
        const double t = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        ms[k].push_back(t);
        ratio[k].push_back(ref / t);
      }
    }
    std::printf("| %s %dx%d | libpng default | %.1f | %zu | 1 |\n", argv[a], w, h, median(ms.back()), bytes.back());
    for (std::size_t k = 0; k < levels.size(); ++k)
      std::printf("| | %d | %.1f | %zu | %.2fx |\n", levels[k], median(ms[k]), bytes[k], median(ratio[k]));
  }
}
