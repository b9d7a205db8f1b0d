// ply_header.h (engine, not installed): the PLY header, line by line up to end_header.
//
// Inputs:  bytes  the whole file; name  for messages
// Output:  PlyHeader: the encoding, the elements with their properties in declared order (each
//          with the header line that declared it), where the body starts and how many lines the
//          header took (ascii bodies count lines from there). Lines end in LF or CRLF, or in a
//          lone CR when the magic line does (`ply` then a lone CR: Rhinoceros 6's exporter);
//          cr_lines says so.
// Errors:  shadetool::Error `NAME:LINE: what` for a missing `ply` magic, format line or
//          end_header, malformed element/property lines, unknown types, unexpected header lines.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <shadetool/io/engine/ply_types.h>
#include <shadetool/io/mesh_io.h>

namespace shadetool::io::ply {

struct PlyHeader {
  Encoding encoding = Encoding::Ascii;
  std::vector<Element> elements;
  std::size_t body_offset = 0;  // bytes before the body
  std::size_t lines = 0;        // header lines, end_header included
  bool cr_lines = false;        // lines end in a lone CR (see above)
  std::vector<std::string> comments;  // `comment` and `obj_info` lines as read (a line without a keyword: "comment LINE")
};

PlyHeader parse_ply_header(std::string_view bytes, const std::string& name, ReadInfo& info);

}  // namespace shadetool::io::ply
