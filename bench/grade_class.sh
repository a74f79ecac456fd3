#!/usr/bin/env bash
# How long `jelly-grade batch` takes for a class (issue 21: "200 submissions in at most 8 minutes on
# 2 cores, with warm objects"). Not a test: it prints wall time, CPU time (when `perf` is there),
# the cost per submission and the --jobs scaling. docs/performance.md, "Grading a class", has the
# figures it gave.
#
#   bench/grade_class.sh [-n N] [-j "1 2 4"] [-g JELLY_GRADE] [-w WORK] [-c CLASS] [-- batch options]
#
#   -n N       students in the made-up class (default 200)
#   -j LIST    the --jobs values to time (default "1 2 4")
#   -g FILE    the grader (default build/grader/jelly-grade)
#   -w DIR     work folder (default /tmp/jelly-grade-class-bench)
#   -c DIR     grade this class instead of making one (a folder of student folders)
#   -t         the made-up files start with their task header's #include, as the stubs do (the
#              reference's files start with <cmath> or <array>: the grader's precompiled headers
#              serve only a file that starts with its task header)
#
# The made-up class: student sNNN is, in turn, the reference (solutions/a1) with one of the
# mutants of assignments/a1/grader/mutants/*.toml applied (find/replace), the plain reference, or
# the stubs (assignments/a1). Every file of every student ends with a comment naming the student
# and the run, so no two students (and no two runs) share a file: each compile is a real one, as in
# a real class, not a hit in the grader's object cache. After the --jobs runs, the last class is
# graded once more unchanged: that run's objects are all in the cache ("warm objects").
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
n=200; jobs_list="1 2 4"; grade="$here/build/grader/jelly-grade"; work=/tmp/jelly-grade-class-bench; class=""
header_first=0
while getopts "n:j:g:w:c:t" o; do
  case "$o" in
    n) n="$OPTARG" ;; j) jobs_list="$OPTARG" ;; g) grade="$OPTARG" ;; w) work="$OPTARG" ;; c) class="$OPTARG" ;;
    t) header_first=1 ;;
    *) sed -n '2,20p' "$0"; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
extra=("$@")
[ -x "$grade" ] || { echo "grade_class.sh: no grader at $grade (-g)"; exit 2; }
command -v python3 >/dev/null || { echo "grade_class.sh: needs python3 (3.11+, tomllib) to make the class"; exit 2; }
mkdir -p "$work"

# make_class DIR TAG: the class of $n, every file marked with its student and TAG.
make_class() {
  rm -rf "$1"
  python3 - "$here" "$1" "$n" "$2" "$header_first" <<'EOF'
import pathlib, re, sys, tomllib
root, out, n, tag = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
header_first = sys.argv[5] == "1"
files = ["springs.cpp", "forces.cpp", "collision.cpp", "contact.cpp", "integrators.cpp"]
mutants = []
for m in sorted((root / "assignments/a1/grader/mutants").glob("*.toml")):
    t = tomllib.loads(m.read_text())
    mutants.append((t["file"], [(r["find"], r["with"]) for r in t.get("replace", [])]))
kinds = len(mutants) + 2  # every mutant, the reference, the stubs
for i in range(n):
    sid = f"s{i:03d}"
    d = out / sid
    d.mkdir(parents=True)
    k = i % kinds
    src = root / ("assignments/a1" if k == kinds - 1 else "solutions/a1")
    for f in files:
        text = (src / f).read_text()
        if k < len(mutants) and mutants[k][0] == f:
            for find, with_ in mutants[k][1]:
                if find not in text:
                    sys.exit(f"mutant {k}: '{find}' not in {f}")
                text = text.replace(find, with_, 1)
        if header_first:
            m = re.search(r'^#include "jelly/a1/[a-z_]+\.hpp"\n', text, re.M)
            if m:
                text = m.group(0) + text[:m.start()] + text[m.end():]
        (d / f).write_text(text + f"\n// {sid} ({tag})\n")
EOF
}

have_perf=0
if command -v perf >/dev/null && perf stat -e task-clock -x, -o /dev/null true 2>/dev/null; then have_perf=1; fi
# timed LABEL CLASS OUT JOBS: one batch; prints its line and appends "label wall cpu" to results.
timed() {
  local label="$1" in="$2" out="$3" jobs="$4" start end wall cpu="-"
  rm -rf "$out"
  start=$(date +%s.%N)
  if [ "$have_perf" = 1 ]; then
    perf stat -e task-clock -x, -o "$work/perf.txt" "$grade" batch "$in" --assignment a1 --out "$out" \
      --jobs "$jobs" "${extra[@]}" >"$out.log" 2>&1 || true
    cpu=$(awk -F, '/task-clock/ {printf "%.1f", $1 / 1000}' "$work/perf.txt")
  else
    "$grade" batch "$in" --assignment a1 --out "$out" --jobs "$jobs" "${extra[@]}" >"$out.log" 2>&1 || true
  fi
  end=$(date +%s.%N)
  wall=$(echo "$end - $start" | bc)
  local count
  count=$(find "$in" -mindepth 1 -maxdepth 1 -type d | wc -l)
  grep -q "graded $count submissions" "$out.log" || { tail -5 "$out.log"; echo "grade_class.sh: the batch did not grade all $count"; exit 1; }
  printf '%-28s --jobs %s: wall %7.1f s  (%5.2f s per submission; %5.2f core-s each)  CPU %s s%s\n' \
    "$label" "$jobs" "$wall" "$(echo "$wall / $count" | bc -l)" "$(echo "$wall * $jobs / $count" | bc -l)" "$cpu" \
    "$([ "$cpu" = - ] || printf ' (%.2f s per submission)' "$(echo "$cpu / $count" | bc -l)")"
  echo "${label// /_} $jobs $wall $cpu $count" >>"$work/results.txt"
}

: >"$work/results.txt"
echo "grade_class.sh: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), grader $grade, batch options: --assignment a1 ${extra[*]}"
last=""
for j in $jobs_list; do
  in="$class"
  if [ -z "$in" ]; then
    in="$work/class-j$j"
    make_class "$in" "run $j $(date +%s%N)"
  fi
  timed "$([ -n "$class" ] && echo "the given class" || echo "distinct files")" "$in" "$work/out-j$j" "$j"
  last="$in"; last_j="$j"
done
# The same class again: every object is in the cache.
timed "warm objects (again)" "$last" "$work/out-warm" "$last_j"
# Scaling against the first --jobs, and what a class of 200 would take at each.
awk 'NR == 1 { base = $3; first = $2 }
     { printf "  %-22s --jobs %s: %.2fx the speed of --jobs %s; a class of 200: %.1f min\n", $1, $2, base / $3, first, $3 / $5 * 200 / 60 }' \
  "$work/results.txt"
echo "load afterwards: $(cut -d' ' -f1-3 /proc/loadavg)"
