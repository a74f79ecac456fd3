#!/usr/bin/env bash
# The handout page that explains the report's words (assignments/ID/handout/reading-your-report.md)
# covers every word the grader's messages link to it, with the values the grader uses:
#   - a heading "### Tolerance `NAME`" for every [tolerance.NAME] of the assignment's
#     grader/cases/tolerances.toml, whose first paragraph starts "atol A, rtol R" with the file's
#     numbers (so a changed tolerance fails here until the page says so);
#   - a heading "### Name contract §N" for every "name contract §N" whose name is one of the
#     manifest's `contracts` (cloth, kinematics), and "### Contract §N" for every other
#     "contract §N" (the physics contract), in the case files and the runner's case code;
#   - the handout's README links the page.
# The report's links point at these headings' anchors (tolerance-NAME, contract-N,
# cloth-contract-N: grader/src/reports/report.cpp, find_terms).
#
#   check_terms_page.sh SOURCE_DIR ID
set -euo pipefail
root="${1:?source dir}"; id="${2:?assignment id}"
page="$root/assignments/$id/handout/reading-your-report.md"
tols="$root/assignments/$id/grader/cases/tolerances.toml"
fail=0
[ -f "$page" ] || { echo "check_terms_page: $page is missing"; exit 1; }
names="$(sed -n 's/^\[tolerance\.\([a-z_]*\)\][[:space:]]*$/\1/p' "$tols")"
[ -n "$names" ] || { echo "check_terms_page: no [tolerance.NAME] in $tols"; exit 1; }
for n in $names; do
  want="$(awk -v n="$n" '/^\[/ { on = ($0 == "[tolerance." n "]") } on && /^(atol|rtol)[ \t]*=/ { sub(/^[a-z]+[ \t]*=[ \t]*/, ""); printf "%s ", $0 }' "$tols")"
  got="$(awk -v h="### Tolerance \`$n\`" '$0 == h { on = 1; next } on && /^atol / { print; exit } on && /^#/ { exit }' "$page")"
  if [ -z "$got" ]; then
    echo "check_terms_page: $page: no \"### Tolerance \`$n\`\" section starting \"atol A, rtol R\" (tolerance $n of $tols)"
    fail=1; continue
  fi
  if ! awk -v want="$want" -v got="$got" 'BEGIN {
         split(want, w, " "); g = got; sub(/^atol /, "", g); split(g, p, /, rtol |\. /)
         exit !((w[1] + 0 == p[1] + 0) && (w[2] + 0 == p[2] + 0)) }'; then
    echo "check_terms_page: $page: tolerance $n says \"$got\", $tols has atol, rtol = $want"
    fail=1
  fi
done
# The manifest's contracts (one line `contracts = ["cloth"]`); any other word before "contract §N"
# is prose ("the contract §9"): the physics contract.
contracts=" $(sed -n 's/^contracts[[:space:]]*=[[:space:]]*\[\(.*\)\][[:space:]]*$/\1/p' "$root/assignments/$id/assignment.toml" | tr -d '",') "
while IFS= read -r term; do
  name="${term%%contract §*}"; name="${name% }"
  if [ -n "$name" ] && [[ "$contracts" == *" $name "* ]]; then
    h="### ${name^} contract §${term##*§}"
  else
    h="### Contract §${term##*§}"
  fi
  grep -qxF "$h" "$page" || { echo "check_terms_page: $page: no \"$h\" heading (\"$term\" is in the grader's cases)"; fail=1; }
done < <(grep -rhoE '([a-z-]+ )?contract §[0-9]+' "$root/assignments/$id/grader/cases" "$root/assignments/$id/grader/runner" | sort -u)
grep -q '(reading-your-report.md)' "$root/assignments/$id/handout/README.md" ||
  { echo "check_terms_page: assignments/$id/handout/README.md does not link reading-your-report.md"; fail=1; }
[ "$fail" = 0 ] && echo "check_terms_page: $id: every tolerance and contract section is explained"
exit "$fail"
