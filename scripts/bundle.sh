#!/usr/bin/env bash
# scripts/bundle.sh OUT_DIR [--build-dir DIR]: a relocatable tessbench for a machine that has a
# Vulkan driver and nothing else installed (a workstation or lab machine with a GPU):
#   OUT_DIR/tessbench, OUT_DIR/<name>_bench   launchers: run them from any folder
#   OUT_DIR/bin/                              the release tessbench and benchmark binaries
#   OUT_DIR/lib/                              the shared libraries they load (ldd) that such a
#                                             machine lacks: everything but glibc, libstdc++,
#                                             libgcc_s and the Vulkan loader (libvulkan.so.1,
#                                             which finds the machine's own driver, the ICD)
#   OUT_DIR/share/tessbench/assets/           the bundled assets (found beside bin/ at run time)
#   OUT_DIR/share/tessbench/chart.js          the Chart.js report.html inlines (libjs-chart.js)
# The launcher puts lib/ first on LD_LIBRARY_PATH and points TESSBENCH_CHARTJS at the bundle's
# Chart.js; nothing in the bundle names the build tree, so OUT_DIR can be moved or copied.
# The target needs glibc 2.36 or newer (Debian 12's) and a Vulkan loader with a driver.
#
# Without --build-dir, builds the release preset's tessbench and benchmarks first. OUT_DIR must
# not exist or be empty: an earlier bundle is never overwritten. Exit 2 on bad input.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=""
build=""
while [[ $# -gt 0 ]]; do
  case $1 in
    --build-dir) build=${2:?--build-dir needs a folder}; shift 2 ;;
    -h|--help) sed -n '2,18p' "$0"; exit 0 ;;
    -*) echo "bundle.sh: unknown option $1 (usage: bundle.sh OUT_DIR [--build-dir DIR])" >&2; exit 2 ;;
    *) [[ -z $out ]] || { echo "bundle.sh: one OUT_DIR only ($out, $1)" >&2; exit 2; }; out=$1; shift ;;
  esac
done
[[ -n $out ]] || { echo "bundle.sh: usage: bundle.sh OUT_DIR [--build-dir DIR]" >&2; exit 2; }
if [[ -e $out && -n $(ls -A "$out" 2>/dev/null) ]]; then
  echo "bundle.sh: $out: exists and is not empty (an earlier bundle is never overwritten)" >&2
  exit 2
fi
if [[ -z $build ]]; then
  build=$root/build/release
  (cd "$root" && cmake --preset release >/dev/null)
  benches=$(cd "$root/bench" && ls ./*_bench.cpp | sed 's|^\./||; s|\.cpp$||')
  # shellcheck disable=SC2086
  (cd "$root" && cmake --build --preset release --target tessbench $benches)
fi
exe=$build/bin/tessbench
[[ -x $exe ]] || { echo "bundle.sh: $exe: no tessbench built there (--build-dir)" >&2; exit 2; }
binaries=("$exe")
for bench in "$build"/bench/*_bench; do
  if [[ -x $bench ]]; then binaries+=("$bench"); fi  # none in a preset without benchmarks
done

mkdir -p "$out/bin" "$out/lib" "$out/share/tessbench"
out=$(cd "$out" && pwd)
cp "${binaries[@]}" "$out/bin/"
cp -r "$root/assets" "$out/share/tessbench/assets"
chartjs=$(sed -n 's/^TB_CHARTJS_PATH:[A-Z]*=//p' "$build/CMakeCache.txt" 2>/dev/null || true)
for candidate in "$chartjs" /usr/share/javascript/chart.js/chart.umd.js \
                 /usr/share/javascript/chart.js/chart.min.js; do
  if [[ -n $candidate && -f $candidate ]]; then cp "$candidate" "$out/share/tessbench/chart.js"; break; fi
done
[[ -f $out/share/tessbench/chart.js ]] || echo "bundle.sh: warning: no Chart.js (libjs-chart.js): report.html will have no charts" >&2

# What a machine with only a Vulkan driver already has: the C runtime and the loader.
system_lib='^(linux-vdso|ld-linux|libc|libm|libmvec|libpthread|libdl|librt|libresolv|libutil|libstdc\+\+|libgcc_s|libvulkan)\.so'
missing=0
for binary in "${binaries[@]}"; do
  while read -r name arrow path _; do
    [[ $arrow == "=>" ]] || continue
    [[ $name =~ $system_lib ]] && continue
    if [[ $path == "not" ]]; then
      echo "bundle.sh: $binary: needs $name, which is not found here" >&2
      missing=1
      continue
    fi
    [[ -e $out/lib/$name ]] || cp -L "$path" "$out/lib/$name"
  done < <(ldd "$binary")
done
[[ $missing == 0 ]] || exit 2

launcher() {
  cat <<EOF
#!/bin/sh
# tessbench bundle launcher (scripts/bundle.sh): runs bin/$1 with the bundle's libraries.
here=\$(CDPATH= cd -- "\$(dirname -- "\$(readlink -f -- "\$0")")" && pwd)
LD_LIBRARY_PATH="\$here/lib\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH}"
export LD_LIBRARY_PATH
if [ -z "\${TESSBENCH_CHARTJS:-}" ] && [ -f "\$here/share/tessbench/chart.js" ]; then
  TESSBENCH_CHARTJS="\$here/share/tessbench/chart.js"
  export TESSBENCH_CHARTJS
fi
exec "\$here/bin/$1" "\$@"
EOF
}
for binary in "${binaries[@]}"; do
  name=$(basename "$binary")
  launcher "$name" >"$out/$name"
  chmod +x "$out/$name"
done

# Every library resolves inside the bundle or among the system's C runtime and loader.
for binary in "$out"/bin/*; do
  unresolved=$(LD_LIBRARY_PATH=$out/lib ldd "$binary" | awk '/not found/ {print $1}')
  if [[ -n $unresolved ]]; then
    echo "bundle.sh: $binary: unresolved in the bundle: $unresolved" >&2
    exit 2
  fi
done
sha=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)
cat >"$out/README.txt" <<EOF
tessbench bundle (commit $sha), made by scripts/bundle.sh on $(date -u +%Y-%m-%d).
Needs glibc 2.36+ and a Vulkan loader with a driver (libvulkan1 and the GPU's ICD).
  ./tessbench list devices         the Vulkan devices this machine has
  ./tessbench run --out results    the default suite (results/<run-id>/)
  ./technique_gpu_bench --benchmark_out=gpu.json --benchmark_out_format=json
EOF
echo "bundle: $out ($(ls "$out/bin" | wc -l) binaries, $(ls "$out/lib" | wc -l) libraries, $(du -sh "$out" | cut -f1))"
