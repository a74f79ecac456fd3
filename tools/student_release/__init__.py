"""The student release (tools/make-student-release): what it copies and rewrites (content), the
checks of a release folder (links, scan), and the from-scratch builds that verify it (verify).
Instructor-only: the release leaves this package out. Python 3.11+, standard library only."""

import sys


class Die(Exception):
    """A failed check: make-student-release prints "FAILED: message" and exits with status 1."""


def say(text):
    print(f"make-student-release: {text}", flush=True)


def warn(text):
    """A line of a check's listing, on stderr (a file:line and what is wrong)."""
    sys.stderr.write(text + "\n")


def records(data):
    """The lines of a file's bytes as awk reads them: split at "\\n" only (a "\\r" stays), a last
    line without "\\n" included; decoded byte for byte (latin-1), so that lengths count bytes."""
    text = data.decode("latin-1")
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    return lines


def shown(text):
    """A line decoded by records(), as the UTF-8 text it was (for messages)."""
    return text.encode("latin-1").decode("utf-8", "replace")
