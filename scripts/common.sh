# shellcheck shell=bash
# Shared helpers for scripts/*: source it, don't run it.
set -euo pipefail

LCT_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export LCT_ROOT

# Debian 12 packages the project needs (xauth: xvfb-run needs it, xvfb only recommends it).
LCT_REQUIRED_PACKAGES=(
  build-essential cmake ninja-build
  libvtk9-dev python3-vtk9 libeigen3-dev
  libgtest-dev libbenchmark-dev
  xvfb xauth libgl1-mesa-dri
  assimp-testmodels nlohmann-json3-dev libassimp-dev liblzma-dev
)

# The clang toolchain of the sanitizer pass (scripts/test) and the fuzz targets (scripts/fuzz):
# libclang-rt-14-dev holds the libFuzzer / ASan / UBSan runtimes and FuzzedDataProvider.h (clang
# only recommends it, so it is named), llvm-14 the llvm-symbolizer for readable stack traces.
# shellcheck disable=SC2034 # used by the scripts that source this file
LCT_CLANG_PACKAGES=(clang-14 libclang-rt-14-dev llvm-14)
# shellcheck disable=SC2034
LCT_CLANG_CC=clang-14
# shellcheck disable=SC2034
LCT_CLANG_CXX=clang++-14
# ASan finds llvm-symbolizer on PATH only under that name; llvm-14 installs it here.
export ASAN_SYMBOLIZER_PATH="${ASAN_SYMBOLIZER_PATH:-/usr/lib/llvm-14/bin/llvm-symbolizer}"

lct_log() { printf '==> %s\n' "$*" >&2; }

# ensure_packages [extra packages...]
# Install missing packages (the project's and the extra ones) as root, or print the command to do
# it (otherwise, then exit 1).
ensure_packages() {
  if ! command -v dpkg-query >/dev/null 2>&1; then
    lct_log "dpkg-query not found (not Debian?): not checking packages"
    return 0
  fi
  local wanted=("${LCT_REQUIRED_PACKAGES[@]}" "$@")
  local installed missing=() p
  installed="$(dpkg-query -W -f='${Package} ${Status}\n' "${wanted[@]}" 2>/dev/null |
    awk '$NF == "installed" { print $1 }' || true)"
  for p in "${wanted[@]}"; do
    grep -qxF "$p" <<<"$installed" || missing+=("$p")
  done
  ((${#missing[@]} == 0)) && return 0
  if [[ "$(id -u)" -eq 0 ]]; then
    lct_log "installing missing packages: ${missing[*]}"
    apt-get update
    DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
  else
    echo "sudo apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
}

# configure_and_build DIR [extra cmake args...]
# DIR is relative to the repository root unless absolute. Configures only when DIR/build.ninja is
# missing or the arguments changed; then builds with Ninja (a fast no-op when nothing changed).
# LCT_BUILD_TARGETS (space separated) restricts the build to those targets.
configure_and_build() {
  local dir="$1"
  shift
  [[ "$dir" == /* ]] || dir="$LCT_ROOT/$dir"
  local args=(-S "$LCT_ROOT" -B "$dir" -G Ninja
    -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 "$@")
  local stamp="$dir/.lct-configure-args" wanted
  wanted="$(printf '%q ' "${args[@]}")"
  if [[ ! -f "$dir/build.ninja" || ! -f "$stamp" || "$(cat "$stamp")" != "$wanted" ]]; then
    lct_log "configuring $dir"
    rm -f "$stamp"
    cmake "${args[@]}"
    printf '%s' "$wanted" >"$stamp"
  fi
  local targets=()
  if [[ -n "${LCT_BUILD_TARGETS:-}" ]]; then
    read -r -a targets <<<"$LCT_BUILD_TARGETS"
    targets=(--target "${targets[@]}")
  fi
  lct_log "building $dir"
  cmake --build "$dir" -j2 "${targets[@]}"
}
