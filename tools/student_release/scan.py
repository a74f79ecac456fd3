"""The content scan of a release folder, and the doc-content check.

Needles are the lines of solutions/*.cpp that are specific to the reference (code and comment text,
whitespace-normalised; lines also present in assignments/ or in the student API headers, and
trivial lines, are shared and skipped), the ids of hidden cases, and the hidden data files
(whole-file hashes and their long lines). Any needle found in the release fails."""

import hashlib
import os
import re
import tomllib
from pathlib import Path

from . import Die, records, say, shown, warn

# ---- Normalised lines --------------------------------------------------------------------------
# Each line gives a code part ("c", its comment removed) and the text of its comment ("t"), each
# whitespace-normalised.

_WS = re.compile(r"[ \t\r]+")
_COMMENT_LINE = re.compile(r"[ \t]*(#|\*|/\*)")
_DIRECTIVE = re.compile(r"[ \t]*#(include|pragma|define|if|endif|else)")
_COMMENT_LEAD = re.compile(r"[ \t]*(#+|\*+|/\*+)")


def _trim(s):
    s = _WS.sub(" ", s)
    if s.startswith(" "):
        s = s[1:]
    if s.endswith(" "):
        s = s[:-1]
    return s


def normalised(data):
    """[(line number, kind, text)] of a file's bytes (kind "c" code, "t" comment text)."""
    out = []
    for number, line in enumerate(records(data), 1):
        code, text = line, ""
        at = line.find("//")
        if at >= 0:
            code, text = line[:at], re.sub(r"^/+!?", "", line[at:], count=1)
        elif _COMMENT_LINE.match(line) and not _DIRECTIVE.match(line):
            code, text = "", _COMMENT_LEAD.sub("", line, count=1)
        code, text = _trim(code), _trim(text)
        if code:
            out.append((number, "c", code))
        if text:
            out.append((number, "t", text))
    return out


def _keys(data):
    return {(kind, text) for _, kind, text in normalised(data)}


# Lines that are shared by construction or too generic to mean anything.
_TRIVIAL = [
    re.compile(r"c\t(\{|\}|\};|\}\)?;?|\) \{|\} else \{|else|return;|return (true|false|0|1|out|result|f|v|s);|"
               r"break;|continue;|#include .*|#pragma .*|namespace [a-z_:]* \{|namespace \{|\} // namespace.*|"
               r"using [A-Za-z_:]+ = .*|public:|private:|protected:|default:)"),
    re.compile(r"c\t(for \(int [a-z0-9_]+ = 0; [a-z0-9_]+ < [A-Za-z0-9_.()]+; (\+\+[a-z0-9_]+|[a-z0-9_]+\+\+)\)"
               r"( \{)?|(const )?(int|double|bool|long|std::size_t|auto) [a-z0-9_]+ = [0-9.]+;)"),
]


def _trivial(kind, text):
    if any(p.fullmatch(f"{kind}\t{text}") for p in _TRIVIAL):
        return True
    return not ((kind == "c" and len(text) >= 14) or (kind == "t" and len(text) >= 30))


# ---- The tree's reference and hidden material ----------------------------------------------------


def _files_under(folder):
    return sorted(p for p in Path(folder).rglob("*") if p.is_file()) if Path(folder).is_dir() else []


class Secrets:
    """What must not be in a release, from the tree at root (of every assignment, shipped or not)."""

    def __init__(self, root, manifests):
        self.root = Path(root)
        self.ids = list(manifests)
        self.solution_files = _files_under(self.root / "solutions")
        self.hidden_data = [f for i in self.ids for f in _files_under(self.root / "grader/data" / i / "hidden")]
        shared = self._shared_lines(manifests)
        # needle (kind, text) -> the file it comes from; a hidden data file's wins over a solution's.
        self.needles = {}
        count = 0
        for group in (self._solution_needles(shared), self._hidden_data_needles(shared)):
            count += len(group)
            self.needles.update(group)
        self.needle_count = count

    def rel(self, path):
        return Path(path).relative_to(self.root).as_posix()

    def _shared_lines(self, manifests):
        """The stubs (each manifest's files), the public headers (include/), the allow-list, and,
        when there is hidden data, the public data's lines (format version, flags, notes)."""
        shared = set()
        for i, manifest in manifests.items():
            folder = self.root / "assignments" / i
            for f in manifest.strings("files", required=False):
                if (folder / f).is_file():
                    shared |= _keys((folder / f).read_bytes())
            if (folder / "include").is_dir():
                for h in sorted((folder / "include").rglob("*.hpp")):
                    if h.is_file():
                        shared |= _keys(h.read_bytes())
        allow = self.root / "tools/release-scan-allow.txt"
        if allow.is_file():
            lines = [line for line in allow.read_bytes().split(b"\n") if not line.startswith(b"#")]
            shared |= _keys(b"\n".join(lines))
        if self.hidden_data:
            for i in self.ids:
                for f in _files_under(self.root / "assignments" / i / "grader/data/public"):
                    shared |= _keys(f.read_bytes())
        return shared

    def _solution_needles(self, shared):
        if not self.solution_files:
            say(f"warning: no solutions/ in {self.root}: nothing to scan for")
        needles = {}
        for f in self.solution_files:
            for _, kind, text in normalised(f.read_bytes()):
                if not _trivial(kind, text) and (kind, text) not in shared:
                    needles.setdefault((kind, text), self.rel(f))
        return needles

    def _hidden_data_needles(self, shared):
        needles = {}
        for f in self.hidden_data:
            for _, kind, text in normalised(f.read_bytes()):
                if len(text) >= 40 and re.search(r"[0-9]", text) and (kind, text) not in shared:
                    needles.setdefault((kind, text), self.rel(f))
        return needles

    def hidden_case_ids(self):
        """(id, file) of every grader case marked visibility = "hidden", in every assignment."""
        found = []
        for f in sorted(self.root.glob("assignments/*/grader/cases/*")):
            if not f.is_file():
                continue
            try:
                cases = tomllib.loads(f.read_text(encoding="utf-8")).get("case", [])
            except (tomllib.TOMLDecodeError, UnicodeDecodeError) as e:
                raise Die(f"{self.rel(f)}: not a valid grader case file: {e}") from None
            for case in cases:
                if case.get("visibility") == "hidden" and case.get("id"):
                    found.append((case["id"], self.rel(f)))
        return found


# ---- The scan ------------------------------------------------------------------------------------


def release_files(folder):
    """Every file of the release (paths from it, sorted), but the top folder's .git/."""
    found = []
    for top, dirs, names in os.walk(folder):
        if top == folder:
            dirs[:] = [d for d in dirs if d != ".git"]
        for name in names:
            found.append(os.path.relpath(os.path.join(top, name), folder).replace(os.sep, "/"))
    return sorted(found)


def _is_text(data):
    return b"\0" not in data and data != b""


def _named_like_secrets(rel, secrets):
    hits = []
    bad = ["solutions"] + [p for i in secrets.ids for p in (f"grader/data/{i}/hidden", f"assignments/{i}/grader/mutants",
                                                             f"assignments/{i}/grader/hints.json")]
    for b in bad:
        if os.path.lexists(os.path.join(rel, b)):
            hits.append(f"  {b}/ is in the release")
    for top, dirs, names in os.walk(rel):
        dirs[:] = sorted(d for d in dirs if d != ".git")
        for d in dirs:
            if d in ("solutions", "hidden", "mutants"):
                hits.append(f"  {os.path.relpath(os.path.join(top, d), rel)} is named like reference or hidden material")
    for f in secrets.hidden_data:
        for top, dirs, names in os.walk(rel):
            dirs[:] = [d for d in dirs if d != ".git"]
            if f.name in names:
                hits.append(f"  {os.path.relpath(os.path.join(top, f.name), rel)} has the name of hidden data file "
                            f"{secrets.rel(f)}")
    return hits


def _lines_of_secrets(contents, secrets):
    hits = []
    for path, data in contents.items():
        if not _is_text(data):
            continue
        for number, kind, text in normalised(data):
            source = secrets.needles.get((kind, text))
            if source is not None:
                hits.append(f"  {path}:{number} has a line of {source}: {shown(text)}")
    return hits


def _copies_of_secrets(contents, secrets):
    hits = []
    if not (secrets.hidden_data or secrets.solution_files):
        return hits
    by_hash = {}
    for path, data in contents.items():
        by_hash.setdefault(hashlib.sha256(data).hexdigest(), []).append(path)
    for f in secrets.hidden_data + secrets.solution_files:
        copies = by_hash.get(hashlib.sha256(f.read_bytes()).hexdigest())
        if copies:
            hits.append(f"  {min(copies)} is a copy of {secrets.rel(f)}")
    return hits


def _hidden_case_names(contents, secrets):
    """Hidden case ids anywhere in the release, the grader's runner code included: an assignment's
    runner (assignments/ID/grader/runner/) holds generic case generators only, and a case's inputs
    are its params in assignments/ID/grader/cases/*.toml, whose hidden entries the copy drops
    (tests/grader/inputs/test_hidden_cases_not_in_code.cpp checks the runners for hidden parameters too).
    Case code kept in assignments/ID/grader/runner/hidden/ is left out altogether."""
    hits = []
    texts = [(p, d) for p, d in contents.items() if _is_text(d) and "/.git/" not in "/" + p]
    for case_id, source in secrets.hidden_case_ids():
        needle = case_id.encode("utf-8")
        where = [p for p, d in texts if needle in d][:3]
        if where:
            hits.append(f"  hidden case '{case_id}' (from {source}) is named in: {' '.join(where)} ")
    return hits


def scan_release(rel, secrets):
    """Fails (after listing every hit) when the folder holds reference or hidden content."""
    say(f"scan: {secrets.needle_count} reference-specific lines from {len(secrets.solution_files)} solution "
        f"and {len(secrets.hidden_data)} hidden data files")
    contents = {}
    for path in release_files(rel):
        with open(os.path.join(rel, path), "rb") as f:
            contents[path] = f.read()
    hits = _named_like_secrets(rel, secrets)
    hits += _lines_of_secrets(contents, secrets)
    hits += _copies_of_secrets(contents, secrets)
    hits += _hidden_case_names(contents, secrets)
    for hit in hits:
        warn(hit)
    if hits:
        raise Die(f"the content scan found {len(hits)} leak(s) of reference or hidden material in {rel} (listed above).\n"
                  "  Remove them from the tree (or, for a line that is truly generic, add it to "
                  "tools/release-scan-allow.txt).")
    say("scan: clean (no solution line, hidden case or hidden data in the release)")
    check_docs(rel)


# ---- The doc-content check -----------------------------------------------------------------------
# What a shipped doc must not say: (regex, why). Instructor-only commands and paths (they fail or do
# not exist in the release) and the threat model's details.

DOC_DENY = [
    (r'JELLY_TASKS *= *"?solutions', "builds solutions/, which the release does not have"),
    (r"make-student-release|release-scan-allow", "an instructor tool the release does not have"),
    (r"jelly-grade (generate-reference|gradescope-zip|mutants)|`(generate-reference|gradescope-zip)`",
     "an instructor command (needs solutions/ or the hidden data)"),
    (r"grader/data/([A-Za-z0-9_-]+/)?hidden|grader/mutants|mutation-table\.md", "a hidden or instructor-only path"),
    (r"Not defended|\*\*Defended\*\*|^#+ .*[Tt]hreat model", "the grader's threat model (instructor guide only)"),
    (r"[Ww]here this page and the seed|the seed report", "internal provenance wording"),
    (r"(^|[^\w.~-])/(tmp/([^c*\s`]|c[^c])|work/|home/|root/|scratch/)",
     "a path of a developer's machine (a clone, a build folder): a development note"),
    (r"[Tt]he lead('s)?([^\w]|_|$)|other helpers|helpers (building|working)|this session",
     "a development note (who ran what, when)"),
]


def check_docs(rel):
    """Fails (listing "file:line: why: text") when a shipped Markdown file says any of DOC_DENY."""
    from .links import markdown_files

    docs = []
    for md in markdown_files(rel):
        with open(os.path.join(rel, md), "rb") as f:
            docs.append((md, records(f.read())))
    hits = 0
    for pattern, why in DOC_DENY:
        regex = re.compile(pattern)
        for md, lines in docs:
            for number, line in enumerate(lines, 1):
                if regex.search(shown(line)):
                    warn(f"  {md}:{number}: {why}: {shown(line[:120])}")
                    hits += 1
    if hits:
        raise Die(f"{hits} line(s) of the release's docs are for instructors (listed above: file:line: why).\n"
                  "  Wrap them in <!-- instructor-only --> ... <!-- /instructor-only --> in the instructor tree (with a\n"
                  "  <!-- student-only: ... :student-only --> version where students need one), or reword them.")
    say("docs: no instructor-only command, path or threat-model detail in the release's Markdown")
