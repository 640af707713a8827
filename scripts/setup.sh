#!/usr/bin/env bash
# Installs what Tessera needs on a fresh Debian 12 machine, and nothing when all is there.
#   Debian packages (apt-get), GLPK's C sources for the wasm build (apt-get source), npm packages (npm ci).
# Idempotent and quiet when nothing is missing.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

packages=(
  build-essential cmake pkg-config dpkg-dev
  emscripten
  libeigen3-dev libglpk-dev glpk-utils coinor-cbc
  libtinygltf-dev nlohmann-json3-dev libstb-dev liblemon-dev
  googletest libgtest-dev
  clang-14 libclang-rt-14-dev clang-format
  chromium
)

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi
}

missing_packages() {
  local p
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}\n' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}

# A deb-src entry for the suite this machine runs, in a file of its own, so that `apt-get source` works.
ensure_deb_src() {
  local list=/etc/apt/sources.list.d/tessera-deb-src.sources
  [ -f "$list" ] && return 1
  local codename
  codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-bookworm}")
  as_root tee "$list" >/dev/null <<SRC
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: ${codename} ${codename}-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
  return 0
}

apt_updated=0
apt_update_once() {
  if [ "$apt_updated" -eq 0 ]; then
    echo "setup: apt-get update" >&2
    as_root apt-get update -qq
    apt_updated=1
  fi
}

install_debian_packages() {
  local missing
  missing=$(missing_packages)
  [ -z "$missing" ] && return 0
  echo "setup: installing" $missing >&2
  apt_update_once
  # shellcheck disable=SC2086
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $missing >/dev/null
}

# GLPK has no wasm build: its C sources are compiled with emcc by CMake (wasm/glpk.cmake).
fetch_glpk_sources() {
  local dest="$root/build/third_party"
  compgen -G "$dest/glpk-*/src/glpk.h" >/dev/null && return 0
  if ensure_deb_src; then apt_updated=0; fi
  apt_update_once
  mkdir -p "$dest"
  echo "setup: apt-get source glpk" >&2
  (cd "$dest" && apt-get source -qq glpk >/dev/null 2>&1) || {
    echo "setup: 'apt-get source glpk' failed; check the deb-src entry in /etc/apt/sources.list.d" >&2
    exit 1
  }
}

install_npm_packages() {
  if [ ! -d node_modules ] || [ package-lock.json -nt node_modules/.package-lock.json ]; then
    echo "setup: npm ci" >&2
    npm ci --no-audit --no-fund --loglevel=error >/dev/null
  fi
}

install_debian_packages
fetch_glpk_sources
install_npm_packages
