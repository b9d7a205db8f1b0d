// load_average.h: the 1-, 5- and 15-minute load averages ("0.52 0.61 0.40"), printed beside every
// benchmark table so that a reader can tell a quiet run from a busy one; empty if unreadable.
#pragma once

#include <cstdio>
#include <string>

inline std::string load_average() {
  char buf[128] = {0};
  if (FILE* f = std::fopen("/proc/loadavg", "r")) {
    if (!std::fgets(buf, sizeof buf, f)) buf[0] = 0;
    std::fclose(f);
  }
  const std::string s(buf);
  std::size_t fields = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s[i] == ' ' && ++fields == 3) return s.substr(0, i);
  return s;
}
