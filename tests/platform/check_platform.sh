#!/usr/bin/env bash
# Same bits on another platform (issue 10): builds the `jelly` CLI for PLATFORM, runs each
# assignment's scenes (A1: the course scene and a few other runs; A2: the course's cloth scenes,
# issue 20) with it and with this (Linux GCC) build's `jelly`, and fails unless every output file is
# the same bytes.
#
#   check_platform.sh PLATFORM HOST_JELLY SOURCE_DIR WORK_DIR TASKS [JOBS [HOST_JELLY_GRADE [HOST_HASH]]]
#   (HOST_HASH may also come from the environment, JELLY_HOST_HASH: CTest sets it)
#   JELLY_PLATFORM_PHASE=build in the environment: configure and build only, then exit 0. CTest runs
#   that phase (it compiles with JOBS jobs) and then the whole script with JELLY_PLATFORM_PHASE=runs,
#   which does not configure again and whose build finds everything up to date (the runs under
#   wine or qemu take one core).
#
#   PLATFORM  mingw   Windows: MinGW-w64 cross-build (cmake/toolchains/mingw-w64-x86_64.cmake), run
#                     under wine; also runs the unit tests that exist on Windows (stubs, session,
#                     render on the null backend, the process launcher) under wine,
#                     and the self-check of every assignment (the `selfcheck-ID` target students
#                     use, on TASKS/ID; jelly-grade.exe --runner on the other folder): 0 points for assignments/ID/'s stubs, full public marks
#                     for the reference (solutions/ID/ and its task modules), and the same report lines as
#                     HOST_JELLY_GRADE (the Linux grader compiling the same code) when given
#             libcxx  clang++ -stdlib=libc++ (the nearest stand-in here for Apple's toolchain)
#             aarch64 ARM64 Linux: g++-aarch64-linux-gnu cross-build (cmake/toolchains/aarch64-linux-gnu.cmake),
#                     run under qemu-aarch64 (the stand-in here for Apple silicon); also runs the
#                     stub and session unit tests and the self-check there (the aarch64 runners
#                     graded by the aarch64 jelly-grade under qemu, each runner started through
#                     qemu), and, when HOST_HASH (this build's tests/determinism/jelly_hash_clones)
#                     is given and TASKS is solutions, the determinism hash program
#   TASKS     assignments | solutions: the same as the host build's JELLY_TASKS
#
# Which assignments: every assignments/ID/assignment.toml of SOURCE_DIR, or those listed in the
# environment's JELLY_PLATFORM_ASSIGNMENTS (comma-separated ids, e.g. a2). Each one's runs are
# below (an assignment with none of its own runs its manifest's default scene); each one's
# self-check must find public grader cases: an assignment with none fails the check (its stubs
# cannot show they score 0), unless JELLY_PLATFORM_ALLOW_NO_CASES=1 (while its cases are written).
#
# Exit 0: same bytes; 1: a difference or a failed build/run; 77: skipped (compiler or wine
# missing; tools/install-deps.sh installs them). Everything is built under WORK_DIR (ccache is used
# when installed), with JELLY_DEPS=bundled: SOURCE_DIR/third_party when it is there, else
# tools/fetch-third-party fills WORK_DIR/third_party.
set -uo pipefail
platform="${1:?platform}"; host_jelly="${2:?host jelly}"; src="${3:?source dir}"; work="${4:?work dir}"
tasks="${5:?tasks}"; jobs="${6:-2}"; host_grade="${7:-}"
host_hash="${8:-${JELLY_HOST_HASH:-}}"
say() { printf 'platform[%s]: %s\n' "$platform" "$*"; }
skip() { say "SKIPPED: $*"; exit 77; }
die() { say "FAILED: $*"; exit 1; }
mkdir -p "$work"
work="$(cd "$work" && pwd)"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
timer() { local t0=$1; echo $(( $(date +%s) - t0 ))s; }
# The assignments (assignments/ID/assignment.toml) and their runners: per assignment the student
# runner, the stub runner (tests/platform/CMakeLists.txt) and, where solutions/ID/ is, the reference's.
ids=()
for m in "$src"/assignments/*/assignment.toml; do
  [ -f "$m" ] || continue
  # A draft (draft = true) is built but has no runner, no scene of its own and no release.
  [ "$(python3 "$src/tools/jelly_manifest.py" get "$m" draft)" = true ] && continue
  ids+=("$(basename "$(dirname "$m")")")
done
[ "${#ids[@]}" -gt 0 ] || die "no assignment in $src/assignments (a folder with an assignment.toml)"
if [ -n "${JELLY_PLATFORM_ASSIGNMENTS:-}" ]; then
  all_ids=("${ids[@]}"); ids=()
  IFS=',' read -r -a wanted <<<"$JELLY_PLATFORM_ASSIGNMENTS"
  for id in "${wanted[@]}"; do
    case " ${all_ids[*]} " in *" $id "*) ids+=("$id") ;;
      *) die "JELLY_PLATFORM_ASSIGNMENTS: no assignment '$id' (assignments/*/assignment.toml: ${all_ids[*]})" ;;
    esac
  done
fi
say "assignments: ${ids[*]}"
runner_targets() {
  local id
  for id in "${ids[@]}"; do
    printf '%s\n' "jelly-grade-$id-student-runner" "jelly_tests_${id}_stub_runner"
    [ -d "$src/solutions/$id" ] && printf '%s\n' "jelly-grade-$id-reference-runner"
  done
}

# ---- the compiler and how to run what it builds ---------------------------------------------
run=()
case "$platform" in
  mingw)
    command -v x86_64-w64-mingw32-g++-posix >/dev/null ||
      skip "x86_64-w64-mingw32-g++-posix not found (Debian package g++-mingw-w64-x86-64-posix)"
    wine=""
    for w in /usr/lib/wine/wine64 "$(command -v wine64 || true)" "$(command -v wine || true)"; do
      [ -n "$w" ] && [ -x "$w" ] && { wine="$w"; break; }
    done
    [ -n "$wine" ] || skip "wine not found (Debian package wine64)"
    export WINEPREFIX="$work/wineprefix" WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
    if [ ! -f "$WINEPREFIX/system.reg" ]; then
      t0=$(date +%s)
      "$wine" wineboot --init >/dev/null 2>&1
      "$(dirname "$wine")/wineserver" -w 2>/dev/null || true
      say "wine prefix created in $(timer "$t0")"
    fi
    run=("$wine")
    exe=.exe
    toolchain=(-DCMAKE_TOOLCHAIN_FILE="$src/cmake/toolchains/mingw-w64-x86_64.cmake")
    targets=(jelly jelly_tests_stubs jelly_tests_session jelly_tests_process_win jelly-grade
             $(runner_targets))
    viewer=OFF
    if command -v xvfb-run >/dev/null; then viewer=ON; targets+=(jelly-lab jelly_tests_render)
    else say "no xvfb-run (Debian package xvfb): jelly-lab.exe is not built nor opened"; fi
    ;;
  libcxx)
    command -v clang++ >/dev/null || skip "clang++ not found (Debian package clang)"
    echo '#include <vector>
int main() { return std::vector<int>{1}.size() == 1 ? 0 : 1; }' >"$work/probe.cpp"
    clang++ -stdlib=libc++ "$work/probe.cpp" -o "$work/probe" 2>/dev/null ||
      skip "clang++ -stdlib=libc++ cannot build a program (Debian packages libc++-dev libc++abi-dev)"
    exe=""
    toolchain=(-DCMAKE_CXX_COMPILER=clang++ -DCMAKE_CXX_FLAGS=-stdlib=libc++
               -DCMAKE_EXE_LINKER_FLAGS="-stdlib=libc++")
    targets=(jelly)
    viewer=OFF
    ;;
  aarch64)
    command -v aarch64-linux-gnu-g++ >/dev/null ||
      skip "aarch64-linux-gnu-g++ not found (Debian package g++-aarch64-linux-gnu)"
    qemu="$(command -v qemu-aarch64 || command -v qemu-aarch64-static || true)"
    [ -n "$qemu" ] || skip "qemu-aarch64 not found (Debian package qemu-user)"
    sysroot=/usr/aarch64-linux-gnu
    [ -f "$sysroot/lib/ld-linux-aarch64.so.1" ] ||
      skip "no aarch64 C library in $sysroot (Debian package libc6-dev-arm64-cross)"
    run=("$qemu" -L "$sysroot")
    exe=""
    toolchain=(-DCMAKE_TOOLCHAIN_FILE="$src/cmake/toolchains/aarch64-linux-gnu.cmake" -DJELLY_GRADER_SECCOMP=OFF)
    targets=(jelly jelly_tests_stubs jelly_tests_session jelly-grade $(runner_targets))
    [ "$tasks" = solutions ] && [ -n "$host_hash" ] && [ -d "$src/solutions/${ids[0]}" ] &&
      targets+=(jelly_hash_clones)
    viewer=OFF  # GLFW would need the X11 libraries for arm64 (multiarch): the viewer is not cross-built
    ;;
  *) die "unknown platform '$platform' (mingw, libcxx or aarch64)" ;;
esac

# ---- third-party libraries: the bundled sources a student release carries -------------------
# (JELLY_DEPS=bundled: nothing from this machine's packages can leak into a cross-build)
third="$src/third_party"
if [ ! -f "$third/VERSIONS" ]; then
  third="$work/third_party"
  if [ ! -f "$third/VERSIONS" ]; then
    t0=$(date +%s)
    "$src/tools/fetch-third-party" "$work" >"$work/fetch.log" 2>&1 ||
      { tail -20 "$work/fetch.log"; die "tools/fetch-third-party could not assemble the bundled sources"; }
    say "third-party sources assembled in $(timer "$t0")"
  fi
fi
deps=(-DJELLY_DEPS=bundled -DJELLY_THIRD_PARTY_DIR="$third")

# ---- configure and build --------------------------------------------------------------------
build="$work/build"
t0=$(date +%s)
tests=OFF
[ "$platform" != libcxx ] && tests=ON
grader=OFF
[ "$platform" != libcxx ] && grader=ON  # the self-check (jelly-grade --runner)
# JELLY_PLATFORM_PHASE=runs (CTest's second test): the build phase configured this folder with the
# same options, so only `cmake --build` runs (it configures again by itself when a CMake file
# changed); a configure from scratch under the cross toolchains takes about a minute.
if [ "${JELLY_PLATFORM_PHASE:-}" = runs ] && grep -q "^JELLY_TASKS:[A-Z]*=$tasks\$" "$build/CMakeCache.txt" 2>/dev/null; then
  say "configured by the build phase: checking the build is up to date"
else
  cmake -S "$src" -B "$build" "${toolchain[@]}" "${deps[@]}" "${launcher[@]}" -DCMAKE_BUILD_TYPE=Release \
        -DJELLY_TASKS="$tasks" -DJELLY_BUILD_TESTS=$tests -DJELLY_BUILD_VIEWER=$viewer -DJELLY_BUILD_GRADER=$grader \
        -DJELLY_BUILD_BENCHMARKS=OFF -DJELLY_BUILD_FUZZERS=OFF >"$work/configure.log" 2>&1 ||
    { tail -40 "$work/configure.log"; die "CMake could not configure the $platform build (log: $work/configure.log)"; }
fi
cmake --build "$build" -j"$jobs" --target "${targets[@]}" >"$work/build.log" 2>&1 ||
  { grep -E 'error|Error' "$work/build.log" | head -30; die "the $platform build failed (log: $work/build.log)"; }
say "configured and built ${targets[*]} in $(timer "$t0")"
if [ "${JELLY_PLATFORM_PHASE:-}" = build ]; then
  say "build phase done (JELLY_PLATFORM_PHASE=build): the runs and comparisons are the next test's"
  exit 0
fi
jelly="$(find "$build" -name "jelly$exe" -type f | head -1)"
[ -n "$jelly" ] || die "no jelly$exe under $build"

# ---- the same runs on both --------------------------------------------------------------------
out="$work/out"
rm -rf "$out"
mkdir -p "$out/host" "$out/$platform"
scene="%S/scenes/course-2023.toml"
corner="%S/scenes/hard/corner-first.toml"
# Each assignment's runs, "name|jelly arguments[|exit status]" (@ is the output folder and %S the
# source folder, put in after the arguments are split: either path may hold a space; the host
# run must end with that status, 0 unless given: two runs that fail alike prove nothing). A1's are
# the same as before A2 existed (its implicit Euler run blows up at t = 1.5 s by design: 3); A2's run the course's cloth scenes with every course integrator (explicit
# Euler on cloth-2022 is chaotic at the collisions, decision 14: the same bits there are the
# strictest test), the kinematic sphere's schedule of cloth-2024, and `jelly check`. A3's and A4's are below.
runs_a1=(
  "course-summary|run $scene --summary @/course-summary.csv"
  "course-rk4-trajectory|run $scene --integrator rk4 --duration 2 --every 250 --out @/course-rk4.csv"
  "course-implicit-summary|run $scene --integrator implicit_euler --duration 2 --summary @/course-implicit.csv|3"
  "corner-first-trajectory|run $corner --duration 1.5 --every 500 --out @/corner-first.csv"
  "course-check|check $scene"
)
c2022="%S/scenes/cloth-2022.toml"
c2024="%S/scenes/cloth-2024.toml"
runs_a2=(
  "cloth-2022-rk4-summary|run $c2022 --integrator rk4 --duration 1 --summary @/cloth-2022-rk4.csv"
  "cloth-2022-explicit-trajectory|run $c2022 --integrator explicit_euler --duration 0.8 --every 2000 --out @/cloth-2022-explicit.csv"
  "cloth-2022-implicit-summary|run $c2022 --integrator implicit_euler --duration 0.8 --summary @/cloth-2022-implicit.csv"
  "cloth-2024-midpoint-trajectory|run $c2024 --integrator midpoint --duration 1.2 --every 2000 --out @/cloth-2024-midpoint.csv"
  "cloth-2024-summary|run $c2024 --duration 2 --summary @/cloth-2024.csv"
  "cloth-2022-check|check $c2022"
)
# A3's: the course's skeleton scenes played through the tasks (forward kinematics of every frame,
# the 2022 keyframe warp and blend, the 2023 retiming: every bone's start, end and warped
# rotation of every frame), and `jelly check` reading the ASF and AMC.
runs_a3=(
  "hw2-fk-2022-summary|run %S/scenes/hw2-fk-2022.toml --summary @/hw2-fk-2022.csv"
  "hw2-warp-2022-summary|run %S/scenes/hw2-warp-2022.toml --summary @/hw2-warp-2022.csv"
  "hw2-blend-2022-summary|run %S/scenes/hw2-blend-2022.toml --summary @/hw2-blend-2022.csv"
  "hw2-retime-2023-summary|run %S/scenes/hw2-retime-2023.toml --summary @/hw2-retime-2023.csv"
  "hw2-warp-2022-check|check %S/scenes/hw2-warp-2022.toml"
)
# A4's: every ik scene solved through the tasks (the chain, the Jacobian, the minimum-norm solve,
# the iteration, limits): the solved posture's every bone and each solve's updates, stable and
# error (the summary's comment lines), and `jelly check` of the course's.
runs_a4=(
  "hw3-ik-summary|run %S/scenes/hw3-ik.toml --summary @/hw3-ik.csv"
  "hw3-ik-limits-summary|run %S/scenes/hw3-ik-limits.toml --summary @/hw3-ik-limits.csv"
  "ik-unreachable-summary|run %S/scenes/ik-unreachable.toml --summary @/ik-unreachable.csv"
  "ik-straight-arm-summary|run %S/scenes/ik-straight-arm.toml --summary @/ik-straight-arm.csv"
  "hw3-ik-2024-summary|run %S/scenes/hw3-ik-2024.toml --summary @/hw3-ik-2024.csv"
  "ik-moving-target-summary|run %S/scenes/ik-moving-target.toml --summary @/ik-moving-target.csv"
  "hw3-ik-check|check %S/scenes/hw3-ik.toml"
)
runs=()
for id in "${ids[@]}"; do
  list="runs_${id}[@]"
  if declare -p "runs_$id" >/dev/null 2>&1; then
    for entry in "${!list}"; do runs+=("$id-${entry}"); done
  else
    # An assignment with no runs of its own here: its default scene for one second.
    default="$(python3 "$src/tools/jelly_manifest.py" get "$src/assignments/$id/assignment.toml" default_scene)" ||
      die "assignments/$id/assignment.toml could not be read (above)"
    [ -n "$default" ] || die "assignments/$id/assignment.toml has no default_scene and check_platform.sh no runs for $id"
    runs+=("$id-default-summary|run %S/scenes/$default.toml --duration 1 --summary @/$id-default.csv")
  fi
done
t0=$(date +%s)
failed=0
# One run on one side: its output files in $out/SIDE, what it printed and its exit status in
# NAME.stdout.
run_side() {  # SIDE NAME ARGS
  local side=$1 name=$2 args=$3 dir="$out/$1" w rc
  local -a words
  read -r -a words <<<"$args"
  set --
  for w in "${words[@]}"; do w="${w//@/$dir}"; set -- "$@" "${w//%S/$src}"; done
  if [ "$side" = host ]; then "$host_jelly" "$@" >"$dir/$name.stdout" 2>&1
  else "${run[@]}" "$jelly" "$@" >"$dir/$name.stdout" 2>&1; fi
  rc=$?
  echo "exit $rc" >>"$dir/$name.stdout"
  return "$rc"
}
for entry in "${runs[@]}"; do
  IFS='|' read -r name args want <<<"$entry"
  want="${want:-0}"
  run_side host "$name" "$args"
  rc=$?
  if [ "$rc" -ne "$want" ]; then
    tail -5 "$out/host/$name.stdout"; say "FAILED: the host run $name ended with exit $rc, not $want (jelly ${args//%S/$src})"; failed=1
  fi
done
# The target's runs, JOBS at a time (under qemu the course scene's run alone takes about a minute):
# each writes only its own files.
for entry in "${runs[@]}"; do
  IFS='|' read -r name args want <<<"$entry"
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n; done
  run_side "$platform" "$name" "$args" &
done
wait
# Printed timings differ ("simulated in 2.4 s"), and so do the output paths: compare the rest.
for f in "$out/host"/*; do
  base="$(basename "$f")"
  other="$out/$platform/$base"
  if [[ "$base" == *.stdout ]]; then
    a="$(sed -e 's/simulated in [0-9.]* s ([0-9]* steps\/s)//' -e "s|$out/host|OUT|g" "$f")"
    b="$(sed -e 's/simulated in [0-9.]* s ([0-9]* steps\/s)//' -e "s|$out/$platform|OUT|g" -e 's/\r$//' "$other" 2>/dev/null)"
    [ "$a" = "$b" ] && { say "same text: $base"; continue; }
    say "DIFFERENT text: $base"; diff <(echo "$a") <(echo "$b") | head -10; failed=1
  elif cmp -s "$f" "$other"; then
    say "same bytes: $base ($(wc -c <"$f") bytes, sha256 $(sha256sum "$f" | cut -c1-16))"
  else
    say "DIFFERENT bytes: $base"; cmp "$f" "$other" | head -3; diff "$f" "$other" | head -6; failed=1
  fi
done
say "runs compared in $(timer "$t0")"

# ---- the determinism hash (tests/determinism) ---------------------------------------------------
# The state hashes of the course scene after 2 s for four integrators: the same program built here
# (x86-64, SSE2 or AVX2 loops chosen at run time) and for the target.
if [[ " ${targets[*]} " == *" jelly_hash_clones "* ]]; then
  target_hash="$(find "$build" -name "jelly_hash_clones$exe" -type f | head -1)"
  "$host_hash" >"$out/host/determinism-hash.txt" 2>&1
  "${run[@]}" "$target_hash" >"$out/$platform/determinism-hash.txt" 2>&1
  if [ -s "$out/host/determinism-hash.txt" ] &&
     cmp -s "$out/host/determinism-hash.txt" "$out/$platform/determinism-hash.txt"; then
    say "same determinism hashes: $(tr '\n' ' ' <"$out/host/determinism-hash.txt")"
  else
    say "DIFFERENT determinism hashes"; diff "$out/host/determinism-hash.txt" "$out/$platform/determinism-hash.txt"
    failed=1
  fi
fi

# ---- unit tests on the target -----------------------------------------------------------------
where="under wine"
[ "$platform" = aarch64 ] && where="under qemu-aarch64"
if [ "$platform" = mingw ] || [ "$platform" = aarch64 ]; then
  t0=$(date +%s)
  stubs="$(find "$build" -name "jelly_tests_stubs$exe" -type f | head -1)"
  if [ -z "$stubs" ]; then say "FAILED: no jelly_tests_stubs$exe"; failed=1
  else
    # The student release's unit tests that exist on Windows: the stubs', the session's and the
    # renderer's (null backend; its picture tests need OSMesa), plus the Windows process launcher's.
    suites=(jelly_tests_session)
    [ "$platform" = mingw ] && suites+=(jelly_tests_process_win)
    [ "$viewer" = ON ] && suites+=(jelly_tests_render)
    for name in jelly_tests_stubs "${suites[@]}"; do
      t="$(find "$build" -name "$name$exe" -type f | head -1)"
      [ -n "$t" ] || { say "FAILED: $name$exe was not built"; failed=1; continue; }
      log="$out/$(basename "$t" "$exe").txt"
      if (cd "$src" && "${run[@]}" "$t" --gtest_brief=1 >"$log" 2>&1); then
        say "unit tests $where: $(basename "$t") $(grep -E '^\[  PASSED  \]' "$log" | tr -d '\r')"
      else
        tail -40 "$log"; say "FAILED: $(basename "$t") $where"; failed=1
      fi
    done
    say "unit tests $where took $(timer "$t0")"
  fi
fi
# ---- the self-check under wine or qemu ------------------------------------------------------------
# The grader's case book, points and messages on runners CMake built for the target, per assignment:
# the stubs must score 0, the reference (solutions/ID/ and its task modules) full public marks, and each report must read as the Linux grader's on the
# same code (sandbox line and timings aside). On Windows the `selfcheck` target itself is run too
# (wine is the toolchain's CMAKE_CROSSCOMPILING_EMULATOR): its exit status is pass/fail. On
# aarch64, jelly-grade runs under qemu and starts each runner through a two-line script that runs
# it under qemu too (without binfmt_misc the kernel cannot start an aarch64 program by itself).
if [ "$platform" = mingw ] || [ "$platform" = aarch64 ]; then
  t0=$(date +%s)
  grade_exe="$(find "$build" -name "jelly-grade$exe" -type f | head -1)"
  through_qemu() {  # RUNNER NAME: prints the path of a script that runs RUNNER under qemu (aarch64)
    [ -n "$1" ] || return 0
    [ "$platform" = aarch64 ] || { echo "$1"; return 0; }
    printf '#!/bin/sh\nexec %q -L %q %q "$@"\n' "$qemu" "$sysroot" "$1" >"$out/$2.sh"
    chmod +x "$out/$2.sh"
    echo "$out/$2.sh"
  }
  selfcheck_case() {  # NAME ID DIR RUNNER zero|full
    local name=$1 id=$2 dir=$3 runner=$4 expect=$5 rc
    [ -n "$runner" ] || { say "FAILED: no runner for the self-check on $name"; failed=1; return; }
    # --timeout 600: every case may take up to 10 minutes here (the grader takes the larger of it
    # and the case's own limit). Under emulation on 2 shared cores the course scenes (A2's RK4
    # cloth-2024 run: 1.2 s natively) came near or over their 60 s; a time limit is not what this
    # check compares.
    (cd "$src" && "${run[@]}" "$grade_exe" grade "$dir" --assignment "$id" --runner "$runner" --visibility public --format terminal --timeout 600 --out "$out/selfcheck-$name" --strict) >"$out/selfcheck-$name.txt" 2>&1
    rc=$?
    selfcheck_judge "$name" "$id" "$dir" "$expect" "$rc"
  }
  # The target students use under wine (cmake --build --preset ... --target selfcheck-ID, wine being
  # the toolchain's CMAKE_CROSSCOMPILING_EMULATOR), on JELLY_TASKS/ID: it grades that folder as
  # selfcheck_case would (the student runner is built from the same files), so it takes that
  # case's place rather than grading the same code twice under wine.
  selfcheck_target() {  # NAME ID DIR zero|full
    local name=$1 id=$2 dir=$3 expect=$4 rc
    cmake --build "$build" --target "selfcheck-$id" >"$out/selfcheck-target-$id.log" 2>&1
    rc=$?
    # The report: from its first line on, without the build tool's own lines ("[100%] Built target").
    sed -n '/^Jelly Lab autograder — /,$p' "$out/selfcheck-target-$id.log" | grep -v '^\[[ 0-9]*%\] ' >"$out/selfcheck-$name.txt"
    [ -s "$out/selfcheck-$name.txt" ] || { tail -30 "$out/selfcheck-target-$id.log"; say "FAILED: the selfcheck-$id target printed no report"; failed=1; return; }
    # make's "exit 2" for a failed command stands for the grader's 1 (tests failed)
    [ "$rc" -ne 0 ] && grep -q '^Total: ' "$out/selfcheck-$name.txt" && rc=1
    where="$where (the selfcheck-$id target)" selfcheck_judge "$name" "$id" "$dir" "$expect" "$rc"
  }
  selfcheck_judge() {  # NAME ID DIR zero|full EXIT: the report in $out/selfcheck-NAME.txt
    local name=$1 id=$2 dir=$3 expect=$4 rc=$5 total
    total="$(sed -n 's#^Total: \([0-9.]*\) / \([0-9.]*\).*#\1 / \2#p' "$out/selfcheck-$name.txt")"
    if [[ "$total" == *"/ 0.00" ]] && [ "${JELLY_PLATFORM_ALLOW_NO_CASES:-0}" = 1 ]; then
      say "NOT CHECKED: the self-check $where on $name: assignments/$id has no public grader case yet ($total; JELLY_PLATFORM_ALLOW_NO_CASES=1)"
      return
    fi
    if ! grep -q '^  sandbox: none — your own code on your own machine: no sandbox' "$out/selfcheck-$name.txt"; then
      cat "$out/selfcheck-$name.txt"; say "FAILED: the self-check on $name does not say it has no sandbox"; failed=1; return
    fi
    case "$expect" in
      zero) [[ "$total" == "0.00 / "* && "$total" != *"/ 0.00" && $rc -eq 1 ]] ;;
      full) [[ -n "$total" && "${total% / *}" == "${total#* / }" && "$total" != "0.00 / 0.00" && $rc -eq 0 ]] ;;
    esac || { cat "$out/selfcheck-$name.txt"; say "FAILED: self-check on $name: $total (exit $rc), expected $expect"; failed=1; return; }
    say "self-check $where on $name: $total (exit $rc), as expected ($expect)"
    if [ -n "$host_grade" ]; then
      # The report only (stdout): the grader's notices to the instructor go to stderr (a Gradescope
      # zip older than the manifest, say) and are no part of what the student sees.
      "$host_grade" grade "$dir" --assignment "$id" --visibility public --format terminal --out "$out/grader-$name" \
        >"$out/grader-$name.txt" 2>"$out/grader-$name.err"
      if bash "$src/tests/grader/grading/same_report.sh" "$out/grader-$name.txt" "$out/selfcheck-$name.txt" >"$out/same-$name.txt"; then
        say "$(cat "$out/same-$name.txt") — Linux grader vs the self-check $where on $name"
      else
        cat "$out/same-$name.txt" "$out/grader-$name.err"
        say "FAILED: the self-check's report on $name differs from the Linux grader's"; failed=1
      fi
    fi
  }
  if [ -z "$grade_exe" ]; then say "FAILED: no jelly-grade$exe"; failed=1
  else
    for id in "${ids[@]}"; do
      if [ "$platform" = mingw ] && [ "$tasks" = assignments ]; then
        selfcheck_target "$id-stubs" "$id" "$src/assignments/$id" zero
      else
        stub_runner="$(through_qemu "$(find "$build" -name "jelly_tests_${id}_stub_runner$exe" -type f | head -1)" "$id-stub-runner")"
        selfcheck_case "$id-stubs" "$id" "$src/assignments/$id" "$stub_runner" zero
      fi
      [ -d "$src/solutions/$id" ] || continue
      # The reference as a submission: solutions/ID/ and its task modules' files, as the build puts
      # them together (BUILD/assignments/ID/reference/).
      if [ "$platform" = mingw ] && [ "$tasks" = solutions ]; then
        selfcheck_target "$id-solutions" "$id" "$build/assignments/$id/reference" full
      else
        ref_runner="$(through_qemu "$(find "$build" -name "jelly-grade-$id-reference-runner$exe" -type f | head -1)" "$id-reference-runner")"
        selfcheck_case "$id-solutions" "$id" "$build/assignments/$id/reference" "$ref_runner" full
      fi
    done
  fi
  say "self-check $where took $(timer "$t0")"
fi
# ---- the viewer opens under wine -------------------------------------------------------------
# Wine's opengl32 goes to the host's GLX: Mesa's llvmpipe under Xvfb gives OpenGL 3.3 core.
# jelly-lab draws the course scene at t = 2.2 s, saves its own framebuffer (scene and ImGui
# panel) and closes itself.
if [ "$platform" = mingw ] && [ "$viewer" = ON ]; then
  t0=$(date +%s)
  lab="$(find "$build" -name "jelly-lab$exe" -type f | head -1)"
  shot="$out/viewer-wine.png"
  if [ -z "$lab" ]; then say "FAILED: no jelly-lab$exe"; failed=1
  else
    # Wine's desktop process keeps the display of the session that started it: end the session
    # of the runs above (no display) first, and this one (Xvfb's, gone after) afterwards.
    # `wineserver -k` only asks: `-w` waits until the old session is gone (in CI a viewer started
    # while it was still ending failed with "Win32: Failed to create helper window").
    wineserver="$(dirname "$wine")/wineserver"
    end_wine_session() { "$wineserver" -k 2>/dev/null; "$wineserver" -w 2>/dev/null || true; }
    for attempt in 1 2; do
      end_wine_session
      (cd "$src" && timeout 300 xvfb-run -a -s "-screen 0 1280x720x24" "${run[@]}" "$lab" "${scene//%S/$src}" \
          --shot-at 2.2 --size 1024x600 --screenshot "$shot" >"$out/viewer.txt" 2>&1)
      rc=$?
      end_wine_session
      # Only wine's own start-up race is retried (once, and said); any other failure counts.
      [ "$rc" -ne 0 ] && [ "$attempt" -eq 1 ] && grep -q 'Failed to create helper window' "$out/viewer.txt" || break
      say "wine could not create a window on the first try (its session start-up race): trying once more"
    done
    size=$(stat -c %s "$shot" 2>/dev/null || echo 0)
    if [ "$rc" -eq 0 ] && [ "$(head -c 8 "$shot" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] &&
       [ "$size" -gt 20000 ]; then
      say "jelly-lab.exe opened under wine + Xvfb and saved $shot ($size bytes) in $(timer "$t0")"
    else
      tail -20 "$out/viewer.txt"; say "FAILED: jelly-lab.exe under wine (exit $rc, screenshot $size bytes)"; failed=1
    fi
  fi
fi
[ "$failed" -eq 0 ] || die "outputs differ from the Linux GCC build, or a run or check failed (see above; files in $out)"
say "PASSED: the $platform build writes the same bytes as the Linux GCC build"
