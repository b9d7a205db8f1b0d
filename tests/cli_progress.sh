#!/usr/bin/env bash
# The progress display (issue 28 item 14; cli/driver.cpp, core/progress.h, core/time_left.h):
#  - stderr a terminal: a long occlusion shows `FILE: occlusion N%` and, once its rate is known,
#    `(about N s left)`; the fraction never falls; redrawn at most about 10 times a second; the
#    line is cleared at the end (the last thing written is ESC[K);
#  - stderr not a terminal (a file, a pipe; stdout a terminal or not), or --quiet, or --json: not
#    one byte of progress, stderr the same bytes as a run without a terminal at all.
set -uo pipefail
bin=$1 src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
check() {  # check NAME CONDITION...
  local name=$1; shift
  if "$@"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $name"; fi
}

source "$src/tests/support/at_terminal.sh"  # at_terminal COMMAND...
if ! at_terminal test -t 2 > /dev/null 2>&1; then
  echo "skipped: neither script(1) nor python3's pty gives a terminal here"
  exit 0
fi

mesh=$src/data/torus_knot.ply
# Samples for a run of about 4 s on this machine (a percentage needs > 0.5 s, a time left > 1 s):
# measured with 256 samples, scaled, capped at the library's limit.
start=$(date +%s.%N)
"$bin" occlusion "$mesh" --samples 256 -o "$tmp/probe.ply" 2> /dev/null
probe=$(echo "$(date +%s.%N) - $start" | bc -l)
samples=$(python3 -c "import math,sys; t=max(float(sys.argv[1]),1e-3); print(min(1<<20, 1<<max(8, math.ceil(math.log2(256*4/t)))))" "$probe")
echo "occlusion of $mesh with $samples samples (256 took ${probe}s)"

# 1. At a terminal: a fraction, a time left, redraws at most about 10 a second, cleared at the end.
start=$(date +%s.%N)
at_terminal "$bin" occlusion "$mesh" --samples "$samples" -o "$tmp/tty.ply" > "$tmp/tty.out"
code=$?
seconds=$(echo "$(date +%s.%N) - $start" | bc -l)
check "terminal: exit 0" test "$code" -eq 0
check "terminal: the output file is written" test -s "$tmp/tty.ply"
tr '\r' '\n' < "$tmp/tty.out" | sed 's/\x1b\[K//g' | grep . > "$tmp/lines"
check "terminal: 'FILE: occlusion N%' shown" grep -Eq "^shadetool: .*torus_knot.ply: occlusion [0-9]+%" "$tmp/lines"
check "terminal: a time left shown" grep -Eq "occlusion [0-9]+% \(about [0-9]+ (s|min) left\)$" "$tmp/lines"
grep -Eo "occlusion [0-9]+%" "$tmp/lines" | grep -Eo "[0-9]+" > "$tmp/percents"
check "terminal: the percentage never falls" bash -c 'sort -n -c "$1"' _ "$tmp/percents"
redraws=$(grep -c "occlusion" "$tmp/lines")
check "terminal: at most about 10 redraws a second ($redraws in ${seconds}s)" \
  python3 -c "import sys; sys.exit(0 if int(sys.argv[1]) <= 10 * float(sys.argv[2]) + 2 else 1)" "$redraws" "$seconds"
check "terminal: the line is cleared at the end" bash -c 'tail -c 4 "$1" | od -c | grep -q "\\[   K"' _ "$tmp/tty.out"

# 2. Not a terminal: the same bytes on stderr as before progress existed: nothing of it.
"$bin" occlusion "$mesh" --samples "$samples" -o "$tmp/file.ply" > "$tmp/file.stdout" 2> "$tmp/file.stderr"
check "stderr a file: exit 0" test $? -eq 0
check "stderr a file: the output is the terminal run's" cmp -s "$tmp/file.ply" "$tmp/tty.ply"
check "stderr a file: no progress text" bash -c '! grep -Eq "occlusion|%|left|\r|\x1b" "$1"' _ "$tmp/file.stderr"
# stdout a terminal, stderr a file: stderr holds exactly what it holds without any terminal.
at_terminal bash -c "$(printf '%q ' "$bin" occlusion "$mesh" --samples "$samples" -o "$tmp/half.ply") 2> $(printf '%q' "$tmp/half.stderr")" > /dev/null
check "stdout a terminal, stderr a file: stderr byte-identical to the run without a terminal" cmp -s "$tmp/half.stderr" "$tmp/file.stderr"
"$bin" occlusion "$mesh" --samples "$samples" -o "$tmp/pipe.ply" 2>&1 | cat > "$tmp/pipe.stderr"
check "stderr a pipe: byte-identical to the file run" cmp -s "$tmp/pipe.stderr" "$tmp/file.stderr"

# 3. At a terminal with --quiet or --json: no progress either.
at_terminal "$bin" occlusion "$mesh" --samples "$samples" -o "$tmp/q.ply" --quiet > "$tmp/quiet.out"
check "terminal --quiet: no progress text" bash -c '! grep -Eq "occlusion [0-9]+%|\x1b" "$1"' _ "$tmp/quiet.out"
at_terminal "$bin" occlusion "$mesh" --samples "$samples" -o "$tmp/j.ply" --json > "$tmp/json.out"
check "terminal --json: no progress text" bash -c '! grep -Eq "occlusion [0-9]+%|\x1b" "$1"' _ "$tmp/json.out"

echo "cli_progress: $pass passed, $fail failed"
test "$fail" -eq 0
