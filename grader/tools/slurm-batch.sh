#!/usr/bin/env bash
# One part of a class graded as a Slurm array job (docs/instructor-guide.md, "Spreading the work"):
# array task I of N grades `jelly-grade batch --shard I/N` into OUT/part-I-of-N; when every task has
# ended, `jelly-grade merge OUT/part-*-of-N --out OUT/class` joins the parts into the same files as
# one batch would have written.
#
#   sbatch --array=1-N grader/tools/slurm-batch.sh SUBMISSIONS OUT [batch options...]
#   e.g.  jobid=$(sbatch --parsable --array=1-8 grader/tools/slurm-batch.sh subs/ graded/ --assignment a1)
#         sbatch --dependency=afterok:$jobid --wrap "jelly-grade merge graded/part-*-of-8 --out graded/class"
#
# --jobs is the task's CPUs (SLURM_CPUS_PER_TASK) unless given. Each part runs with --resume, so a
# task that was requeued or cancelled and submitted again keeps the students it had finished. The
# grader is JELLY_GRADE, else jelly-grade on PATH. The array must be one step of 1 (1-N, 0-M, ...):
# the part number is the task's place in it. SUBMISSIONS and OUT must be on a file system every node
# sees (or copy the parts to one machine before the merge).
#SBATCH --job-name=jelly-grade
#SBATCH --cpus-per-task=2
#SBATCH --mem-per-cpu=2G
#SBATCH --time=01:00:00
#SBATCH --output=jelly-grade-%A_%a.log
set -euo pipefail
die() { echo "slurm-batch.sh: $*" >&2; exit 2; }
[ $# -ge 2 ] || die "usage: sbatch --array=1-N $0 SUBMISSIONS OUT [jelly-grade batch options...]"
in="$1"; out="$2"; shift 2
: "${SLURM_ARRAY_TASK_ID:?not an array task: submit with sbatch --array=1-N (or set SLURM_ARRAY_TASK_ID, _MIN, _MAX and _COUNT)}"
count="${SLURM_ARRAY_TASK_COUNT:?SLURM_ARRAY_TASK_COUNT is not set (Slurm 17.11 or later sets it)}"
min="${SLURM_ARRAY_TASK_MIN:-1}"
max="${SLURM_ARRAY_TASK_MAX:-$count}"
for v in "$SLURM_ARRAY_TASK_ID" "$count" "$min" "$max"; do
  [[ "$v" =~ ^[0-9]+$ ]] || die "SLURM_ARRAY_TASK_* must be whole numbers, got '$v'"
done
[ $((max - min + 1)) -eq "$count" ] ||
  die "the array $min-$max has $count tasks: use one step of 1 (--array=1-$count), not a list or a step"
part=$((SLURM_ARRAY_TASK_ID - min + 1))
[ "$part" -ge 1 ] && [ "$part" -le "$count" ] || die "task $SLURM_ARRAY_TASK_ID is outside $min-$max"
grade="${JELLY_GRADE:-jelly-grade}"
jobs=()
case " $* " in *" --jobs "*) ;; *) jobs=(--jobs "${SLURM_CPUS_PER_TASK:-1}") ;; esac
mkdir -p "$out"
echo "slurm-batch.sh: task $SLURM_ARRAY_TASK_ID grades part $part of $count into $out/part-$part-of-$count"
exec "$grade" batch "$in" --out "$out/part-$part-of-$count" --shard "$part/$count" --resume "${jobs[@]}" "$@"
