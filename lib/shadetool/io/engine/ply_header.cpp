// ply_header.cpp: the PLY header (see ply_header.h).
#include <shadetool/io/engine/ply_header.h>

#include <cstdint>
#include <cstring>

#include <shadetool/core/error.h>
#include <shadetool/io/engine/text_encoding.h>
#include <shadetool/io/engine/text_parse.h>

namespace shadetool::io::ply {

PlyHeader parse_ply_header(std::string_view bytes, const std::string& name, ReadInfo& info) {
  refuse_utf16(bytes, name);
  const char* p = bytes.data();
  const char* const end = p + bytes.size();
  std::size_t line = 0;
  // Header lines end in LF (CRLF: the CR is trailing space), or, when the magic line is `ply`
  // followed by a lone CR, in CR (classic Mac; Rhinoceros 6's PLY exporter, draco's
  // testdata/Box.ply): assimp and draco read those. A binary body then starts right after
  // `end_header` and its CR, so no LF is eaten from it. Decided once, from the magic line, so
  // every file that reads with LF lines reads the same.
  const bool cr_lines = bytes.size() > 4 && bytes.substr(0, 4) == "ply\r" && bytes[4] != '\n' && bytes[4] != '\r';
  const char eol_char = cr_lines ? '\r' : '\n';

  auto next_line = [&](std::string_view& out) -> bool {
    if (p >= end) return false;
    const char* eol = static_cast<const char*>(std::memchr(p, eol_char, std::size_t(end - p)));
    const char* stop = eol ? eol : end;
    const char* e = stop;
    while (e > p && is_space(e[-1])) --e;
    out = std::string_view(p, std::size_t(e - p));
    p = eol ? eol + 1 : end;
    ++line;
    return true;
  };
  auto split = [](std::string_view s) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < s.size()) {
      while (i < s.size() && is_space(s[i])) ++i;
      const std::size_t b = i;
      while (i < s.size() && !is_space(s[i])) ++i;
      if (i > b) words.push_back(s.substr(b, i - b));
    }
    return words;
  };

  std::string_view l;
  if (!next_line(l) || l != "ply") fail(name, 1, "not a PLY file (first line is not 'ply')");
  PlyHeader header;
  std::size_t unknown_lines = 0;
  std::string first_unknown;
  Encoding& enc = header.encoding;
  bool have_format = false, have_end = false;
  std::vector<Element>& elements = header.elements;
  while (next_line(l)) {
    const auto w = split(l);
    if (w.empty()) continue;
    if (w[0] == "comment" || w[0] == "obj_info") {
      header.comments.emplace_back(l);
      continue;
    }
    if (w[0] == "format") {
      if (w.size() < 3) fail(name, line, "malformed format line");
      if (w[1] == "ascii") enc = Encoding::Ascii;
      else if (w[1] == "binary_little_endian") enc = Encoding::BinaryLE;
      else if (w[1] == "binary_big_endian") enc = Encoding::BinaryBE;
      else fail(name, line, "unknown PLY format '" + std::string(w[1]) + "'");
      have_format = true;
    } else if (w[0] == "element") {
      if (w.size() != 3) fail(name, line, "malformed element line (expected: element NAME COUNT)");
      Element e;
      e.name = std::string(w[1]);
      e.line = line;
      const char* b = w[2].data();
      std::int64_t count;
      if (!parse_int64(b, w[2].data() + w[2].size(), count) || b != w[2].data() + w[2].size() || count < 0)
        fail(name, line, "malformed element count '" + std::string(w[2]) + "'");
      e.count = std::uint64_t(count);
      elements.push_back(std::move(e));
    } else if (w[0] == "property") {
      if (elements.empty()) fail(name, line, "property before any element");
      Property prop;
      if (w.size() >= 2 && w[1] == "list") {
        if (w.size() != 5) fail(name, line, "malformed list property (expected: property list COUNT_TYPE ITEM_TYPE NAME)");
        prop.is_list = true;
        if (!parse_type(w[2], prop.count_type) || is_float_type(prop.count_type))
          fail(name, line, "bad list count type '" + std::string(w[2]) + "'");
        if (!parse_type(w[3], prop.type)) fail(name, line, "unknown property type '" + std::string(w[3]) + "'");
        prop.name = std::string(w[4]);
      } else {
        if (w.size() != 3) fail(name, line, "malformed property line (expected: property TYPE NAME)");
        if (!parse_type(w[1], prop.type)) fail(name, line, "unknown property type '" + std::string(w[1]) + "'");
        prop.name = std::string(w[2]);
      }
      elements.back().props.push_back(std::move(prop));
    } else if (w[0] == "end_header") {
      have_end = true;
      break;
    } else {
      // A line without a PLY keyword (Blender 2.4x wrote `Created by Blender3D ...` there): read
      // as a comment, as other readers do, and counted in a note.
      if (unknown_lines++ == 0) first_unknown = quoted_excerpt(l, 40);
      header.comments.push_back("comment " + std::string(l));
    }
  }
  if (unknown_lines > 0)
    info.notes.push_back(std::to_string(unknown_lines) + " header line" + (unknown_lines == 1 ? "" : "s") +
                         " without a PLY keyword read as comment" + (unknown_lines == 1 ? "" : "s") + " (first: '" +
                         first_unknown + "')");
  if (!have_end) fail(name, line, "PLY header has no end_header");
  if (!have_format) fail(name, 2, "PLY header has no format line");
  header.body_offset = std::size_t(p - bytes.data());
  header.lines = line;
  header.cr_lines = cr_lines;
  return header;
}

}  // namespace shadetool::io::ply
