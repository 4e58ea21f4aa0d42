#!/usr/bin/env bash
# Installs the Debian 12 packages Fluence builds and tests with, when they are missing.
# Idempotent: does nothing (and never runs apt-get update) when everything is installed.
set -euo pipefail

packages=(
  cmake g++ ninja-build pkg-config ccache
  libembree-dev libtbb-dev
  libopenimageio-dev libopenexr-dev libopencolorio-dev
  libosd-dev
  libopenvdb-dev libboost-iostreams-dev
  libgtest-dev
  libpugixml-dev
  liblz4-dev
  clang-16 libclang-rt-16-dev llvm-16
  libcpp-httplib-dev  # fluence review: its HTTP server
  chromium  # tests/browser: the review page in headless Chromium
  clang-format-14  # make format-check (part of make test): the tree follows .clang-format
  slurm-wlm munge openimageio-tools  # tests/farm/slurm_farm_test.sh: a one-node Slurm cluster; oiiotool
)
# tests/browser drives Chromium with puppeteer-core from npm (installed into the build folder by the
# test itself): Debian's nodejs and npm, unless a Node.js with npm is installed some other way.
command -v npm >/dev/null || packages+=(nodejs npm)
# `install_dependencies.sh bench` adds what bench/run.py (make figures) runs with, under /usr/bin/python3.
[[ "${1:-}" == bench ]] && packages+=(python3-numpy python3-openimageio python3-matplotlib)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "dependencies: all ${#packages[@]} Debian packages are installed"
  exit 0
fi

echo "dependencies: installing ${missing[*]}"
if [[ $(id -u) -ne 0 ]]; then
  echo "error: installing packages needs root; run as root, or install them yourself:" >&2
  echo "  apt-get install ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -q
apt-get install -y -q --no-install-recommends "${missing[@]}"
