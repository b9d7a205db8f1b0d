// mesh_file_list.h: every mesh file under the source tree's data/ and the real-file corpus (the
// corpus lies beside the source tree in CI, ../shared/corpus, and two levels up from a worktree
// under wt/), whose name ends in one of `extensions` (compared case-insensitively), in directory
// walk order. Used by the tests that run a kernel over every real file (normals/tangents.cpp,
// normals/corner_normals_bitwise.cpp).
#pragma once

#include <cctype>
#include <cstring>
#include <initializer_list>
#include <string>
#include <vector>

#include <dirent.h>
#include <sys/stat.h>

namespace shadetool::testing {

inline std::vector<std::string> data_and_corpus_mesh_files(std::initializer_list<const char*> extensions) {
  std::vector<std::string> out;
  const std::string src = SHADETOOL_SOURCE_DIR;
  std::vector<std::string> roots = {src + "/data"};
  for (const std::string& corpus : {src + "/../shared/corpus", src + "/../../shared/corpus"}) {
    struct stat st;
    if (::stat(corpus.c_str(), &st) == 0) {
      roots.push_back(corpus);
      break;
    }
  }
  while (!roots.empty()) {
    const std::string dir = roots.back();
    roots.pop_back();
    DIR* d = ::opendir(dir.c_str());
    if (!d) continue;
    while (dirent* e = ::readdir(d)) {
      const std::string name = e->d_name;
      if (name == "." || name == "..") continue;
      const std::string path = dir + "/" + name;
      struct stat st;
      if (::stat(path.c_str(), &st) != 0) continue;
      if (S_ISDIR(st.st_mode)) {
        roots.push_back(path);
        continue;
      }
      std::string lower = name;
      for (char& ch : lower) ch = char(std::tolower(static_cast<unsigned char>(ch)));
      for (const char* ext : extensions) {
        const std::size_t n = std::strlen(ext);
        if (lower.size() > n && lower.compare(lower.size() - n, n, ext) == 0) out.push_back(path);
      }
    }
    ::closedir(d);
  }
  return out;
}

}  // namespace shadetool::testing
