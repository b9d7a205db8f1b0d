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
      good + "f 1 2 \\ 3\n",                                // a `\` not ending its line (malformed)
      good + "f 1 2 \\\n 99\n",                             // range, on a continued line
      good + "vn 0 0\n",
      good + "f 1 2 /3\n",
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

TEST_CASE("OBJ in chunks: a corner with an empty field before a space (`1/ 2`) is two corners, in one pass and in chunks",
          "[obj][parallel]") {
  // An empty vt field is absent (tinyobjloader, assimp; trimesh splits the line at spaces): `-4/`
  // is a corner without vt and `-1` the next corner, as the counting pass's tokens say.
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 1\n";
  for (int i = 0; i < 30; ++i) text += "f 1/1 2/2 3/1\n";
  text += "f -4/ -1 3/-1 -2/-1 -1/-1\n";
  const Read one = read_with(text, 0, 1);
  REQUIRE(one.error.empty());
  CHECK(one.mesh.face_size(30) == 5);
  CHECK(std::vector<std::uint32_t>(one.mesh.corner_vertex.begin() + 90, one.mesh.corner_vertex.end()) ==
        std::vector<std::uint32_t>{0, 3, 2, 2, 3});
  CHECK(std::vector<std::uint32_t>(one.mesh.corner_texcoord_index.begin() + 90, one.mesh.corner_texcoord_index.end()) ==
        std::vector<std::uint32_t>{kNoTexcoord, kNoTexcoord, 1, 1, 1});
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
  // file whose last line makes the chunked read fall back to the one pass (a face continued on the
  // next line: the counting pass counts its `\` as a corner and not the next line's) after chunks
  // were parsed and their pages released.
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
    INFO((fallback ? "with" : "without") << " a continued face at the end");
    const std::string bytes = fallback ? text + "f 1 \\\n 2/1 3/1\n" : text;
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

TEST_CASE("OBJ in chunks: statements continued by `\\` read the same in chunks of any size and on 2 threads above 4 MiB",
          "[obj][parallel][xcorpus]") {
  // v lines continued after their second coordinate, faces after their first corner, grouping
  // lines and comments continued: a chunk cut after a line ending in `\` would read the rest of
  // the statement as a line of its own (a `v` of 2 values is an error), so the splitter must never
  // cut there; the counting pass miscounts continued faces, and the read falls back to one pass.
  // The truth: the same text with the continuations joined, read in one pass.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coord(-1, 1);
  auto make = [&](std::size_t bytes, bool continue_faces) {
    std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    char line[160];
    for (std::size_t i = 0; text.size() < bytes; ++i) {
      const bool cont = i % 3 == 0;
      std::snprintf(line, sizeof line, cont ? "v %.9g %.9g \\\n  %.9g\n" : "v %.9g %.9g %.9g\n", coord(rng), coord(rng), coord(rng));
      text += line;
      text += continue_faces && i % 5 == 0 ? "f -1 \\\n-2 -3\n" : "f -1 -2 -3\n";
      if (i % 97 == 0) text += "g part \\\n  " + std::to_string(i) + "\n# note \\\n  more\n";
    }
    return text;
  };
  auto joined = [](const std::string& text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
      if (text[i] == '\\' && i + 1 < text.size() && text[i + 1] == '\n') {
        while (!out.empty() && out.back() == ' ') out.pop_back();
        out += ' ';
        for (++i; i + 1 < text.size() && text[i + 1] == ' ';) ++i;
        continue;
      }
      out += text[i];
    }
    return out;
  };
  {
    const std::string small = make(20000, true);
    require_chunk_independent(small, {1, 7, 61, 4093});
    const Read one = read_with(small, 0, 1), truth = read_with(joined(small), 0, 1);
    REQUIRE(one.error.empty());
    require_same_mesh(one.mesh, truth.mesh);
  }
  for (const bool continue_faces : {false, true}) {
    INFO((continue_faces ? "faces continued (falls back to one pass)" : "only v and grouping lines continued (read in chunks)"));
    const std::string big = make(std::size_t(9) << 19, continue_faces);  // 4.5 MiB: chunks on 2 threads
    const Read one = read_with(big, 0, 1), two = read_with(big, 0, 2), truth = read_with(joined(big), 0, 1);
    REQUIRE(one.error.empty());
    REQUIRE(two.error.empty());
    require_same_mesh(two.mesh, one.mesh);
    require_same_mesh(one.mesh, truth.mesh);
    CHECK(two.notes == one.notes);
  }
}

TEST_CASE("OBJ in chunks: empty vt/vn fields and faces of 1 or 2 vertices read the same in chunks", "[obj][parallel][xcorpus]") {
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";
  for (int i = 0; i < 300; ++i) {
    text += i % 4 == 0 ? "f 1/1/ 2/1/ 3/1/\n" : i % 4 == 1 ? "f 1// 2//1\n" : i % 4 == 2 ? "f 1/ 2/ 3/\n" : "f -3//1 -2// -1/1/1\n";
    if (i % 50 == 0) text += "f 2\n";
  }
  require_chunk_independent(text, {1, 7, 61, 997});
}
