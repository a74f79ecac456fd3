#!/usr/bin/env bash
# In a tree with several assignments, `tools/selfcheck --task ID` checks the assignment whose tasks
# the id names (a task page's command works as printed, whatever else the release holds); an id no
# assignment has, or one several share, is a usage error (status 2) that says what to do. On a copy
# of the self-check beside the tree's manifests and no task files: the run stops at the first
# missing file, which names the assignment chosen. No build; seconds.
#   test_selfcheck_task.sh SOURCE_DIR WORK_DIR
set -uo pipefail
src="${1:?source dir}"; work="${2:?work dir}"
failures=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; failures=$((failures + 1)); fi; }

rm -rf "$work"; mkdir -p "$work/tree/tools"
cp "$src/tools/selfcheck" "$src/tools/jelly_manifest.py" "$work/tree/tools/"
ids=()
for m in "$src"/assignments/*/assignment.toml; do
  [ "$(python3 "$src/tools/jelly_manifest.py" get "$m" draft)" = true ] && continue  # not graded
  id="$(basename "$(dirname "$m")")"; ids+=("$id")
  mkdir -p "$work/tree/assignments/$id"; cp "$m" "$work/tree/assignments/$id/"
done
[ "${#ids[@]}" -ge 2 ] || { echo "SKIPPED: this tree has fewer than two assignments"; exit 0; }
run() { (cd "$work/tree" && tools/selfcheck --no-install --build-dir "$work/build" "$@") >"$work/out.txt" 2>&1; echo $? >"$work/rc"; }

for id in "${ids[@]}"; do
  # The last task of each manifest, as its task page prints it (--task A1.T13).
  task="$(awk '/^[ \t]*\[\[task\]\]/ { t = 1 } t && /^[ \t]*id[ \t]*=/ { v = $0; sub(/^[^=]*=[ \t]*"/, "", v); sub(/".*/, "", v); last = v } END { print last }' "$src/assignments/$id/assignment.toml")"
  run --task "$task"
  check "--task $task checks $id" 'grep -q "assignments/$id/assignment.toml lists it" "$work/out.txt" || { cat "$work/out.txt"; false; }'
  run --task "$(printf '%s' "$task" | tr 'A-Z' 'a-z')"
  check "--task in lower case checks $id too" 'grep -q "assignments/$id/assignment.toml lists it" "$work/out.txt"'
done
run --task ZZ9.T1
check "an id no assignment has: status 2, named" '[ "$(cat "$work/rc")" -eq 2 ] && grep -q -- "--task ZZ9.T1: no assignment here" "$work/out.txt" || { cat "$work/out.txt"; false; }'
run
check "no --task and no --assignment outside a folder: status 2, says --assignment" '[ "$(cat "$work/rc")" -eq 2 ] && grep -q -- "--assignment" "$work/out.txt"'

# A draft (draft = true): never chosen, and named as a draft when asked for.
mkdir -p "$work/tree/assignments/zdraft"
sed -e '0,/^id = .*/s//id = "zdraft"/' -e 's/^namespace = .*/namespace = "zdraft"/' \
  "$src/assignments/${ids[0]}/assignment.toml" >"$work/tree/assignments/zdraft/assignment.toml"
printf 'draft = true\n' | cat - "$work/tree/assignments/zdraft/assignment.toml" >"$work/draft.toml"
mv "$work/draft.toml" "$work/tree/assignments/zdraft/assignment.toml"
run --assignment zdraft
check "--assignment of a draft: status 2, says it is a draft" '[ "$(cat "$work/rc")" -eq 2 ] && grep -q -- "--assignment zdraft: .*says draft = true: a draft is built but not graded" "$work/out.txt" || { cat "$work/out.txt"; false; }'
check "the draft is not among the assignments it lists" '! grep -q "assignments here: .*zdraft" "$work/out.txt"'
# The draft's manifest is a copy of the first assignment's: its tasks would make --task ambiguous.
first_task="$(awk '/^[ \t]*\[\[task\]\]/ { t = 1 } t && /^[ \t]*id[ \t]*=/ { v = $0; sub(/^[^=]*=[ \t]*"/, "", v); sub(/".*/, "", v); print v; exit }' "$src/assignments/${ids[0]}/assignment.toml")"
run --task "$first_task"
check "--task of a task the draft shares still picks ${ids[0]}" 'grep -q "assignments/${ids[0]}/assignment.toml lists it" "$work/out.txt" || { cat "$work/out.txt"; false; }'

[ "$failures" -eq 0 ] || { echo "$failures check(s) failed"; exit 1; }
echo "selfcheck --task: OK"
