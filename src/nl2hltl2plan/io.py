"""Every JSON / JSON-lines file the package reads or writes goes through here.

Reading is bounded and never raises anything but `DataError` with a one-line message naming the
file: a size limit (`MAX_BYTES`, stated in the error) so `/dev/zero` or a huge file cannot exhaust
memory, UTF-8 decoding errors, malformed JSON, and nesting deeper than `MAX_DEPTH` (Python's JSON
parser recurses, so a 10,000-deep list would otherwise end in RecursionError). Writing creates the
folder and turns `OSError` into `DataError` naming the path; output paths are checked before any
work (`ensure_writable_dir`, `check_output_file`). Benchmark results files (JSON lines appended as
scenarios finish) are read and repaired by `evaluation.runner`.

>>> import tempfile, pathlib
>>> p = pathlib.Path(tempfile.mkdtemp()) / "x.json"
>>> write_json(p, {"a": [1, 2]})
>>> read_json(p)
{'a': [1, 2]}
"""

from __future__ import annotations

import json
import stat
from pathlib import Path
from typing import Any

from nl2hltl2plan.errors import DataError

MAX_BYTES = 64 * 1024 * 1024  # 64 MiB: far above any spec, plan or ground-truth file
MAX_DEPTH = 200  # nesting of JSON containers


def read_text(path: str | Path, what: str = "file", max_bytes: int = MAX_BYTES) -> str:
    """The UTF-8 text of a file, at most `max_bytes` long."""
    p = Path(path)
    try:
        if stat.S_ISDIR(p.stat().st_mode):
            raise DataError(f"cannot read {what} {p}: it is a folder")
        with p.open("rb") as fh:  # read one byte past the limit: devices report size 0
            raw = fh.read(max_bytes + 1)
    except FileNotFoundError:
        raise DataError(f"cannot read {what} {p}: no such file") from None
    except PermissionError:
        raise DataError(f"cannot read {what} {p}: permission denied") from None
    except OSError as exc:
        raise DataError(f"cannot read {what} {p}: {exc.strerror or exc}") from None
    if len(raw) > max_bytes:
        raise DataError(f"{what} {p} is larger than the limit of {max_bytes // (1024 * 1024)} MiB")
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise DataError(f"{what} {p} is not UTF-8 text (byte {exc.start}): a binary file?") from None


def _depth_ok(text: str, limit: int = MAX_DEPTH) -> bool:
    """True when brackets outside strings nest at most `limit` deep (checked before json.loads)."""
    depth = deepest = 0
    in_str = escaped = False
    for ch in text:
        if in_str:
            if escaped:
                escaped = False
            elif ch == "\\":
                escaped = True
            elif ch == '"':
                in_str = False
        elif ch == '"':
            in_str = True
        elif ch in "[{":
            depth += 1
            if depth > deepest:
                deepest = depth
                if deepest > limit:
                    return False
        elif ch in "]}":
            depth -= 1
    return True


def loads(text: str, where: str = "input") -> Any:
    """`json.loads` with one-line errors and a nesting limit."""
    if not _depth_ok(text):
        raise DataError(f"{where}: JSON nested deeper than {MAX_DEPTH} levels")
    try:
        return json.loads(text)
    except json.JSONDecodeError as exc:
        raise DataError(
            f"{where}: not valid JSON ({exc.msg} at line {exc.lineno} column {exc.colno})"
        ) from None
    except (RecursionError, ValueError) as exc:
        raise DataError(f"{where}: not valid JSON ({exc})") from None


def read_json(path: str | Path, what: str = "JSON file", max_bytes: int = MAX_BYTES) -> Any:
    """A JSON document from a file (bounded, one-line errors)."""
    return loads(read_text(path, what, max_bytes), f"{what} {path}")


def read_jsonl(path: str | Path, what: str = "JSON-lines file") -> list[Any]:
    """Records of a JSON-lines file; the first bad line is an error naming it."""
    text = read_text(path, what)
    out = []
    for n, line in enumerate(text.splitlines(), start=1):
        if line.strip():
            out.append(loads(line, f"{what} {path}:{n}"))
    return out


def _prepare(path: Path, what: str) -> None:
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise DataError(f"cannot write {what} {path}: {exc.strerror or exc}") from None


def write_text(path: str | Path, text: str, what: str = "file") -> None:
    """Write a text file (UTF-8), creating its folder; `DataError` naming the path on failure."""
    p = Path(path)
    _prepare(p, what)
    try:
        p.write_text(text, encoding="utf-8")
    except OSError as exc:
        raise DataError(f"cannot write {what} {p}: {exc.strerror or exc}") from None


def write_json(path: str | Path, obj: Any, what: str = "JSON file", indent: int | None = 1) -> None:
    """Write one JSON document (non-JSON values as their `str`)."""
    write_text(path, json.dumps(obj, indent=indent, default=str) + "\n", what)


def ensure_writable_dir(path: str | Path, what: str = "output folder") -> Path:
    """Create `path` as a folder (parents too) and check that a file can be written in it."""
    p = Path(path)
    if p.exists() and not p.is_dir():
        raise DataError(f"cannot use {what} {p}: it is a file, not a folder")
    try:
        p.mkdir(parents=True, exist_ok=True)
        probe = p / ".nl2hltl2plan-write-test"
        probe.write_text("")
        probe.unlink()
    except OSError as exc:
        raise DataError(f"cannot write to {what} {p}: {exc.strerror or exc}") from None
    return p


PICTURE_FORMATS = ("png", "svg", "pdf", "jpg", "jpeg", "webp", "tif", "tiff", "eps")


def check_output_file(path: str | Path, formats: tuple[str, ...] = (), what: str = "output file") -> Path:
    """Refuse, before any work, an output path whose format is unknown or whose folder cannot be made
    or written to (`formats`: allowed suffixes without the dot; empty: any)."""
    p = Path(path)
    suffix = p.suffix.lower().lstrip(".")
    if formats and suffix not in formats:
        raise DataError(f"cannot write {what} {p}: unknown format {suffix or '(none)'!r}; use one of "
                        f"{', '.join('.' + f for f in formats)}")
    if p.is_dir():
        raise DataError(f"cannot write {what} {p}: it is a folder")
    ensure_writable_dir(p.parent if str(p.parent) else ".", f"folder of the {what}")
    return p
