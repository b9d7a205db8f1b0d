// mikktspace_reference.h: the reference MikkTSpace (npm `mikktspace`, the gltf-rs port of
// mikktspace.c built to WebAssembly, run by tests/normals/mikktspace_reference.js under node) for
// the tests that check tangents against it (tests/normals/tangents.cpp, tests/gltf/gltf_tangents.cpp).
//
// mikktspace_reference_dir(): the npm prefix in the build tree (tests/ of the build directory,
//   wherever the test executable is started from), installed on first use under flock(1), since two test executables may ask at once; empty when
//   node, npm or the registry is missing (the caller skips loudly).
// mikktspace_reference(corners, scratch): the reference's frames of unindexed triangles.
//   Input:  8 floats per triangle corner (px py pz nx ny nz u v), 3 corners per triangle
//   Output: 4 floats per corner (tangent xyz, w) as the reference returns them; empty (and `error`
//           set) when node failed. `scratch` names the temporary files (one per caller).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

#include "support/run_process.h"

namespace shadetool_test {

inline std::string mikktspace_reference_dir() {
  static const std::string dir = [] {
    const std::string prefix = std::string(SHADETOOL_TEST_BINARY_DIR) + "/mikktspace-node";
    struct stat st;
    if (::stat((prefix + "/node_modules/mikktspace").c_str(), &st) != 0) {
      if (std::system("command -v node > /dev/null && command -v npm > /dev/null && command -v flock > /dev/null") != 0)
        return std::string();
      const std::string cmd = "mkdir -p '" + prefix + "' && flock '" + prefix + "/.install-lock' sh -c '[ -d \"" + prefix +
                              "/node_modules/mikktspace\" ] || npm install --silent --no-audit --no-fund --prefix \"" + prefix +
                              "\" mikktspace' > /dev/null 2>&1";
      if (std::system(cmd.c_str()) != 0) return std::string();
    }
    return prefix;
  }();
  return dir;
}

inline std::vector<float> mikktspace_reference(const std::vector<float>& corners, const std::string& scratch,
                                               std::string& error) {
  const std::string in = scratch + "_in.f32", out = scratch + "_out.f32";
  {
    std::ofstream f(in, std::ios::binary);
    f.write(reinterpret_cast<const char*>(corners.data()), std::streamsize(corners.size() * sizeof(float)));
  }
  const auto run = run_process({"/usr/bin/env", "NODE_PATH=" + mikktspace_reference_dir() + "/node_modules", "node",
                                std::string(SHADETOOL_SOURCE_DIR) + "/tests/normals/mikktspace_reference.js", in, out});
  std::vector<float> frames;
  if (run.code != 0) {
    error = run.err;
  } else {
    const std::string bytes = read_file(out);
    frames.resize(bytes.size() / sizeof(float));
    std::memcpy(frames.data(), bytes.data(), frames.size() * sizeof(float));
  }
  std::remove(in.c_str());
  std::remove(out.c_str());
  return frames;
}

}  // namespace shadetool_test
