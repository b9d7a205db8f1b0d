// png_encode.cpp: how long io/image_png.h's encoder takes on rendered frames at each compression
// level, against libpng's own default settings (zlib 6, adaptive filters) in the same run, and
// where the floor of the default level lies (experiments, bench only):
//   zlib-only   the Up filter applied by hand and zlib's deflate (level 1, Z_RLE) called directly:
//               the same compressed stream without libpng, i.e. libpng's own overhead
//   none+rle    level 1, Z_RLE, filter None instead of Up
//   up+default  level 1, filter Up, zlib's default strategy instead of Z_RLE
//   copy        one memcpy of the pixels: the memory traffic no encoder can avoid
// Usage: bench_png_encode ROUNDS FRAME.png...   (frames made by bench/render/png_encode.sh)
// Prints per frame and variant: median thread-CPU ms, median wall ms, bytes, and the median of the
// per-round ratios (libpng default CPU time / this variant's), rounds interleaved (every variant
// once per round) so drift on the shared machine hits all alike.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

#include <png.h>
#include <zlib.h>

#include <shadetool/io/image_png.h>

namespace {

void append(png_structp png, png_bytep data, png_size_t n) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), n);
}
void flush(png_structp) {}

// libpng with the given settings (level < 0: every setting at libpng's default).
std::string libpng_encode(int w, int h, const std::vector<std::uint8_t>& px, int level, int filter, int strategy) {
  std::string out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_set_write_fn(png, &out, append, flush);
  if (level >= 0) {
    png_set_compression_level(png, level);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, filter);
    png_set_compression_strategy(png, strategy);
  }
  png_set_IHDR(png, info, png_uint_32(w), png_uint_32(h), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < h; ++y) png_write_row(png, const_cast<png_bytep>(px.data() + std::size_t(y) * std::size_t(w) * 3));
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return out;
}

// The IDAT payload of the default level without libpng: each row prefixed by filter byte 2 (Up),
// filtered into a row buffer, deflated by zlib level 1 with Z_RLE (chunk framing and CRCs left
// out: a few microseconds).
std::string zlib_only(int w, int h, const std::vector<std::uint8_t>& px) {
  const std::size_t stride = std::size_t(w) * 3;
  z_stream z{};
  deflateInit2(&z, 1, Z_DEFLATED, 15, 8, Z_RLE);
  std::string out(deflateBound(&z, uLong((stride + 1) * std::size_t(h))), '\0');
  z.next_out = reinterpret_cast<Bytef*>(&out[0]);
  z.avail_out = uInt(out.size());
  std::vector<std::uint8_t> row(stride + 1);
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* cur = px.data() + std::size_t(y) * stride;
    row[0] = 2;
    if (y == 0) {
      std::memcpy(row.data() + 1, cur, stride);
    } else {
      const std::uint8_t* up = cur - stride;
      for (std::size_t i = 0; i < stride; ++i) row[i + 1] = std::uint8_t(cur[i] - up[i]);
    }
    z.next_in = row.data();
    z.avail_in = uInt(row.size());
    deflate(&z, y + 1 == h ? Z_FINISH : Z_NO_FLUSH);
  }
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

double thread_cpu_ms() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}
double wall_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Variant {
  Variant(std::string n, std::function<std::size_t()> f) : name(std::move(n)), run(std::move(f)) {}
  std::string name;
  std::function<std::size_t()> run;  // returns the bytes written
  std::vector<double> cpu, wall, ratio;
  std::size_t bytes = 0;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: bench_png_encode ROUNDS FRAME.png...\n");
    return 2;
  }
  const int rounds = std::atoi(argv[1]);
  std::printf("| frame | encoder | median CPU ms | median wall ms | bytes | libpng default / this (CPU, median of rounds) |\n"
              "|---|---|---|---|---|---|\n");
  for (int a = 2; a < argc; ++a) {
    png_image im{};
    im.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&im, argv[a])) return 1;
    im.format = PNG_FORMAT_RGB;
    std::vector<std::uint8_t> px(PNG_IMAGE_SIZE(im));
    if (!png_image_finish_read(&im, nullptr, px.data(), 0, nullptr)) return 1;
    const int w = int(im.width), h = int(im.height);
    std::vector<Variant> v;
    v.emplace_back("libpng default (zlib 6, adaptive filters)", [&] { return libpng_encode(w, h, px, -1, 0, 0).size(); });
    for (int level : {0, 1, 2, 3, 6, 9})
      v.emplace_back("shadetool level " + std::to_string(level) + (level == 1 ? " (default)" : ""),
                   [&, level] { return shadetool::io::encode_png_srgb8(w, h, px, "bench", level).size(); });
    v.emplace_back("experiment: zlib-only (level 1, Up, Z_RLE, no libpng)", [&] { return zlib_only(w, h, px).size(); });
    v.emplace_back("experiment: level 1, filter None, Z_RLE",
                 [&] { return libpng_encode(w, h, px, 1, PNG_FILTER_NONE, Z_RLE).size(); });
    v.emplace_back("experiment: level 1, filter Up, default strategy",
                 [&] { return libpng_encode(w, h, px, 1, PNG_FILTER_UP, Z_DEFAULT_STRATEGY).size(); });
    v.emplace_back("experiment: copy (one memcpy of the pixels)", [&] {
                   std::vector<std::uint8_t> copy(px.size());
                   std::memcpy(copy.data(), px.data(), px.size());
                   return std::size_t(copy[px.size() / 2]) * 0 + copy.size();
                 });
    for (int r = 0; r < rounds + 1; ++r) {  // round 0 warms up
      for (Variant& x : v) {
        const double c0 = thread_cpu_ms(), t0 = wall_ms();
        x.bytes = x.run();
        const double c = thread_cpu_ms() - c0, t = wall_ms() - t0;
        if (r == 0) continue;
        x.cpu.push_back(c);
        x.wall.push_back(t);
        x.ratio.push_back(v[0].cpu.back() / c);
      }
    }
    std::printf("| %s %dx%d | | | | | |\n", argv[a], w, h);
    for (const Variant& x : v)
      std::printf("| | %s | %.1f | %.1f | %zu | %.2fx |\n", x.name.c_str(), median(x.cpu), median(x.wall), x.bytes,
                  median(x.ratio));
  }
}
