#!/usr/bin/env bash
# Installs what linemap needs on Debian 12 (only what is missing) and builds it
# into build/. Idempotent. Used by tools/quickstart.sh and tools/run_tests.sh.
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(build-essential cmake pkg-config libeigen3-dev zlib1g-dev libpng-dev libdraco-dev
          libyaml-cpp-dev libgtest-dev googletest libzstd-dev liblzma-dev netpbm jbigkit-bin)
PACKAGES+=(libjxl-tools webp)  # bench anchors
PACKAGES+=(clang libclang-rt-14-dev)  # the fuzz smoke (libFuzzer) that CI runs
PACKAGES+=(pybind11-dev python3-dev python3-numpy python3-pytest)  # Python module
PACKAGES+=(libroscpp-dev libnav-msgs-dev librosbag-dev ros-core python3-nav-msgs python3-geometry-msgs)  # ROS 1 nodes and tests
# (rostopic echo needs the Python messages; python3-nav-msgs does not pull in geometry_msgs)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

BUILD_DIR=${LINEMAP_BUILD_DIR:-build}
WERROR=OFF
if [ "${CI:-}" = "true" ]; then WERROR=ON; fi
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLINEMAP_WARNINGS_AS_ERRORS=$WERROR \
  "$@" >/dev/null
cmake --build "$BUILD_DIR" -j"$(nproc)"
