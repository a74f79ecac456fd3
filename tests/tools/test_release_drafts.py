"""The student release never hands out a draft (`draft = true` in its manifest): the default choice
leaves it out, naming it is a usage error that says why, and a tree of drafts alone has nothing to
release. Runs make-student-release's own choose() on two small manifests; no release is made.

    test_release_drafts.py SOURCE_DIR WORK_DIR
"""

import contextlib
import importlib.machinery
import importlib.util
import io
import shutil
import sys
from pathlib import Path

src, work = Path(sys.argv[1]), Path(sys.argv[2])
sys.path.insert(0, str(src / "tools"))
import jelly_manifest  # noqa: E402

loader = importlib.machinery.SourceFileLoader("release", str(src / "tools" / "make-student-release"))
spec = importlib.util.spec_from_loader("release", loader)
release = importlib.util.module_from_spec(spec)
loader.exec_module(release)

shutil.rmtree(work, ignore_errors=True)
manifests = {}
for name, draft in (("ready", False), ("soon", True)):
    folder = work / "assignments" / name
    folder.mkdir(parents=True)
    text = f'id = "{name}"\nnamespace = "{name}"\nfiles = ["a.cpp"]\n' + ("draft = true\n" if draft else "")
    (folder / "assignment.toml").write_text(text)
    manifests[name] = jelly_manifest.Manifest(folder / "assignment.toml")

failures = 0


def check(what, ok, detail=""):
    global failures
    print(("ok: " if ok else "FAIL: ") + what + ("" if ok else f"\n  {detail}"))
    failures += 0 if ok else 1


check("the default release leaves the draft out", release.choose("", manifests) == ["ready"],
      release.choose("", manifests))
check("the assignment that is not a draft may be named", release.choose("ready", manifests) == ["ready"])
err = io.StringIO()
with contextlib.redirect_stderr(err):
    try:
        release.choose("ready,soon", manifests)
        status = 0
    except SystemExit as e:
        status = e.code
check("naming the draft is a usage error (status 2) that says it is a draft",
      status == 2 and "--assignments: soon is a draft (" in err.getvalue() and "draft = true" in err.getvalue(),
      f"status {status}: {err.getvalue()}")
try:
    release.choose("", {"soon": manifests["soon"]})
    said = ""
except release.Die as e:
    said = str(e)
check("a tree of drafts alone has nothing to release", "holds only drafts (soon): nothing to release" in said, said)

if failures:
    sys.exit(f"{failures} check(s) failed")
print("release drafts: OK")
