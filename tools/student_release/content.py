"""What the release rewrites as it copies: the student version of a Markdown file (audience
markers), a grader case file without its hidden cases, the scenes README without the scenes left
out, and Markdown links made relative to another folder. Bytes in, bytes out (lines as awk reads
them, see records())."""

import re

from . import Die, records, shown, warn

# ---- Audience markers --------------------------------------------------------------------------
# A Markdown file of the instructor tree may hold lines for one audience only, each block's markers
# alone on their lines:
#   <!-- instructor-only -->  ...  <!-- /instructor-only -->   left out of the release
#   <!-- student-only:        ...  :student-only -->           a comment here, text in the release

_OPEN_INSTRUCTOR = re.compile(r"[ \t]*<!-- instructor-only -->[ \t]*")
_CLOSE_INSTRUCTOR = re.compile(r"[ \t]*<!-- /instructor-only -->[ \t]*")
_OPEN_STUDENT = re.compile(r"[ \t]*<!-- student-only:[ \t]*")
_CLOSE_STUDENT = re.compile(r"[ \t]*:student-only -->[ \t]*")


class MarkerError(Exception):
    pass


def strip_markers(data, name):
    """The student version of a Markdown file; MarkerError ("name:line: ...") on a marker out of place."""
    out, mode, start = [], "", 0
    for number, line in enumerate(records(data), 1):
        if _OPEN_INSTRUCTOR.fullmatch(line) or _OPEN_STUDENT.fullmatch(line):
            if mode:
                raise MarkerError(f"{name}:{number}: misplaced audience marker")
            mode, start = ("i" if "instructor" in line else "s"), number
        elif _CLOSE_INSTRUCTOR.fullmatch(line) or _CLOSE_STUDENT.fullmatch(line):
            if mode != ("i" if "instructor" in line else "s"):
                raise MarkerError(f"{name}:{number}: misplaced audience marker")
            mode = ""
        elif mode != "i":
            out.append(line + "\n")
    if mode:
        raise MarkerError(f"{name}:{start}: audience marker never closed")
    return "".join(out).encode("latin-1")


# ---- Hidden grader cases -----------------------------------------------------------------------

_TABLE = re.compile(r"[ \t]*\[")
_CASE_SUBTABLE = re.compile(r"[ \t]*\[case\.")
_HIDDEN = re.compile(r'[ \t]*visibility[ \t]*=[ \t]*"hidden"')


def filter_hidden_cases(data):
    """A grader case file without its hidden cases: a case is its [[case]] table plus any
    [case.xxx] sub-tables after it, dropped when it says visibility = "hidden". Everything else
    (comments, [tolerance.*] tables, public cases) is kept as it is."""
    out, block, hidden = [], [], False
    for line in records(data):
        if _TABLE.match(line) and not _CASE_SUBTABLE.match(line):
            if not hidden:
                out.extend(block)
            block, hidden = [], False
        if _HIDDEN.match(line):
            hidden = True
        block.append(line + "\n")
    if not hidden:
        out.extend(block)
    return "".join(out).encode("latin-1")


# ---- Scenes left out ---------------------------------------------------------------------------
# A release names only the scenes it ships. The names left out are the scenes' ("course-2023",
# "hard/n2") and each folder all of whose scenes are left out ("hard/").

_BEFORE = re.compile(r"[A-Za-z0-9_.-]")
_AFTER = re.compile(r"[A-Za-z0-9_/-]")


def _names_one(line, names):
    """Whether line names one of names: the name, with or without .toml, not part of a longer name."""
    for name in names:
        rest = line
        while (at := rest.find(name)) >= 0:
            before = rest[at - 1] if at > 0 else ""
            end = at + len(name)
            after = rest[end + 5:end + 6] if rest[end:end + 5] == ".toml" else rest[end:end + 1]
            if (at == 0 or not _BEFORE.fullmatch(before)) and (name.endswith("/") or not _AFTER.fullmatch(after)):
                return True
            rest = rest[at + 1:]
    return False


def scene_mentions(data, names):
    """[(line number, text)] of the lines that name a scene left out."""
    if not names:
        return []
    return [(n, line) for n, line in enumerate(records(data), 1) if _names_one(line, names)]


def drop_scene_rows(data, names):
    """The file without its table rows ("| ...") and indented example lines that name one."""
    keep = [line + "\n" for line in records(data)
            if not (names and _names_one(line, names) and (line.startswith("|") or line.startswith("    ")))]
    return "".join(keep).encode("latin-1")


def check_scene_mentions(what, data, names):
    """Fails, naming the lines, when data names a scene left out."""
    found = scene_mentions(data, names)
    if found:
        for number, line in found:
            warn(f"  {what}:{number}\t{shown(line)}")
        raise Die(f"{what} names scenes this release leaves out (lines above): {' '.join(names)}")


# ---- Links made relative to another folder -----------------------------------------------------

_LINK = re.compile(r"\]\(([^)]*)\)")
_NOT_RELATIVE = re.compile(r"(#|/|[A-Za-z][A-Za-z0-9+.-]*:)")


def _norm(path):
    parts = []
    for part in path.split("/"):
        if part in ("", "."):
            continue
        if part == "..":
            if not parts:
                return ""
            parts.pop()
            continue
        parts.append(part)
    result = "/".join(parts)
    if path.endswith("/") and result:
        result += "/"
    return result


def _rebase_target(target, folder):
    if target == "" or _NOT_RELATIVE.match(target):
        return target
    path, title, frag = target, "", ""
    if " " in path:  # target "title"
        at = path.index(" ")
        path, title = path[:at], path[at:]
    if "#" in path:
        at = path.index("#")
        path, frag = path[:at], path[at:]
    normal = _norm(folder + "/" + path)
    return normal + frag + title if normal else target


def rebase_links(data, folder):
    """Every relative Markdown link of a file in folder (a path from the top) rewritten as a path
    from the top folder; links that climb above the top are left as they are."""
    out = []
    for line in records(data):
        out.append(_LINK.sub(lambda m: "](" + _rebase_target(m.group(1), folder) + ")", line) + "\n")
    return "".join(out).encode("latin-1")


def project_readme(data):
    """The project README moved to docs/: its links from the top made relative to docs/
    (docs/x -> x, y -> ../y)."""
    out = []
    for line in records(rebase_links(data, "")):
        line = re.sub(r"\]\(docs/", "](@@", line)
        line = re.sub(r"\]\(([^@)\\#][^):]*)\)", r"](../\1)", line)
        line = re.sub(r"\]\(@@", "](", line)
        out.append(line + "\n")
    return "".join(out).encode("latin-1")
