#!/usr/bin/env bash
# The real-file corpus (issue 27, "Done when"): every mesh in ../shared/corpus (39 files other
# programs wrote; MANIFEST.tsv names source and exporter) through every subcommand, one process at
# a time; tests/corpus/check.py asserts per file: exit status, no zero or non-finite normal
# written, no face reversed against agreeing authored normals by repair, vertices, faces and every
# attribute kept or named in a note. Skips loudly when the corpus is not beside the clone.
set -uo pipefail
bin=$1 src=$2
corpus=${SHADETOOL_CORPUS:-$src/../shared/corpus}
if [ ! -f "$corpus/MANIFEST.tsv" ]; then
  echo "skipped: no real-file corpus at $corpus (it is kept beside the clone as shared/corpus; set SHADETOOL_CORPUS)"
  exit 0
fi
py=/usr/bin/python3; [ -x "$py" ] || py=python3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$src" && "$py" "$src/tests/corpus/check.py" "$bin" "$src" "$corpus" "$tmp"
