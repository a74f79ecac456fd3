#!/usr/bin/env bash
# The release's link check is a test that can fail (issue 12: the release shipped docs linking to
# files it leaves out). On a small folder, no build: the check passes on good links (files, folders,
# images, anchors, web links, links inside code), then fails on each planted dead link, naming the
# file, the line and the target.
#   test_release_links.sh SOURCE_DIR WORK_DIR
set -uo pipefail
src="${1:?source dir}"; work="${2:?work dir}"
tool="$src/tools/make-student-release"
failures=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; failures=$((failures + 1)); fi; }

rm -rf "$work"; mkdir -p "$work/good/docs/handout/figures" "$work/good/tools"
good="$work/good"
touch "$good/README.md" "$good/docs/physics.md" "$good/docs/handout/figures/plane.svg" "$good/tools/selfcheck"
cat >"$good/docs/handout/T6.md" <<'MD'
# T6
See [the contract](../physics.md#5-contact), ![the plane](figures/plane.svg "a plane"),
[the top](../../README.md), [a folder](../../tools/), [a section](#check-yourself),
[the web](https://example.org/x.md), [mail](mailto:a@b.c), the contract `docs/physics.md`,
a file the tools write `report.md`, and `[not a link](missing.md)` in code.

```sh
cat [also code](missing-too.md)
```
MD
"$tool" --check-links "$good" >"$work/good.log" 2>&1
check "good links pass" '[ $? -eq 0 ] || { cat "$work/good.log"; false; }'

plant() {  # plant WHAT LINE-TO-ADD EXPECTED-TEXT
  local copy="$work/copy" want="$3"
  rm -rf "$copy"; cp -a "$good" "$copy"
  printf '%s\n' "$2" >>"$copy/docs/handout/T6.md"
  "$tool" --check-links "$copy" >"$work/plant.log" 2>&1
  local rc=$?
  check "fails on $1" '[ $rc -ne 0 ] && grep -qF -- "$want" "$work/plant.log" || { cat "$work/plant.log"; false; }'
}
plant "a link outside the folder" "The [spec](../../../shared/spec/physics.md)." \
  "docs/handout/T6.md:10: links to ../../../shared/spec/physics.md, which the release does not contain"
plant "a link to a left-out file" "The [table](../mutation-table.md#t6)." "links to ../mutation-table.md#t6"
plant "a dead image" "![plot](figures/missing.png)" "links to figures/missing.png"
plant "a Markdown file named by its path in code" 'See `docs/instructor-guide.md`.' "names docs/instructor-guide.md"
plant "a link in a table row" "| a | [b](../../tests/grader/) |" "links to ../../tests/grader/"

[ "$failures" -eq 0 ] && echo "all link checks passed" || echo "$failures check(s) failed"
exit $(( failures > 0 ))
