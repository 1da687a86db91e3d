#!/usr/bin/env bash
# Lloydscope set-up on Debian 12: installs the missing packages, builds, then
#   ./build.sh run    opens the inspector on the bundled default mesh (without a display:
#                     remeshes it, prints the before/after table and renders the inspector to
#                     build/inspector.png)
#   ./build.sh test   runs every test (what CI runs)
#   ./build.sh        only installs and builds
set -euo pipefail
cd "$(dirname "$0")"

PACKAGES=(cmake g++ make pkg-config libcgal-dev libcgal-demo libeigen3-dev libgtest-dev
          libcli11-dev nlohmann-json3-dev libtbb-dev
          libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslang-tools libglfw3-dev
          libimgui-dev libglm-dev libstb-dev fonts-dejavu-core xvfb xauth xdotool x11-utils libx11-dev)
# CGAL's sample meshes used by tests and benchmarks, from libcgal-demo: five disks, and closed
# surfaces of genus 2 and 3 (eight, femur, elephant) and 0 (the cow, which touches itself at a
# point; the triceratops, whose first resampling no map holds) for cutting and stitching, and
# the lion (5 boundary loops), whose charts' seams meet its border close together; the camel,
# the bull, the triceratops and the armadillo clipped in half are disks with limbs and horns;
# the dino's tail, at 500 vertices, no map of it as it is holds.
CGAL_SAMPLES=(nefertiti mushroom three_peaks lion-head mannequin-devil eight elephant femur cow
              triceratops lion camel bull armadillo man dino)

install_missing() {
  local missing=()
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return
  echo "Installing: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

extract_cgal_samples() {
  mkdir -p data/cgal
  local wanted=()
  for m in "${CGAL_SAMPLES[@]}"; do
    [ -f "data/cgal/$m.off" ] || wanted+=("data/meshes/$m.off")
  done
  [ ${#wanted[@]} -eq 0 ] && return
  tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C data/cgal --strip-components=2 "${wanted[@]}"
}

build() {
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build -j"$(nproc)"
}

install_missing
extract_cgal_samples
build
case "${1:-}" in
  run)
    if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
      ./build/app/lloydscope inspect assets/bumpy_disk.off
    else
      echo "No display: remeshing headless (under xvfb-run you get the window)."
      ./build/app/lloydscope remesh assets/bumpy_disk.off -o build/bumpy_disk_remeshed.off
      ./build/app/lloydscope inspect assets/bumpy_disk.off --screenshot build/inspector.png
      echo "The inspector's picture: build/inspector.png"
    fi ;;
  test) ctest --test-dir build --output-on-failure -j"$(nproc)" ;;
  "") ;;
  *) echo "usage: ./build.sh [run|test]" >&2; exit 2 ;;
esac
