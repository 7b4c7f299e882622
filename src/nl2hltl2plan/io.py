"""Every JSON / JSON-lines file the package reads or writes goes through here.

Reading is bounded and never raises anything but `DataError` with a one-line message naming the
file: a size limit (`MAX_BYTES`, stated in the error) so `/dev/zero` or a huge file cannot exhaust
memory, UTF-8 decoding errors, malformed JSON, and nesting deeper than `MAX_DEPTH` (Python's JSON
parser recurses, so a 10,000-deep list would otherwise end in RecursionError). Only regular files are
opened: a FIFO, a device or a socket is refused before `open` (which would block on a FIFO forever).
Writing is atomic: every file goes to a temporary file in the same folder that is renamed over the
target (`atomic_path`), so a kill leaves the old file or the new one, never a torn one; the folder is
created and `OSError` becomes a `DataError` naming the path. Output paths are checked before any work
(`ensure_writable_dir`, `check_output_file`, `check_new_file`). Benchmark results files (JSON lines
appended as scenarios finish, the one exception) are read and repaired by `suites.runner`.

>>> import tempfile, pathlib
>>> p = pathlib.Path(tempfile.mkdtemp()) / "x.json"
>>> write_json(p, {"a": [1, 2]})
>>> read_json(p)
{'a': [1, 2]}
"""

from __future__ import annotations

import contextlib
import gzip
import json
import os
import platform
import secrets
import stat
import zlib
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from nl2hltl2plan.errors import DataError

MAX_BYTES = 64 * 1024 * 1024  # 64 MiB: far above any spec, plan or ground-truth file
MAX_DEPTH = 200  # nesting of JSON containers


def require_regular_file(path: str | Path, what: str = "file") -> Path:
    """`path` if it is a regular file (after symlinks); `DataError` naming what it is otherwise.
    Checked before opening: opening a FIFO for reading blocks until a writer comes, maybe never."""
    p = Path(path)
    try:
        mode = p.stat().st_mode
    except FileNotFoundError:
        raise DataError(f"cannot read {what} {p}: no such file") from None
    except PermissionError:
        raise DataError(f"cannot read {what} {p}: permission denied") from None
    except (OSError, ValueError) as exc:  # ValueError: a NUL byte in the name
        raise DataError(f"cannot read {what} {p}: {getattr(exc, 'strerror', None) or exc}") from None
    if not stat.S_ISREG(mode):
        kind = _FILE_KINDS.get(stat.S_IFMT(mode), "not a regular file")
        raise DataError(f"cannot read {what} {p}: it is {kind}, not a regular file")
    return p


_FILE_KINDS = {
    stat.S_IFDIR: "a folder",
    stat.S_IFIFO: "a FIFO (named pipe)",
    stat.S_IFCHR: "a character device",
    stat.S_IFBLK: "a block device",
    stat.S_IFSOCK: "a socket",
}


def read_bytes(path: str | Path, what: str = "file", max_bytes: int = MAX_BYTES) -> bytes:
    """The bytes of a regular file, at most `max_bytes` long (one-line `DataError`s)."""
    p = require_regular_file(path, what)
    try:
        with p.open("rb") as fh:  # one byte past the limit: /proc files report size 0
            raw = fh.read(max_bytes + 1)
    except FileNotFoundError:
        raise DataError(f"cannot read {what} {p}: no such file") from None
    except PermissionError:
        raise DataError(f"cannot read {what} {p}: permission denied") from None
    except OSError as exc:
        raise DataError(f"cannot read {what} {p}: {exc.strerror or exc}") from None
    if len(raw) > max_bytes:
        raise DataError(f"{what} {p} is larger than the limit of {max_bytes // (1024 * 1024)} MiB")
    return raw


def read_text(path: str | Path, what: str = "file", max_bytes: int = MAX_BYTES) -> str:
    """The UTF-8 text of a regular file, at most `max_bytes` long."""
    p = Path(path)
    raw = read_bytes(p, what, max_bytes)
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


def iter_gzip_jsonl(path: str | Path, what: str = "JSON-lines.gz file") -> Iterator[tuple[int, Any]]:
    """(line number, record) of a gzip-compressed JSON-lines data file, streamed; a damaged file (cut
    short, not gzip, bad JSON on a line) is one `DataError` naming the file and the line."""
    p = require_regular_file(path, what)
    n = 0
    try:
        with gzip.open(p, "rt", encoding="utf-8") as fh:
            for n, line in enumerate(fh, start=1):  # noqa: B007 - n names the line in errors
                if line.strip():
                    yield n, _record(line, f"{what} {p}:{n}")
    except (OSError, EOFError, zlib.error, UnicodeDecodeError) as exc:
        where = f" after line {n}" if n else ""
        raise DataError(f"cannot read {what} {p}{where}: damaged ({type(exc).__name__}: {exc})") from None


def _record(line: str, where: str) -> Any:
    """One line of a trusted data file (no nesting pre-check: those files are large and flat)."""
    try:
        return json.loads(line)
    except (ValueError, RecursionError) as exc:
        raise DataError(f"{where}: not valid JSON ({exc})") from None


def load_npy(path: str | Path, what: str = "array file") -> Any:
    """A NumPy .npy array (no pickles); a damaged file is one `DataError` naming it."""
    import numpy as np

    p = require_regular_file(path, what)
    try:
        return np.load(p, allow_pickle=False)
    except (OSError, ValueError, EOFError) as exc:
        raise DataError(f"cannot read {what} {p}: damaged ({type(exc).__name__}: {exc})") from None


def _prepare(path: Path, what: str) -> None:
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise DataError(f"cannot write {what} {path}: {exc.strerror or exc}") from None


@contextlib.contextmanager
def atomic_path(path: str | Path, what: str = "file") -> Iterator[Path]:
    """A temporary path beside `path` (same suffix, so writers that pick the format by it still do) to
    write to; renamed over `path` when the block ends without error, removed otherwise. A kill
    while writing leaves `path` as it was. `DataError` naming `path` when the folder cannot be written.

    >>> import tempfile, pathlib
    >>> p = pathlib.Path(tempfile.mkdtemp()) / "a.txt"
    >>> with atomic_path(p) as tmp:
    ...     _ = tmp.write_text("new")
    >>> p.read_text(), sorted(x.name for x in p.parent.iterdir())
    ('new', ['a.txt'])
    """
    p = Path(path)
    _prepare(p, what)
    tmp = p.with_name(f".{p.stem}.{secrets.token_hex(4)}.tmp{p.suffix}")
    try:
        yield tmp
        os.replace(tmp, p)
    except OSError as exc:
        raise DataError(f"cannot write {what} {p}: {exc.strerror or exc}") from None
    finally:
        with contextlib.suppress(OSError):
            tmp.unlink()


def write_bytes(path: str | Path, data: bytes, what: str = "file") -> None:
    """Write a file atomically (temporary file, flushed to disk, renamed), creating its folder."""
    with atomic_path(path, what) as tmp:
        with open(tmp, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())


def save_figure(fig: Any, path: str | Path, what: str = "picture", **savefig_kwargs: Any) -> Path:
    """`fig.savefig` through `atomic_path` (the format from the suffix, as matplotlib picks it)."""
    p = Path(path)
    with atomic_path(p, what) as tmp:
        fig.savefig(tmp, format=p.suffix.lstrip(".").lower() or None, **savefig_kwargs)
    return p


def write_text(path: str | Path, text: str, what: str = "file") -> None:
    """Write a text file (UTF-8) atomically, creating its folder; `DataError` naming the path on failure."""
    write_bytes(path, text.encode("utf-8"), what)


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


def check_new_file(path: str | Path, what: str = "output file") -> Path:
    """Refuse, before any work, an output path that exists already (it is never overwritten silently)
    or whose folder cannot be written to."""
    p = Path(path)
    if p.exists() or p.is_symlink():
        raise DataError(f"{what} {p} exists already; remove it or choose another name (never overwritten)")
    ensure_writable_dir(p.parent if str(p.parent) else ".", f"folder of the {what}")
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


def machine_description() -> str:
    """The machine line every report states: system, architecture, cores and Python."""
    cores = os.cpu_count()
    return f"{platform.system()} {platform.machine()}, {cores} cores, Python {platform.python_version()}"
