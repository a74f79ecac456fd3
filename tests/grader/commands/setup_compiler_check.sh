#!/usr/bin/env bash
# The Gradescope setup.sh's compiler check (the block between "# BEGIN compiler check" and "# END
# compiler check" that `jelly-grade gradescope-zip` writes), run alone as setup.sh runs it (bash,
# set -euo pipefail) with stand-in g++, g++-11, cmake and apt-get first on the PATH, so that each
# image the check must tell apart is reproduced on any machine:
#   GCC 12 + CMake 3.25 (Debian 12)       passes, CXX=g++
#   GCC 11 + CMake 3.22 (Ubuntu 22.04)    passes, CXX=g++
#   GCC 9  + CMake 3.16 (Ubuntu 20.04), g++-11 installable      passes, CXX=g++-11
#   GCC 9,  no g++-11 in the archive      fails, naming GCC 11 and the Ubuntu 22.04 image
#   GCC 12 + CMake 3.10                   fails, naming CMake 3.16
#   this machine's own g++ and cmake      passes (what tools/run-tests builds with)
#   setup_compiler_check.sh JELLY_GRADE WORK_DIR
set -uo pipefail
grade="${1:?jelly-grade}"; work="${2:?work dir}"
rm -rf "$work"; mkdir -p "$work"
"$grade" gradescope-zip "$work/autograder.zip" --assignment a1 >"$work/zip.log" 2>&1 || { cat "$work/zip.log"; exit 1; }
(cd "$work" && unzip -q -o autograder.zip setup.sh) || { echo "no setup.sh in the zip"; exit 1; }
sed -n '/^# BEGIN compiler check/,/^# END compiler check/p' "$work/setup.sh" >"$work/block.sh"
grep -q '^# END compiler check' "$work/block.sh" || { echo "setup.sh has no compiler check block:"; cat "$work/setup.sh"; exit 1; }
# The block must come before the configure that uses the compiler it exports.
[ "$(grep -n '^# END compiler check' "$work/setup.sh" | cut -d: -f1)" -lt "$(grep -n '^cmake -S' "$work/setup.sh" | cut -d: -f1)" ] ||
  { echo "setup.sh configures before its compiler check"; exit 1; }

failures=0
# fake NAME OUTPUT-OF-DUMPVERSION: a stand-in compiler in $bin
fake_gcc() {
  cat >"$bin/$1" <<EOS
#!/bin/sh
case "\$1" in
  -dumpfullversion|-dumpversion) echo $2 ;;
  --version) echo "$1 (stand-in) $2" ;;
esac
EOS
  chmod +x "$bin/$1"
}
fake_cmake() { printf '#!/bin/sh\necho "cmake version %s"\n' "$1" >"$bin/cmake"; chmod +x "$bin/cmake"; }
# apt_get OK|FAIL: a stand-in apt-get; OK "installs" a GCC 11 g++-11
fake_apt() {
  if [ "$1" = OK ]; then
    printf '#!/bin/sh\necho "apt-get $*" >>"%s/apt.log"\n' "$bin" >"$bin/apt-get"
    printf 'cat >"%s/g++-11" <<"EOG"\n#!/bin/sh\ncase "$1" in -dump*) echo 11.4.0 ;; --version) echo "g++-11 (stand-in) 11.4.0" ;; esac\nEOG\nchmod +x "%s/g++-11"\n' "$bin" "$bin" >>"$bin/apt-get"
  else
    printf '#!/bin/sh\necho "E: Unable to locate package g++-11" >&2\nexit 100\n' >"$bin/apt-get"
  fi
  chmod +x "$bin/apt-get"
}
# run NAME EXPECT-STATUS EXPECT-TEXT: the block with the stand-ins of $bin first on the PATH
run() {
  local name="$1" want_rc="$2" want="$3" out rc
  out="$(cd "$work" && env -u CXX PATH="$bin:$PATH" bash -c 'set -euo pipefail; source ./block.sh; echo "CXX=$CXX"' 2>&1)"
  rc=$?
  if [ "$rc" -eq "$want_rc" ] && grep -qF -- "$want" <<<"$out"; then
    echo "ok: $name"
  else
    echo "FAIL: $name (status $rc, expected $want_rc and '$want'):"; printf '%s\n' "$out" | sed 's/^/  /'
    failures=$((failures + 1))
  fi
}
setup() { bin="$work/bin-$1"; rm -rf "$bin"; mkdir -p "$bin"; }

setup debian12; fake_gcc g++ 12.2.0; fake_cmake 3.25.1; fake_apt FAIL
run "GCC 12 + CMake 3.25 passes" 0 "CXX=g++"
setup ubuntu2204; fake_gcc g++ 11.4.0; fake_cmake 3.22.1; fake_apt FAIL
run "GCC 11 + CMake 3.22 (Ubuntu 22.04) passes" 0 "CXX=g++"
setup ubuntu2004; fake_gcc g++ 9.4.0; fake_cmake 3.16.3; fake_apt OK
run "GCC 9 with g++-11 installable switches to g++-11" 0 "CXX=g++-11"
setup old; fake_gcc g++ 9.4.0; fake_cmake 3.16.3; fake_apt FAIL
run "GCC 9 without g++-11 stops, naming what it needs" 1 "Jelly Lab needs GCC 11 or newer"
run "... and the image to choose" 1 "Ubuntu 22.04 base image"
setup oldcmake; fake_gcc g++ 12.2.0; fake_cmake 3.10.2; fake_apt FAIL
run "CMake 3.10 stops, naming CMake 3.16" 1 "CMake 3.10.2; Jelly Lab needs CMake 3.16 or newer"
bin="$work/bin-none"; mkdir -p "$bin"
run "this machine's g++ and cmake pass" 0 "setup.sh: compiler g++"

[ "$failures" -eq 0 ] && echo "all checks passed" && exit 0
echo "$failures check(s) failed"; exit 1
