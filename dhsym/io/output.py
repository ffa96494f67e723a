"""Writing result files atomically: a temporary file beside the target, then a rename.

A failure at any point leaves either the old file or no file, never half of a new one. A target
that is not a regular file (/dev/stdout, /dev/null, /dev/full, a pipe) is written in place:
renaming over it would replace the device itself. A named pipe is written only if a program
reads it already (dhsym never waits for a reader); a socket or a disk is refused.

>>> import tempfile, os
>>> folder = tempfile.mkdtemp()
>>> write_atomic(os.path.join(folder, "T.tex"), "x")
>>> open(os.path.join(folder, "T.tex")).read()
'x'
"""
from __future__ import annotations

import errno
import os
import stat
import tempfile
from pathlib import Path

from ..errors import Location, UserError
from .yamlsafe import NONBLOCKING, special_file_refusal


def write_atomic(path, data: str | bytes, inputs=()) -> None:
    """Write `data` to `path`; refuse to overwrite any of the `inputs` files."""
    target = Path(path)
    for source in inputs:
        try:
            if Path(source).exists() and target.exists() and os.path.samefile(source, target):
                raise UserError("refusing to overwrite the input file with the output", Location(str(target)))
        except OSError:
            pass
    try:
        mode = target.stat().st_mode
    except OSError:
        mode = None  # a new file, or a path that the writing below reports on
    if mode is not None and not stat.S_ISREG(mode) and not stat.S_ISDIR(mode):
        refusal = special_file_refusal(mode, "file to write to")
        if refusal:
            raise UserError(refusal, Location(str(target)))
        _write_in_place(target, data)
        return
    folder = target.parent if str(target.parent) else Path(".")
    if not folder.is_dir():
        raise UserError(f"folder {str(folder)!r} does not exist", Location(str(target)))
    binary = isinstance(data, bytes)
    try:
        handle, temporary = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=folder)
    except OSError as exc:
        raise UserError(f"cannot write here: {exc.strerror}", Location(str(target))) from None
    try:
        with os.fdopen(handle, "wb" if binary else "w", **({} if binary else {"encoding": "utf-8"})) as stream:
            stream.write(data)
            stream.flush()
            os.fsync(stream.fileno())  # the bytes are on disk before the name points at them
        os.chmod(temporary, _mode_for(target))
        os.replace(temporary, target)
    except OSError as exc:
        _remove_quietly(temporary)
        raise UserError(f"cannot write file: {exc.strerror}", Location(str(target))) from None
    except BaseException:
        _remove_quietly(temporary)
        raise


def _write_in_place(target: Path, data: str | bytes) -> None:
    """Write to a device or a pipe as it is; its errors (a full device) are the user's to know."""
    binary = isinstance(data, bytes)
    try:
        handle = os.open(target, os.O_WRONLY | NONBLOCKING)  # a pipe with no reader fails at once (ENXIO)
    except OSError as exc:
        if exc.errno == errno.ENXIO:
            raise UserError("is a named pipe that no program reads, and dhsym does not wait for one; start the "
                            "reader first, or write to a file", Location(str(target))) from None
        raise UserError(f"cannot write file: {exc.strerror or exc}", Location(str(target))) from None
    try:
        with open(handle, "wb" if binary else "w", **({} if binary else {"encoding": "utf-8"})) as stream:
            if NONBLOCKING:
                os.set_blocking(handle, True)  # a reader is there: wait for it as any pipe does
            stream.write(data)
    except OSError as exc:
        raise UserError(f"cannot write file: {exc.strerror or exc}", Location(str(target))) from None


def _mode_for(target: Path) -> int:
    """The existing file's permissions, else the usual ones (mkstemp alone would give 0600)."""
    try:
        return target.stat().st_mode & 0o7777
    except OSError:
        mask = os.umask(0)
        os.umask(mask)
        return 0o666 & ~mask


def _remove_quietly(path) -> None:
    try:
        os.unlink(path)
    except OSError:
        pass
