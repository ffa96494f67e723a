"""Reading YAML that may be hostile: composed into nodes, never constructed into objects.

Nodes keep their line and column, so every later message can point into the file. Tags,
aliases, more than one document, nesting deeper than 10 and more than 20,000 values are
refused while composing, so a hostile file costs little; files over 1 MiB or not UTF-8
are refused before that.

>>> compose("joints: [{joint: R}]", "arm.yaml").value[0][0].value
'joints'
>>> compose("a: &x 1\\nb: *x", "arm.yaml")
Traceback (most recent call last):
dhsym.errors.UserError: arm.yaml:2:4: YAML aliases (*name) are not allowed in robot files
"""
from __future__ import annotations

import os
import stat
from pathlib import Path

import yaml

from ..errors import Location, UserError
from .yamlhints import explain

MAX_FILE_BYTES = 1 << 20
MAX_YAML_DEPTH = 10  # a robot file needs 3 (file, joints list, row)
MAX_JOINTS = 24  # of one robot file, DH rows or axes
MAX_YAML_NODES = 20_000  # a 24-joint robot with notes needs a few hundred
YAML_TAG = "tag:yaml.org,2002:"  # prefix of the core schema tags: null, bool, int, ...


def read_text_file(path: str | Path) -> str:
    """A small UTF-8 text file's contents; folders, sockets, huge or non-UTF-8 files are UserErrors.

    A named pipe is read only if a program writes to it already: dhsym never waits for a writer
    (opening a pipe for reading would otherwise block until one comes, perhaps for ever).
    """
    path = Path(path)
    where = Location(str(path))
    try:
        mode = path.stat().st_mode
        refusal = special_file_refusal(mode, "robot file")
        if refusal:
            raise UserError(refusal, where)
        handle = os.open(path, os.O_RDONLY | NONBLOCKING)  # a pipe's open returns at once
        if NONBLOCKING:
            os.set_blocking(handle, True)  # and its read waits for the writer that is there
        with os.fdopen(handle, "rb") as stream:
            data = stream.read(MAX_FILE_BYTES + 1)  # never more than the limit, whatever stat says
    except OSError as exc:
        raise UserError(f"cannot read file: {exc.strerror or exc}", where) from None
    if not data and stat.S_ISFIFO(mode):
        raise UserError("is a named pipe that no program writes to, and dhsym does not wait for one; start the "
                        "writer first, or give the file itself, or - to read standard input", where)
    if len(data) > MAX_FILE_BYTES:
        raise UserError(f"file is larger than {MAX_FILE_BYTES // (1 << 20)} MiB, the limit for robot files",
                        Location(str(path), 1, 1))
    return decode_utf8(data, str(path))


NONBLOCKING = getattr(os, "O_NONBLOCK", 0)


def special_file_refusal(mode: int, what: str) -> str | None:
    """Why a file of this `stat` mode cannot be a `what` (a folder, a socket, a disk), or None.

    >>> special_file_refusal(stat.S_IFSOCK, "robot file")
    'is a socket, not a robot file'
    """
    for test, kind in ((stat.S_ISDIR, "a folder"), (stat.S_ISSOCK, "a socket"), (stat.S_ISBLK, "a block device")):
        if test(mode):
            return f"is {kind}, not a {what}"
    return None


def decode_utf8(data: bytes, filename: str) -> str:
    """The text of a file, or a UserError at the line and column of the first bad byte."""
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        before = data[:exc.start].decode("utf-8", errors="replace")
        line = before.count("\n") + 1
        column = len(before) - (before.rfind("\n") + 1) + 1
        hint = "it looks like UTF-16; " if data[:2] in (b"\xff\xfe", b"\xfe\xff") else ""
        raise UserError(f"file is not UTF-8 text (byte 0x{data[exc.start]:02X}); {hint}save it as UTF-8",
                        Location(filename, line, column)) from None




def compose(text: str, filename: str, tags=frozenset(), what: str = "robot file") -> yaml.Node:
    """The root node of the one YAML document in `text`, composed but never constructed; local
    `tags` (xacro's `!degrees`) are let through, and messages speak of a `what`."""
    loader = None
    try:
        loader = _GuardedLoader(text, filename, tags, what)
        node = loader.single_node()
    except yaml.reader.ReaderError as exc:
        line = text.count("\n", 0, exc.position) + 1
        column = exc.position - (text.rfind("\n", 0, exc.position) + 1) + 1
        character = exc.character if isinstance(exc.character, str) else chr(exc.character)
        raise UserError(f"character U+{ord(character):04X} is not allowed in a {what}",
                        Location(filename, line, column)) from None
    except yaml.MarkedYAMLError as exc:
        message, line, column = explain(exc, text)
        raise UserError(f"YAML syntax error: {message}", Location(filename, line + 1, column + 1)) from None
    except yaml.YAMLError as exc:
        raise UserError(f"YAML error: {_one_line(str(exc))}", Location(filename, 1, 1)) from None
    finally:
        if loader is not None:
            loader.dispose()
    if node is None:
        raise UserError(f"file is empty; expected a {'robot description' if what == 'robot file' else what}",
                        Location(filename, 1, 1))
    return node


def _one_line(message: str) -> str:
    return " ".join(message.split())


class _GuardedLoader(yaml.SafeLoader):
    """The safe loader's composer, refusing aliases, tags, deep nesting and too many nodes.

    The checks run as each node is composed, before any recursion into it, so a hostile
    file is refused after reading only as much of it as the first offence.
    """

    def __init__(self, text: str, filename: str, tags=frozenset(), what: str = "robot file"):
        super().__init__(text)
        self.filename, self.depth, self.count = filename, 0, 0
        self.tags, self.what = tags, what

    def single_node(self) -> yaml.Node | None:
        """The one document's root node; a second document is a mistake, not ignored."""
        self.get_event()  # stream start
        root = None if self.check_event(yaml.StreamEndEvent) else self.compose_document()
        if not self.check_event(yaml.StreamEndEvent):
            raise UserError(f"a {self.what} holds one YAML document, but a second one starts here",
                            mark_location(self.filename, self.peek_event().start_mark))
        return root

    def compose_node(self, parent, index):
        event = self.peek_event()
        where = mark_location(self.filename, event.start_mark)
        if isinstance(event, yaml.AliasEvent):
            raise UserError(f"YAML aliases (*name) are not allowed in {self.what}s", where)
        tag = getattr(event, "tag", None)
        if tag is not None and tag not in self.tags:
            shown = "!!" + tag[len(YAML_TAG):] if tag.startswith(YAML_TAG) else tag
            raise UserError(f"YAML tags ({shown}) are not allowed in {self.what}s", where)
        self.count += 1
        if self.count > MAX_YAML_NODES:
            raise UserError(f"more than {MAX_YAML_NODES} YAML values; this is not a {self.what}", where)
        if self.depth >= MAX_YAML_DEPTH:
            raise UserError(f"YAML nested deeper than {MAX_YAML_DEPTH} levels", where)
        self.depth += 1
        try:
            return super().compose_node(parent, index)
        finally:
            self.depth -= 1


def mark_location(filename: str, mark) -> Location:
    return Location(filename, mark.line + 1, mark.column + 1) if mark else Location(filename, 1, 1)
