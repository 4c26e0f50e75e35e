#!/usr/bin/env bash
# Installs the Debian 12 packages scenfuzz needs to build, test and fuzz. Fast when they are all
# there already (checked with dpkg-query): no apt work at all then. Needs root (or sudo).
set -euo pipefail

packages=(
  build-essential cmake ninja-build
  clang libclang-rt-14-dev                       # libFuzzer + sanitizers (scripts/fuzz.sh)
  libeigen3-dev libnlopt-cxx-dev libompl-dev libfcl-dev libccd-dev libtbb-dev
  # OMPL links these without its package depending on them
  libboost-serialization-dev libboost-filesystem-dev libboost-system-dev
  libprotobuf-dev protobuf-compiler              # Apollo HD maps
  libcli11-dev nlohmann-json3-dev
  libtomlplusplus-dev libsqlite3-dev             # campaigns: campaign.toml and campaign.db
  libpugixml-dev                                 # campaigns: JUnit XML
  libgtest-dev libgmock-dev libbenchmark-dev
  librsvg2-bin                                   # rsvg-convert: tests render every trace picture
  chromium                                       # the campaign report's test loads it headless
  openmpi-bin libopenmpi-dev                     # campaigns scale out with mpirun
)

missing=()
for package in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$package" 2>/dev/null || true)
  [[ "$status" == installed ]] || missing+=("$package")
done

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

sudo=()
if ((EUID != 0)); then
  command -v sudo >/dev/null || { echo "install-deps: run as root (or install sudo)" >&2; exit 1; }
  sudo=(sudo)
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
