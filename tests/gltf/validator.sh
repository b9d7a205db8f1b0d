# tests/gltf/validator.sh, sourced by tests/gltf_cli.sh and tests/gltf_fit.sh (which set $bin, $src
# and $tmp): the Khronos glTF Validator, node and the npm package gltf-validator installed under the
# build tree. The install runs under a lock: ctest -j runs both scripts at once, and two npm
# installs into one prefix can break each other. Sets $validate ("" when skipped) and defines
# `valid FILE...` (true when the validator reports no error, or when it is skipped).
validator_dir=$(dirname "$bin")/gltf-validator-node
validate=""
if command -v node > /dev/null; then
  if [ ! -d "$validator_dir/node_modules/gltf-validator" ] && command -v npm > /dev/null; then
    mkdir -p "$validator_dir"
    (
      flock 9
      [ -d "$validator_dir/node_modules/gltf-validator" ] ||
        npm install --silent --no-audit --no-fund --prefix "$validator_dir" gltf-validator > "$tmp/npm.log" 2>&1 ||
        cat "$tmp/npm.log"
    ) 9> "$validator_dir.lock"
  fi
  if [ -d "$validator_dir/node_modules/gltf-validator" ]; then
    validate="node $src/tests/gltf/validate.js"
    export NODE_PATH=$validator_dir/node_modules
  else
    echo "skipped: Khronos glTF Validator (npm install gltf-validator failed: no registry?)"
  fi
else
  echo "skipped: Khronos glTF Validator (no node: install nodejs and npm)"
fi
valid() {  # valid FILE...: no validator error
  [ -z "$validate" ] && return 0
  $validate "$@" > "$tmp/validator.txt" || { cat "$tmp/validator.txt"; return 1; }
}
