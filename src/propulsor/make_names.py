"""File names in a make depfile: escaped so that GNU make reads back exactly the name (and runs nothing
from it), or refused when make cannot name the file at all.

What GNU make 4.3 does with each character in a rule (tests/test_make_names.py runs make on each):
``$`` is expanded (written ``$$``); ``#`` starts a comment, a space or ``:`` ends a name (each written
with a backslash); ``|`` is plain in a target but ends a name among the prerequisites (backslash
there); ``%`` is plain among the prerequisites of an explicit rule but makes a target a pattern
(backslash there); a backslash is plain except before one of these, where it is doubled.  A name with
a tab, newline or other control character (white space or worse to make), ``;`` (a recipe follows),
``=`` (a variable assignment), ``*``, ``?`` or ``[`` (make expands the name as a pattern even with a
backslash in front: it also names the files the pattern matches), a backslash at its end (it would
escape what follows), a ``~`` at its start (a home folder) or, in make's own folder, a ``.`` at its
start (a special target such as ``.SILENT`` or ``.SECONDEXPANSION``) cannot be written at all.
"""

from __future__ import annotations

from .errors import InputError

#: written with a backslash in front: among a rule's prerequisites, in its target list
_PREREQ_META = frozenset(" #:|")
_TARGET_META = frozenset(" #:%")

_NAMED = {"\t": "a tab", "\n": "a newline", "\r": "a carriage return",
          ";": "a ';' (make reads a recipe after it)", "=": "an '=' (make reads a variable assignment)",
          **{g: f"a {g!r} (make expands the name as a pattern)" for g in "*?["}}

#: the variable each depfile adds its prerequisites to (the Makefile's complete run depends on them)
READ_VARIABLE = "PROPULSOR_READ"


def refusal(name: str) -> str | None:
    """Why make cannot name the file `name` (a path relative to make's folder), or None when it can."""
    for ch in name:
        if ch in _NAMED:
            return _NAMED[ch]
        if ch < " " or ch == "\x7f":
            return f"a control character ({ch!r})"
    if name.endswith("\\"):
        return "a backslash at its end"
    if name.startswith("~"):
        return "a '~' at its start (make reads a home folder)"
    if name.startswith(".") and "/" not in name:
        return "a '.' at its start in make's folder (make reads a special target such as .SILENT)"
    return None


def escape(name: str, target: bool = False) -> str:
    """`name` as make reads it back exactly: among a rule's prerequisites, or in its target list
    (`target`).  ValueError for a name make cannot express (:func:`refusal`)."""
    why = refusal(name)
    if why is not None:
        raise ValueError(f"make cannot name a file with {why}")
    special = _TARGET_META if target else _PREREQ_META
    out: list[str] = []
    i, n = 0, len(name)
    while i < n:
        ch = name[i]
        if ch == "\\":
            j = i
            while j < n and name[j] == "\\":
                j += 1
            # a run of backslashes before a character written with one: each doubled
            out.append(name[i:j] * (2 if j < n and name[j] in special else 1))
            i = j
            continue
        out.append("$$" if ch == "$" else "\\" + ch if ch in special else ch)
        i += 1
    return "".join(out)


def depfile_text(target: str, prerequisites: list[str]) -> str:
    """The depfile of `target`: its rule, an empty rule for each prerequisite (a file deleted since is
    then out of date, not an error: ``gcc -MP``), and the prerequisites added to :data:`READ_VARIABLE`.
    InputError for a name make cannot express."""
    try:
        deps = " ".join(escape(p) for p in prerequisites)
        lines = [f"{escape(target, target=True)}: {deps}".rstrip()]
        lines += [f"{escape(p, target=True)}:" for p in dict.fromkeys(prerequisites)]
    except ValueError as exc:
        bad = next(p for p in [target, *prerequisites] if refusal(p) is not None)
        raise InputError("depfile", bad, f"{exc}; rename it") from None
    lines.append(f"{READ_VARIABLE} += {deps}".rstrip())
    return "\n".join(lines) + "\n"


def vet(named) -> None:
    """InputError naming the key and value of the first file make cannot name: `named` holds
    (key, value as written, path relative to make's folder)."""
    for key, value, name in named:
        why = refusal(name)
        if why is not None:
            raise InputError(key, value, f"make cannot name a file with {why}; rename it")
