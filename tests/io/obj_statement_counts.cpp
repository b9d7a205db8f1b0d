// Tests of io/engine/obj_statement_counts: the counting pass of the parallel OBJ reader. The block
// (bit mask) counter in each of its builds (Best, AVX-512BW, AVX2, SSE2, plain C++) gives the counts of
// the byte-by-byte rule on every text, at every alignment; both give what a hand count and the
// parser itself (read_obj's mesh) find.
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <shadetool/io/engine/obj_statement_counts.h>
#include <shadetool/io/obj_format.h>

#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::io;

namespace {

bool same(const ObjCounts& a, const ObjCounts& b) {
  return a.v == b.v && a.vt == b.vt && a.vn == b.vn && a.faces == b.faces && a.corners == b.corners && a.lines == b.lines &&
         a.cr == b.cr && a.nul == b.nul;
}

std::string show(const ObjCounts& c) {
  return "v " + std::to_string(c.v) + " vt " + std::to_string(c.vt) + " vn " + std::to_string(c.vn) + " faces " +
         std::to_string(c.faces) + " corners " + std::to_string(c.corners) + " lines " + std::to_string(c.lines) +
         (c.cr ? " CR" : "") + (c.nul ? " NUL" : "");
}

void require_all_agree(const std::string& text, std::size_t begin, std::size_t end) {
  const char* p = text.data() + begin;
  const char* e = text.data() + end;
  const ObjCounts rule = count_obj_statements_scalar(p, e);
  for (ObjCountMasks m : {ObjCountMasks::Best, ObjCountMasks::Avx512, ObjCountMasks::Avx2, ObjCountMasks::Sse2, ObjCountMasks::Plain}) {
    const ObjCounts c = count_obj_statements(p, e, m);
    INFO("masks " << int(m) << ", bytes [" << begin << ", " << end << "): " << show(c) << " against the rule's " << show(rule));
    REQUIRE(same(c, rule));
  }
}

}  // namespace

TEST_CASE("OBJ statement counts: a hand count of keywords, empty faces, comments and a last line without a line feed",
          "[io][obj]") {
  const std::string text =
      "# header f 1 2 3\n"
      "v 1 2 3\n"
      "vn 0 0 1\n"
      "vt 0 0\n"
      "vtx 1 2\n"        // not a keyword the counter counts
      "f 1 2 3 4\n"      // 4 corners
      "f\n"              // no corner: not a face
      "\n"
      "  f 1 2 3 # c\n"  // leading spaces, a comment after 3 corners
      "f 1/2/3 4//5 6/7 8\n"
      "fo 1 2 3\n"
      "f 1 2 3";  // 3 corners, no line feed
  ObjCounts want;
  want.v = 1;
  want.vn = 1;
  want.vt = 1;
  want.faces = 4;
  want.corners = 4 + 3 + 4 + 3;
  want.lines = 12;
  const ObjCounts rule = count_obj_statements_scalar(text.data(), text.data() + text.size());
  INFO(show(rule));
  CHECK(same(rule, want));
  for (ObjCountMasks m : {ObjCountMasks::Best, ObjCountMasks::Avx512, ObjCountMasks::Avx2, ObjCountMasks::Sse2, ObjCountMasks::Plain}) {
    const ObjCounts c = count_obj_statements(text.data(), text.data() + text.size(), m);
    INFO(show(c));
    CHECK(same(c, want));
  }
}

TEST_CASE("OBJ statement counts: the mask counter gives the byte rule's counts on random lines at every alignment",
          "[io][obj]") {
  const std::vector<std::string> kinds = {
      "v 1 2 3", "v -0.5 1e-3 2.25 0.1 0.2 0.3", "vn 0 0 1", "vt 0.5 0.5", "vt 1", "f 1 2 3", "f 1/1/1 2/2/2 3/3/3 4/4/4",
      "f -1 -2 -3", "f 1 2 3 # comment", "f 1 2 3#x", "f 1 2 3 #x", "  v 1 2 3", "\tf 1 2 3", "f", "f ", "f  1 2 3",
      "f\t1\t2\t3", "# v 1 2 3", "", "   ", "g group", "usemtl m", "vtx 1", "fo 1 2", "v\t1 2 3", "vn\t1 2 3",
      "f 1 2 3   ", "f 1 2 3\r", "o object", "s 1", "l 1 2", "p 1", "v", "vn", "vt",
      "f 10/20/30 11/21/31 12/22/32 13/23/33 14/24/34 15/25/35 16/26/36 17/27/37 18/28/38 19/29/39 20/30/40",
      "v 0.123456789012345 0.98765432109876 -0.55555555555555555 1 1 1", std::string("v 1 2\0 3", 9), "v 1\r2 3"};
  std::mt19937 rng(31);
  for (int round = 0; round < 60; ++round) {
    // Mostly well-formed lines (the mask path), in some rounds any kind (the scalar fallback).
    const bool plain_only = round % 3 != 0;
    std::string text;
    const int lines = 1 + int(rng() % 400);
    for (int i = 0; i < lines; ++i) {
      std::size_t k = rng() % kinds.size();
      if (plain_only) k = std::vector<std::size_t>{0, 1, 2, 3, 4, 5, 6, 7, 18, 20, 21, 22, 23, 24, 25, 26, 35, 36}[rng() % 18];
      text += kinds[k];
      if (i + 1 < lines || rng() % 2) text += '\n';
    }
    // Runs of whole lines starting at every offset in the first 70 bytes' line starts, ending at
    // a line feed or the text's end.
    std::vector<std::size_t> starts{0};
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n' && i + 1 < text.size()) starts.push_back(i + 1);
    for (std::size_t s = 0; s < starts.size() && s < 40; ++s) {
      require_all_agree(text, starts[s], text.size());
      const std::size_t cut = starts[s] + rng() % (text.size() - starts[s] + 1);
      const std::size_t lf = text.find('\n', cut);
      require_all_agree(text, starts[s], lf == std::string::npos ? text.size() : lf + 1);
    }
  }
}

TEST_CASE("OBJ statement counts: every byte value is classed by the masks as the byte rule classes it, in every lane",
          "[io][obj]") {
  // Each byte value inside a face's token list, after each keyword and before a corner, shifted
  // through the 64 positions of a block by a comment line of 1..64 bytes: a byte the masks class
  // otherwise than is_space (a high byte such as 0x89 = 0x80 | tab taken for a space, a byte
  // taken for a line feed) changes the corner, keyword or line counts.
  for (int c = 0; c < 256; ++c) {
    const std::string b(1, char(c));
    const std::string lines = "f 1" + b + "2 3\n" + "v" + b + "1 2 3\n" + "vn" + b + "0 0 1\n" + "vt" + b + "0 0\n" + "f" + b + "1 2\n" +
                              "f 1 2 3" + b + "\n";
    for (int k = 0; k < 64; ++k) {
      const std::string text = "#" + std::string(std::size_t(k), 'x') + "\n" + lines;
      require_all_agree(text, 0, text.size());
    }
  }
}

TEST_CASE("OBJ statement counts: the counts are what the parser reads from the same text", "[io][obj]") {
  std::string text;
  std::mt19937 rng(7);
  std::size_t v = 0;
  for (int i = 0; i < 3000; ++i) {
    if (v < 4 || rng() % 3 == 0) {
      text += "v " + std::to_string(rng() % 100) + " " + std::to_string(rng() % 100) + ".5 -" + std::to_string(rng() % 7) + "\n";
      ++v;
      continue;
    }
    const int corners = 3 + int(rng() % 5);
    text += "f";
    for (int c = 0; c < corners; ++c) text += (rng() % 2 ? " -" : " ") + std::to_string(1 + rng() % 4);
    text += rng() % 5 == 0 ? " # note\n" : "\n";
  }
  ReadInfo info;
  const Mesh mesh = read_obj(text, "counts.obj", info);
  const ObjCounts c = count_obj_statements(text.data(), text.data() + text.size());
  CHECK(c.v == mesh.num_vertices());
  CHECK(c.faces == mesh.num_faces());
  CHECK(c.corners == mesh.num_corners());
  CHECK(c.lines == 3000);
}

TEST_CASE("OBJ statement counts: obj_text_has_cr_or_nul finds a CR or a NUL at every position, as memchr does",
          "[io][obj]") {
  // A text of 700 bytes (256-byte steps and a tail) with at most one CR or NUL, at every position
  // and every starting offset: the answer must be memchr's.
  std::string text;
  for (int i = 0; text.size() < 700; ++i) text += i % 2 ? "f 1 2 3\n" : "v 1.5 -2 3e4\n";
  for (std::size_t begin : {std::size_t(0), std::size_t(1), std::size_t(63), std::size_t(200)}) {
    const char* b = text.data() + begin;
    const char* e = text.data() + text.size();
    CHECK(!obj_text_has_cr_or_nul(b, e));
    for (char c : {'\r', '\0'}) {
      for (std::size_t at = begin; at < text.size(); ++at) {
        std::string t = text;
        t[at] = c;
        const char* tb = t.data() + begin;
        const char* te = t.data() + t.size();
        const bool want = std::memchr(tb, '\r', std::size_t(te - tb)) || std::memchr(tb, '\0', std::size_t(te - tb));
        INFO("byte " << int(c) << " at " << at << ", run from " << begin);
        REQUIRE(obj_text_has_cr_or_nul(tb, te) == want);
      }
    }
  }
}
