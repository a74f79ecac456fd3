"""Every test that runs hostile code in the sandboxes holds the lock of the sandbox users.

The red-team tests that grade in user mode end by checking that no process of any sandbox user is
left. A test that starts such processes at the same time, without the lock, makes them fail (CI
run of stop 39: SandboxLanes ran beside HostileNeighboursInUserMode). Reads what CTest itself will
run (`ctest --show-only=json-v1`), so a property CMake dropped is seen as dropped: a list value
that gtest_discover_tests splits ("a;b" unescaped) loses every property after it.

    test_ctest_locks.py CTEST BUILD_DIR
"""

import json
import subprocess
import sys

ctest, build = sys.argv[1], sys.argv[2]
listing = subprocess.run([ctest, "--show-only=json-v1"], cwd=build, capture_output=True, text=True,
                         check=True)
tests = json.loads(listing.stdout)["tests"]


def properties(test):
    return {p["name"]: p["value"] for p in test.get("properties", [])}


failures = []
sandboxed = 0
for test in tests:
    props = properties(test)
    if "security" not in props.get("LABELS", []):
        continue
    sandboxed += 1
    if "jelly_sandbox_users" not in props.get("RESOURCE_LOCK", []):
        failures.append(f"{test['name']}: labelled security but holds no RESOURCE_LOCK "
                        f"jelly_sandbox_users (its properties: {sorted(props)})")
    if "TIMEOUT" not in props:
        failures.append(f"{test['name']}: labelled security but has no TIMEOUT")

if sandboxed < 10:
    failures.append(f"only {sandboxed} tests are labelled security; the red-team suite has more "
                    "(is the build complete?)")
for line in failures:
    print(line)
print(f"{sandboxed} security tests, {len(failures)} problem(s)")
sys.exit(1 if failures else 0)
