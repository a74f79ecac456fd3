#!/usr/bin/env bash
# `jelly-grade grade DIR --runner RUNNER` (the self-check's prebuilt-runner mode) gives the same
# report as the grader compiling DIR itself (with the default, relative --out), and says there is
# no sandbox; --strict's exit status
# is the pass/fail the `selfcheck` target reports.
#
#   check_runner_mode.sh JELLY_GRADE DIR RUNNER WORK zero|full
#
# RUNNER must be built by CMake from the same code as DIR (e.g. jelly_tests_stub_runner from
# assignments/a1/). Exit 0 when everything holds.
set -uo pipefail
grade="${1:?jelly-grade}"; dir="${2:?dir}"; runner="${3:?runner}"; work="${4:?work}"; expect="${5:?zero|full}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
fail() { echo "check_runner_mode: FAILED: $*"; exit 1; }
rm -rf "$work"
mkdir -p "$work"
# The compile path as the handouts write it: no --out, so the default, relative grade-results/ of
# the folder it runs in (the compiler and the linker run in other folders).
(cd "$work" && "$grade" grade "$dir" --visibility public --format terminal) >"$work/compiled.txt" 2>&1 ||
  { cat "$work/compiled.txt"; fail "the compile path failed"; }
"$grade" grade "$dir" --runner "$runner" --visibility public --format terminal --out "$work/runner" --strict \
  >"$work/runner.txt" 2>&1
rc=$?
cat "$work/runner.txt"
grep -qx '  sandbox: none — your own code on your own machine: no sandbox' "$work/runner.txt" ||
  fail "the --runner report does not say that it ran without a sandbox"
total="$(sed -n 's#^Total: \([0-9.]*\) / \([0-9.]*\).*#\1 \2#p' "$work/runner.txt")"
[ -n "$total" ] || fail "no Total line"
# An assignment with a bonus task: "Total: S / M + bonus B / BM"; its bonus must be 0 or full too.
bonus="$(sed -n 's#^Total: .* + bonus \([0-9.]*\) / \([0-9.]*\).*#\1 \2#p' "$work/runner.txt")"
[ -n "$bonus" ] || bonus="0.00 0.00"
set -- $total $bonus
case "$expect" in
  zero) [ "$1" = 0.00 ] && [ "$2" != 0.00 ] && [ "$3" = 0.00 ] && [ "$rc" -eq 1 ] || fail "expected 0 of $2 points, no bonus and --strict status 1, got $1 + bonus $3 (status $rc)" ;;
  full) [ "$1" = "$2" ] && [ "$2" != 0.00 ] && [ "$3" = "$4" ] && [ "$rc" -eq 0 ] || fail "expected full marks (and the whole bonus) and --strict status 0, got $1 / $2 + bonus $3 / $4 (status $rc)" ;;
  *) fail "expect zero or full" ;;
esac
bash "$here/same_report.sh" "$work/compiled.txt" "$work/runner.txt" || fail "the --runner report differs from the compile path's"
echo "check_runner_mode: PASSED ($expect: $1 / $2)"
