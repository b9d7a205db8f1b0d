#!/usr/bin/env bash
# Shell completion (cli/completion/, issue 28 item 15): bash's and zsh's, driven the way the shells
# drive them (COMP_WORDS/COMP_CWORD for bash; words/CURRENT for zsh with compadd and _files
# recorded), against the built CLI's own --help: subcommands, flags, flag values from the fixed lists,
# mesh files by extension. zsh's is checked where zsh is installed (skipped loudly otherwise).
set -uo pipefail
bin=$1 src=$2
pass=0 fail=0
check() {  # check NAME EXPECTED ACTUAL
  if [ "$2" = "$3" ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1: expected '$2', got '$3'"; fi
}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/dir" && touch "$tmp/a.obj" "$tmp/b.PLY" "$tmp/notes.txt"
cd "$tmp"
ln -s "$bin" "$tmp/shadetool"

bash_complete() {  # bash_complete WORD...: the completions of the last word
  bash -c '
    source "$1"; shift
    COMP_WORDS=("$@"); COMP_CWORD=$(( $# - 1 ))
    _shadetool
    printf "%s\n" "${COMPREPLY[@]}" | sort | tr "\n" " " | sed "s/ $//"' _ "$src/cli/completion/shadetool.bash" "$@"
}
B=$tmp/shadetool
check "bash: subcommands" "normals" "$(bash_complete "$B" nor)"
check "bash: all subcommands" "bake-lighting info normals occlusion render repair transform" "$(bash_complete "$B" "" | tr ' ' '\n' | grep -v '^--' | tr '\n' ' ' | sed 's/ $//')"
check "bash: a subcommand's flags" "--weight --weight-strength --weight-threshold" "$(bash_complete "$B" normals --wei)"
check "bash: one flag" "--weight-threshold" "$(bash_complete "$B" normals --weight-t)"
check "bash: a flag's values" "angle area" "$(bash_complete "$B" normals a.obj --weight a)"
check "bash: render's shading values" "flat gouraud phong" "$(bash_complete "$B" render a.obj --shading "")"
check "bash: inputs are meshes and folders" "a.obj b.PLY dir" "$(bash_complete "$B" info "")"
check "bash: -o takes any file" "notes.txt" "$(bash_complete "$B" normals a.obj -o no)"
check "bash: --output-dir takes folders" "dir" "$(bash_complete "$B" normals a.obj --output-dir "")"

if command -v zsh > /dev/null; then
  zsh_complete() {  # zsh_complete WORD...: what the function handed to compadd / _files
    zsh -f -c '
      fpath=("$1" $fpath); shift
      compadd() { [[ $1 == -- ]] && shift; print -rl -- "$@" }
      _files() { print -r -- "_files $*" }
      words=("$@"); CURRENT=$#
      autoload -Uz _shadetool
      _shadetool' _ "$src/cli/completion" "$@" | grep -v '^$' | sort | tr '\n' ' ' | sed 's/ $//'
  }
  check "zsh: subcommands" "--help --version bake-lighting info normals occlusion render repair transform" "$(zsh_complete "$B" nor)"
  check "zsh: a subcommand's flags include --weight" "--weight" "$(zsh_complete "$B" normals --wei | tr ' ' '\n' | grep -x -- --weight)"
  check "zsh: a flag's values" "angle area corner-angle face-area face-area-angle max uniform" "$(zsh_complete "$B" normals a.obj --weight a)"
  check "zsh: inputs are meshes" "_files -g *.(#i)(obj|ply|off|stl|glb|gltf)(-.)" "$(zsh_complete "$B" info "")"
  check "zsh: --output-dir takes folders" "_files -/" "$(zsh_complete "$B" normals a.obj --output-dir "")"
else
  echo "skipped: zsh completion (no zsh: apt-get install zsh)"
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
