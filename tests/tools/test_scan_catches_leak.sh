#!/usr/bin/env bash
# The release's content scan is a test that can fail: make a release without the build check, prove
# the scan passes on it and that no hidden case entry is left, then plant leaks one at a time and
# prove the scan fails each time, naming the leaked file.
#   test_scan_catches_leak.sh SOURCE_DIR WORK_DIR [JELLY]
# With JELLY (this build's jelly CLI), also: the help of a release of one assignment, whose examples
# come from its scenes folder, names none of the scenes that release leaves out.
set -uo pipefail
src="${1:?source dir}"; work="${2:?work dir}"; jelly="${3:-}"
tool="$src/tools/make-student-release"
failures=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; failures=$((failures + 1)); fi; }

rm -rf "$work"; mkdir -p "$work"
# The first assignment of the tree (its folder has the manifest; its reference is solutions/ID/).
id="$(basename "$(dirname "$(ls "$src"/assignments/*/assignment.toml | head -1)")")"
asg="assignments/$id"
manifest_key() { python3 "$src/tools/jelly_manifest.py" get "$@"; }  # the manifest's one reader
files="$(manifest_key "$src/$asg/assignment.toml" files)"
check "the manifest $asg/assignment.toml lists the student's files" '[ -n "$files" ]'

"$tool" "$work/out" --assignments no-such-assignment --no-verify >"$work/bad.log" 2>&1
check "an unknown --assignments id is a usage error naming it" '[ $? -eq 2 ] && grep -q "no assignment .no-such-assignment." "$work/bad.log"'

"$tool" "$work/out" --assignments "$id" --no-verify >"$work/make.log" 2>&1
check "the release is made and its scan is clean" '[ $? -eq 0 ] || { cat "$work/make.log"; false; }'
rel="$work/out/jelly-lab-student"
check "no solutions/ in the release" '[ ! -e "$rel/solutions" ]'
check "no hidden data in the release" '[ ! -e "$rel/grader/data/$id" ]'
check "no mutants in the release" '[ ! -e "$rel/$asg/grader/mutants" ]'
check "no hints made from the mutants in the release" '[ ! -e "$rel/$asg/grader/hints.json" ]'
for f in $files; do
  check "the stub $asg/$f is in the release" '[ -f "$rel/$asg/$f" ]'
done
check "the front page is the handout's overview, its links made relative to the top" \
  'grep -q "](assignments/$id/handout/" "$rel/README.md" && [ -f "$rel/docs/project-readme.md" ]'
if [ -d "$src/$asg/grader/cases" ]; then
  check "no hidden case entry left in $asg/grader/cases" '! grep -rqs "visibility *= *\"hidden\"" "$rel/$asg/grader/cases"'
  pub_src=$(cat "$src/$asg"/grader/cases/*.toml 2>/dev/null | grep -c 'visibility *= *"public"')
  pub_rel=$(cat "$rel/$asg"/grader/cases/*.toml 2>/dev/null | grep -c 'visibility *= *"public"')
  check "every public case kept ($pub_src)" '[ "$pub_src" = "$pub_rel" ]'
fi

# The scenes follow the assignments: a release ships exactly the scenes one of its assignments claims
# (its manifest's `bodies`: the scene's kind, its [body] type, "cube" when absent; or kind:variant,
# the variant of a skeleton scene being its body.mode, "playback" when absent), so that an A1
# release has no cloth scene and an A2 release no cube; and data/mocap/ only when one of them
# claims skeleton scenes. check_scenes RELEASE ID...
bodies_of() { manifest_key "$src/assignments/$1/assignment.toml" bodies; }
body_key() { awk -v key="$2" '/^[ \t]*\[/ { body = ($0 ~ /^[ \t]*\[body\]/); next } body && $0 ~ "^[ \t]*" key "[ \t]*=" { v = $0; sub(/^[^=]*=[ \t]*"/, "", v); sub(/".*/, "", v); k = v } END { print k }' "$1"; }
kind_of() { local k; k="$(body_key "$1" type)"; echo "${k:-cube}"; }
variant_of() { local v; v="$(body_key "$1" mode)"; [ -z "$v" ] && [ "$(kind_of "$1")" = skeleton ] && v=playback; echo "$v"; }
check_scenes() {
  local r="$1" kinds="" i f rel_path want kept=0 left=0 k v; shift
  for i in "$@"; do kinds="$kinds $(bodies_of "$i" | tr '\n' ' ')"; done
  check "the manifests of $* name their bodies ($kinds)" '[ -n "${kinds// /}" ]'
  while IFS= read -r f; do
    rel_path="${f#"$src"/}"; k="$(kind_of "$f")"; v="$(variant_of "$f")"
    want=0; case " $kinds " in *" $k "* | *" $k:$v "*) want=1 ;; esac
    if [ "$want" -eq 1 ]; then kept=$((kept + 1)); check "$rel_path ($k $v) is in the release of $*" '[ -f "$r/$rel_path" ]'
    else left=$((left + 1)); check "$rel_path ($k $v) is not in the release of $*" '[ ! -e "$r/$rel_path" ]'; fi
  done < <(cd "$src" && git ls-files -- 'scenes/*.toml' | sed "s|^|$src/|")
  check "the release of $* ships some scenes ($kept kept, $left left out)" '[ "$kept" -gt 0 ]'
  case " $kinds " in
    *" skeleton "* | *" skeleton:"*) check "the release of $* (skeleton scenes) has data/mocap/" '[ -f "$r/data/mocap/skeleton.asf" ]' ;;
    *) check "the release of $* (no skeleton scene) has no data/mocap/" '[ ! -e "$r/data/mocap" ]' ;;
  esac
}
check_scenes "$rel" "$id"
# What a release says about scenes names only the ones it ships: its scenes/README.md, and the help of
# jelly, jelly run and jelly render (run here with the release's scenes folder, JELLY_SCENES, as the
# release's own build finds it). check_scene_names RELEASE ID...
check_scene_names() {
  local r="$1" f name help out; shift
  local left=()
  while IFS= read -r f; do [ -e "$r/$f" ] || left+=("$(printf '%s' "${f#scenes/}" | sed 's/\.toml$//')"); done \
    < <(cd "$src" && git ls-files -- 'scenes/*.toml')
  check "the release of $* leaves scenes out (${#left[@]})" '[ "${#left[@]}" -gt 0 ]'
  names() {  # names FILE: the lines of FILE naming a left-out scene
    for name in "${left[@]}"; do grep -nE "(^|[^A-Za-z0-9_.-])$name(\.toml)?([^A-Za-z0-9_/-]|$)" "$1"; done
  }
  check "the release of $*: scenes/README.md names no scene it leaves out" \
    'out="$(names "$r/scenes/README.md")"; [ -z "$out" ] || { printf "%s\n" "$out"; false; }'
  check "the release of $*: scenes/README.md still has a row for each scene it ships" \
    '[ "$(grep -c "^| \`" "$r/scenes/README.md")" -ge "$(cd "$r/scenes" && ls *.toml | wc -l)" ]'
  [ -n "$jelly" ] || return 0
  for help in "" run render; do
    if [ "$help" = render ] && ! "$jelly" render --help >/dev/null 2>&1; then continue; fi  # no viewer
    JELLY_SCENES="$r/scenes" "$jelly" $help --help >"$work/help.txt" 2>&1
    check "the release of $*: jelly $help --help names no scene it leaves out" \
      'out="$(names "$work/help.txt")"; [ -z "$out" ] || { printf "%s\n" "$out"; false; }'
    check "the release of $*: jelly $help --help names a scene it ships" \
      'grep -qE "(^|[ /])$(cd "$r/scenes" && ls *.toml | head -1 | sed "s/\.toml$//")([ ,.]|$)" "$work/help.txt"'
  done
}
check_scene_names "$rel" "$id"
# Every other assignment on its own: its folder and scenes only, none of the others' folders, and a
# clean scan (A2 on its own: the cloth scenes and assignments/a2/ only).
for m in "$src"/assignments/*/assignment.toml; do
  other="$(basename "$(dirname "$m")")"
  [ "$other" != "$id" ] || continue
  [ "$(manifest_key "$m" draft)" != true ] || continue  # a draft is never released
  "$tool" "$work/out-$other" --assignments "$other" --no-verify >"$work/make-$other.log" 2>&1
  check "the release of $other alone is made and its scan is clean" '[ $? -eq 0 ] || { cat "$work/make-$other.log"; false; }'
  r="$work/out-$other/jelly-lab-student"
  check "the release of $other has assignments/$other/ and not assignments/$id/" '[ -d "$r/assignments/$other" ] && [ ! -e "$r/assignments/$id" ]'
  check "the release of $other has no solutions/" '[ ! -e "$r/solutions" ]'
  check_scenes "$r" "$other"
  check_scene_names "$r" "$other"
  rm -rf "$work/out-$other"
done

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

# 1. One line of the reference (the longest code line of a solutions/ID/ file not in its stub: the
# first of the manifest's files that has one).
line="" ; stub=""
for f in $files; do
  line="$(grep -vxFf "$src/$asg/$f" "$src/solutions/$id/$f" | grep -v '^ *//' |
          awk '{ if (length($0) > length(best)) best = $0 } END { print best }')"
  [ -n "$line" ] && { stub="$f"; break; }
done
check "found a reference line to plant" '[ -n "$line" ]'
plant "one solution line pasted into a stub" \
  'printf "%s\n" "$line" >>"$copy/$asg/$stub"' "$asg/$stub"
# 2. A whole solution file under another name, with different indentation (the last of the
# manifest's files that solutions/ID/ holds: a shared task's is in a task module, solutions/tasks/).
last="$(for f in $files; do [ -f "$src/solutions/$id/$f" ] && printf '%s\n' "$f"; done | tail -1)"
plant "a re-indented solution file under another name" \
  'sed "s/^  /\t/" "$src/solutions/$id/$last" >"$copy/docs/notes.txt"' "docs/notes.txt"
# 3. A solutions/ folder.
plant "a solutions/ folder" 'mkdir -p "$copy/solutions/$id" && cp "$src/$asg/$stub" "$copy/solutions/$id/"' "solutions"
# 4. A hidden case id and a hidden data file (when the grader has them), and the mutants.
hidden_id="$(cat "$src/$asg"/grader/cases/*.toml 2>/dev/null | awk '/^\[\[case\]\]/ { id = "" } /^id *=/ { id = $0 } /visibility *= *"hidden"/ && id != "" { print id; exit }' | sed 's/^[^"]*"//; s/".*//')"
if [ -n "$hidden_id" ]; then
  plant "a hidden case id" 'printf "# %s\n" "$hidden_id" >>"$copy/$asg/handout/README.md"' "$hidden_id"
fi
if [ -d "$src/$asg/grader/mutants" ]; then
  plant "the mutants folder" 'mkdir -p "$copy/$asg/grader/mutants"' "$asg/grader/mutants/ is in the release"
fi
if [ -f "$src/$asg/grader/hints.json" ]; then
  plant "the hints made from the mutants" 'cp "$src/$asg/grader/hints.json" "$copy/$asg/grader/"' "$asg/grader/hints.json/ is in the release"
fi
hidden_file="$(find "$src/grader/data/$id/hidden" -type f 2>/dev/null | head -1)"
if [ -n "$hidden_file" ]; then
  plant "a hidden data file" 'cp "$hidden_file" "$copy/docs/data.json"' "docs/data.json"
fi

# 5. Instructor material in a shipped doc (the doc-content check): a command that needs solutions/,
# the threat model's list, the release tool. The message names file and line.
lines=$(wc -l <"$rel/docs/viewer.md")
plant "an instructor-only build command in a doc" \
  'printf "Build the reference: cmake -S . -B build -DJELLY_TASKS=solutions\n" >>"$copy/docs/viewer.md"' "docs/viewer.md:$((lines + 1)):"
plant "the threat model's undefended list in a doc" \
  'printf "**Not defended**: timing side channels\n" >>"$copy/$asg/handout/README.md"' "$asg/handout/README.md:"
plant "the release tool named in the front page" \
  'printf "Made with tools/make-student-release.\n" >>"$copy/README.md"' "README.md:"
# The self-check's configuration without -D, as the test command's notes in performance.md said it.
plant "the instructor build's configuration named without -D" \
  'printf "The build is configured with \`JELLY_TASKS=solutions\`.\n" >>"$copy/docs/viewer.md"' "docs/viewer.md:$((lines + 1)):"
# Development notes: a developer's clone or worktree path, who ran a measurement.
plant "a clone path under /tmp in a doc" \
  'printf "| a clone in \`/tmp/jelly lab/main\` | 29 min |\n" >>"$copy/docs/viewer.md"' "docs/viewer.md:$((lines + 1)):"
plant "a developer's build folder in a doc" \
  'printf "The figures ran the build in /work/main.\n" >>"$copy/docs/viewer.md"' "docs/viewer.md:$((lines + 1)):"
plant "a development note naming who ran it" \
  'printf "The whole suite is the lead'"'"'s final run.\n" >>"$copy/docs/viewer.md"' "docs/viewer.md:$((lines + 1)):"
# ... but the compiler's own temporary files (/tmp/cc*.s), which the student's messages may name,
# are no machine path.
cp -a "$rel" "$work/copy-ok" && rm -rf "$work/copy-ok/third_party"
printf 'Assembler messages point into `/tmp/ccAbC123.s`.\n' >>"$work/copy-ok/docs/viewer.md"
"$tool" --scan "$work/copy-ok" >"$work/scan-ok.log" 2>&1
check "the scan lets the compiler's temporary file /tmp/cc*.s pass" '[ $? -eq 0 ] || { cat "$work/scan-ok.log"; false; }'
rm -rf "$work/copy-ok"
check "the release's performance.md names no instructor build option and no machine path" \
  '! grep -nE "JELLY_TASKS=solutions|/tmp/jelly|/work/" "$rel/docs/performance.md"'
check "the release's grader.md has the student's sandbox section, not the threat model" \
  'grep -q "^## The sandbox" "$rel/docs/grader.md" && ! grep -qi "threat model" "$rel/docs/grader.md"'
check "no audience marker is left in the release" \
  '! grep -rlE --include="*.md" --exclude-dir=third_party -- "<!-- (/?instructor-only|student-only:)|:student-only -->" "$rel"'

[ "$failures" -eq 0 ] && echo "all checks passed" && exit 0
echo "$failures check(s) failed"; exit 1
