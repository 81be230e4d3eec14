#!/usr/bin/env bash
# Installs argine's build dependencies from Debian 12 packages, only what is missing.
# Idempotent: a second run installs nothing and takes well under a second.
set -euo pipefail

packages=(
  g++ make cmake pkg-config
  libopenmpi-dev openmpi-bin
  trilinos-all-dev libptscotch-dev
  libexodusii-dev libnetcdf-dev
  libeigen3-dev libgtest-dev
  python3 python3-matplotlib python3-scipy python3-yaml   # yaml: scripts/strength_sensitivity.py
  clang libclang-rt-14-dev   # the libFuzzer targets of the `fuzz` tests (scripts/fuzz.sh)
)
packages+=("$@")   # callers may ask for more (e.g. the ParaView check)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "argine setup: installing ${missing[*]}"
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "argine setup: run as root or install sudo" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
