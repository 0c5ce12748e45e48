#!/usr/bin/env bash
# Installs, with apt, whatever lazyrad needs that is missing. Idempotent and
# quiet when everything is already there. Debian packages only.
set -euo pipefail

packages=(g++ make cmake libembree-dev libopenexr-dev libpng-dev libgtest-dev libbenchmark-dev libpugixml-dev)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}" >&2
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
