#!/usr/bin/env bash
# Checks glTF files with the Khronos glTF-Validator (the npm package `gltf-validator`), as
# issue 60 asks of the bundled asset: prints each file's numbers of errors, warnings, infos
# and hints and exits 1 when any file has an error. Not part of the build or of ctest: it needs
# Node.js and, once, the network to install the package.
#   scripts/validate_gltf.sh                    the bundled glTF assets (assets/**/*.glb, *.gltf)
#   scripts/validate_gltf.sh FILE...            those files
# The package is installed (npm install gltf-validator) into ${TB_GLTF_VALIDATOR_DIR:-
# build/gltf-validator} the first time; without node or npm, or when npm cannot reach its
# registry, the script says so and exits 3 (nothing was validated).
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${TB_GLTF_VALIDATOR_DIR:-build/gltf-validator}
files=("$@")
if [[ ${#files[@]} -eq 0 ]]; then
  mapfile -t files < <(find assets -name '*.glb' -o -name '*.gltf' | sort)
fi
for tool in node npm; do
  if ! command -v "$tool" >/dev/null; then
    echo "validate_gltf: $tool is not installed (apt-get install nodejs npm); nothing validated" >&2
    exit 3
  fi
done
if [[ ! -d $dir/node_modules/gltf-validator ]]; then
  mkdir -p "$dir"
  if ! (cd "$dir" && npm install --no-audit --no-fund --silent gltf-validator >npm.log 2>&1); then
    echo "validate_gltf: npm could not install gltf-validator (offline? see $dir/npm.log);" \
      "nothing validated" >&2
    exit 3
  fi
fi
status=0
for file in "${files[@]}"; do
  # validateBytes gives the report as JSON; external buffers are read beside the file.
  if ! NODE_PATH="$dir/node_modules" node - "$file" <<'JS'; then status=1; fi
const fs = require("fs"), path = require("path"), validator = require("gltf-validator");
const file = process.argv[2];
validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
  uri: file,
  externalResourceFunction: (uri) => new Promise((resolve, reject) => {
    fs.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)),
                (err, data) => err ? reject(err.toString()) : resolve(new Uint8Array(data)));
  }),
}).then((report) => {
  const i = report.issues;
  console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos, ` +
              `${i.numHints} hints`);
  for (const m of i.messages.filter((m) => m.severity === 0)) {
    console.log(`  ${m.code} ${m.pointer || ""}: ${m.message}`);
  }
  process.exit(i.numErrors === 0 ? 0 : 1);
}, (error) => { console.log(`${file}: the validator failed: ${error}`); process.exit(1); });
JS
done
exit $status
