#!/usr/bin/env bash
# Grading a class in parts (issue 21): `jelly-grade batch` in 4 shards then `merge` gives the same
# class files, byte for byte, as one batch; a batch stopped by SIGINT or SIGKILL while a student is
# being graded leaves no half-made student folder and no sandboxed process, and --resume grades
# only those not finished and ends with the same class files; a changed submission, --timeout or
# --visibility is graded again; merge refuses a missing shard, a shard given twice, parts graded
# differently and a folder that is not a batch's, naming the part; and grader/tools/slurm-batch.sh
# run as a Slurm array would run it (its environment set by hand) gives the same class files too.
#
#   batch_parts.sh JELLY_GRADE SOURCE WORK REFERENCE
#
# REFERENCE is A1's reference as a submission (the build's build/assignments/a1/reference/).
#
# Exit 0 when everything holds.
set -uo pipefail
grade="$(realpath "${1:?jelly-grade}")"; source="$(realpath "${2:?source tree}")"
work="$(realpath -m "${3:?work folder}")"; reference="$(realpath "${4:?reference folder}")"
fail() { echo "batch_parts: FAILED: $*"; exit 1; }
rm -rf "$work"
mkdir -p "$work/in"
in="$work/in"
# Few seconds of --timeout: ben's one endless case ends after it (on a busy machine a normal case
# takes well under a second).
opts=(--assignment a1 --no-frames --timeout 3)

# The class: alice the reference, ben the reference with one endless case (spring_force loops for
# ks = 1e6, which only a1.t4.spring_force.values uses: one time-out), bob the stubs, carol a flipped
# spring sign, dave no task file at all.
cp -r "$reference" "$in/alice"
cp -r "$reference" "$in/ben"
sed -i '0,/  const Vec3 d = xa - xb;/s||  if (ks == 1e6) {\n    volatile bool spin = true;\n    while (spin) {\n    }\n  }\n  const Vec3 d = xa - xb;|' \
  "$in/ben/forces.cpp"
grep -q 'volatile bool spin' "$in/ben/forces.cpp" || fail "the reference forces.cpp changed: update ben"
cp -r "$source/assignments/a1" "$in/bob"
cp -r "$reference" "$in/carol"
sed -i 's|return (-ks \* (length - rest_length)) \* u;|return (ks * (length - rest_length)) * u;|' "$in/carol/forces.cpp"
grep -q 'return (ks \*' "$in/carol/forces.cpp" || fail "the reference forces.cpp changed: update carol"
mkdir -p "$in/dave"
echo "I ran out of time" >"$in/dave/notes.txt"
students=(alice ben bob carol dave)

# The top-level files of two batch folders: the same names and the same bytes.
same_class_files() {
  local a="$1" b="$2" f
  [ "$(cd "$a" && find . -maxdepth 1 -type f | sort)" = "$(cd "$b" && find . -maxdepth 1 -type f | sort)" ] ||
    fail "$a and $b hold different class files: $(cd "$a" && ls -p | grep -v /) | $(cd "$b" && ls -p | grep -v /)"
  for f in "$a"/*; do
    [ -f "$f" ] || continue
    cmp -s "$f" "$b/$(basename "$f")" || { diff "$f" "$b/$(basename "$f")" | head -20; fail "$(basename "$f") differs between $a and $b"; }
  done
}
# Each student's folder: the same files, the same bytes; results.json but for its execution_time
# (the seconds that student's grading took).
same_students() {
  local a="$1" b="$2" s f
  [ "$(ls -A "$a/students")" = "$(ls -A "$b/students")" ] || fail "$a and $b hold other students"
  for s in "${students[@]}"; do
    [ "$(cd "$a/students/$s" && find . -type f | sort)" = "$(cd "$b/students/$s" && find . -type f | sort)" ] ||
      fail "$s's files differ between $a and $b"
    cmp -s "$a/students/$s/record.json" "$b/students/$s/record.json" || fail "$s's record.json differs"
    [ -f "$a/students/$s/results.json" ] || continue
    [ "$(jq -S 'del(.execution_time)' "$a/students/$s/results.json")" = \
      "$(jq -S 'del(.execution_time)' "$b/students/$s/results.json")" ] || fail "$s's results.json differs beyond its time"
    for f in $(cd "$a/students/$s" && find . -type f ! -name results.json); do
      cmp -s "$a/students/$s/$f" "$b/students/$s/$f" || { diff "$a/students/$s/$f" "$b/students/$s/$f" | head; fail "$s's $f differs"; }
    done
  done
}
# Every sandboxed or compiling process below PID (recursively).
descendants() {
  local p
  for p in $(ps -o pid= --ppid "$1" 2>/dev/null); do
    echo "$p"
    descendants "$p"
  done
}

# 1. One batch, the whole class.
"$grade" batch "$in" "${opts[@]}" --jobs 2 --out "$work/one" >"$work/one.txt" 2>&1 ||
  { cat "$work/one.txt"; fail "one batch failed"; }
grep -q '^ben,' "$work/one/scores.csv" || fail "no ben in scores.csv"
grep -q '^alice,80.00,80.00' "$work/one/scores.csv" || fail "alice is not 80 / 80: $(cat "$work/one/scores.csv")"
jq -e '.cases[] | select(.id == "a1.t4.spring_force.values") | .abnormal == "timed out"' \
  "$work/one/students/ben/record.json" >/dev/null || fail "ben's endless case did not time out"

# 2. The same class in 4 shards, then merged.
for i in 1 2 3 4; do
  "$grade" batch "$in" "${opts[@]}" --jobs 1 --shard "$i/4" --out "$work/part$i" >"$work/part$i.txt" 2>&1 ||
    { cat "$work/part$i.txt"; fail "shard $i/4 failed"; }
done
[ "$(jq -r '.students | join(" ")' "$work/part1/batch.json")" = "alice dave" ] ||
  fail "shard 1/4 is not alice and dave: $(jq -c .students "$work/part1/batch.json")"
"$grade" merge "$work/part1" "$work/part2" "$work/part3" "$work/part4" --out "$work/merged" >"$work/merged.txt" 2>&1 ||
  { cat "$work/merged.txt"; fail "merge failed"; }
same_class_files "$work/one" "$work/merged"
same_students "$work/one" "$work/merged"
echo "batch_parts: 4 shards merged = one batch"

# 3. What merge refuses, naming the part.
refuses() {  # refuses WHAT EXPECTED-TEXT PARTS...
  local what="$1" expect="$2" out
  shift 2
  out="$("$grade" merge "$@" --out "$work/refused" 2>&1)" && fail "merge took $what"
  [ -e "$work/refused/scores.csv" ] && fail "merge wrote scores.csv for $what"
  grep -qF -- "$expect" <<<"$out" || fail "merge's message for $what does not say '$expect': $out"
  echo "batch_parts: merge refuses $what: $(tail -1 <<<"$out")"
}
refuses "a missing shard" "shard 3/4 is missing" "$work/part1" "$work/part2" "$work/part4"
refuses "the same shard twice" "$work/part2" "$work/part1" "$work/part2" "$work/part2" "$work/part3" "$work/part4"
"$grade" batch "$in" --assignment a1 --no-frames --timeout 4 --shard 4/4 --out "$work/part4-timeout" \
  >"$work/part4-timeout.txt" 2>&1 || { cat "$work/part4-timeout.txt"; fail "shard 4/4 with --timeout 4 failed"; }
refuses "parts graded with another --timeout" "$work/part4-timeout/batch.json was graded differently" \
  "$work/part1" "$work/part2" "$work/part3" "$work/part4-timeout"
refuses "a folder that is not a batch's" "$in/batch.json does not exist" "$work/part1" "$work/part2" "$work/part3" "$in"

# 4. A batch stopped while ben's endless case runs, then --resume; SIGINT (Ctrl-C), SIGTERM (a
# scheduler's cancel) and SIGKILL.
for sig in INT TERM KILL; do
  out="$work/stopped-$sig"
  env --default-signal=INT "$grade" batch "$in" "${opts[@]}" --jobs 1 --out "$out" >"$out.txt" 2>&1 &
  pid=$!
  # ben is the second in id order: stop when his case runs (his folder is being made and the
  # runner has started), so alice is finished and bob, carol and dave are not begun.
  for _ in $(seq 600); do
    [ -d "$out/students/.ben.partial" ] && [ -n "$(descendants "$pid")" ] && break
    sleep 0.1
  done
  sleep 1
  [ -d "$out/students/.ben.partial" ] || fail "SIG$sig: the batch never reached ben: $(cat "$out.txt")"
  kids="$(descendants "$pid")"
  [ -n "$kids" ] || fail "SIG$sig: nothing ran under the batch while ben was graded"
  kill -"$sig" "$pid"
  wait "$pid"
  rc=$?
  [ "$rc" -ne 0 ] || fail "SIG$sig: the stopped batch exited 0"
  # Within 5 s nothing of the batch runs: the lane keeper (a child of the grader) outlives a
  # SIGKILLed grader for the moment it takes to end the lanes, then exits too.
  for _ in $(seq 50); do
    alive=""
    for k in $kids; do
      if [ -e "/proc/$k" ] && [ "$(awk '{print $3}' "/proc/$k/stat" 2>/dev/null)" != Z ]; then
        alive="$alive $k ($(tr '\0' ' ' <"/proc/$k/cmdline" 2>/dev/null))"
      fi
    done
    [ -z "$alive" ] && break
    sleep 0.1
  done
  [ -z "$alive" ] || fail "SIG$sig: process$alive still runs 5 s after the batch was stopped"
  # No half-made student folder: alice is whole, ben only as .ben.partial, the rest not begun.
  [ -f "$out/students/alice/record.json" ] || fail "SIG$sig: alice's finished folder is gone"
  [ "$(ls -A "$out/students" | sort | tr '\n' ' ')" = ".ben.partial alice " ] ||
    fail "SIG$sig: students/ holds $(ls -A "$out/students" | tr '\n' ' ')(expected .ben.partial alice)"
  [ -e "$out/batch.json" ] && fail "SIG$sig: a stopped batch left a batch.json (merge would take it)"
  refuses "a stopped part (SIG$sig)" "$out/batch.json does not exist" "$out"
  finished=$(find "$out/students" -mindepth 2 -maxdepth 2 -name record.json | wc -l)
  "$grade" batch "$in" "${opts[@]}" --jobs 2 --out "$out" --resume >"$out-resumed.txt" 2>&1 ||
    { cat "$out-resumed.txt"; fail "SIG$sig: --resume failed"; }
  grep -qF "1 of 5 submissions already graded (kept), 4 to grade" "$out-resumed.txt" ||
    fail "SIG$sig: --resume did not keep the $finished finished one and grade 4: $(cat "$out-resumed.txt")"
  grep -q "5 graded, 0 not graded; this run took 4, kept 1 into" "$out-resumed.txt" || fail "SIG$sig: no 'kept 1': $(cat "$out-resumed.txt")"
  [ -e "$out/students/.ben.partial" ] && fail "SIG$sig: .ben.partial is still there after --resume"
  same_class_files "$work/one" "$out"
  same_students "$work/one" "$out"
  echo "batch_parts: SIG$sig while ben was graded, then --resume: kept $finished, graded 4, the same class files"
done

# 5. --resume grades again what changed: a submission's file, --timeout, --visibility.
out="$work/stopped-KILL"
echo "// resubmitted" >>"$in/carol/forces.cpp"
"$grade" batch "$in" "${opts[@]}" --jobs 2 --out "$out" --resume >"$out-changed.txt" 2>&1 ||
  { cat "$out-changed.txt"; fail "--resume after carol's change failed"; }
grep -qF "4 of 5 submissions already graded (kept), 1 to grade" "$out-changed.txt" ||
  fail "carol's changed file was not graded again: $(cat "$out-changed.txt")"
grep -q '] carol: ' "$out-changed.txt" || fail "not carol graded again: $(cat "$out-changed.txt")"
# Another --timeout or --visibility: nobody is kept (stopped as soon as it has said so).
for other in "--timeout 4" "--timeout 3 --visibility public"; do
  log="$work/changed-$(tr -dc a-z <<<"$other").txt"
  # shellcheck disable=SC2086 # $other is two or four words
  "$grade" batch "$in" --assignment a1 --no-frames $other --jobs 1 --out "$out" --resume >"$log" 2>&1 &
  pid=$!
  for _ in $(seq 300); do grep -q "to grade" "$log" && break; sleep 0.1; done
  kill -KILL "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  grep -qF "0 of 5 submissions already graded (kept), 5 to grade" "$log" ||
    fail "$other: --resume kept students graded otherwise: $(cat "$log")"
done
echo "batch_parts: --resume grades again a changed file, --timeout and --visibility"

# 6. The Slurm array script, its environment set by hand as sbatch --array=1-3 sets it.
slurm="$source/grader/tools/slurm-batch.sh"
for t in 1 2 3; do
  SLURM_ARRAY_TASK_ID=$t SLURM_ARRAY_TASK_COUNT=3 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_MAX=3 \
    JELLY_GRADE="$grade" bash "$slurm" "$in" "$work/slurm" "${opts[@]}" >"$work/slurm-$t.txt" 2>&1 ||
    { cat "$work/slurm-$t.txt"; fail "slurm-batch.sh task $t failed"; }
done
[ -f "$work/slurm/part-2-of-3/batch.json" ] || fail "slurm-batch.sh task 2 wrote no part-2-of-3"
"$grade" merge "$work/slurm"/part-*-of-3 --out "$work/slurm/class" >"$work/slurm-merge.txt" 2>&1 ||
  { cat "$work/slurm-merge.txt"; fail "merge of the Slurm parts failed"; }
# carol changed in step 5: grade the class once more in one batch to compare with.
"$grade" batch "$in" "${opts[@]}" --jobs 2 --out "$work/one-again" >"$work/one-again.txt" 2>&1 ||
  { cat "$work/one-again.txt"; fail "the second whole batch failed"; }
same_class_files "$work/one-again" "$work/slurm/class"
same_students "$work/one-again" "$work/slurm/class"
echo "batch_parts: the Slurm array's 3 parts merged = one batch"

# 7. The GNU parallel lines of docs/instructor-guide.md (with this test's options added), when the
# Debian package `parallel` is installed.
if command -v parallel >/dev/null; then
  mkdir -p "$work/parallel"
  ln -s ../in "$work/parallel/submissions"
  (
    cd "$work/parallel" || exit 1
    PATH="$(dirname "$grade"):$PATH"
    parallel jelly-grade batch submissions/ --assignment a1 --jobs 1 --out parts/{} --shard {}/4 \
      --no-frames --timeout 3 ::: 1 2 3 4 </dev/null >parallel.txt 2>&1 || { cat parallel.txt; exit 1; }
    jelly-grade merge parts/1 parts/2 parts/3 parts/4 --out results/ >merge.txt 2>&1 || { cat merge.txt; exit 1; }
  ) || fail "the GNU parallel commands failed"
  same_class_files "$work/one-again" "$work/parallel/results"
  # The reports name the submission's folder (here parallel/submissions/<id>, not in/<id>): only
  # the records can be the same bytes.
  for s in "${students[@]}"; do
    cmp -s "$work/one-again/students/$s/record.json" "$work/parallel/results/students/$s/record.json" ||
      fail "$s's record.json differs between one batch and GNU parallel's parts"
  done
  echo "batch_parts: GNU parallel's 4 parts merged = one batch"
else
  echo "batch_parts: no GNU parallel here (Debian package parallel): its lines were not run"
fi
echo "batch_parts: PASSED"
