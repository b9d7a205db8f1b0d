// Tests of io/byte_sink.h and of the writers streaming through it (issue 31 goal 5): the bytes a
// sink drains are the bytes appended, whatever its buffer size; every writer's output through a
// sink of 1, 7 or 4096 bytes is the output written to a string; a full device is an Error naming
// the output and leaves neither the output nor a temporary behind.
#include <fcntl.h>
#include <unistd.h>

#include <shadetool/io/atomic_write.h>
#include <shadetool/io/byte_sink.h>
#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;

namespace {

// Records every drain, to check that chunks are bounded by the buffer (or are one long append).
class RecordingSink final : public io::ByteSink {
 public:
  explicit RecordingSink(std::size_t buffer_bytes) : ByteSink(buffer_bytes) {}
  std::string bytes;
  std::vector<std::size_t> chunks;

 private:
  void drain(const char* b, std::size_t n) override {
    bytes.append(b, n);
    chunks.push_back(n);
  }
};

std::size_t files_in(const ScratchDir& d) {
  std::size_t n = 0;
  for (auto& e : std::filesystem::directory_iterator(d.path)) n += e.is_regular_file();
  return n;
}

}  // namespace

TEST_CASE("byte sink: what is drained is exactly what was appended, for any buffer size", "[byte_sink]") {
  for (const std::size_t size : {std::size_t(1), std::size_t(7), std::size_t(4096)}) {
    std::mt19937 rng{static_cast<std::uint32_t>(size)};
    RecordingSink sink(size);
    std::string expected;  // the same operations on a std::string: the truth
    std::size_t long_appends = 0;  // appends longer than the buffer: the only ones that may skip it
    for (int op = 0; op < 3000; ++op) {
      const unsigned kind = rng() % 4;
      if (kind == 0) {
        const char c = char('a' + rng() % 26);
        sink += c;
        expected += c;
      } else if (kind == 1) {
        std::string s(rng() % (op % 100 == 0 ? 3 * size + 10 : 20), ' ');  // sometimes longer than the buffer
        for (char& c : s) c = char(rng());
        sink.append(s.data(), s.size());
        expected += s;
        long_appends += s.size() > size;
      } else if (kind == 2) {
        const std::size_t n = rng() % 12;
        sink.append(n, '#');
        expected.append(n, '#');
      } else {
        sink += std::string_view("vn ");
        expected += "vn ";
        long_appends += 3 > size;
      }
      REQUIRE(sink.bytes_appended() == expected.size());
    }
    sink.flush();
    CHECK(sink.bytes == expected);
    // Bounded chunks: a drain longer than the buffer is (the tail of) one long append.
    std::size_t over = 0;
    for (std::size_t n : sink.chunks) over += n > size;
    CHECK(over <= long_appends);
    CHECK(sink.chunks.size() >= expected.size() / std::max<std::size_t>(size, 1) / 4);  // not one whole-output drain
  }
}

TEST_CASE("byte sink: an append as long as the buffer is drained without being buffered", "[byte_sink]") {
  RecordingSink sink(8);
  sink += std::string_view("abc");
  const std::string big(100, 'x');
  sink.append(big.data(), big.size());
  sink += 'z';
  sink.flush();
  CHECK(sink.bytes == "abc" + big + "z");
  // The buffer filled up to 8 (abc + 5 x), then 95 bytes straight through, then "z".
  CHECK(sink.chunks == std::vector<std::size_t>{8, 95, 1});
}

TEST_CASE("every writer streams the bytes it writes to a string, through any buffer size", "[byte_sink][writers]") {
  std::vector<std::pair<std::string, Mesh>> meshes;
  meshes.emplace_back("rich", rich_mesh());  // polygons, corner normals, texcoords, vertex and face colours
  meshes.emplace_back("materials.obj", read_mesh(data_path("materials.obj")));  // groups, usemtl
  meshes.emplace_back("torus_knot.ply", read_mesh(data_path("torus_knot.ply")));
  struct Out {
    Format format;
    bool binary;
    const char* name;
  };
  const Out outs[] = {{Format::Obj, false, "o.obj"}, {Format::Ply, true, "o.ply"},  {Format::Ply, false, "o.ply"},
                      {Format::Off, false, "o.off"}, {Format::Stl, true, "o.stl"},  {Format::Stl, false, "o.stl"},
                      {Format::Gltf, true, "o.glb"}, {Format::Gltf, false, "o.gltf"}};
  ScratchDir dir;
  for (const auto& [mesh_name, mesh] : meshes)
    for (const Out& o : outs) {
      WriteOptions wo;
      wo.format = o.format;
      wo.binary = o.binary;
      wo.name = o.name;
      WriteInfo whole_info;
      const std::string whole = write_mesh_to_memory(mesh, wo, &whole_info);
      REQUIRE(whole.size() > 100);
      for (const std::size_t size : {std::size_t(1), std::size_t(7), std::size_t(4096)}) {
        INFO(mesh_name << " -> " << o.name << (o.binary ? " binary" : " text") << ", buffer " << size);
        std::string streamed;
        io::StringSink sink(streamed, size);
        WriteInfo info;
        write_mesh_to_sink(mesh, wo, sink, &info);
        sink.flush();
        CHECK(streamed.size() == whole.size());
        CHECK(streamed == whole);
        CHECK(info.notes == whole_info.notes);
        CHECK(info.split_vertices == whole_info.split_vertices);
      }
      // And through write_mesh: a file descriptor, a temporary renamed into place.
      const std::string path = dir / (std::string("f.") + format_extension(o.format));
      write_mesh(mesh, path, wo);
      CHECK(read_file(path) == whole);
    }
}

TEST_CASE("a full device: an Error naming the output, nothing left behind", "[byte_sink][errors]") {
  const int fd = ::open("/dev/full", O_WRONLY);
  if (fd < 0) {
    WARN("no /dev/full here: the full-device case is not run");
    return;
  }
  {
    io::FdSink sink(fd, "stdout", 16);
    sink += std::string_view("0123456789");  // buffered: nothing written yet
    CHECK(error_of([&] { sink.append(std::string(40, 'x').data(), 40); }) == "stdout: cannot write: No space left on device");
  }
  ::close(fd);

  // A producer that fails after more than a buffer has reached the temporary (the disk filling up
  // looks the same to write_files_atomically: an Error out of the sink): no temporary, the
  // existing output untouched, the producer's Error passed on unchanged.
  ScratchDir dir;
  write_file(dir / "out.obj", "precious");
  const std::string err = error_of([&] {
    io::write_file_atomically(dir / "out.obj", [](io::ByteSink& s) {
      const std::string chunk(io::kSinkBufferBytes / 3, 'v');
      for (int i = 0; i < 5; ++i) s.append(chunk.data(), chunk.size());
      fail("out.obj", 0, "cannot write: No space left on device");
    });
  });
  CHECK(err == "out.obj: cannot write: No space left on device");
  CHECK(read_file(dir / "out.obj") == "precious");
  CHECK(files_in(dir) == 1);
}
