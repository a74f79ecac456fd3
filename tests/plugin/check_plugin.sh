#!/usr/bin/env bash
# Proof that an assignment is a plug-in (issue 19, docs/new-assignment.md):
#   check_plugin.sh SOURCE_DIR FIXTURE_DIR WORK_DIR [CMAKE_ARG...]
# copies SOURCE_DIR's files (git's tracked and unignored files: no build/) to WORK_DIR/tree, adds
# FIXTURE_DIR's assignments/projectile/ and solutions/projectile/ and its toy body kind
# framework/bodies/point/ (which the projectile's manifest simulates; plugin.body,
# check_plugin_body.sh, checks it on this build) and NOTHING else, then in that
# tree: configures and builds (JELLY_TASKS=solutions, no viewer, benchmarks or tests), generates
# the projectile reference data, grades the reference (full marks), the stubs (0) and the mutants
# (each caught in its own task), builds selfcheck-projectile, grades A1's reference (80/80 beside
# the new assignment), makes a student release of projectile alone (when the release tool has
# --assignments) and checks that not one tracked file of the tree changed. Last, the same
# assignment made a draft (`draft = true`): its task libraries still build, but the grader, the
# self-check's config and the release refuse it, each saying it is a draft (the grader grades it
# with --draft, its author's try); then the line goes again.
# The CMAKE_ARGs (the calling build's compiler, JELLY_WERROR, JELLY_DEPS, ...) go to the configure
# step: with the same flags and ccache (CCACHE_BASEDIR set to the copy) the framework's objects come
# from the cache.
set -euo pipefail

if [[ $# -lt 3 ]]; then
  echo "usage: $0 SOURCE_DIR FIXTURE_DIR WORK_DIR [CMAKE_ARG...]" >&2
  exit 2
fi
src=$(cd "$1" && pwd)
fixture=$(cd "$2" && pwd)
work=$3
shift 3
extra_args=("$@")
id=projectile
kind=point
jobs=${JELLY_PLUGIN_JOBS:-2}
start=$SECONDS

step() { echo "== plugin: $* ($((SECONDS - start)) s)"; }
fail() {
  echo "plugin: FAILED: $*" >&2
  exit 1
}

# The score and maximum of a Gradescope results.json ("score", and the tests' max_score summed).
score_of() {
  python3 - "$1" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
total = sum(t.get("max_score", 0) for t in r.get("tests", []))
print(f"{r['score']:g} {total:g}")
PY
}

rm -rf "$work"
mkdir -p "$work"
tree=$work/tree

step "copying the tracked files of $src"
mkdir -p "$tree"
(cd "$src" && git ls-files -z --cached --others --exclude-standard |
  tar --null --ignore-failed-read -T - -cf -) | tar -xf - -C "$tree"
# Third-party sources are never tracked (tools/fetch-third-party): the copy uses the same ones.
if compgen -G "$src/third_party/*/" >/dev/null; then
  for d in "$src"/third_party/*/; do cp -a "$d" "$tree/third_party/"; done
fi
[[ -e $tree/assignments/$id || -e $tree/solutions/$id ]] &&
  fail "the source tree already has an assignment '$id'"
[[ -e $tree/framework/bodies/$kind ]] && fail "the source tree already has a body kind '$kind'"
# A baseline commit, so that `git status` shows exactly what the steps below change.
git -C "$tree" init -q
git -C "$tree" add -A
git -C "$tree" -c user.name=plugin -c user.email=plugin@invalid commit -q -m baseline

step "adding the fixture: assignments/$id, solutions/$id and framework/bodies/$kind only"
cp -a "$fixture/assignments/$id" "$tree/assignments/$id"
cp -a "$fixture/solutions/$id" "$tree/solutions/$id"
cp -a "$fixture/framework/bodies/$kind" "$tree/framework/bodies/$kind"

step "configuring and building"
launcher=()
if command -v ccache >/dev/null; then
  export CCACHE_BASEDIR=$tree CCACHE_NOHASHDIR=1
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
cmake -S "$tree" -B "$tree/build" -DCMAKE_BUILD_TYPE=Release -DJELLY_TASKS=solutions \
  -DJELLY_BUILD_VIEWER=OFF -DJELLY_BUILD_BENCHMARKS=OFF -DJELLY_BUILD_TESTS=OFF \
  "${launcher[@]}" "${extra_args[@]}" >"$work/configure.log" 2>&1 || {
  tail -30 "$work/configure.log"
  fail "configure (log: $work/configure.log)"
}
grep -q "assignment $id, student tasks from solutions/$id" "$work/configure.log" ||
  fail "CMake did not pick up assignments/$id (log: $work/configure.log)"
cmake --build "$tree/build" -j"$jobs" >"$work/build.log" 2>&1 || {
  tail -30 "$work/build.log"
  fail "build (log: $work/build.log)"
}
grade=$(find "$tree/build" -name jelly-grade -type f -perm -u+x | head -1)
[[ -x $grade ]] || fail "no jelly-grade in $tree/build"

step "generate-reference --assignment $id"
"$grade" generate-reference --assignment "$id" >"$work/generate.log" 2>&1 || {
  cat "$work/generate.log"
  fail "generate-reference"
}
n_public=$(find "$tree/assignments/$id/grader/data/public" -name '*.json' | wc -l)
n_hidden=$(find "$tree/grader/data/$id/hidden" -name '*.json' | wc -l)
[[ $n_public -eq 2 && $n_hidden -eq 2 ]] ||
  fail "expected 2 public and 2 hidden reference files, found $n_public and $n_hidden"

step "generate-reference again: only the files whose data changed are rewritten"
data_files() { find "$tree/assignments/$id/grader/data/public" "$tree/grader/data/$id/hidden" -name '*.json'; }
touch "$work/generated.stamp"
sleep 1
"$grade" generate-reference --assignment "$id" >"$work/generate-again.log" 2>&1 ||
  fail "generate-reference (again): $(cat "$work/generate-again.log")"
grep -q "4 cases: 0 rewritten, 4 unchanged, 0 removed" "$work/generate-again.log" ||
  fail "an unchanged regeneration should rewrite nothing: $(cat "$work/generate-again.log")"
[[ -z $(data_files | xargs -r -I{} find {} -newer "$work/generated.stamp") ]] ||
  fail "an unchanged regeneration touched a data file"
# One case's parameter changed: that case's file alone is rewritten, and named.
cases_file=$tree/assignments/$id/grader/cases/step.toml
cp "$cases_file" "$work/step.toml.orig"
sed -i 's/h = 0.1, steps = 5/h = 0.05, steps = 5/' "$cases_file"
"$grade" generate-reference --assignment "$id" >"$work/generate-changed.log" 2>&1 ||
  fail "generate-reference (one case changed): $(cat "$work/generate-changed.log")"
grep -q "4 cases: 1 rewritten, 3 unchanged, 0 removed" "$work/generate-changed.log" &&
  grep -q "rewrote projectile.t2.step.throw.json" "$work/generate-changed.log" ||
  fail "one changed case should rewrite its file alone: $(cat "$work/generate-changed.log")"
[[ $(data_files | xargs -r -I{} find {} -newer "$work/generated.stamp" | wc -l) -eq 1 ]] ||
  fail "a regeneration after one case changed touched other data files"
cp "$work/step.toml.orig" "$cases_file"
"$grade" generate-reference --assignment "$id" >"$work/generate-restored.log" 2>&1 ||
  fail "generate-reference (restored): $(cat "$work/generate-restored.log")"

step "grading the reference (full marks) and the stubs (0)"
"$grade" grade "$tree/solutions/$id" --assignment "$id" --visibility all --format gradescope \
  --out "$work/reference" >"$work/reference.log" 2>&1 || true
read -r ref_score ref_max < <(score_of "$work/reference/results.json")
[[ $ref_score == 20 && $ref_max == 20 ]] ||
  fail "the reference scores $ref_score / $ref_max, expected 20 / 20 ($work/reference.log)"
# Inferred assignment: the stubs' folder holds exactly projectile's files.
"$grade" grade "$tree/assignments/$id" --visibility all --format gradescope \
  --out "$work/stubs" >"$work/stubs.log" 2>&1 || true
read -r stub_score stub_max < <(score_of "$work/stubs/results.json")
[[ $stub_score == 0 && $stub_max == 20 ]] ||
  fail "the stubs score $stub_score / $stub_max, expected 0 / 20 ($work/stubs.log)"

step "a hidden case without reference data beside the others' is an error, not a silent skip"
hidden_file=$tree/grader/data/$id/hidden/projectile.t1.drag.random.json
mv "$hidden_file" "$work/hidden-aside.json"
rc=0
"$grade" grade "$tree/solutions/$id" --assignment "$id" --visibility all --format gradescope \
  --out "$work/hidden-missing" >"$work/hidden-missing.log" 2>&1 || rc=$?
mv "$work/hidden-aside.json" "$hidden_file"
[[ $rc -eq 2 ]] && grep -q "projectile.t1.drag.random.json is missing (the other hidden cases have theirs)" "$work/hidden-missing.log" ||
  fail "grading with one hidden case's data missing: exit $rc, expected 2 naming the file: $(cat "$work/hidden-missing.log")"
[[ ! -e $work/hidden-missing/results.json ]] || fail "a grader error still wrote results.json"

step "mutants --assignment $id"
"$grade" mutants --assignment "$id" --jobs "$jobs" --out "$work/mutants" >"$work/mutants.log" 2>&1 || {
  cat "$work/mutants.log"
  fail "the mutation self-test of $id"
}
for m in t1-linear-drag t2-explicit-euler; do
  grep -q "^| $m | .*caught in its task only ✓ |$" "$work/mutants.log" ||
    fail "mutant $m not caught in its own task only ($work/mutants.log)"
done

step "selfcheck-$id (JELLY_TASKS=solutions: full marks)"
cmake --build "$tree/build" --target "selfcheck-$id" >"$work/selfcheck.log" 2>&1 || {
  cat "$work/selfcheck.log"
  fail "selfcheck-$id"
}

step "A1 beside it: its reference still 80/80"
# A1's reference as a submission: solutions/a1/ and its task module's files, as the build puts them.
"$grade" grade "$tree/build/assignments/a1/reference" --assignment a1 --visibility all --format gradescope \
  --jobs "$jobs" --out "$work/a1" >"$work/a1.log" 2>&1 || true
read -r a1_score a1_max < <(score_of "$work/a1/results.json")
[[ $a1_score == 80 && $a1_max == 80 ]] ||
  fail "A1's reference scores $a1_score / $a1_max beside $id, expected 80 / 80 ($work/a1.log)"

step "no tracked file changed"
changed=$(git -C "$tree" status --porcelain --untracked-files=all |
  grep -v -E "^\?\? (assignments/$id/|solutions/$id/|grader/data/$id/hidden/|framework/bodies/$kind/)" || true)
if [[ -n $changed ]]; then
  echo "$changed" | head -40 >&2
  fail "the plug-in needed changes outside its own folders (above)"
fi
git -C "$tree" diff --quiet HEAD || fail "git diff of the tree is not empty"

if "$tree/tools/make-student-release" --help 2>&1 | grep -q -- --assignments; then
  step "make-student-release --assignments $id"
  release=$work/release
  # The instructor commits the new folders (the release ships what git tracks).
  git -C "$tree" add "assignments/$id" "solutions/$id" "grader/data/$id" "framework/bodies/$kind"
  git -C "$tree" -c user.name=plugin -c user.email=plugin@invalid commit -q -m "add $id"
  "$tree/tools/make-student-release" "$release" --assignments "$id" --no-verify \
    >"$work/release.log" 2>&1 || {
    tail -30 "$work/release.log"
    fail "make-student-release --assignments $id"
  }
  release=$release/jelly-lab-student
  [[ -f $release/assignments/$id/assignment.toml ]] || fail "the release has no assignments/$id"
  [[ ! -e $release/solutions ]] || fail "the release holds solutions/"
  [[ ! -e $release/assignments/a1 ]] || fail "the release holds A1 (assignments/a1)"
  [[ ! -e $release/grader/data/$id/hidden ]] || fail "the release holds $id's hidden data"
  [[ ! -e $release/grader/data/a1 ]] || fail "the release holds A1's grader data"
else
  step "SKIPPED the release step: tools/make-student-release has no --assignments yet"
fi

step "$id as a draft (draft = true): built, but not graded, self-checked or released"
manifest=$tree/assignments/$id/assignment.toml
cp "$manifest" "$work/manifest.toml"
{ printf 'draft = true\n'; cat "$work/manifest.toml"; } >"$manifest"
cmake "$tree/build" >"$work/draft-configure.log" 2>&1 || fail "configure with the draft ($work/draft-configure.log)"
grep -q "assignment $id is a draft" "$work/draft-configure.log" ||
  fail "CMake did not say that $id is a draft ($work/draft-configure.log)"
config=$tree/build/grader/grade-config.json
python3 -c 'import json, sys; c = json.load(open(sys.argv[1])); sys.exit(sys.argv[2] in c["assignments"] or sys.argv[2] not in c["drafts"])' \
  "$config" "$id" || fail "grade-config.json lists $id among the assignments, or not among the drafts"
cmake --build "$tree/build" --target "jelly_${id}_tasks_solutions" "jelly_${id}_tasks_assignments" \
  >"$work/draft-build.log" 2>&1 || fail "the draft's task libraries did not build ($work/draft-build.log)"
status=0
"$grade" grade "$tree/solutions/$id" --assignment "$id" --out "$work/draft-grade" >"$work/draft-grade.log" 2>&1 ||
  status=$?
[[ $status == 2 ]] && grep -q -- "--assignment $id: $id is a draft in this build" "$work/draft-grade.log" &&
  grep -q -- "tries its grader with --draft" "$work/draft-grade.log" ||
  fail "grading the draft: status $status, expected 2, 'is a draft' and --draft ($work/draft-grade.log)"
# Its author grades it on request: the draft keeps its grader (grade-config.json's
# draft_assignments), and --draft grades its reference with full marks.
python3 -c 'import json, sys; c = json.load(open(sys.argv[1])); sys.exit(sys.argv[2] not in c["draft_assignments"])' \
  "$config" "$id" || fail "grade-config.json does not list $id among the draft_assignments"
cmake --build "$tree/build" --target jelly-grade >"$work/draft-grader-build.log" 2>&1 ||
  fail "the draft's grader did not build ($work/draft-grader-build.log)"
"$grade" grade "$tree/solutions/$id" --assignment "$id" --draft --visibility all --format gradescope \
  --out "$work/draft-on-request" >"$work/draft-on-request.log" 2>&1 || true
read -r draft_score draft_max < <(score_of "$work/draft-on-request/results.json")
[[ $draft_score == 20 && $draft_max == 20 ]] ||
  fail "the draft's reference graded with --draft scores $draft_score / $draft_max, expected 20 / 20 ($work/draft-on-request.log)"
status=0
"$tree/tools/make-student-release" "$work/draft-release" --assignments "$id" --no-verify \
  >"$work/draft-release.log" 2>&1 || status=$?
[[ $status == 2 ]] && grep -q -- "--assignments: $id is a draft" "$work/draft-release.log" ||
  fail "releasing the draft: status $status, expected 2 and 'is a draft' ($work/draft-release.log)"
cp "$work/manifest.toml" "$manifest"  # plugin.body runs the assignment's scene with this build
cmake "$tree/build" >"$work/undraft-configure.log" 2>&1 || fail "configure without the draft line"

step "PASSED: $id built, graded ($ref_score/$ref_max reference, $stub_score stubs), mutants caught, self-checked; A1 $a1_score/$a1_max"
echo "plugin: wall time $((SECONDS - start)) s"
