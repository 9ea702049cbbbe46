#!/usr/bin/env bash
# Installs the Debian packages Sweep needs, only those that are missing.
# Run by scripts/start.sh and scripts/test.sh; safe to run again.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  libglm-dev libglfw3-dev libimgui-dev libosmesa6-dev libstb-dev libcli11-dev
  python3-glad libgtest-dev libbenchmark-dev libbenchmark-tools python3-scipy librapidcheck-dev libosd-dev libtinyobjloader-dev libtinygltf-dev libtinyxml2-dev libmeshoptimizer-dev
  xvfb xauth xdotool imagemagick assimp-utils admesh time
  help2man desktop-file-utils shared-mime-info libglib2.0-bin dpkg-dev lintian appstream
  clang libclang-rt-14-dev clang-format
  libportal-dev dbus-daemon
  nlohmann-json3-dev chromium libxml2-utils
  pybind11-dev python3-pybind11 python3-dev python3-numpy python3-pytest lib3mf-dev prusa-slicer
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "Installing missing packages: ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
