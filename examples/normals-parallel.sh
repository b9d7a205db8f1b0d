#!/usr/bin/env bash
# Vertex normals for every mesh in a folder with GNU parallel (Debian package `parallel`),
# one shadetool call per file, locally or across hosts.
#
#   examples/normals-parallel.sh IN_DIR OUT_DIR [extra parallel options...]
#
# Across hosts (shadetool installed on each, IN_DIR/OUT_DIR on a shared file system; ':' is
# this machine; run from the shared directory):
#   examples/normals-parallel.sh meshes/ out/ --sshlogin 2/node1,2/node2,2/: --workdir "$PWD"
# Without a shared file system, let parallel move the files (needs rsync on both ends):
#   parallel --sshlogin node1,node2 --transferfile {} --return out/{/.}.ply --cleanup \
#     "mkdir -p out && shadetool normals {} -o out/{/.}.ply --quiet" ::: meshes/*.obj
# Both were run here against an sshd on 127.0.0.1:2222 (--sshlogin "1/ssh -p 2222 127.0.0.1,1/:"),
# with --joblog confirming jobs on both "hosts".
#
# Each call prints one JSON line (--json); parallel keeps lines whole (--line-buffer), so the
# combined output is valid JSON Lines. The exit status is the number of failed files (0 = all ok).
set -euo pipefail
in_dir=$1 out_dir=$2
shift 2
shadetool=${SHADETOOL:-shadetool}
mkdir -p "$out_dir"
find "$in_dir" -maxdepth 1 -type f \( -name '*.obj' -o -name '*.ply' -o -name '*.off' -o -name '*.stl' \) -print0 |
  parallel -0 --line-buffer --halt never "$@" \
    "$shadetool" normals {} -o "$out_dir"/{/.}.ply --json --quiet
