#!/usr/bin/env bash
# Proof that a body kind is a plug-in (issue 30, docs/new-assignment.md section 8):
#   check_plugin_body.sh WORK_DIR
# runs on the tree plugin.projectile (check_plugin.sh) built in WORK_DIR/tree: that tree got the
# fixture's toy body kind framework/bodies/point/ and the projectile assignment, whose manifest
# simulates it (bodies = ["point"]) and whose folder holds a scene of it, and no other file
# (check_plugin.sh fails when a tracked file changed). Here: CMake registered the kind; `jelly run`
# steps the point with the assignment's tasks and the framework's symplectic Euler to the bits of
# the closed form (x = x0 + N h v0, y = y0 - g h^2 N(N+1)/2); `jelly check` and `jelly params` know
# its keys; a misspelt key and a terrain in a point scene are errors naming the file, line and key.
set -euo pipefail

if [[ $# -ne 1 ]]; then
  echo "usage: $0 WORK_DIR" >&2
  exit 2
fi
work=$(cd "$1" && pwd)
tree=$work/tree
out=$work/body
rm -rf "$out"
mkdir -p "$out"
fail() {
  echo "plugin.body: FAILED: $*" >&2
  exit 1
}
[[ -d $tree/build ]] || fail "no built tree in $tree (plugin.projectile builds it)"
jelly=$(find "$tree/build" -name jelly -type f -perm -u+x | head -1)
[[ -x $jelly ]] || fail "no jelly in $tree/build"
scene=$tree/assignments/projectile/scenes/point-drop.toml

echo "== plugin.body: CMake registered the kind"
grep -q "Jelly Lab body kinds: cube, particles, cloth, skeleton, point" "$work/configure.log" ||
  fail "CMake did not register the point kind: $(grep 'body kinds' "$work/configure.log" || true)"

echo "== plugin.body: jelly run steps the point (the projectile assignment's scene)"
"$jelly" run "$scene" --summary "$out/point.csv" >"$out/run.log" 2>&1 ||
  fail "jelly run $scene: $(cat "$out/run.log")"
grep -q "1 particles, 0 springs, 0 terrains" "$out/run.log" || fail "the run's report: $(cat "$out/run.log")"
python3 - "$out/point.csv" <<'PY' || fail "the point's trajectory (above)"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
h, g, m, x0, y0, vx = 0.01, 9.8, 0.5, 0.0, 10.0, 2.0
assert len(rows) > 10, f"{len(rows)} summary rows"
for r in rows:
    t = float(r["time"])
    n = round(t / h)
    x = x0 + n * h * vx
    y = y0 - g * h * h * n * (n + 1) / 2
    ke = 0.5 * m * (vx * vx + (g * n * h) ** 2)
    for name, got, want in (("com_x", r["com_x"], x), ("com_y", r["com_y"], y), ("kinetic", r["kinetic"], ke)):
        if abs(float(got) - want) > 1e-9 * max(1.0, abs(want)):
            sys.exit(f"t = {t}: {name} = {got}, closed form {want}")
last = rows[-1]
if abs(float(last["time"]) - 1.0) > 1e-9:
    sys.exit(f"the run ends at t = {last['time']}, not 1 s")
print(f"plugin.body: {len(rows)} rows match the closed form; y(1 s) = {last['com_y']}")
PY

echo "== plugin.body: jelly check and jelly params know its keys"
"$jelly" check "$scene" >"$out/check.log" 2>&1 || fail "jelly check: $(cat "$out/check.log")"
grep -q "point-drop: valid. 1 particles, 0 springs; gravity on; 0 terrains" "$out/check.log" ||
  fail "jelly check: $(cat "$out/check.log")"
"$jelly" params "$scene" >"$out/params.log" 2>&1 || fail "jelly params: $(cat "$out/params.log")"
for key in body.type body.position body.velocity body.mass; do
  grep -q "$key" "$out/params.log" || fail "jelly params lists no $key: $(cat "$out/params.log")"
done
grep -q "body.n" "$out/params.log" && fail "jelly params lists a cube's key in a point scene"

echo "== plugin.body: its errors name the file, the line and the key"
sed 's/^mass = 0.5/mas = 0.5/' "$scene" >"$out/misspelt.toml"
rc=0
"$jelly" run "$out/misspelt.toml" --quiet >"$out/misspelt.log" 2>&1 || rc=$?
line=$(grep -n '^mas = 0.5' "$out/misspelt.toml" | cut -d: -f1)
[[ $rc -eq 2 ]] && grep -q "misspelt.toml:$line:1: body.mas" "$out/misspelt.log" ||
  fail "a misspelt key: exit $rc, expected 2 naming misspelt.toml:$line and body.mas: $(cat "$out/misspelt.log")"
{ cat "$scene"; printf '\n[[terrain]]\npreset = "course-2021-plane"\n'; } >"$out/terrain.toml"
rc=0
"$jelly" run "$out/terrain.toml" --quiet >"$out/terrain.log" 2>&1 || rc=$?
[[ $rc -eq 2 ]] && grep -q "terrain.toml:.*a point scene has no terrains" "$out/terrain.log" ||
  fail "a terrain in a point scene: exit $rc: $(cat "$out/terrain.log")"
echo "plugin.body: PASSED"
