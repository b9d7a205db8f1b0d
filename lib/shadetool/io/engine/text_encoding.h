// text_encoding.h: what text readers (OBJ, OFF, PLY headers, ascii STL) do before parsing.
//
//   refuse_utf16(bytes, name)    Error `NAME: UTF-16 text: save the file as UTF-8 or ASCII` when
//                                the bytes start with a UTF-16 byte-order mark (FF FE, FE FF) or
//                                show its NUL pattern (one of each two bytes NUL over the first
//                                64 bytes, where ASCII text in UTF-16 puts them). Mesh files are
//                                ASCII in practice; UTF-16 is refused by name, not as "binary data".
//   skip_utf8_bom(bytes)         the bytes after a UTF-8 byte-order mark (EF BB BF), if any.
//   LineEndings                  CR (classic Mac), LF and CRLF, mixed in any way, as LF: the
//                                bytes unchanged when they hold no CR (no copy), else a copy with
//                                each CRLF and each lone CR replaced by one LF, so line numbers in
//                                messages count lines as an editor shows them.
#pragma once

#include <cstddef>
#include <cstring>
#include <string>
#include <string_view>

#include <shadetool/core/error.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::io {

inline void refuse_utf16(std::string_view bytes, const std::string& name) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(bytes[i]); };
  bool utf16 = bytes.size() >= 2 && ((byte(0) == 0xFF && byte(1) == 0xFE) || (byte(0) == 0xFE && byte(1) == 0xFF));
  if (!utf16 && bytes.size() >= 8) {
    const std::size_t n = std::min<std::size_t>(bytes.size() & ~std::size_t(1), 64);
    std::size_t even_nul = 0, odd_nul = 0;
    for (std::size_t i = 0; i < n; i += 2) {
      even_nul += byte(i) == 0;
      odd_nul += byte(i + 1) == 0;
    }
    utf16 = (even_nul == n / 2 && odd_nul == 0) || (odd_nul == n / 2 && even_nul == 0);
  }
  if (utf16) fail(name, 0, "UTF-16 text: save the file as UTF-8 or ASCII");
}

inline std::string_view skip_utf8_bom(std::string_view bytes) {
  return bytes.substr(0, 3) == "\xEF\xBB\xBF" ? bytes.substr(3) : bytes;
}

class LineEndings {
 public:
  explicit LineEndings(std::string_view bytes) : view_(bytes) {
    // An empty view may have a null data(): memchr must not see it (UBSan: null argument).
    if (bytes.empty() || !std::memchr(bytes.data(), '\r', bytes.size())) return;
    copy_.reserve(bytes.size());
    for (std::size_t i = 0; i < bytes.size(); ++i) {
      if (bytes[i] != '\r') {
        copy_ += bytes[i];
        continue;
      }
      copy_ += '\n';
      if (i + 1 < bytes.size() && bytes[i + 1] == '\n') ++i;
    }
    view_ = copy_;
  }
  LineEndings(const LineEndings&) = delete;
  LineEndings& operator=(const LineEndings&) = delete;
  std::string_view lf() const { return view_; }

 private:
  std::string copy_;
  std::string_view view_;
};

}  // namespace shadetool::io
#pragma GCC visibility pop
