# bash completion for shadetool (installed as share/bash-completion/completions/shadetool).
# Read from the program's own --help, so it never falls behind the CLI: subcommands, each
# subcommand's flags, the values of flags with a fixed list ({a,b,c} in the help), and otherwise
# files (meshes by extension for the inputs; any file after -o, --scene, --report ...; folders after
# --output-dir).
_shadetool_help() {  # _shadetool_help [SUBCOMMAND]: the help text, cached per shell
  local key=_shadetool_help_cache_${1//-/_}
  if [ -z "${!key+x}" ]; then
    printf -v "$key" '%s' "$(command "${_shadetool_bin:-shadetool}" ${1:+"$1"} --help 2>/dev/null)"
  fi
  printf '%s\n' "${!key}"
}

_shadetool() {
  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]}
  _shadetool_bin=${COMP_WORDS[0]}
  local subs sub="" w
  subs=$(_shadetool_help | sed -n '/^Subcommands:/,$p' | awk 'NR > 1 && $1 ~ /^[a-z][a-z-]*$/ { print $1 }')
  for w in "${COMP_WORDS[@]:1:COMP_CWORD-1}"; do
    case " $(echo $subs) " in *" $w "*) sub=$w; break;; esac
  done
  if [ -z "$sub" ]; then
    COMPREPLY=($(compgen -W "$subs --help --version" -- "$cur"))
    return
  fi
  local help
  help=$(_shadetool_help "$sub")
  if [[ $prev == -* ]]; then
    # the flag's line in the help: "  -o,--output TEXT ..." or "  --weight TEXT:{a,b} ..."
    local line choices
    line=$(printf '%s\n' "$help" | grep -E "^ +((-[a-zA-Z],)?${prev}( |$)|${prev},)" | head -n 1)
    choices=$(sed -nE 's/^[^{]*:\{([^}]*)\}.*/\1/p' <<<"$line")
    if [ -n "$choices" ]; then
      COMPREPLY=($(compgen -W "${choices//,/ }" -- "$cur"))
      return
    fi
    if [ -n "$line" ] && [[ $line =~ ^\ +(-[a-zA-Z],)?--[a-z-]+\ +[A-Z] ]]; then  # the flag takes a value
      case $prev in
        --output-dir) COMPREPLY=($(compgen -d -- "$cur"));;
        -j|--jobs|--threads|--samples|--shadow-samples|--size|--crease|--background|--scale|--rotate|--translate) COMPREPLY=();;
        *) COMPREPLY=($(compgen -f -- "$cur"));;
      esac
      return
    fi
  fi
  if [[ $cur == -* ]]; then
    COMPREPLY=($(compgen -W "$(printf '%s\n' "$help" | grep -oE '^ +(-[a-zA-Z],)?--[a-z][a-z-]*' | sed -E 's/^ +//; s/,/ /')" -- "$cur"))
    return
  fi
  # inputs: meshes and folders
  local IFS=$'\n'
  COMPREPLY=($(compgen -d -- "$cur") $(compgen -f -X '!*.@(obj|ply|off|stl|glb|gltf|OBJ|PLY|OFF|STL|GLB|GLTF)' -- "$cur"))
}
shopt -s extglob
complete -o filenames -F _shadetool shadetool
