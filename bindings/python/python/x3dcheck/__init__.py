"""x3dcheck from Python: check X3D scenes in memory or on disk.

>>> import x3dcheck
>>> report = x3dcheck.check(open("scene.x3d", "rb").read(), path="scene.x3d")
>>> for d in report.diagnostics:
...     print(f"{d.file}:{d.line}:{d.column}: {d.severity}[{d.code}] {d.message}")

Everything is done by the Rust library (``x3dcheck::api``, the functions the command line
calls); this module turns its JSON report into typed objects.
"""

from __future__ import annotations

import json
import signal
import sys
from dataclasses import dataclass
from os import PathLike
from typing import Iterable, Optional, Union

from . import _native
from ._native import CheckError

__all__ = [
    "CheckError",
    "Diagnostic",
    "FileReport",
    "Report",
    "Rule",
    "check",
    "check_file",
    "main",
    "rules",
]

Selectors = Union[str, Iterable[str], None]
Path = Union[str, "PathLike[str]"]


@dataclass(frozen=True)
class Diagnostic:
    """One finding: ``x3dcheck rules CODE`` explains its code."""

    code: str
    severity: str  # error, warning, info or hint
    message: str
    line: int  # 1-based; columns count Unicode characters
    column: int
    end_line: int
    end_column: int
    path: str  # the structural path: /X3D/Scene/Shape[0]/Appearance
    clause: str  # the ISO/IEC 19775-1 clause
    help: Optional[str]
    file: str  # the name of the file it is in, as in FileReport.path

    @classmethod
    def _of(cls, d: dict, file: str) -> "Diagnostic":
        return cls(
            code=d["code"],
            severity=d["severity"],
            message=d["message"],
            line=d["line"],
            column=d["column"],
            end_line=d["endLine"],
            end_column=d["endColumn"],
            path=d["path"],
            clause=d["clause"],
            help=d.get("help"),
            file=file,
        )


@dataclass(frozen=True)
class FileReport:
    """The report of one file: the input, or a file its Inlines load (deep level)."""

    path: str
    encoding: Optional[str]  # xml, json, classicvrml, vrml97; None when it is no scene
    x3d_version: Optional[str]
    profile: Optional[str]
    diagnostics: tuple
    truncated: bool

    @classmethod
    def _of(cls, f: dict) -> "FileReport":
        return cls(
            path=f["path"],
            encoding=f["encoding"],
            x3d_version=f["x3dVersion"],
            profile=f["profile"],
            diagnostics=tuple(Diagnostic._of(d, f["path"]) for d in f["diagnostics"]),
            truncated=f["truncated"],
        )


@dataclass(frozen=True)
class Report:
    """What ``x3dcheck --format json`` reports; ``to_json()`` is that text."""

    files: tuple
    summary: dict  # files, errors, warnings, infos, hints
    _json: str

    @property
    def diagnostics(self) -> list:
        """The findings of every file, the input's first."""
        return [d for f in self.files for d in f.diagnostics]

    def to_json(self) -> str:
        """The command line's JSON report, byte for byte."""
        return self._json

    @classmethod
    def _of(cls, text: str) -> "Report":
        data = json.loads(text)
        return cls(
            files=tuple(FileReport._of(f) for f in data["files"]),
            summary=data["summary"],
            _json=text,
        )


@dataclass(frozen=True)
class Rule:
    """A rule of the catalogue, as ``x3dcheck rules --format json`` lists it."""

    code: str
    severity: str
    level: str
    versions: str
    clause: str
    summary: str
    doc: str  # Markdown


def _selectors(selectors: Selectors) -> list:
    if selectors is None:
        return []
    if isinstance(selectors, str):
        return [selectors]
    return list(selectors)


def check(
    source: Union[str, bytes],
    *,
    path: Optional[Path] = None,
    level: Optional[str] = None,
    select: Selectors = None,
    ignore: Selectors = None,
    config: Optional[Path] = None,
) -> Report:
    """Checks a scene held in memory, as ``x3dcheck - --stdin-filename PATH`` does.

    ``source``: the scene; a ``str`` is checked as its UTF-8 bytes (pass ``bytes`` for a
    file in another encoding or gzip-compressed). ``path``: the name it is reported under;
    its directory is where x3dcheck.toml is looked up and the deep level reads
    referenced files. ``level``: fast, standard or deep (None: x3dcheck.toml's, else
    standard). ``select``/``ignore``: codes, prefixes of codes or ALL. ``config``: an
    x3dcheck.toml to use instead of the one found from ``path``. Raises ``CheckError``
    when nothing could be checked (an unknown code or level, a wrong x3dcheck.toml).
    """
    if isinstance(source, str):
        source = source.encode("utf-8")
    text = _native.check(
        source,
        path=path,
        level=level,
        select=_selectors(select),
        ignore=_selectors(ignore),
        config=config,
    )
    return Report._of(text)


def check_file(
    path: Path,
    *,
    level: Optional[str] = None,
    select: Selectors = None,
    ignore: Selectors = None,
    config: Optional[Path] = None,
) -> Report:
    """Checks the file at ``path`` as ``x3dcheck PATH`` does; options as for ``check``.

    Raises ``CheckError`` also when the file cannot be read.
    """
    text = _native.check_file(
        path,
        level=level,
        select=_selectors(select),
        ignore=_selectors(ignore),
        config=config,
    )
    return Report._of(text)


def rules() -> list:
    """Every rule, in catalogue order."""
    return [Rule(**r) for r in json.loads(_native.rules_json())]


def main() -> None:
    """The ``x3dcheck`` command: the Rust command line, run in this process."""
    # The check runs without the GIL, so Python would only see Ctrl-C when it ends; the
    # default action stops it at once, as it stops the binary.
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    sys.exit(_native.main(sys.argv))
