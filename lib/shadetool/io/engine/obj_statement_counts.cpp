// obj_statement_counts.cpp: the counting pass of the parallel OBJ reader, by bytes and by masks.
#include <shadetool/io/engine/obj_statement_counts.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>

#include <shadetool/io/engine/text_parse.h>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define SHADETOOL_OBJ_COUNT_X86 1
#endif

namespace shadetool::io {

namespace {

// What the scalar counter tells apart: is_space's bytes, the line feed, `#`, anything else.
enum class CharClass : unsigned char { Other, Space, LineFeed, Hash };
constexpr std::array<CharClass, 256> make_char_class() {
  std::array<CharClass, 256> t{};
  for (int c = 0; c < 256; ++c)
    t[std::size_t(c)] = c == '\n' ? CharClass::LineFeed : c == '#' ? CharClass::Hash : is_space(char(c)) ? CharClass::Space : CharClass::Other;
  return t;
}
constexpr std::array<CharClass, 256> kCharClass = make_char_class();

// One 64-byte block as bit masks, bit i for byte i: line feeds, is_space's bytes (not the line
// feed), `#`, the letters the keywords v, vn, vt, f are made of, and CR or NUL bytes.
struct BlockMasks {
  std::uint64_t lf = 0, sp = 0, hash = 0, v = 0, f = 0, n = 0, t = 0, cr_or_nul = 0;
};

struct PlainMasks {
  static inline BlockMasks of(const char* b) {
    BlockMasks m;
    for (int i = 0; i < 64; ++i) {
      const char c = b[i];
      const std::uint64_t bit = std::uint64_t(1) << i;
      m.lf |= c == '\n' ? bit : 0;
      m.sp |= is_space(c) ? bit : 0;
      m.hash |= c == '#' ? bit : 0;
      m.v |= c == 'v' ? bit : 0;
      m.f |= c == 'f' ? bit : 0;
      m.n |= c == 'n' ? bit : 0;
      m.t |= c == 't' ? bit : 0;
      m.cr_or_nul |= c == '\r' || c == '\0' ? bit : 0;
    }
    return m;
  }
};

#if defined(SHADETOOL_OBJ_COUNT_X86)
// is_space's bytes: ' ' and 9..13 except the line feed (10).
struct Sse2Masks {
  __attribute__((always_inline)) static inline BlockMasks of(const char* b) {
    BlockMasks m;
    for (int k = 0; k < 4; ++k) {
      const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(b + 16 * k));
      auto eq = [&](char c) {
        return std::uint64_t(unsigned(_mm_movemask_epi8(_mm_cmpeq_epi8(x, _mm_set1_epi8(c))))) << (16 * k);
      };
      const __m128i d = _mm_sub_epi8(x, _mm_set1_epi8(9));
      const std::uint64_t ctl = std::uint64_t(unsigned(_mm_movemask_epi8(_mm_cmpeq_epi8(_mm_min_epu8(d, _mm_set1_epi8(4)), d))))
                                << (16 * k);
      const std::uint64_t lf = eq('\n');
      m.lf |= lf;
      m.sp |= eq(' ') | (ctl & ~lf);
      m.hash |= eq('#');
      m.v |= eq('v');
      m.f |= eq('f');
      m.n |= eq('n');
      m.t |= eq('t');
      m.cr_or_nul |= eq('\r') | eq('\0');
    }
    return m;
  }
};

struct Avx2Masks {
  __attribute__((target("avx2"))) static inline BlockMasks of(const char* b) {
    BlockMasks m;
    for (int k = 0; k < 2; ++k) {
      const __m256i x = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(b + 32 * k));
      auto eq = [&](char c) __attribute__((target("avx2"))) {
        return std::uint64_t(unsigned(_mm256_movemask_epi8(_mm256_cmpeq_epi8(x, _mm256_set1_epi8(c))))) << (32 * k);
      };
      const __m256i d = _mm256_sub_epi8(x, _mm256_set1_epi8(9));
      const std::uint64_t ctl =
          std::uint64_t(unsigned(_mm256_movemask_epi8(_mm256_cmpeq_epi8(_mm256_min_epu8(d, _mm256_set1_epi8(4)), d))))
          << (32 * k);
      const std::uint64_t lf = eq('\n');
      m.lf |= lf;
      m.sp |= eq(' ') | (ctl & ~lf);
      m.hash |= eq('#');
      m.v |= eq('v');
      m.f |= eq('f');
      m.n |= eq('n');
      m.t |= eq('t');
      m.cr_or_nul |= eq('\r') | eq('\0');
    }
    return m;
  }
};
#endif

inline std::size_t ones(std::uint64_t x) { return std::size_t(__builtin_popcountll(x)); }

// The counts of [p, end) from block masks; false when a line needs the scalar rule (see the header).
template <class Masks>
__attribute__((always_inline)) inline bool count_blocks(const char* p, const char* const end, ObjCounts& c) {
  std::uint64_t line_start_in = 1;  // the run starts at a line start, as after a separator
  std::uint64_t sep_in = 1;
  std::uint64_t span_in = 0;        // an `f` line's span continues from the block before
  std::uint64_t odd = 0, cr_or_nul = 0;
  char pad[64];
  for (const char* b = p; b < end; b += 64) {
    const std::size_t left = std::size_t(end - b);
    const char* block = b;
    if (left < 64) {  // the last block, padded with spaces: no keyword, token or line feed
      std::memcpy(pad, b, left);
      std::memset(pad + left, ' ', 64 - left);
      block = pad;
    }
    const BlockMasks m = Masks::of(block);
    // The two bytes after the block (a keyword's next bytes), spaces past the end.
    const char c64 = left > 64 ? b[64] : ' ', c65 = left > 65 ? b[65] : ' ';
    const std::uint64_t s64 = is_space_or_newline(c64), s65 = is_space_or_newline(c65);
    const std::uint64_t lf = m.lf, sep = m.sp | m.lf;
    const std::uint64_t valid = left >= 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << left) - 1;
    // Bit i of `x_next` is x of byte i + 1 (i + 2 for x_next2).
    const std::uint64_t sep_next = (sep >> 1) | (s64 << 63);
    const std::uint64_t sep_next2 = (sep >> 2) | (s64 << 62) | (s65 << 63);
    const std::uint64_t n_next = (m.n >> 1) | (std::uint64_t(c64 == 'n') << 63);
    const std::uint64_t t_next = (m.t >> 1) | (std::uint64_t(c64 == 't') << 63);
    const std::uint64_t lf_next = (lf >> 1) | (std::uint64_t(c64 == '\n') << 63);
    const std::uint64_t line_start = ((lf << 1) | line_start_in) & valid;
    line_start_in = lf >> 63;
    const std::uint64_t token = ~sep & ((sep << 1) | sep_in);
    sep_in = sep >> 63;
    const std::uint64_t token_next2 = (token >> 2) | ((s64 ? 0 : sep >> 63) << 62) | ((s65 ? 0 : s64) << 63);
    const std::uint64_t v = line_start & m.v;
    const std::uint64_t f = line_start & m.f & sep_next;
    c.v += ones(v & sep_next);
    c.vn += ones(v & n_next & sep_next2);
    c.vt += ones(v & t_next & sep_next2);
    // Spans of `f` lines: subtracting a line's `f` bit from the line feed that ends it sets the
    // bits from the `f` up to (not including) the line feed; a borrow out of bit 63 carries the
    // span into the next block.
    std::uint64_t minus_f, minus_in;
    const bool borrow_f = __builtin_sub_overflow(lf, f, &minus_f);
    const bool borrow_in = __builtin_sub_overflow(minus_f, span_in, &minus_in);
    span_in = borrow_f || borrow_in;
    const std::uint64_t span = minus_in & ~lf;
    c.faces += ones(f);
    c.corners += ones(token & span) - ones(f);
    c.lines += ones(lf);
    // Lines the masks do not read as the rule does: leading spaces, a `#` token in an `f` line,
    // an `f` whose next bytes are not a space and a token (`f` alone, `f  1`, `f\t`).
    cr_or_nul |= m.cr_or_nul;
    odd |= (line_start & m.sp) | (token & span & m.hash) | (f & ~token_next2) | (f & lf_next);
  }
  if (p < end && end[-1] != '\n') ++c.lines;
  if (cr_or_nul != 0) {  // rare: which of the two, by the byte rule
    c.cr = std::memchr(p, '\r', std::size_t(end - p)) != nullptr;
    c.nul = std::memchr(p, '\0', std::size_t(end - p)) != nullptr;
  }
  return odd == 0;
}

template <class Masks>
__attribute__((always_inline)) inline ObjCounts count_with(const char* p, const char* end) {
  ObjCounts c;
  if (!count_blocks<Masks>(p, end, c)) return count_obj_statements_scalar(p, end);
  return c;
}

#if defined(SHADETOOL_OBJ_COUNT_X86)
// flatten: the mask code and the loop are inlined into this AVX2 function (an always_inline
// AVX2 callee cannot be inlined into the generic template).
__attribute__((target("avx2,popcnt"), flatten)) ObjCounts count_avx2(const char* p, const char* end) {
  return count_with<Avx2Masks>(p, end);
}
ObjCounts count_sse2(const char* p, const char* end) { return count_with<Sse2Masks>(p, end); }
#endif

}  // namespace

ObjCounts count_obj_statements_scalar(const char* p, const char* const end) {
  ObjCounts c;
  c.cr = std::memchr(p, '\r', std::size_t(end - p)) != nullptr;
  c.nul = std::memchr(p, '\0', std::size_t(end - p)) != nullptr;
  auto line_feed = [end](const char* q) {
    if (q == end || *q == '\n') return q;
    const void* lf = std::memchr(q, '\n', std::size_t(end - q));
    return lf ? static_cast<const char*>(lf) : end;
  };
  while (p < end) {
    ++c.lines;
    const char* q = skip_spaces(p, end);
    if (q != end && *q != '\n' && *q != '#') {
      const char* kw = q;
      while (q < end && !is_space_or_newline(*q)) ++q;
      switch (obj_keyword(kw, std::size_t(q - kw))) {
        case ObjKeyword::V: ++c.v; break;
        case ObjKeyword::Vn: ++c.vn; break;
        case ObjKeyword::Vt: ++c.vt; break;
        case ObjKeyword::F: {  // its tokens up to the line feed or a comment
          // A token starts where a byte that is not a space follows a space; a `#` starting a
          // token starts a comment (the parser's rule).
          std::size_t n = 0;
          bool after_space = true;
          for (; q < end; ++q) {
            const CharClass k = kCharClass[static_cast<unsigned char>(*q)];
            if (k == CharClass::LineFeed || (k == CharClass::Hash && after_space)) break;
            n += after_space && k != CharClass::Space;
            after_space = k == CharClass::Space;
          }
          if (n > 0) {
            ++c.faces;
            c.corners += n;
          }
          break;
        }
        case ObjKeyword::Grouping:
        case ObjKeyword::L:
        case ObjKeyword::P:
        case ObjKeyword::Other: break;
      }
    }
    const char* eol = line_feed(q);
    if (eol == end) break;
    p = eol + 1;
  }
  return c;
}

ObjCounts count_obj_statements(const char* p, const char* end) { return count_obj_statements(p, end, ObjCountMasks::Best); }

ObjCounts count_obj_statements(const char* p, const char* end, ObjCountMasks masks) {
  switch (masks) {
    case ObjCountMasks::Best: {
#if defined(SHADETOOL_OBJ_COUNT_X86)
      static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("popcnt");
      return avx2 ? count_avx2(p, end) : count_sse2(p, end);
#else
      return count_with<PlainMasks>(p, end);
#endif
    }
    case ObjCountMasks::Sse2:
#if defined(SHADETOOL_OBJ_COUNT_X86)
      return count_sse2(p, end);
#else
      return count_with<PlainMasks>(p, end);
#endif
    case ObjCountMasks::Plain: return count_with<PlainMasks>(p, end);
  }
  return count_obj_statements_scalar(p, end);
}

}  // namespace shadetool::io
