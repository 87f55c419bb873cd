"""Every file ttsgc writes goes through here: atomically (a reader sees the old file or the whole new one, never
half of it), never over an input of the running command, never over a read-only file or someone else's file,
and with a clear error (exit 2) naming the path when the output cannot be written."""

from __future__ import annotations

import os
import stat
import tempfile
from pathlib import Path

from ttsgc.errors import UsageError


class OutputError(UsageError):
    """An output that cannot or must not be written: a folder, an input, a read-only file, an unwritable place."""


def real_path(path: str | Path) -> Path:
    """The absolute path with symlinks followed. A symlink loop (RuntimeError before Python 3.13) gives the
    absolute path unresolved, which then fails to open like any unreadable file, with an OSError."""
    try:
        return Path(path).resolve()
    except RuntimeError:
        return Path(os.path.abspath(path))


def missing_why(path: Path) -> str:
    """Why a file the command needs cannot be read as one: 'does not exist' or 'is not a regular file'."""
    return "is not a regular file" if path.exists() else "does not exist"


_INPUTS: set[tuple[int, int]] = set()  # (device, inode) of the files the running command reads
_INPUT_PATHS: set[Path] = set()


def protect_inputs(*paths: str | Path) -> None:
    """Mark files as inputs of the running command: no output may replace them (the same file under any name,
    hard links included)."""
    for path in paths:
        path = Path(path)
        _INPUT_PATHS.add(real_path(path))
        try:
            st = path.stat()
        except OSError:
            continue
        _INPUTS.add((st.st_dev, st.st_ino))


def release_inputs() -> None:
    """Forget the inputs (a command has ended; the next one in the same process marks its own)."""
    _INPUTS.clear()
    _INPUT_PATHS.clear()


def check_output(path: str | Path) -> Path:
    """Refuse an output path before anything is written: a folder, an input, a read-only or foreign file."""
    path = Path(path)
    if path.is_dir():
        raise OutputError(f"{path}: is a folder; name the file to write (e.g. {path / 'scene.xosc'})")
    if real_path(path) in _INPUT_PATHS:
        raise OutputError(f"{path}: is an input of this command; ttsgc never overwrites its input (name another "
                          f"output with -o)")
    try:
        st = path.stat()
    except OSError:
        return path
    if not stat.S_ISREG(st.st_mode):  # renaming over /dev/null or a pipe would replace it with a plain file
        raise OutputError(f"{path}: is not a regular file (a device, pipe or socket); ttsgc writes only files")
    if (st.st_dev, st.st_ino) in _INPUTS:
        raise OutputError(f"{path}: is an input of this command (under another name); ttsgc never overwrites "
                          f"its input")
    if not st.st_mode & 0o222 or not os.access(path, os.W_OK):
        raise OutputError(f"{path}: is read-only; ttsgc does not replace a file it may not write")
    return path


def check_outputs(*paths: str | Path) -> None:
    """check_output for each, and no two outputs of one command at the same path."""
    seen: dict[Path, Path] = {}
    for path in map(Path, paths):
        check_output(path)
        other = seen.setdefault(real_path(path), path)
        if other is not path:
            raise OutputError(f"{path}: two outputs of this command would be written there ({other} and {path})")


def write_output(path: str | Path, data: str | bytes) -> None:
    """Write one user-visible output: checked by check_output, then written atomically."""
    path = check_output(path)
    try:
        write_atomic(path, data)
    except OSError as exc:
        raise OutputError(f"{path}: cannot be written in the folder {path.parent}: {exc.strerror or exc}") from None


def write_atomic(path: str | Path, data: str | bytes) -> None:
    """Write through a temporary file in the same folder, renamed over the target; a replaced file keeps its
    mode and owner. Raises OSError; write_output turns it into a message."""
    path = Path(path)
    payload = data.encode("utf-8") if isinstance(data, str) else data
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as handle:
            handle.write(payload)
        try:
            st = path.stat()
        except FileNotFoundError:
            os.chmod(tmp, 0o644)
        else:
            os.chmod(tmp, st.st_mode & 0o777)
            if (st.st_uid, st.st_gid) != (os.geteuid(), os.getegid()):
                os.chown(tmp, st.st_uid, st.st_gid)  # fails (PermissionError) rather than take the file over
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
