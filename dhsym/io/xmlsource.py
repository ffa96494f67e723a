"""XML robot files read safely, with every element and attribute placed at its FILE:LINE:COL.

The bytes are decoded first (byte-order mark, else the XML declaration's encoding, else UTF-8),
and only then checked: a DOCTYPE or entity declaration is refused in any encoding (entities can
expand without bound), and so is anything that still needs xacro (an element or attribute in the
xacro namespace, a `${…}` or `$(…)` substitution). A bare `xmlns:xacro` declaration, which
every file that xacro wrote still carries, is fine, and so is a substitution where it changes
nothing (`refuse_substitutions` is told where: a URDF's meshes, say). lxml parses with entities, DTDs and network
access off. A default namespace (`<robot xmlns="…">`) is read as none, as ROS's parser does.
Input must be a regular file of at most 2 MiB: a named pipe or a device is refused
before it is opened, so that reading never blocks.

>>> source = parse_xml_text('<robot name="a">\\n  <link name="b"/></robot>'.encode("utf-16"), "a.urdf")
>>> link = source.root[0]
>>> str(source.place(link)), str(source.place(link, "name"))
('a.urdf:2:3', 'a.urdf:2:15')
>>> parse_xml_text(b'<robot>\\n<link name="${x}"/></robot>', "b.urdf").refuse_substitutions()  # doctest: +ELLIPSIS
Traceback (most recent call last):
dhsym.errors.UserError: b.urdf:2:13: ${x} is a xacro substitution, not URDF; ...
"""
from __future__ import annotations

import codecs
import os
import re
import stat
from pathlib import Path

from lxml import etree

from ..errors import Location, UserError

MAX_XML_BYTES = 2 << 20
XACRO_NAMESPACES = ("http://www.ros.org/wiki/xacro", "http://ros.org/wiki/xacro", "http://wiki.ros.org/xacro")
_BOMS = ((codecs.BOM_UTF32_LE, "utf-32-le"), (codecs.BOM_UTF32_BE, "utf-32-be"), (codecs.BOM_UTF8, "utf-8-sig"),
         (codecs.BOM_UTF16_LE, "utf-16-le"), (codecs.BOM_UTF16_BE, "utf-16-be"))
_DECLARED = re.compile(rb"""^<\?xml[^>]*?encoding\s*=\s*["']([A-Za-z0-9._-]{1,40})["']""")
# What the checks skip: comments, CDATA and processing instructions; then start tags in document order.
_SKIPPED = re.compile(r"<!--.*?-->|<!\[CDATA\[.*?\]\]>|<\?.*?\?>", re.DOTALL)
_START_TAG = re.compile(r"<([A-Za-z_][\w.:-]*)")
_ATTRIBUTE = re.compile(r"""\s+([A-Za-z_][\w.:-]*)\s*=\s*("[^"]*"|'[^']*')""")
_EXPAND = "name the file *.xacro to have dhsym expand it, or expand it with xacro first"
_SUBSTITUTION = re.compile(r"\$\{[^}]*\}?|\$\([^)]*\)?")


def read_regular_file(path: str | Path, limit: int = MAX_XML_BYTES, what: str = "URDF files") -> bytes:
    """The bytes of a regular file of at most `limit` bytes; a folder, pipe or device is refused
    without opening it (opening a named pipe would wait for a writer)."""
    path = Path(path)
    try:
        kind = os.stat(path).st_mode
        if stat.S_ISDIR(kind):
            raise UserError("is a folder, not a file", Location(str(path)))
        if not stat.S_ISREG(kind):
            raise UserError("is not a regular file (a pipe, socket or device); give a file", Location(str(path)))
        with path.open("rb") as handle:
            data = handle.read(limit + 1)
    except OSError as exc:
        raise UserError(f"cannot read file: {exc.strerror or exc}", Location(str(path))) from None
    if len(data) > limit:
        raise UserError(f"file is larger than {limit >> 20} MiB, the limit for {what}", Location(str(path), 1, 1))
    return data


def decode_xml(data: bytes, filename: str) -> str:
    """The text of an XML file as its byte-order mark or declaration says (UTF-8 by default)."""
    encoding = next((name for bom, name in _BOMS if data.startswith(bom)), None)
    if encoding is None and data[:2] in (b"<\x00", b"\x00<"):  # UTF-16 without a byte-order mark
        encoding = "utf-16-le" if data[0] == 0x3C else "utf-16-be"
    if encoding is None:
        declared = _DECLARED.match(data)
        encoding = declared.group(1).decode("ascii") if declared else "utf-8"
    try:
        text = data.decode(encoding)
    except LookupError:
        raise UserError(f"unknown encoding {encoding!r} in the XML declaration", Location(filename, 1, 1)) from None
    except UnicodeDecodeError as exc:
        line = data[:exc.start].count(b"\n") + 1
        raise UserError(f"not valid {encoding} text (byte {exc.start + 1})", Location(filename, line)) from None
    return text.lstrip("\ufeff")


class XmlSource:
    """A parsed XML file and the places of its elements and attributes in the text."""

    def __init__(self, root, text: str, filename: str):
        self.root, self.filename = root, filename
        self.starts = {}  # element -> offset of its "<" in the text
        self.line_starts = [0] + [m.end() for m in re.finditer("\n", text)]
        self.text = text
        blanked = _blank(text)
        offsets = [m.start() for m in _START_TAG.finditer(blanked)]
        for element, offset in zip(root.iter(tag=etree.Element), offsets):
            self.starts[element] = offset

    def location(self, offset: int) -> Location:
        line = _line_of(self.line_starts, offset)
        return Location(self.filename, line, offset - self.line_starts[line - 1] + 1)

    def place(self, element, attribute: str | None = None, word: int | None = None) -> Location:
        """Where an element starts; with `attribute`, where its value starts; with `word`, where
        the word-th (from 0) space-separated part of the value starts."""
        start = self.starts.get(element)
        if start is None:
            return Location(self.filename, element.sourceline)
        if attribute is None:
            return self.location(start)
        tag = _START_TAG.match(self.text, start)
        for match in _ATTRIBUTE.finditer(self.text, tag.end()):
            if match.start() != tag.end() and not self.text[tag.end():match.start()].isspace():
                break
            tag = match
            if match.group(1) == attribute:
                offset = match.start(2) + 1
                if word:
                    parts = list(re.finditer(r"\S+", match.group(2)[1:-1]))
                    offset += parts[word].start() if word < len(parts) else 0
                return self.location(offset)
        return self.location(start)


    def refuse_substitutions(self, ignored: tuple = ()) -> None:
        """Refuse a `${…}` or `$(…)` left in an attribute, except under the `ignored` elements
        (a mesh's `$(find robot)/base.stl` changes nothing that dhsym reads)."""
        waiting = [self.root]
        while waiting:
            element = waiting.pop()
            if element.tag in ignored:
                continue
            for key, value in element.attrib.items():
                found = _SUBSTITUTION.search(value)
                if found:
                    where = self.place(element, key).shifted(found.start())
                    raise UserError(f"{found.group(0)[:40]} is a xacro substitution, not URDF; {_EXPAND}", where)
            waiting.extend(reversed([child for child in element if isinstance(child.tag, str)]))


def parse_xml_text(data: bytes, filename: str) -> XmlSource:
    """Decode, check and parse; see the module's docstring."""
    text = decode_xml(data, filename)
    blanked = _blank(text)
    declaration = re.search(r"<!(DOCTYPE|ENTITY)", text, re.IGNORECASE)
    if declaration:
        raise UserError("DOCTYPE and entity declarations are not allowed in a URDF file (entities can expand "
                        "without bound)", _location(text, filename, declaration.start()))
    _refuse_xacro(blanked, filename)
    parser = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False, huge_tree=False,
                             remove_comments=True, remove_pis=True)
    try:
        root = etree.fromstring(re.sub(r"^\s*<\?xml[^>]*\?>", "", text).encode("utf-8"), parser)
    except etree.XMLSyntaxError as exc:
        line, column = exc.position if exc.position else (None, None)
        raise UserError(f"not well-formed XML: {exc.msg.split(', line')[0]}", Location(filename, line, column)) \
            from None
    if root.getroottree().docinfo.doctype:
        raise UserError("DOCTYPE declarations are not allowed in a URDF file", Location(filename, 1, 1))
    _drop_default_namespace(root)
    return XmlSource(root, text, filename)


def _drop_default_namespace(root) -> None:
    """Read `<robot xmlns="…">` as `<robot>`: ROS's own URDF parser ignores namespaces, so files
    that declare a default one are published and used; elements of other namespaces stay apart."""
    default = root.nsmap.get(None)
    if default is None:
        return
    prefix = "{" + default + "}"
    for element in root.iter():
        if isinstance(element.tag, str) and element.tag.startswith(prefix):
            element.tag = element.tag[len(prefix):]


def xacro_element(data: bytes, filename: str) -> tuple[Location, str] | None:
    """Where an XML file first uses a xacro element or attribute, and its name (`xacro:property`),
    or None: such a file is a xacro file whatever its name."""
    return _xacro_use(_blank(decode_xml(data, filename)), filename)


def _xacro_use(blanked: str, filename: str) -> tuple[Location, str] | None:
    prefixes = {m.group(1) for m in re.finditer(r"""xmlns:([\w.-]+)\s*=\s*["']([^"']*)["']""", blanked)
                if m.group(2).rstrip("/") in XACRO_NAMESPACES} | {"xacro"}
    names = "|".join(map(re.escape, prefixes))
    used = re.search(rf"</?(?:{names}):[\w.-]+|\s(?:{names}):[\w.-]+\s*=", blanked)
    if used is None:
        return None
    where = _location(blanked, filename, used.start() + (1 if used.group(0)[0].isspace() else 0))
    return where, used.group(0).strip().lstrip("</")


def _refuse_xacro(blanked: str, filename: str) -> None:
    """Refuse what only xacro can read: xacro elements or attributes and ${…}/$(…) substitutions."""
    used = _xacro_use(blanked, filename)
    if used is not None:
        raise UserError(f"<{used[1]}> is a xacro element, not URDF; {_EXPAND}", used[0])


def _blank(text: str) -> str:
    """The text with comments, CDATA and processing instructions blanked out (same offsets)."""
    return _SKIPPED.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


def _line_of(line_starts: list, offset: int) -> int:
    low, high = 0, len(line_starts)
    while high - low > 1:
        middle = (low + high) // 2
        low, high = (middle, high) if line_starts[middle] <= offset else (low, middle)
    return low + 1


def _location(text: str, filename: str, offset: int) -> Location:
    line = text.count("\n", 0, offset) + 1
    return Location(filename, line, offset - (text.rfind("\n", 0, offset) + 1) + 1)
