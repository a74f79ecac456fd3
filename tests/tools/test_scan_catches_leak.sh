#!/usr/bin/env bash
# The release's content scan is a test that can fail: make a release without the build check, prove
# the scan passes on it and that no hidden case entry is left, then plant leaks one at a time and
# prove the scan fails each time, naming the leaked file.
#   test_scan_catches_leak.sh SOURCE_DIR WORK_DIR
set -uo pipefail
src="${1:?source dir}"; work="${2:?work dir}"
tool="$src/tools/make-student-release"
failures=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; failures=$((failures + 1)); fi; }

rm -rf "$work"; mkdir -p "$work"
"$tool" "$work/out" --no-verify >"$work/make.log" 2>&1
check "the release is made and its scan is clean" '[ $? -eq 0 ] || { cat "$work/make.log"; false; }'
rel="$work/out/jelly-lab-student"
check "no solutions/ in the release" '[ ! -e "$rel/solutions" ]'
check "the stubs are in the release" '[ -f "$rel/assignments/forces.cpp" ]'
if [ -d "$src/grader/cases" ]; then
  check "no hidden case entry left in grader/cases" '! grep -rqs "visibility *= *\"hidden\"" "$rel/grader/cases"'
  pub_src=$(cat "$src"/grader/cases/*.toml 2>/dev/null | grep -c 'visibility *= *"public"')
  pub_rel=$(cat "$rel"/grader/cases/*.toml 2>/dev/null | grep -c 'visibility *= *"public"')
  check "every public case kept ($pub_src)" '[ "$pub_src" = "$pub_rel" ]'
fi

# A planted leak must fail the scan; the copy is restored after each.
plant() {  # plant NAME COMMAND-THAT-MODIFIES-$copy EXPECTED-TEXT
  local copy="$work/copy" what="$1" want="$3"
  rm -rf "$copy"; cp -a "$rel" "$copy"
  # The leaks are planted in our files; the third-party sources (16 MB, scanned clean above as part
  # of the whole release) would only make each of these scans slower.
  rm -rf "$copy/third_party"
  eval "$2"
  "$tool" --scan "$copy" >"$work/scan.log" 2>&1
  local rc=$?
  check "scan fails on $what" '[ $rc -ne 0 ] && grep -qF -- "$want" "$work/scan.log" || { cat "$work/scan.log"; false; }'
}

# 1. One line of the reference (the longest code line of solutions/forces.cpp not in the stub).
line="$(grep -vxFf "$src/assignments/forces.cpp" "$src/solutions/forces.cpp" | grep -v '^ *//' |
        awk '{ if (length($0) > length(best)) best = $0 } END { print best }')"
check "found a reference line to plant" '[ -n "$line" ]'
plant "one solution line pasted into a stub" \
  'printf "%s\n" "$line" >>"$copy/assignments/forces.cpp"' "assignments/forces.cpp"
# 2. A whole solution file under another name, with different indentation.
plant "a re-indented solution file under another name" \
  'sed "s/^  /\t/" "$src/solutions/integrators.cpp" >"$copy/docs/notes.txt"' "docs/notes.txt"
# 3. A solutions/ folder.
plant "a solutions/ folder" 'mkdir -p "$copy/solutions" && cp "$src/assignments/forces.cpp" "$copy/solutions/"' "solutions"
# 4. A hidden case id and a hidden data file (when the grader has them).
hidden_id="$(cat "$src"/grader/cases/*.toml 2>/dev/null | awk '/^\[\[case\]\]/ { id = "" } /^id *=/ { id = $0 } /visibility *= *"hidden"/ && id != "" { print id; exit }' | sed 's/^[^"]*"//; s/".*//')"
if [ -n "$hidden_id" ]; then
  plant "a hidden case id" 'printf "# %s\n" "$hidden_id" >>"$copy/docs/handout/README.md"' "$hidden_id"
fi
hidden_file="$(find "$src/grader/data/hidden" -type f 2>/dev/null | head -1)"
if [ -n "$hidden_file" ]; then
  plant "a hidden data file" 'cp "$hidden_file" "$copy/docs/data.json"' "docs/data.json"
fi

# 5. Instructor material in a shipped doc (the doc-content check): a command that needs solutions/,
# the threat model's list, the release tool. The message names file and line.
lines=$(wc -l <"$rel/docs/viewer.md")
plant "an instructor-only build command in a doc" \
  'printf "Build the reference: cmake -S . -B build -DJELLY_TASKS=solutions\n" >>"$copy/docs/viewer.md"' "docs/viewer.md:$((lines + 1)):"
plant "the threat model's undefended list in a doc" \
  'printf "**Not defended**: timing side channels\n" >>"$copy/docs/handout/README.md"' "docs/handout/README.md:"
plant "the release tool named in the front page" \
  'printf "Made with tools/make-student-release.\n" >>"$copy/README.md"' "README.md:"
check "the release's grader.md has the student's sandbox section, not the threat model" \
  'grep -q "^## The sandbox" "$rel/docs/grader.md" && ! grep -qi "threat model" "$rel/docs/grader.md"'
check "no audience marker is left in the release" \
  '! grep -rlE --include="*.md" --exclude-dir=third_party -- "<!-- (/?instructor-only|student-only:)|:student-only -->" "$rel"'

[ "$failures" -eq 0 ] && echo "all checks passed" && exit 0
echo "$failures check(s) failed"; exit 1
