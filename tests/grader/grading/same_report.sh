#!/usr/bin/env bash
# The self-check must say what the grader says (issue 10): same tasks, points, tests and messages.
# Compares two `jelly-grade grade --format terminal` reports after removing only what may differ
# by design: the sandbox line and a missing-sandbox warning (the self-check has no sandbox), the
# timings on the Total line, and Windows line ends.
#
#   same_report.sh GRADER_REPORT SELFCHECK_REPORT
#
# Exit 0: the same; 1: different (the diff is printed).
set -uo pipefail
normal() {
  sed -e 's/\r$//' -e '/^  sandbox: /d' -e '/^  note: WARNING: /d' \
      -e 's/^\(Total: [0-9.]* \/ [0-9.]*\).*/\1/' "$1"
}
a="$(normal "${1:?grader report}")" || exit 1
b="$(normal "${2:?self-check report}")" || exit 1
if [ -z "$a" ] || [ "$a" != "$b" ]; then
  echo "same_report: the reports differ (< $1, > $2):"
  diff <(echo "$a") <(echo "$b") | head -40
  exit 1
fi
echo "same_report: same report lines ($(echo "$a" | wc -l) lines, $(echo "$a" | grep '^Total:'))"
