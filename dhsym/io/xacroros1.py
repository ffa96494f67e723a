"""Tags that ROS 1's xacro (up to 1.13, Melodic) took without the `xacro:` prefix, read as it
read them, with one deprecation warning per file at the first of them; ROS 2's xacro leaves
them as plain XML: `<property>`, `<macro>`, `<arg>`, `<if>`, `<unless>`, `<insert_block>`;
`<include>` only when it holds nothing but text (one with elements inside, such as Gazebo's
`<include><uri>…`, stays XML); and an element named like a macro that a `<macro>` tag defined is
a call of it (ROS 1 let any macro be called so; a file written for ROS 2 that has a plain element
named like one of its xacro:macros keeps it as XML).

>>> from xml.dom import minidom
>>> document = minidom.parseString("<robot><property name='l' value='1'/><include><uri/></include></robot>")
>>> reading = Ros1Tags()
>>> reading.adopt(document, Path("arm.xacro"))
>>> [element.tagName for element in document.documentElement.childNodes]
['xacro:property', 'include']
"""
from __future__ import annotations

import re
from pathlib import Path

from ..errors import Location

ROS1_TAGS = ("property", "macro", "arg", "if", "unless", "insert_block")
_NOT_MARKUP = re.compile(r"<!--.*?-->|<!\[CDATA\[.*?\]\]>|<\?.*?\?>", re.DOTALL)
_START_TAG = re.compile(r"<(?![/!?])([^\s/>]+)")


def blank_markup(text: str) -> str:
    """The text with comments, CDATA sections and processing instructions blanked, in document
    order (a `<!--` inside a processing instruction starts no comment), offsets and lines kept."""
    return _NOT_MARKUP.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


class Ros1Tags:
    """Where each file has unprefixed tags read as xacro's, for the warnings."""

    def __init__(self):
        self.starts = {}  # resolved path -> [(tag name, offset)] of its start tags, in document order
        self.found = {}  # resolved path -> {offset: tag name} of the unprefixed tags read as xacro
        self.macros = set()  # the names of macros defined by <macro>, which ROS 1 let <name/> call

    def note_text(self, path: Path, text: str) -> None:
        self.starts[path] = [(m.group(1), m.start()) for m in _START_TAG.finditer(blank_markup(text))]

    def adopt(self, document, path: Path) -> None:
        """Rename the tags ROS 1's xacro took without the prefix to xacro:NAME, as it read them."""
        elements = [document.documentElement, *document.documentElement.getElementsByTagName("*")]
        starts = self.starts.get(path, [])
        placed = len(starts) == len(elements) and all(e.tagName == name for e, (name, _) in zip(elements, starts))
        for index, element in enumerate(elements):
            name = element.tagName
            children = element.childNodes
            only_text = not children or (len(children) == 1 and children[0].nodeType == children[0].TEXT_NODE)
            if name in ROS1_TAGS or (name == "include" and only_text):
                element.tagName = element.nodeName = "xacro:" + name
                self.found.setdefault(path, {})[starts[index][1] if placed else -1] = name
                if name == "macro":
                    self.macros.add(element.getAttribute("name"))

    def is_call(self, name: str) -> bool:
        """Whether <name> may be a ROS 1 call of a macro that a <macro> tag defined."""
        return ":" not in name and name.rsplit(".", 1)[-1] in self.macros

    def note_call(self, name: str, current: Path) -> None:
        """Remember where the unprefixed macro call <name> is written: first in `current`."""
        for path in sorted(self.starts, key=lambda path: path != current):
            offset = next((offset for tag, offset in self.starts[path] if tag == name), None)
            if offset is not None:
                self.found.setdefault(path, {})[offset] = name
                return
        self.found.setdefault(current, {})[-1] = name

    def warnings(self, texts: dict, names: dict, top: str) -> list[str]:
        """One line per file with unprefixed xacro tags, at the first of them."""
        lines = []
        for path, found in self.found.items():
            tags = list(dict.fromkeys(found[offset] for offset in sorted(found)))
            first = min(found)
            where = place(texts[path], names[path], first) if first >= 0 else Location(names.get(path, top))
            one = len(tags) == 1
            lines.append(f"{where}: {', '.join(f'<{name}>' for name in tags)} without the xacro: prefix "
                         f"{'is read as a xacro tag' if one else 'are read as xacro tags'}, as ROS 1's xacro "
                         f"read {'it' if one else 'them'} (deprecated there; ROS 2's xacro leaves "
                         f"{'it' if one else 'them'} as plain XML)")
        return lines


def place(text: str, shown: str, offset: int) -> Location:
    """FILE:LINE:COL of an offset in a file's text."""
    line = text.count("\n", 0, offset) + 1
    return Location(shown, line, offset - (text.rfind("\n", 0, offset) + 1) + 1)
