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

// A set of bytes, as a type: the masks' tests are made of these.
template <char... Cs>
struct ByteSet {
  static constexpr bool contains(char c) { return ((c == Cs) || ...); }
};
using LineFeed = ByteSet<'\n'>;
using Spaces = ByteSet<' ', '\t', '\v', '\f', '\r'>;  // is_space's bytes (checked below)
using CrOrNul = ByteSet<'\r', '\0'>;

constexpr bool spaces_are_is_space() {
  for (int c = 0; c < 256; ++c)
    if (Spaces::contains(char(c)) != is_space(char(c))) return false;
  return true;
}
static_assert(spaces_are_is_space(), "the masks' spaces are is_space's bytes");

// The one byte test block_masks is made of, at one width: match(b, ByteSet<Cs...>{}), bit i set
// when byte i of the kBytes bytes from b is one of Cs (one compare per byte of the set, or-ed,
// one movemask: the movemasks, not the compares, bound the counting pass's speed). Pointers in,
// integers out: no vector value crosses a function (so no ABI warning), and the AVX2 lanes
// (target("avx2"), not always_inline: a generic function cannot inline them) are inlined only
// into count_avx2, which flattens its callees.
//
// Plain C++: 8 bytes in one 64-bit word (SWAR). A byte's test leaves its high bit (0x80) set;
// bits() gathers the 8 high bits into bits 0..7, byte i to bit i.
struct PlainLanes {
  static constexpr int kBytes = 8;
  static constexpr std::uint64_t kOnes = 0x0101010101010101u, kLow7 = 0x7f7f7f7f7f7f7f7fu, kHigh = 0x8080808080808080u;
  static inline std::uint64_t word(const char* b) {  // byte i of b in bits 8i..8i+7
    std::uint64_t w;
    std::memcpy(&w, b, 8);
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
    w = __builtin_bswap64(w);
#endif
    return w;
  }
  // 0x80 in each byte of w equal to c. A byte is zero iff adding 0x7f to its low 7 bits, or-ed
  // with itself, leaves the high bit clear (no carry crosses a byte: (x & 0x7f) + 0x7f <= 0xfe).
  static inline std::uint64_t equal_high(std::uint64_t w, char c) {
    const std::uint64_t x = w ^ (kOnes * static_cast<unsigned char>(c));
    return ~(((x & kLow7) + kLow7) | x) & kHigh;
  }
  // Flags 0x80 per byte -> bit i for byte i: each flag (0 or 1 at bit 8i) times the constant
  // lands at bit 56 + i, no two products overlapping.
  static inline std::uint64_t bits(std::uint64_t high) { return ((high >> 7) * 0x0102040810204080u) >> 56; }
  template <char... Cs>
  static inline std::uint64_t match(const char* b, ByteSet<Cs...>) {
    const std::uint64_t w = word(b);
    return bits((equal_high(w, Cs) | ...));
  }
};

#if defined(SHADETOOL_OBJ_COUNT_X86)
struct Sse2Lanes {
  static constexpr int kBytes = 16;
  template <char... Cs>
  static inline std::uint64_t match(const char* b, ByteSet<Cs...>) {
    const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(b));
    const __m128i m = (_mm_cmpeq_epi8(x, _mm_set1_epi8(Cs)) | ...);
    return unsigned(_mm_movemask_epi8(m));
  }
};

struct Avx2Lanes {
  static constexpr int kBytes = 32;
  template <char... Cs>
  __attribute__((target("avx2"))) static inline std::uint64_t match(const char* b, ByteSet<Cs...>) {
    const __m256i x = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(b));
    const __m256i m = (_mm256_cmpeq_epi8(x, _mm256_set1_epi8(Cs)) | ...);
    return unsigned(_mm256_movemask_epi8(m));
  }
};

// AVX-512BW: a whole block per compare, the result straight into a 64-bit mask register.
struct Avx512Lanes {
  static constexpr int kBytes = 64;
  template <char... Cs>
  __attribute__((target("avx512f,avx512bw"))) static inline std::uint64_t match(const char* b, ByteSet<Cs...>) {
    const __m512i x = _mm512_loadu_si512(b);
    return (_mm512_cmpeq_epi8_mask(x, _mm512_set1_epi8(Cs)) | ...);
  }
};
#endif

// The block's masks, 64 / kBytes lanes at a time: the one home of which byte goes into which mask.
template <class Lanes>
__attribute__((always_inline)) inline BlockMasks block_masks(const char* b) {
  BlockMasks m;
  for (int k = 0; k < 64 / Lanes::kBytes; ++k) {
    const char* const lane = b + Lanes::kBytes * k;
    const int at = Lanes::kBytes * k;
    m.lf |= Lanes::match(lane, LineFeed{}) << at;
    m.sp |= Lanes::match(lane, Spaces{}) << at;
    m.hash |= Lanes::match(lane, ByteSet<'#'>{}) << at;
    m.v |= Lanes::match(lane, ByteSet<'v'>{}) << at;
    m.f |= Lanes::match(lane, ByteSet<'f'>{}) << at;
    m.n |= Lanes::match(lane, ByteSet<'n'>{}) << at;
    m.t |= Lanes::match(lane, ByteSet<'t'>{}) << at;
    m.cr_or_nul |= Lanes::match(lane, CrOrNul{}) << at;
  }
  return m;
}

inline std::size_t ones(std::uint64_t x) { return std::size_t(__builtin_popcountll(x)); }

// The counts of [p, end) from block masks; false when a line needs the scalar rule (see the header).
// The counts of [p, end) from block masks; false when a line needs the scalar rule (see the header).
template <class Lanes>
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
    const BlockMasks m = block_masks<Lanes>(block);
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

template <class Lanes>
__attribute__((always_inline)) inline ObjCounts count_with(const char* p, const char* end) {
  ObjCounts c;
  if (!count_blocks<Lanes>(p, end, c)) return count_obj_statements_scalar(p, end);
  return c;
}

#if defined(SHADETOOL_OBJ_COUNT_X86)
// flatten: the mask code and the loop are inlined into this AVX2 function (an always_inline
// AVX2 callee cannot be inlined into the generic template).
__attribute__((target("avx2,popcnt"), flatten)) ObjCounts count_avx2(const char* p, const char* end) {
  return count_with<Avx2Lanes>(p, end);
}
__attribute__((target("avx512f,avx512bw,popcnt"), flatten)) ObjCounts count_avx512(const char* p, const char* end) {
  return count_with<Avx512Lanes>(p, end);
}
ObjCounts count_sse2(const char* p, const char* end) { return count_with<Sse2Lanes>(p, end); }
#endif

// Whether [p, end) holds a CR or a NUL byte: the CrOrNul masks of 256 bytes or-ed, one branch per
// 256 bytes; the last bytes one by one.
template <class Lanes>
__attribute__((always_inline)) inline bool any_cr_or_nul(const char* p, const char* const end) {
  const char* b = p;
  for (; end - b >= 256; b += 256) {
    std::uint64_t any = 0;
    for (int k = 0; k < 256; k += Lanes::kBytes) any |= Lanes::match(b + k, CrOrNul{});
    if (any != 0) return true;
  }
  for (; b < end; ++b)
    if (CrOrNul::contains(*b)) return true;
  return false;
}

#if defined(SHADETOOL_OBJ_COUNT_X86)
__attribute__((target("avx2"), flatten)) bool any_cr_or_nul_avx2(const char* p, const char* end) {
  return any_cr_or_nul<Avx2Lanes>(p, end);
}
__attribute__((target("avx512f,avx512bw"), flatten)) bool any_cr_or_nul_avx512(const char* p, const char* end) {
  return any_cr_or_nul<Avx512Lanes>(p, end);
}
#endif

}  // namespace

bool obj_text_has_cr_or_nul(const char* p, const char* end) {
#if defined(SHADETOOL_OBJ_COUNT_X86)
  static const bool avx2 = __builtin_cpu_supports("avx2");
  static const bool avx512 = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw");
  return avx512 ? any_cr_or_nul_avx512(p, end) : avx2 ? any_cr_or_nul_avx2(p, end) : any_cr_or_nul<Sse2Lanes>(p, end);
#else
  return any_cr_or_nul<PlainLanes>(p, end);
#endif
}

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
#if defined(SHADETOOL_OBJ_COUNT_X86)
  static const bool popcnt = __builtin_cpu_supports("popcnt");
  static const bool avx2 = popcnt && __builtin_cpu_supports("avx2");
  static const bool avx512 = popcnt && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw");
  switch (masks) {  // a width the CPU lacks: the widest below it
    case ObjCountMasks::Best:
    case ObjCountMasks::Avx512: return avx512 ? count_avx512(p, end) : avx2 ? count_avx2(p, end) : count_sse2(p, end);
    case ObjCountMasks::Avx2: return avx2 ? count_avx2(p, end) : count_sse2(p, end);
    case ObjCountMasks::Sse2: return count_sse2(p, end);
    case ObjCountMasks::Plain: return count_with<PlainLanes>(p, end);
  }
#else
  switch (masks) {
    case ObjCountMasks::Best:
    case ObjCountMasks::Avx512:
    case ObjCountMasks::Avx2:
    case ObjCountMasks::Sse2:
    case ObjCountMasks::Plain: return count_with<PlainLanes>(p, end);
  }
#endif
  return count_obj_statements_scalar(p, end);
}

}  // namespace shadetool::io
