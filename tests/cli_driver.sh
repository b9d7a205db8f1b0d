#!/usr/bin/env bash
# The shared driver of every subcommand: several inputs, --output-dir, -j, stdin/stdout, JSON
# Lines, a failing file that does not stop the others, exit codes, no output on failure.
set -uo pipefail
bin=$1 src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
check() {  # check NAME CONDITION...
  local name=$1; shift
  if "$@"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $name"; fi
}
cp "$src/data/torus.obj" "$tmp/a.obj"; cp "$src/data/cube.obj" "$tmp/b.obj"
printf 'v 0 0 0\nf 1 2 3\n' > "$tmp/bad.obj"
mkdir "$tmp/out"

# Several inputs into a directory, in parallel; one bad file fails alone.
"$bin" normals "$tmp/a.obj" "$tmp/bad.obj" "$tmp/b.obj" --output-dir "$tmp/out" --format ply -j 2 --json > "$tmp/lines.jsonl" 2> "$tmp/err.txt"
code=$?
check "exit 1 when one of several files fails" test "$code" -eq 1
check "good outputs written" test -s "$tmp/out/a.ply" -a -s "$tmp/out/b.ply"
check "no output for the bad file" test ! -e "$tmp/out/bad.ply"
check "three JSON lines" test "$(wc -l < "$tmp/lines.jsonl")" -eq 3
check "JSON lines parse, 2 ok and 1 error" python3 -c '
import json,sys
rows=[json.loads(l) for l in open(sys.argv[1])]
st=sorted(r["status"] for r in rows)
assert st==["error","ok","ok"], st
bad=[r for r in rows if r["status"]=="error"][0]
assert "bad.obj" in bad["error"] and bad["input"].endswith("bad.obj")
ok=[r for r in rows if r["status"]=="ok"][0]
assert set(ok["time_ms"])=={"read","compute","write"} and ok["stats"]["faces"]>0
' "$tmp/lines.jsonl"
check "error line names the file" grep -q "bad.obj" "$tmp/err.txt"

# All good: exit 0.
"$bin" normals "$tmp/a.obj" "$tmp/b.obj" --output-dir "$tmp/out" -j 1 --quiet
check "exit 0 when all succeed" test $? -eq 0
check "extension from the input" test -s "$tmp/out/a.obj"

# stdin and stdout.
"$bin" normals - --input-format obj -o - --format ply < "$tmp/a.obj" > "$tmp/piped.ply"
check "stdin to stdout" test $? -eq 0 -a -s "$tmp/piped.ply"
check "stdout is a PLY" grep -qa '^end_header' "$tmp/piped.ply"

# Usage errors exit 2.
"$bin" normals "$tmp/a.obj" "$tmp/b.obj" -o "$tmp/x.ply" 2>/dev/null
check "-o with two inputs is a usage error" test $? -eq 2
"$bin" normals - -o "$tmp/x.ply" < /dev/null 2>/dev/null
check "stdin without --input-format is a usage error" test $? -eq 2
"$bin" normals "$tmp/a.obj" --no-such-flag 2>/dev/null
check "unknown flag exits 2" test $? -eq 2
# The design card's typo (issue 28, item 15): the unknown flag is named even without an input, and
# the usage shown is the subcommand's.
"$bin" normals --bogus 2> "$tmp/bogus.err"
check "normals --bogus exits 2" test $? -eq 2
check "normals --bogus names the flag" grep -q "unknown option '--bogus' for 'normals'" "$tmp/bogus.err"
check "normals --bogus shows normals' usage" grep -q "^Usage: shadetool normals \[OPTIONS\]" "$tmp/bogus.err"
check "normals --bogus points at normals' help" grep -q "shadetool normals --help" "$tmp/bogus.err"
"$bin" normals "$tmp/a.obj" --output-dir "$tmp/missing-dir" 2>/dev/null
check "missing output directory exits 1" test $? -eq 1

# Nothing overwritten (issue 21, items 1-3): every path a command writes differs from every input
# and from each other, checked before any work (exit 2); files that belong together are
# committed together.
mkdir -p "$tmp/ow/a" "$tmp/ow/b" "$tmp/ow/od"
cp "$src/data/cube.obj" "$tmp/ow/in.obj"; cp "$src/data/cube.obj" "$tmp/ow/a/x.obj"; cp "$src/data/torus.obj" "$tmp/ow/b/x.obj"
ln -s in.obj "$tmp/ow/link.obj"
sum_in=$(cksum < "$tmp/ow/in.obj")
"$bin" repair "$tmp/ow/in.obj" -o "$tmp/ow/out.obj" --report "$tmp/ow/in.obj" 2> "$tmp/ow/err"
check "--report equal to the input: exit 2" test $? -eq 2
check "--report equal to the input: input intact, no output" test "$(cksum < "$tmp/ow/in.obj")" = "$sum_in" -a ! -e "$tmp/ow/out.obj"
check "--report equal to the input: one line naming it" test "$(wc -l < "$tmp/ow/err")" -eq 1
"$bin" repair "$tmp/ow/in.obj" -o "$tmp/ow/out.obj" --report "$tmp/ow/link.obj" 2> /dev/null
check "--report through a link to the input: exit 2" test $? -eq 2 -a "$(cksum < "$tmp/ow/in.obj")" = "$sum_in"
"$bin" repair "$tmp/ow/in.obj" -o "$tmp/ow/out.obj" --report "$tmp/ow/./out.obj" 2> "$tmp/ow/err"
check "--report equal to -o: exit 2, nothing written" test $? -eq 2 -a ! -e "$tmp/ow/out.obj"
check "--report equal to -o: says so" grep -q "same file" "$tmp/ow/err"
"$bin" normals "$tmp/ow/a/x.obj" "$tmp/ow/b/x.obj" --output-dir "$tmp/ow/od" 2> "$tmp/ow/err"
check "colliding names under --output-dir: exit 2" test $? -eq 2
check "colliding names: nothing written" test -z "$(ls -A "$tmp/ow/od")"
check "colliding names: both inputs named" grep -q "a/x.obj and .*b/x.obj" "$tmp/ow/err"
"$bin" normals "$tmp/ow/a/x.obj" "$tmp/ow/in.obj" --output-dir "$tmp/ow" --format obj 2> /dev/null
check "an output that is another input: exit 2" test $? -eq 2 -a "$(cksum < "$tmp/ow/in.obj")" = "$sum_in"
# The report cannot be written (its path is a directory): exit 1 and -o not replaced either.
echo old > "$tmp/ow/out.obj"; mkdir "$tmp/ow/r.json"
"$bin" repair "$tmp/ow/in.obj" -o "$tmp/ow/out.obj" --report "$tmp/ow/r.json" 2> /dev/null
check "report not writable: exit 1" test $? -eq 1
check "report not writable: -o untouched" test "$(cat "$tmp/ow/out.obj")" = old
check "report not writable: no temporaries left" test -z "$(ls "$tmp/ow" | grep tmp-)"
"$bin" repair "$tmp/ow/in.obj" -o "$tmp/ow/out.obj" --report "$tmp/ow/r2.json" -q
check "mesh and report both written" test $? -eq 0 -a -s "$tmp/ow/r2.json" -a "$(head -c 1 "$tmp/ow/out.obj")" = "#"

# Flags (issue 21, item 13): non-finite values are usage errors saying so; numbers in shortest form;
# a singular map is fine for a mesh with no normals, refused (exit 2) for one with normals.
"$bin" normals "$tmp/a.obj" -o "$tmp/f.obj" --crease nan 2> "$tmp/err.txt"
check "--crease nan: exit 2, not finite" test $? -eq 2 -a -n "$(grep "'nan' is not a finite number" "$tmp/err.txt")"
"$bin" normals "$tmp/a.obj" -o "$tmp/f.obj" --crease abc 2> "$tmp/err.txt"
check "--crease abc: not a number" test $? -eq 2 -a -n "$(grep "'abc' is not a number" "$tmp/err.txt")"
"$bin" repair "$tmp/a.obj" -o "$tmp/f.obj" --weld -1 2> "$tmp/err.txt"
check "--weld -1: shortest numbers" test $? -eq 2 -a "$(head -1 "$tmp/err.txt")" = "shadetool: --weld: -1 is out of range (>= 0)"
"$bin" repair "$tmp/a.obj" -o "$tmp/f.obj" --weld inf 2> /dev/null
check "--weld inf: exit 2" test $? -eq 2
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\n' > "$tmp/plain.obj"
"$bin" transform "$tmp/plain.obj" -o "$tmp/flat.obj" --scale 0,1,1 2> "$tmp/err.txt"
check "singular map, no normals: exit 0" test $? -eq 0 -a -s "$tmp/flat.obj"
check "singular map, no normals: a note says flattened" grep -q "flattened" "$tmp/err.txt"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n' > "$tmp/withn.obj"
"$bin" transform "$tmp/withn.obj" -o "$tmp/flat2.obj" --scale 0,1,1 2> /dev/null
check "singular map with normals: exit 2, no output" test $? -eq 2 -a ! -e "$tmp/flat2.obj"

# No subcommand writes a zero normal (issue 21, item 11): transform replaces a zero vn by the
# computed one with a counted note (issue 27, item 14); the plane's +z is written. STL facet
# normals are replaced on read.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 0\nf 1//1 2//1 3//1\n' > "$tmp/zero_vn.obj"
"$bin" transform "$tmp/zero_vn.obj" -o "$tmp/zero_out.ply" --ascii --translate 1,0,0 2> "$tmp/err.txt"
check "zero normal never written: exit 0, output" test $? -eq 0 -a -s "$tmp/zero_out.ply"
check "zero normal never written: one counted note" test "$(grep -c "1 input normal had no direction" "$tmp/err.txt")" -eq 1
check "zero normal never written: +z written" test "$(sed -n '/end_header/,$p' "$tmp/zero_out.ply" | awk 'NF == 6 {print $4, $5, $6}' | sort -u)" = "0 0 1"
"$bin" normals "$src/data/part.stl" -o "$tmp/part.ply" --ascii 2> "$tmp/err.txt"
check "STL zero facet normals replaced on read, counted" grep -q "2 zero, 2 against the winding" "$tmp/err.txt"
check "no zero normal in the PLY" test -z "$(awk '/end_header/{b=1;next} b && NF>=6 && $4==0 && $5==0 && $6==0' "$tmp/part.ply")"

# Help and CLI11's parse errors (man/shadetool.1, EXIT STATUS): --help and --version exit 0 with
# their text on stdout; every parse error (unknown subcommand or option, missing argument, a value
# outside a flag's list) exits 2 with the error on stderr and nothing on stdout.
for args in "--help" "normals --help" "render --help" "--version"; do
  "$bin" $args > "$tmp/help.txt" 2> "$tmp/err.txt"
  check "shadetool $args: exit 0, text on stdout only" test $? -eq 0 -a -s "$tmp/help.txt" -a ! -s "$tmp/err.txt"
done
for args in "" "no-such-command" "normals" "normals $tmp/a.obj --crease" "normals $tmp/a.obj --weight heaviest" \
            "normals $tmp/a.obj --recompute=maybe" "info $tmp/a.obj --json extra-positional-is-an-input --no-such"; do
  "$bin" $args > "$tmp/out.txt" 2> "$tmp/err.txt"
  check "shadetool $args: parse error exits 2" test $? -eq 2 -a ! -s "$tmp/out.txt" -a -s "$tmp/err.txt"
done
# A list option before the inputs takes its one value, not the input after it (`--size 160,120
# IN`, as people type it: CLI11 took IN as a third value and refused the line), and W H still works.
for args in "--size 32,24" "--size 32 24" "--size 32,24 --background 0.1,0.2,0.3"; do
  rm -f "$tmp/size.png"
  "$bin" render $args "$tmp/a.obj" -o "$tmp/size.png" -q 2> "$tmp/err.txt"
  check "render $args IN: exit 0, a 32 x 24 image" test $? -eq 0 -a "$(od -An -tu1 -j16 -N8 "$tmp/size.png" 2>/dev/null | tr -s ' ')" = " 0 0 0 32 0 0 0 24"
done
"$bin" render --size 32 "$tmp/a.obj" -o "$tmp/size1.png" > "$tmp/out.txt" 2> "$tmp/err.txt"
check "render --size W IN: parse error exits 2, no image" test $? -eq 2 -a ! -e "$tmp/size1.png"
# Subcommands in --help by section (inspect, edit, shade), then by name (cli/command_registry.h).
order=$("$bin" --help | awk '/^Subcommands:/{s=1; next} s && /^  [a-z]/{printf "%s ", $1}')
check "--help lists the subcommands in section order" test "$order" = "info normals repair transform bake-lighting occlusion render "

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
