#!/usr/bin/env python3
"""The one reader of an assignment's manifest (assignments/<id>/assignment.toml) outside the programs.

tools/selfcheck and tools/make-student-release import it; CMake runs it (cmake/JellyAssignments.cmake)
to write the keys it needs as a .cmake file. The programs read the whole manifest with toml++
(framework/manifest). Python 3.11+ (tomllib), standard library only.

    jelly_manifest.py cmake MANIFEST OUT.cmake   write the keys CMake reads (JELLY_MANIFEST_*)
    jelly_manifest.py get MANIFEST KEY           print a top-level key: a string, true or false, or a
                                                 list one item a line
    jelly_manifest.py claims MANIFEST            print its `bodies` checked, one claim a line: KIND or
                                                 KIND VARIANT (the entry "kind:variant")

Every error names the file and the key, and what was expected (docs/new-assignment.md).
"""

import hashlib
import re
import sys
from pathlib import Path

try:
    import tomllib
except ModuleNotFoundError:  # Python < 3.11
    tomllib = None

MANIFEST_NAME = "assignment.toml"

# The keys CMake reads: (key, kind, required). kind "string", "list" (of strings) or "bool"
# (written as ON or OFF).
CMAKE_KEYS = (
    ("id", "string", True),
    ("namespace", "string", True),
    ("files", "list", True),
    ("reference_files", "list", False),
    ("task_modules", "list", False),
    ("default_scene", "string", False),
    ("draft", "bool", False),
)


# A `bodies` entry: a body kind's name, or kind:variant (framework/manifest's BodyClaim).
_NAME = r"[A-Za-z_-][A-Za-z0-9_-]*"
_CLAIM = re.compile(rf"({_NAME})(?::({_NAME}))?")
CLAIM_FORM = ("a body kind's name (a scene's [body] type: every scene of the kind) or kind:variant (only its "
              "scenes of that variant, docs/new-assignment.md), names of letters, digits, '_' and '-'")


class Claim:
    """One entry of a manifest's `bodies`: every scene of a body kind ("cube"), or only its scenes
    of one variant ("skeleton:ik"; the variant of a skeleton scene is its body.mode)."""

    def __init__(self, kind, variant=""):
        self.kind, self.variant = kind, variant

    def claims(self, kind, variant):
        """Whether it claims a scene of body kind `kind` whose variant is `variant`."""
        return self.kind == kind and (not self.variant or self.variant == variant)

    def __str__(self):
        return f"{self.kind}:{self.variant}" if self.variant else self.kind

    def __repr__(self):
        return f"Claim({str(self)!r})"


class ManifestError(Exception):
    """A manifest that cannot be read or lacks a key; the message names file and key."""


def _need_tomllib():
    if tomllib is None:
        raise ManifestError(
            f"reading assignment manifests needs Python 3.11 or newer (tomllib); this is Python "
            f"{sys.version.split()[0]} ({sys.executable})"
        )


class Manifest:
    """One assignment.toml, read whole with tomllib."""

    def __init__(self, path):
        _need_tomllib()
        self.path = Path(path)
        try:
            with open(self.path, "rb") as f:
                self.data = tomllib.load(f)
        except OSError as e:
            raise ManifestError(f"{self.path}: cannot read it ({e.strerror})") from None
        except tomllib.TOMLDecodeError as e:
            raise ManifestError(f"{self.path}: not valid TOML: {e}") from None

    def _fail(self, key, expected):
        raise ManifestError(f"{self.path}: {key}: expected {expected} (docs/new-assignment.md)")

    def string(self, key, required=True):
        """A top-level string key; "" when it is absent and not required."""
        if key not in self.data:
            if required:
                self._fail(key, f'a line `{key} = "..."`')
            return ""
        value = self.data[key]
        if not isinstance(value, str):
            self._fail(key, f'a string (`{key} = "..."`), not {type(value).__name__}')
        return value

    def strings(self, key, required=True):
        """A top-level list of strings; [] when it is absent and not required."""
        if key not in self.data:
            if required:
                self._fail(key, f'a list `{key} = ["...", ...]`')
            return []
        value = self.data[key]
        if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
            self._fail(key, f'a list of strings (`{key} = ["...", ...]`)')
        return list(value)

    def boolean(self, key):
        """A top-level true/false key; False when it is absent."""
        value = self.data.get(key, False)
        if not isinstance(value, bool):
            self._fail(key, f"true or false (`{key} = true`), not {value!r}")
        return value

    @property
    def draft(self):
        """An assignment in preparation (`draft = true`): built, its own tests run and its scenes
        playable, but graded only on request (`--draft`) and never released (docs/new-assignment.md,
        "A draft")."""
        return self.boolean("draft")

    def tasks(self):
        """The [[task]] tables, in the manifest's (handout) order."""
        tasks = self.data.get("task", [])
        if not isinstance(tasks, list) or not all(isinstance(t, dict) for t in tasks):
            self._fail("task", "[[task]] tables")
        return tasks

    def task_ids(self):
        """The ids of the [[task]] tables, in order."""
        ids = []
        for i, task in enumerate(self.tasks()):
            if not isinstance(task.get("id"), str):
                self._fail(f"task[{i}].id", 'a string (`id = "A1.T1"`)')
            ids.append(task["id"])
        return ids

    @property
    def id(self):
        return self.string("id")

    @property
    def files(self):
        return self.strings("files")

    @property
    def bodies(self):
        """The `bodies` entries as written."""
        return self.strings("bodies", required=False)

    def claims(self):
        """The `bodies` entries as Claims, checked as the programs check them: each a kind or
        kind:variant, each scene claimed once."""
        out = []
        for text in self.bodies:
            m = _CLAIM.fullmatch(text)
            if not m or text[0].isdigit() or (m.group(2) or "x")[0].isdigit():
                self._fail("bodies", f'{CLAIM_FORM}, not "{text}"')
            claim = Claim(m.group(1), m.group(2) or "")
            for before in out:
                if before.kind == claim.kind and (not before.variant or not claim.variant
                                                  or before.variant == claim.variant):
                    self._fail("bodies", f'each scene claimed once, and "{before}" already claims the scenes '
                                         f'"{text}" does')
            out.append(claim)
        return out

    def claims_scene(self, kind, variant):
        """Whether one of its `bodies` claims a scene of body kind `kind` and variant `variant`."""
        return any(c.claims(kind, variant) for c in self.claims())


def assignment_manifests(root):
    """{id: Manifest} for every assignments/<id>/assignment.toml of the tree at root, sorted by id,
    drafts included (Manifest.draft); each manifest's id must be its folder's name."""
    found = {}
    for path in sorted(Path(root, "assignments").glob(f"*/{MANIFEST_NAME}")):
        manifest = Manifest(path)
        folder = path.parent.name
        if manifest.id != folder:
            raise ManifestError(f'{path}: id: expected the folder\'s name "{folder}", not "{manifest.id}"')
        found[folder] = manifest
    return found


# ---- The keys for CMake ------------------------------------------------------------------------


def _cmake_quote(path, key, value):
    """A CMake bracket argument (no variable expansion, no escapes)."""
    if ";" in value or "]==]" in value or "\n" in value:
        raise ManifestError(f"{path}: {key}: {value!r} holds a character CMake cannot take (';', newline)")
    return f"[==[{value}]==]"


def cmake_keys(manifest):
    """The text of a .cmake file setting JELLY_MANIFEST_<KEY> for each key CMake reads, and
    JELLY_MANIFEST_SHA256, the manifest's hash without its "\r"s (CMake checks it against the file it
    reads; a Windows checkout may have CR LF line ends)."""
    digest = hashlib.sha256(manifest.path.read_bytes().replace(b"\r", b"")).hexdigest()
    manifest.claims()  # `bodies` is checked here too: a bad entry stops the configure, naming it
    lines = [
        f"# Written by tools/jelly_manifest.py from {manifest.path.name}; do not edit.",
        f"set(JELLY_MANIFEST_SHA256 {digest})",
    ]
    for key, kind, required in CMAKE_KEYS:
        var = "JELLY_MANIFEST_" + key.upper()
        if kind == "bool":
            lines.append(f"set({var} {'ON' if manifest.boolean(key) else 'OFF'})")
            continue
        if kind == "string":
            values = [manifest.string(key, required)]
        else:
            values = manifest.strings(key, required)
        quoted = " ".join(_cmake_quote(manifest.path, key, v) for v in values)
        lines.append(f'set({var} {quoted if quoted else "[==[]==]"})')
    return "\n".join(lines) + "\n"


def write_cmake_keys(manifest_path, out_path):
    """Writes the .cmake keys of a manifest; the file is rewritten only when its text changes."""
    text = cmake_keys(Manifest(manifest_path))
    out = Path(out_path)
    if not out.exists() or out.read_text(encoding="utf-8") != text:
        out.parent.mkdir(parents=True, exist_ok=True)
        out.write_text(text, encoding="utf-8", newline="\n")


def _main(argv):
    usage = "usage: jelly_manifest.py cmake MANIFEST OUT.cmake | get MANIFEST KEY | claims MANIFEST"
    try:
        if len(argv) == 3 and argv[0] == "cmake":
            write_cmake_keys(argv[1], argv[2])
            return 0
        if len(argv) == 3 and argv[0] == "get":
            manifest = Manifest(argv[1])
            value = manifest.data.get(argv[2])
            if isinstance(value, bool):
                print("true" if value else "false")
            elif isinstance(value, list):
                print("\n".join(manifest.strings(argv[2])))
            elif value is not None:
                print(manifest.string(argv[2]))
            return 0
        if len(argv) == 2 and argv[0] == "claims":
            for claim in Manifest(argv[1]).claims():
                print(f"{claim.kind} {claim.variant}".rstrip())
            return 0
    except ManifestError as e:
        print(f"jelly_manifest: {e}", file=sys.stderr)
        return 1
    print(usage, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(_main(sys.argv[1:]))
