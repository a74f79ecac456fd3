#!/usr/bin/env bash
# How much `jelly-grade batch` costs per student, cold and warm (issue 21: "200 submissions in at
# most 8 minutes on 2 cores, with warm objects"; issue 28: "a cold class costs three times the CPU
# of a warm one on many cores"). Not a test: for each --jobs value it grades a new class whose every
# file is new (cold: every compile is real) and then the same class again (warm: every object is in
# the cache), and prints the CPU seconds per submission of each (`perf stat`, which counts the
# sandboxed children; else /usr/bin/time), their ratio, and the wall time. With -r R each is run R
# times and the median printed. docs/performance.md, "Grading a class", has the figures it gave.
#
#   bench/grade_class.sh [-n N] [-j "1 2 4"] [-r R] [-e] [-t] [-g JELLY_GRADE] [-w WORK] [-c CLASS]
#                        [-- batch options]
#
#   -n N       students in the made-up class (default 200)
#   -j LIST    the --jobs values to time (default "1 2 CORES": this machine's core count)
#   -r R       runs of each (cold and warm) per --jobs value; the median is reported (default 1)
#   -e         every cold run starts from an empty object cache (its own $JELLY_GRADE_CACHE): it
#              then also builds the artefacts every student shares (the stubs' objects, the
#              precompiled task headers), as the first batch of a new build does
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
# a real class, not a hit in the grader's object cache. After each cold run the same class is graded
# once more unchanged, at the same --jobs: that run's objects are all in the cache ("warm").
# With -c the given class is graded instead (cold only when its objects are not yet cached).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cores="$(nproc 2>/dev/null || echo 2)"
n=200; jobs_list="$(printf '%s\n' 1 2 "$cores" | awk '!seen[$0]++' | tr '\n' ' ')"; repeats=1; empty_cache=0; grade="$here/build/grader/jelly-grade"; work=/tmp/jelly-grade-class-bench; class=""
header_first=0
while getopts "n:j:r:g:w:c:te" o; do
  case "$o" in
    n) n="$OPTARG" ;; j) jobs_list="$OPTARG" ;; g) grade="$OPTARG" ;; w) work="$OPTARG" ;; c) class="$OPTARG" ;;
    r) repeats="$OPTARG" ;; t) header_first=1 ;; e) empty_cache=1 ;;
    *) sed -n '2,30p' "$0"; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
extra=("$@")
case "$repeats" in ''|*[!0-9]*|0) echo "grade_class.sh: -r needs a positive number"; exit 2 ;; esac
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
have_time=0; [ -x /usr/bin/time ] && have_time=1
# run_batch CLASS OUT JOBS: one batch; prints "wall cpu" (cpu "-" without perf or /usr/bin/time).
run_batch() {
  local in="$1" out="$2" jobs="$3" start end cpu="-"
  rm -rf "$out"
  start=$(date +%s.%N)
  if [ "$have_perf" = 1 ]; then
    perf stat -e task-clock -x, -o "$work/cpu.txt" "$grade" batch "$in" --assignment a1 --out "$out" \
      --jobs "$jobs" "${extra[@]}" >"$out.log" 2>&1 || true
    cpu=$(awk -F, '/task-clock/ {printf "%.2f", $1 / 1000}' "$work/cpu.txt")
  elif [ "$have_time" = 1 ]; then
    /usr/bin/time -f "%U %S" -o "$work/cpu.txt" "$grade" batch "$in" --assignment a1 --out "$out" \
      --jobs "$jobs" "${extra[@]}" >"$out.log" 2>&1 || true
    cpu=$(awk 'END {printf "%.2f", $1 + $2}' "$work/cpu.txt")
  else
    "$grade" batch "$in" --assignment a1 --out "$out" --jobs "$jobs" "${extra[@]}" >"$out.log" 2>&1 || true
  fi
  end=$(date +%s.%N)
  local count
  count=$(find "$in" -mindepth 1 -maxdepth 1 -type d | wc -l)
  grep -q "graded $count submissions" "$out.log" || { tail -5 "$out.log" >&2; echo "grade_class.sh: the batch did not grade all $count" >&2; exit 1; }
  echo "$(echo "$end - $start" | bc) $cpu"
}

# median: the median of the numbers on stdin ("-" when there are none).
median() { sort -g | awk '{ v[NR] = $1 } END { if (!NR) print "-"; else if (NR % 2) print v[(NR + 1) / 2]; else printf "%.3f\n", (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

echo "grade_class.sh: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), grader $grade"
echo "  class: $([ -n "$class" ] && echo "$class" || echo "$n made-up students$([ "$header_first" = 1 ] && echo ", files start with their task header (-t)")"); batch options: --assignment a1 ${extra[*]}"
echo "  cold runs: $([ "$empty_cache" = 1 ] && echo "empty object cache (-e: the shared artefacts are built too)" || echo "the object cache as it is (stubs and precompiled headers of earlier runs kept)"); $repeats run(s) of each; CPU by $([ "$have_perf" = 1 ] && echo "perf stat" || { [ "$have_time" = 1 ] && echo "/usr/bin/time (the sandboxed runs may be missed)" || echo "nothing (install perf)"; })"
: >"$work/results.txt"
for j in $jobs_list; do
  for ((r = 1; r <= repeats; r++)); do
    in="$class"
    if [ -z "$in" ]; then
      in="$work/class-j$j"
      make_class "$in" "run $j.$r $(date +%s%N)"
    fi
    count=$(find "$in" -mindepth 1 -maxdepth 1 -type d | wc -l)
    if [ "$empty_cache" = 1 ]; then
      rm -rf "$work/cache"; export JELLY_GRADE_CACHE="$work/cache"
    fi
    res=$(run_batch "$in" "$work/out-cold" "$j"); read -r wall cpu <<<"$res"
    echo "cold $j $wall $cpu $count" >>"$work/results.txt"
    printf '  --jobs %-3s run %s cold: wall %7.1f s, CPU %s s\n' "$j" "$r" "$wall" "$cpu"
    res=$(run_batch "$in" "$work/out-warm" "$j"); read -r wall cpu <<<"$res"
    echo "warm $j $wall $cpu $count" >>"$work/results.txt"
    printf '  --jobs %-3s run %s warm: wall %7.1f s, CPU %s s\n' "$j" "$r" "$wall" "$cpu"
  done
done
# Per --jobs: the medians per submission, cold and warm, and their ratio; what a class of 200 takes.
echo
echo "| --jobs | CPU per submission, cold | warm | cold / warm | wall per submission, cold | warm | a class of 200, cold / warm |"
echo "|---|---|---|---|---|---|---|"
for j in $jobs_list; do
  per() { awk -v k="$1" -v j="$j" -v f="$2" '$1 == k && $2 == j && $f != "-" { printf "%.3f\n", $f / $5 }' "$work/results.txt" | median; }
  cc=$(per cold 4); wc_=$(per warm 4); cw=$(per cold 3); ww=$(per warm 3)
  ratio=$(awk -v a="$cc" -v b="$wc_" 'BEGIN { if (a == "-" || b == "-" || b == 0) print "-"; else printf "%.2fx", a / b }')
  printf '| %s | %s s | %s s | %s | %s s | %s s | %.1f / %.1f min |\n' "$j" "$cc" "$wc_" "$ratio" "$cw" "$ww" \
    "$(echo "$cw * 200 / 60" | bc -l)" "$(echo "$ww * 200 / 60" | bc -l)"
done
echo "load afterwards: $(cut -d' ' -f1-3 /proc/loadavg)"
