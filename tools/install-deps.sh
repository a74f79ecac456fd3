#!/usr/bin/env bash
# Installs every Debian 12 package Jelly Lab needs to build, test, grade and run headless.
# Idempotent: installs only what is missing, runs `apt-get update` once first, prints what it does.
#
#   sudo tools/install-deps.sh             # everything needed to build, test and self-check
#   sudo tools/install-deps.sh --student   # only what a student needs: build, viewer, self-check
#   sudo tools/install-deps.sh --demo      # only what tools/run-demo needs: jelly and jelly-lab
#   sudo tools/install-deps.sh --ffmpeg    # also ffmpeg (turning recorded frames into videos)
#   tools/install-deps.sh --check          # only list what is missing; exit 1 if anything is
#
# Nothing is downloaded at build time: CMake finds these system packages.
set -euo pipefail

PACKAGES=(
  build-essential cmake g++ pkg-config git
  python3  # tools/make-student-release, tools/selfcheck and CMake's manifest reader (tools/jelly_manifest.py)
  libeigen3-dev nlohmann-json3-dev libtomlplusplus-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libglfw3-dev libimgui-dev libosmesa6-dev libgl-dev libstb-dev
  libseccomp-dev bubblewrap
  # the instructor's grader: class exports (submission_metadata.yml, zips); the HTML reports' templates
  libyaml-cpp-dev libzip-dev libkainjow-mustache-dev
  gnuplot-nox xvfb xauth zip unzip
  similarity-tester  # sim_c++: `jelly-grade similarity` (who copied) and its test
  ccache    # run-tests compiles through it when present: repeated runs and the release builds reuse objects
  clang-format-14  # the house style of the C++ sources (.clang-format; tools/format, test house.clang_format)
  clang libclang-rt-14-dev
  # the student release's bundled builds: GLFW's X11 backend from source, Clang + libc++ (the
  # stand-in for Apple's toolchain), unpacking Debian source packages (tools/fetch-third-party)
  libx11-dev libxrandr-dev libxinerama-dev libxcursor-dev libxi-dev
  libc++-dev libc++abi-dev xz-utils bzip2
  # the Windows checks (label platform): MinGW-w64 cross-compiler, wine, Mesa's GL for Xvfb
  g++-mingw-w64-x86-64-posix wine64 libgl1-mesa-dri
  # the ARM64 check (label platform, the stand-in for Apple silicon): cross-compiler and qemu-user
  g++-aarch64-linux-gnu qemu-user
)

# A student's machine: the compiler, the libraries of the framework, its tests and viewer, and the
# self-check's sandbox; none of the instructor's cross-compilers, emulators or formatters.
STUDENT_PACKAGES=(
  build-essential cmake g++ pkg-config python3
  libeigen3-dev nlohmann-json3-dev libtomlplusplus-dev libcli11-dev
  libgtest-dev libgmock-dev
  libglfw3-dev libimgui-dev libosmesa6-dev libgl-dev libstb-dev
  libseccomp-dev bubblewrap
  libkainjow-mustache-dev libyaml-cpp-dev libzip-dev  # jelly-grade (the self-check's)
)

# tools/run-demo: what the targets jelly and jelly-lab need with tests, benchmarks and the grader
# off (the find_package / pkg-config calls of cmake/JellyDeps.cmake and JellyDepsViewer.cmake: Eigen,
# toml++, nlohmann/json, CLI11, GLFW, GL headers, stb, Dear ImGui with its backends; OpenMP and
# threads come with g++), and libOSMesa.so.8, which the off-screen renderer dlopens to draw without
# a display. Not ffmpeg: the demo writes PNG frames and adds a video only when ffmpeg is there
# (--ffmpeg installs it). On a fresh machine of this project's Debian 12 image (the package list
# of a new machine, `apt-get install --simulate` against it, 2026-11) this set pulls 11 packages,
# 6 MB to download and 30 MB installed; the default set pulls 91 packages, 259 MB and 1.4 GB
# (with ffmpeg the demo set would be 102 packages, 60 MB and 180 MB).
DEMO_PACKAGES=(
  g++ make cmake pkg-config python3
  libeigen3-dev nlohmann-json3-dev libtomlplusplus-dev libcli11-dev
  libglfw3-dev libimgui-dev libgl-dev libstb-dev libosmesa6
)

check_only=0
extra=()
for arg in "$@"; do
  case "$arg" in
    --student) PACKAGES=("${STUDENT_PACKAGES[@]}") ;;
    --demo) PACKAGES=("${DEMO_PACKAGES[@]}") ;;
    --ffmpeg) extra+=(ffmpeg) ;;
    --check) check_only=1 ;;
    -h|--help) sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "install-deps.sh: unknown option '$arg' (expected --student, --demo, --ffmpeg, --check or --help)" >&2; exit 2 ;;
  esac
done
PACKAGES+=("${extra[@]}")

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if [ "${#missing[@]}" -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages are installed."
  exit 0
fi

echo "install-deps: missing: ${missing[*]}"
if [ "$check_only" -eq 1 ]; then
  exit 1
fi
if ! command -v apt-get >/dev/null 2>&1; then
  echo "install-deps: apt-get not found. This script targets Debian 12 (bookworm);" >&2
  echo "  install the packages above with your system's package manager." >&2
  exit 1
fi
SUDO=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    SUDO=(sudo)
  else
    echo "install-deps: run as root (or install sudo) to install: ${missing[*]}" >&2
    exit 1
  fi
fi
echo "install-deps: apt-get update"
"${SUDO[@]}" apt-get update
echo "install-deps: apt-get install -y --no-install-recommends ${missing[*]}"
DEBIAN_FRONTEND=noninteractive "${SUDO[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
echo "install-deps: done."
