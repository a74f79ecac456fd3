"""The link check: a student reads the release's Markdown on GitHub or on disk, where a link to a
file the release leaves out (the instructor guide, the mutation table, a spec outside the tree) is
a dead end. Every relative link and image, [text](target) or ![alt](target), outside code (fenced
blocks and `spans`), must resolve to a file or folder inside the folder checked; so must a Markdown
file named by its path as a `code span` (`docs/physics.md`), from the file's folder or the top (a
bare `report.md` may be a file the tools write, and is not checked)."""

import os
import re

from . import Die, records, say, shown, warn

_FENCE = re.compile(r"[ \t]*(```|~~~)")
_CODE_PATH = re.compile(r"`[A-Za-z0-9_.-]*/[A-Za-z0-9_./-]*\.md`")  # a path: dir/file.md
_CODE_SPAN = re.compile(r"`[^`]*`")
_LINK = re.compile(r"\]\([^)]*\)")


def markdown_files(folder):
    """The *.md files under folder (paths from it, sorted), outside .git, third_party and build*."""
    found = []
    for top, dirs, names in os.walk(folder):
        dirs[:] = [d for d in dirs if not (d in (".git", "third_party") or d.startswith("build"))]
        for name in names:
            if name.endswith(".md"):
                found.append(os.path.relpath(os.path.join(top, name), folder).replace(os.sep, "/"))
    return sorted(found)


def targets(data):
    """(line, kind, target) of each Markdown file named in code ("code") and each link ("link")."""
    fenced = False
    for number, line in enumerate(records(data), 1):
        if _FENCE.match(line):
            fenced = not fenced
            continue
        if fenced:
            continue
        for m in _CODE_PATH.finditer(line):
            yield number, "code", m.group(0)[1:-1]
        for m in _LINK.finditer(_CODE_SPAN.sub("", line)):
            target = m.group(0)[2:-1]
            target = re.sub(r"^[ \t]*<", "", target, count=1)  # <target>
            target = re.sub(r">.*$", "", target, count=1)
            target = re.sub(r'[ \t]+".*$', "", target, count=1)  # target "title"
            yield number, "link", target


def _inside(path, top):
    return (path + "/").startswith(top + "/")


def dead_target(top, md, kind, target):
    """Whether target, named in the file md (a path from top), is outside top or missing."""
    if target == "" or target.startswith("#") or "://" in target or target.startswith("mailto:"):
        return False
    path = target.split("#", 1)[0].split("?", 1)[0]
    if not path:
        return False
    if path.startswith("/"):
        resolved = os.path.realpath(top + path)
    else:
        resolved = os.path.realpath(os.path.join(os.path.dirname(os.path.join(top, md)), path))
    if kind == "code" and not os.path.exists(resolved):  # a file named in code may be a path from the top
        resolved = os.path.realpath(os.path.join(top, path))
    return not _inside(resolved, top) or not os.path.exists(resolved)


def check_links(folder):
    """Fails (after listing every dead link, "file:line: target") when one is dead."""
    top = os.path.realpath(folder)
    dead = 0
    for md in markdown_files(top):
        with open(os.path.join(top, md), "rb") as f:
            data = f.read()
        for number, kind, target in targets(data):
            if dead_target(top, md, kind, shown(target)):
                verb = "names" if kind == "code" else "links to"
                warn(f"  {md}:{number}: {verb} {shown(target)}, which the release does not contain")
                dead += 1
    if dead:
        raise Die(f"{dead} Markdown link(s) in {top} point to files it does not contain (listed above).\n"
                  "  Link to a file the release ships, or write the reference as plain text.")
    say(f"links: every relative Markdown link and image resolves inside {top}")
