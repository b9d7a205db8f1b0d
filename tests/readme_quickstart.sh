#!/usr/bin/env bash
# The README's Quick start has exactly two commands, and .ci/run runs the second one verbatim.
set -euo pipefail
src=$2
mapfile -t cmds < <(awk '/^## Quick start/{q=1} q&&/^```sh/{getline; print} /^## /&&!/Quick start/{q=0}' "$src/README.md")
[ "${#cmds[@]}" -eq 2 ] || { echo "README Quick start has ${#cmds[@]} commands, expected 2"; exit 1; }
grep -qxF "${cmds[1]}" "$src/.ci/run" || { echo ".ci/run does not run the README's second command verbatim"; exit 1; }
case "${cmds[0]}" in *"shadetool normals data/"*) ;; *) echo "first command does not run shadetool normals on data/"; exit 1;; esac
echo "1 passed, 0 failed"
