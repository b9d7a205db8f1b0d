// vocabulary.h: the names of an enumerated option, in one table beside its enum, and the three
// things every front end needs from it: parse a name, name a value, list the names.
//
// Inputs:  table  NamedValue<E>[N]: each value of E once, with its one name (what the CLI flag,
//                 the scene file and the Python argument accept, and what reports print)
//          text   a name to parse; what  who is asking ("--model", "$.model", "render: shading"),
//                 the start of the error message
// Outputs: parse_named  the value whose name is `text` (exact, case-sensitive); else throws
//                       shadetool::Error "WHAT: 'TEXT' is not one of a, b, c" (the names in
//                       table order)
//          name_of      the value's name; "?" when the table lacks the value (each table is
//                       checked complete by its round-trip test, tests/core/vocabulary.cpp)
//          names_of     every name, in table order (CLI::IsMember's list, help text)
//
// A new value of an enum is one new row in its table: the CLI's allowed values, its help, the
// scene reader and Python's error messages all follow. tests/option_vocabulary.sh fails when a
// name in any table is compared against text outside lib/ (a second parser).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <shadetool/core/error.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

template <class E>
struct NamedValue {
  E value;
  const char* name;
};

// "a, b, c": the names of a table, for messages and help.
template <class E, std::size_t N>
std::string joined_names(const NamedValue<E> (&table)[N], const char* separator = ", ") {
  std::string s;
  for (std::size_t i = 0; i < N; ++i) s += (i == 0 ? "" : separator) + std::string(table[i].name);
  return s;
}

template <class E, std::size_t N>
E parse_named(const NamedValue<E> (&table)[N], std::string_view text, const std::string& what) {
  for (const NamedValue<E>& entry : table)
    if (text == entry.name) return entry.value;
  throw Error(what + ": '" + std::string(text) + "' is not one of " + joined_names(table));
}

template <class E, std::size_t N>
const char* name_of(const NamedValue<E> (&table)[N], E value) {
  for (const NamedValue<E>& entry : table)
    if (entry.value == value) return entry.name;
  return "?";
}

template <class E, std::size_t N>
std::vector<std::string> names_of(const NamedValue<E> (&table)[N]) {
  std::vector<std::string> names;
  for (const NamedValue<E>& entry : table) names.emplace_back(entry.name);
  return names;
}

}  // namespace shadetool
#pragma GCC visibility pop
