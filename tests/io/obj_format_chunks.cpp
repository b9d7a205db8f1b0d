// Tests of io/obj_format's parallel reading: a file cut into chunks of lines (ObjReadOptions::
// chunk_bytes forced small, 1 and 2 threads) reads to the same mesh, bit for bit, with the same
// notes and the same first error (file and line) as the one pass; relative (negative) indices and
// the statements whose meaning depends on order (o, g, s, usemtl, mtllib, colours, partial vt/vn)
// cross chunk boundaries.
#include <cstdio>
#include <cstring>
#include <random>

#include <tbb/task_arena.h>

#include <shadetool/files/mesh_files.h>
#include <shadetool/io/obj_format.h>

#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;

namespace {

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// Every array and field a reader fills, compared bit for bit (NaN included).
void require_same_mesh(const Mesh& a, const Mesh& b) {
  CHECK(same_bits(a.positions, b.positions));
  CHECK(a.face_start == b.face_start);
  CHECK(a.corner_vertex == b.corner_vertex);
  CHECK(same_bits(a.vertex_normals, b.vertex_normals));
  CHECK(same_bits(a.corner_normals, b.corner_normals));
  CHECK(a.corner_normal_index == b.corner_normal_index);
  CHECK(same_bits(a.face_normals, b.face_normals));
  CHECK(same_bits(a.texcoords, b.texcoords));
  CHECK(a.texcoord_dims == b.texcoord_dims);
  CHECK(a.corner_texcoord_index == b.corner_texcoord_index);
  CHECK(same_bits(a.vertex_colors, b.vertex_colors));
  CHECK(a.color_channels == b.color_channels);
  CHECK(a.colors_are_float == b.colors_are_float);
  CHECK(a.group_statements == b.group_statements);
  CHECK(a.face_group_run == b.face_group_run);
  CHECK(a.comments == b.comments);
  CHECK(a.precision == b.precision);
}

struct Read {
  Mesh mesh;
  std::vector<std::string> notes;
  std::string error;  // empty when the file was read
};

Read read_with(const std::string& bytes, std::size_t chunk_bytes, int threads, const std::string& name = "m.obj") {
  Read r;
  tbb::task_arena arena(threads);
  arena.execute([&] {
    try {
      ReadInfo info;
      io::ObjReadOptions options;
      options.chunk_bytes = chunk_bytes;
      r.mesh = io::read_obj(bytes, name, info, options);
      r.notes = info.notes;
    } catch (const Error& e) {
      r.error = e.what();
    }
  });
  return r;
}

// The one pass (one thread, no chunks) against chunks of every given size on 1 and 2 threads.
void require_chunk_independent(const std::string& bytes, const std::vector<std::size_t>& chunk_sizes,
                               const std::string& name = "m.obj") {
  const Read one = read_with(bytes, 0, 1, name);
  for (std::size_t chunk : chunk_sizes)
    for (int threads : {1, 2}) {
      INFO(name << ": chunks of " << chunk << " bytes, " << threads << " threads");
      const Read r = read_with(bytes, chunk, threads, name);
      REQUIRE(r.error == one.error);
      CHECK(r.notes == one.notes);
      if (one.error.empty()) require_same_mesh(r.mesh, one.mesh);
    }
}

}  // namespace

TEST_CASE("OBJ in chunks: every OBJ of data/ and the corpus reads the same as in one pass", "[obj][parallel][corpus]") {
  std::vector<std::string> paths;
  for (const char* dir : {SHADETOOL_SOURCE_DIR "/data", "/work/shared/corpus"}) {
    if (!fs::is_directory(dir)) {
      WARN(dir << " not here: its files skipped");
      continue;
    }
    for (const auto& e : fs::recursive_directory_iterator(dir))
      if (e.is_regular_file() && e.path().extension() == ".obj") paths.push_back(e.path().string());
  }
  REQUIRE(!paths.empty());
  for (const std::string& path : paths) {
    const std::string bytes = read_file(path);
    // Chunks of one line each on small files; a few sizes that cut lines anywhere on large ones.
    std::vector<std::size_t> sizes{61, 4093, std::size_t(1) << 16};
    if (bytes.size() < 200000) sizes.insert(sizes.begin(), {1, 7});
    require_chunk_independent(bytes, sizes, path);
  }
}

TEST_CASE("OBJ in chunks: negative indices, interleaved v and f, groups and colours across chunks keep the mesh written",
          "[obj][parallel]") {
  // The truth is the generator's own face list: faces use only vertices (vt, vn) defined before
  // them, written as positive or negative indices at random; grouping lines, comments, blank
  // lines, CRLF and unknown keywords fall between them.
  std::mt19937 rng(31);
  std::uniform_int_distribution<int> pick(0, 99);
  // Faces before the first grouping line: face_group_run gives them run 0 (none before them).
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf -1 -2 -3\n";
  std::vector<std::uint32_t> truth_corners{0, 1, 2, 2, 1, 0}, truth_start{0, 3, 6}, truth_tex(6, kNoTexcoord);
  std::size_t nv = 3, nt = 0;
  auto index = [&](std::size_t i, std::size_t count) {
    return pick(rng) < 50 ? std::to_string(i + 1) : std::to_string(std::int64_t(i) - std::int64_t(count));
  };
  for (int step = 0; step < 3000; ++step) {
    const int r = pick(rng);
    if (r < 30 || nv < 3) {
      text += "v " + std::to_string(pick(rng)) + "." + std::to_string(step) + " " + std::to_string(step) + " -0.5";
      if (nv % 7 == 3) text += " 0.25 0.5 1";  // some vertices coloured: the others white
      text += pick(rng) < 10 ? "\r\n" : "\n";
      ++nv;
    } else if (r < 40) {
      text += "vt 0." + std::to_string(step) + " 0.5\n";
      ++nt;
    } else if (r < 80) {
      const int size = 3 + pick(rng) % 3;
      text += "f";
      for (int k = 0; k < size; ++k) {
        const std::size_t v = std::size_t(pick(rng)) * nv / 100;
        truth_corners.push_back(std::uint32_t(v));
        text += " " + index(v, nv);
        if (nt > 0) {
          const std::size_t t = std::size_t(pick(rng)) * nt / 100;
          truth_tex.push_back(std::uint32_t(t));
          text += "/" + index(t, nt);
        } else {
          truth_tex.push_back(kNoTexcoord);
        }
      }
      text += pick(rng) < 5 ? " # comment\n" : "\n";
      truth_start.push_back(std::uint32_t(truth_corners.size()));
    } else if (r < 85) {
      text += "g part" + std::to_string(step) + "\n";
    } else if (r < 88) {
      text += "usemtl m" + std::to_string(step % 3) + "\ns " + std::to_string(step % 2) + "\n";
    } else if (r < 92) {
      text += "# a comment line\n\n   \n";
    } else if (r < 94) {
      text += "l 1 2\ncstype bezier\n";
    } else if (r < 96) {
      text += "f\n";  // an empty face: skipped, counted
    } else {
      text += "o object" + std::to_string(step) + "  \t\n";
    }
  }
  text += "g trailing\n";
  const Read one = read_with(text, 0, 1);
  REQUIRE(one.error.empty());
  CHECK(one.mesh.corner_vertex == truth_corners);
  CHECK(one.mesh.face_start == truth_start);
  CHECK(one.mesh.corner_texcoord_index == truth_tex);
  CHECK(one.mesh.has_vertex_colors());
  CHECK(one.mesh.has_groups());
  require_chunk_independent(text, {1, 2, 5, 17, 64, 333, 4096});
}

TEST_CASE("OBJ in chunks: vt and vn defined only after the first chunk's faces, colours only in a later chunk",
          "[obj][parallel]") {
  // The first faces name vt/vn while none is defined: ignored (counted); later faces resolve them.
  const std::string text =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1 2/1/1 3/1/1\n"
      "vt 0.5 0.5\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\nf -3/-1/-1 -2//-1 -1/-1\nf 1 2 3\n"
      "v 1 1 0 0.5 0.5 0.5\nf -1 -2 -3\n";
  const Read one = read_with(text, 0, 1);
  REQUIRE(one.error.empty());
  CHECK(one.mesh.corner_texcoord_index ==
        std::vector<std::uint32_t>{kNoTexcoord, kNoTexcoord, kNoTexcoord, 0, 0, 0, 0, kNoTexcoord, 0, kNoTexcoord,
                                   kNoTexcoord, kNoTexcoord, kNoTexcoord, kNoTexcoord, kNoTexcoord});
  CHECK(one.mesh.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 3, 2, 1});
  CHECK(one.mesh.vertex_colors == std::vector<float>{1, 1, 1, 1, 1, 1, 1, 1, 1, 0.5f, 0.5f, 0.5f});
  require_chunk_independent(text, {1, 3, 9, 20, 40, 80});
}

TEST_CASE("OBJ in chunks: the first error in the file is raised, with its line, whatever the chunks", "[obj][parallel][errors]") {
  std::string good;
  for (int i = 0; i < 40; ++i) good += "v " + std::to_string(i) + " 0 0\n";
  for (int i = 3; i <= 40; ++i) good += "f " + std::to_string(i - 2) + " " + std::to_string(i - 1) + " -1\n";
  const std::vector<std::string> bad{
      good + "f 1 2 41\n",                                  // range, in the last chunk
      good + "f -41 1 2\n",                                 // relative index before the first vertex
      "v 0 0 0\nv 1 0 0\nf 1 2 3\n" + good,                 // range error early, valid lines after
      good + "v 1 0x 0\n" + "f 1 2 99\n",                   // two errors: the first one wins
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n" + good + "f 0 1 2\n",
      good + "vt 0 0\nf 1/2 2/1 3/1\n",
      good + "f 1 2 \\\n 3\n",                              // `\` continuation: not OBJ we read (malformed)
      good + "vn 0 0\n",
      good + "f 1 2\n",
      "# nothing\r\n\r\n" + good + "v 1 2 e\r\n",
      good + std::string("v 0 0 0\0\n", 9),                 // a NUL byte
  };
  for (const std::string& text : bad) {
    const Read one = read_with(text, 0, 1);
    INFO(one.error);
    REQUIRE(!one.error.empty());
    REQUIRE(one.error.rfind("m.obj:", 0) == 0);
    require_chunk_independent(text, {1, 4, 16, 64, 200});
  }
  CHECK(read_with(bad[3], 16, 2).error == "m.obj:79: malformed number '0x'");
  CHECK(read_with(bad[0], 16, 2).error == "m.obj:79: vertex index 41 out of range (40 vertices defined so far)");
}

TEST_CASE("OBJ in chunks: a corner split by a space after its slash (`1/ 2`) reads as in one pass", "[obj][parallel]") {
  // The reader takes the vt across the space (one corner), the counting pass sees two tokens: the
  // chunked read notices the disagreement and reads the file in one pass.
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 1\n";
  for (int i = 0; i < 30; ++i) text += "f 1/1 2/2 3/1\n";
  text += "f -4/ -1 3/-1 -2/-1 -1/-1\n";
  const Read one = read_with(text, 0, 1);
  REQUIRE(one.error.empty());
  CHECK(one.mesh.face_size(30) == 4);
  CHECK(one.mesh.corner_texcoord_index[90] == 1);
  require_chunk_independent(text, {1, 16, 100});
}

TEST_CASE("OBJ in chunks: mutated files (bytes inserted, deleted, replaced) read the same or fail the same as in one pass",
          "[obj][parallel][errors]") {
  // Differential: the counting pass and the reading pass must agree on every line they accept,
  // and the first error must be the one pass's, on text no exporter writes.
  const std::vector<std::string> seeds{
      "v 0 0 0\nv 1 0 0\nv 0 1 0 1 0 0\nvt 0 0\nvn 0 0 1\ng a\nf 1/1/1 2/1/1 3/1/1\ns 1\nf -1 -2 -3 # c\nusemtl m\nf 1//1 2//1 3//1\n",
      "o q\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n\n# x\nvt 0.5 0.5 0.5\nf -4/-1 -3/-1 -2/-1 -1/-1\nl 1 2\nf\n"};
  const std::string alphabet = " \t\r\n/#-+0123456789.evfnto\\x";
  std::mt19937 rng(2026);
  for (int round = 0; round < 600; ++round) {
    std::string text = seeds[std::size_t(round) % seeds.size()];
    const int edits = 1 + int(rng() % 4);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = rng() % (text.size() + 1);
      const char c = alphabet[rng() % alphabet.size()];
      switch (rng() % 3) {
        case 0: text.insert(at, 1, c); break;
        case 1: if (at < text.size()) text.erase(at, 1); break;
        default: if (at < text.size()) text[at] = c; break;
      }
    }
    INFO("text: '" << text << "'");
    require_chunk_independent(text, {1, 3, 16});
  }
}

TEST_CASE("OBJ in chunks from a mapped file: pages released behind the parser do not change the mesh", "[obj][parallel]") {
  // read_mesh maps a file of 1 MiB or more; above 4 MiB on two threads it is read in chunks and
  // every chunk's pages are released once it is parsed (io/file_bytes.h release_mapped_pages).
  // The mesh must equal the one pass over the same text held in a string (no mapping); so must a
  // file whose last line makes the chunked read fall back to the one pass (`1/ 2`: counting and
  // reading split it differently) after chunks were parsed and their pages released.
  ScratchDir dir;
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> coord(-1, 1);
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 1\n";
  char line[128];
  while (text.size() < (std::size_t(6) << 20)) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\nf -1 -2 -3\n", coord(rng), coord(rng), coord(rng));
    text += line;
  }
  for (const bool fallback : {false, true}) {
    INFO((fallback ? "with" : "without") << " a `1/ 2` corner at the end");
    const std::string bytes = fallback ? text + "f 1/ 2 2/1 3/1\n" : text;
    const std::string path = dir / (fallback ? "fallback.obj" : "plain.obj");
    write_file(path, bytes);
    const Read one = read_with(bytes, 0, 1);
    REQUIRE(one.error.empty());
    for (int threads : {1, 2}) {
      INFO(threads << " threads");
      Mesh m;
      tbb::task_arena arena(threads);
      arena.execute([&] { m = read_mesh(path); });
      require_same_mesh(m, one.mesh);
    }
  }
}
