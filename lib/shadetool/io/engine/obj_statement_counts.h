// obj_statement_counts.h (engine, not installed): how many v, vt, vn, faces and face corners a run
// of OBJ lines holds, and its number of lines: the counting pass of the parallel OBJ reader
// (io/obj_format.cpp), which gives every chunk of lines its place in the mesh's arrays before the
// chunks are parsed in parallel.
//
// Inputs:  [p, end)  whole lines (p at a line start; end just after a line feed or the text's end),
//                    line endings already LF (io/engine/text_encoding.h)
// Output:  ObjCounts: v, vt, vn (lines whose keyword is that word), faces (`f` lines with at
//          least one corner), corners (the tokens of `f` lines after the keyword, up to the line
//          feed or a `#` that starts a token), lines (line feeds, plus one for a last line without
//          one); cr, nul: whether the run holds a CR byte, a NUL byte. Malformed lines are counted by their tokens; the parser refuses them with their
//          line number. The counts are a forecast the parser checks: a chunk whose parse finds other
//          counts is read again in one pass (obj_format.cpp), so a miscount costs time, never a
//          wrong mesh.
//
// count_obj_statements_scalar: the rule, byte by byte (the keyword as obj_keyword reads it; a
// face's tokens by byte class). count_obj_statements: the same counts from 64-byte blocks of
// bit masks (line feeds, spaces, `#`, the letters v f n t), popcounts instead of a loop per byte:
// a keyword is a letter at a line start followed by a space; an `f` line's span is found for all
// lines of a block at once by one subtraction (line feeds minus `f` line starts: each borrow runs
// from an `f` to the next line feed), its corners are the token starts in the span less the
// keyword. Lines the masks do not read as the rule does (leading spaces, a `#` token inside an
// `f` line, an `f` not followed by one space and a token) send the whole run to the scalar
// counter. AVX-512BW or AVX2 where the CPU has it (chosen at run time), SSE2 on other x86-64, plain C++ (8 bytes
// per 64-bit word) on other machines: one mask builder over one byte test (is the byte in a set:
// one movemask per set) at each width, so the same masks and the same counts.
#pragma once

#include <cstddef>
#include <string_view>

namespace shadetool::io {

struct ObjCounts {
  std::size_t v = 0, vt = 0, vn = 0, faces = 0, corners = 0, lines = 0;
  // Bytes the reader looks for before parsing, found in the same pass: a CR (the text's line
  // endings are converted to LF first, and counted again) and a NUL (binary data: refused).
  bool cr = false, nul = false;
};

// Which statement a line starts with; the keyword is the line's first token.
enum class ObjKeyword { V, Vn, Vt, F, Grouping, L, P, Other };

inline ObjKeyword obj_keyword(const char* kw, std::size_t kwlen) {
  if (kwlen == 1) {
    switch (kw[0]) {
      case 'v': return ObjKeyword::V;
      case 'f': return ObjKeyword::F;
      case 'o': case 'g': case 's': return ObjKeyword::Grouping;
      case 'l': return ObjKeyword::L;
      case 'p': return ObjKeyword::P;
    }
    return ObjKeyword::Other;
  }
  if (kwlen == 2 && kw[0] == 'v' && kw[1] == 'n') return ObjKeyword::Vn;
  if (kwlen == 2 && kw[0] == 'v' && kw[1] == 't') return ObjKeyword::Vt;
  const std::string_view k(kw, kwlen);
  if (k == "usemtl" || k == "mtllib") return ObjKeyword::Grouping;
  return ObjKeyword::Other;
}

ObjCounts count_obj_statements_scalar(const char* p, const char* end);

// Whether [p, end) holds a CR or a NUL byte (ObjCounts::cr || ObjCounts::nul without the counts):
// the one-pass reader's test before it converts line endings or refuses binary data, one scan of
// the same masks instead of a memchr for each byte.
bool obj_text_has_cr_or_nul(const char* p, const char* end);
ObjCounts count_obj_statements(const char* p, const char* end);

// Which mask code count_obj_statements uses: Best (the widest the CPU has: AVX-512BW, AVX2, SSE2 on
// x86-64; Plain elsewhere), or one forced, for tests that compare each with the scalar rule (a
// forced width the CPU lacks runs the widest below it).
enum class ObjCountMasks { Best, Sse2, Plain, Avx2, Avx512 };
ObjCounts count_obj_statements(const char* p, const char* end, ObjCountMasks masks);

}  // namespace shadetool::io
