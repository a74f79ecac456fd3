#!/usr/bin/env python3
"""Largest difference, per case and output, between a runner's outputs and the stored reference.

Used for docs/tolerances.md: build a variant runner (FMA flags through a copied grade-config.json,
or solutions/ with a 1e-12 perturbation) with `JELLY_GRADE_KEEP_WORK=1 jelly-grade grade DIR --out X`,
then run:  measure_spread.py X/.work/build/runner grader/data
"""
import json, math, os, subprocess, sys, tempfile

runner, data = sys.argv[1], sys.argv[2]
rows = []
for vis in ("public", "hidden"):
    d = os.path.join(data, vis)
    if not os.path.isdir(d):
        continue
    for f in sorted(os.listdir(d)):
        ref = json.load(open(os.path.join(d, f)))
        args = [runner, "--case", ref["case_id"], "--no-sandbox"]
        if "input" in ref:
            tmp = tempfile.NamedTemporaryFile("w", suffix=".json", delete=False)
            json.dump(ref["input"], tmp)
            tmp.close()
            args += ["--input", tmp.name]
        out = json.loads(subprocess.run(args, capture_output=True, text=True, env=dict(os.environ, OMP_NUM_THREADS="1")).stdout)
        mine = out.get("outputs", {})
        for name, r in ref["outputs"].items():
            a, b = mine.get(name, {}).get("value"), r["value"]
            if isinstance(b, str):
                continue
            a = a if isinstance(a, list) else [a]
            b = b if isinstance(b, list) else [b]
            diff = max((abs(x - y) if x is not None and y is not None else math.inf) for x, y in zip(a, b)) if b else 0
            rows.append((ref["case_id"], name, diff))
for case, name, diff in rows:
    print(f"{case}\t{name}\t{diff:.3g}")
