"""`.xacro` files expanded to URDF by the `xacro` package (an optional extra: pip install
'dhsym[xacro]'), with everything that could run code, read other files or run without end
taken out of its hands.

- `${…}` is worked out by `xacroexpr` (numbers, property names, arithmetic, a few math
  functions), never by xacro's eval; each expression of each file is checked, with its
  FILE:LINE:COL, before anything is expanded.
- `$(…)`: only `$(arg NAME)` and `$(find PKG)`; `$(eval …)`, `$(env …)`, `$(optenv …)`,
  `$(dirname)`, `$(cwd)` and `$(anon …)` are refused. `$(find PKG)` looks for a folder PKG
  (or PKG_description, or PKG without _support) in the robot's own tree: the file's folder, or
  for a file in a package's `urdf/` or `robots/` folder, the folder that holds the package.
- `xacro:include` reads only .xacro, .urdf and .xml files inside that tree, each a regular file
  of at most 2 MiB, no DOCTYPE, at most 200 files and 8 MiB in all; no wildcards.
- Expansion stops after 50,000 elements (macros can call themselves, or double at each level)
  or 64 nested macro calls.
- Tags written without the `xacro:` prefix are read as ROS 1's xacro (up to 1.13, Melodic) read
  them, with a deprecation warning, where xacro 2 leaves them as plain XML: `<property>`,
  `<macro>`, `<arg>`, `<if>`, `<unless>`, `<insert_block>`; `<include>` only when it holds nothing
  but text (one with elements inside, such as Gazebo's `<include><uri>…`, stays XML); and an
  element named like a macro that a `<macro>` tag defined is a call of it (ROS 1 let any macro be
  called so; a file written for ROS 2 that has a plain element named like one of its xacro:macros
  keeps it as XML). Each file that has them gets one warning, at the first of them
  (`expand_xacro(path, warnings)` appends it to `warnings`).

>>> from pathlib import Path
>>> import tempfile
>>> folder = Path(tempfile.mkdtemp())
>>> _ = (folder / "arm.xacro").write_text('''<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">
...   <xacro:property name="l" value="0.5"/><link name="a"/><link name="b"/>
...   <joint name="j" type="revolute"><parent link="a"/><child link="b"/>
...     <origin xyz="0 0 ${l / 2}"/></joint></robot>''')
>>> b'xyz="0 0 0.25"' in expand_xacro(folder / "arm.xacro")
True
>>> _ = (folder / "bad.xacro").write_text('<robot xmlns:xacro="http://www.ros.org/wiki/xacro">\\n'
...                                       '<link name="${open(1)}"/></robot>')
>>> expand_xacro(folder / "bad.xacro")  # doctest: +ELLIPSIS
Traceback (most recent call last):
dhsym.errors.UserError: .../bad.xacro:2:13: calling 'open' is not allowed in a xacro expression; ...
>>> _ = (folder / "old.xacro").write_text('<robot name="old">\\n  <property name="l" value="0.5"/>\\n'
...                                       '  <link name="a" length="${l}"/></robot>')
>>> warnings = []
>>> b'length="0.5"' in expand_xacro(folder / "old.xacro", warnings)
True
>>> print(warnings[0])  # doctest: +ELLIPSIS
/.../old.xacro:2:3: <property> without the xacro: prefix is read as a xacro tag, as ROS 1's xacro read it ...
"""
from __future__ import annotations

import contextlib
import io
import os
import re
from pathlib import Path

from ..errors import Location, UserError
from .xacroexpr import Refused, check_syntax, evaluate
from .xmlsource import MAX_XML_BYTES, decode_xml, read_regular_file

MAX_FILES = 200
MAX_TOTAL_BYTES = 8 << 20
MAX_ELEMENTS = 50_000
MAX_MACRO_DEPTH = 64
INCLUDABLE = (".xacro", ".urdf", ".xml")
PACKAGE_FOLDERS = ("urdf", "robots", "xacro", "model", "models")
_EXPRESSION = re.compile(r"(?<!\$)\$\{([^}]*)\}")
_EXTENSION = re.compile(r"(?<!\$)\$\(\s*(\S*)([^)]*)\)")
_DECLARATION = re.compile(r"<!(DOCTYPE|ENTITY)", re.IGNORECASE)
_COMMENT = re.compile(r"<!--.*?-->", re.DOTALL)
# ROS 1's xacro took these without the prefix (and `include` holding only text); see adopt_ros1_tags.
ROS1_TAGS = ("property", "macro", "arg", "if", "unless", "insert_block")
_NOT_MARKUP = re.compile(r"<!--.*?-->|<!\[CDATA\[.*?\]\]>|<\?.*?\?>", re.DOTALL)
_START_TAG = re.compile(r"<(?![/!?])([^\s/>]+)")


def expand_xacro(path: str | Path, warnings: list | None = None) -> bytes:
    """The URDF that xacro makes of the file, as UTF-8 bytes; see the module's docstring. The
    warnings of the expansion (FILE:LINE:COL: message) are appended to `warnings` if given."""
    try:
        import xacro
    except ImportError:
        raise UserError("reading .xacro files needs the xacro package (pip install 'dhsym[xacro]'); or expand "
                        "the file yourself: xacro FILE.xacro > FILE.urdf", Location(str(path))) from None
    top = Path(path)
    read_regular_file(top)  # a folder, pipe, missing or huge file: one clear line before xacro sees it
    expander = _Expander(xacro, top)
    with expander.guarded():
        try:
            document = xacro.process_file(str(top.resolve()))
        except UserError:
            raise
        except Exception as error:  # xacro's own errors (XacroException, ExpatError, NameError…)
            raise expander.user_error(error) from None
        text = document.toprettyxml(indent="  ")
    if len(text) > 4 * MAX_XML_BYTES:
        raise UserError("the expanded URDF is larger than 8 MiB", Location(str(path)))
    if warnings is not None:
        warnings.extend(expander.ros1_warnings())
    return text.encode("utf-8")


class _Expander:
    """Stands between xacro and the files, the expressions and the substitutions."""

    def __init__(self, xacro, top: Path):
        self.xacro, self.top = xacro, top
        folder = top.resolve().parent
        self.tree = folder.parent.parent if folder.name in PACKAGE_FOLDERS and folder.parent.parent != folder.parent \
            else folder
        self.names = {}  # resolved path -> the name the user knows it by
        self.written = {}  # the path xacro opens -> the include's filename as written
        self.texts = {}
        self.starts = {}  # resolved path -> [(tag name, offset)] of its start tags, in document order
        self.ros1 = {}  # resolved path -> {offset: tag name} of the unprefixed tags read as xacro
        self.ros1_macros = set()  # the names of macros defined by <macro>, which ROS 1 let <name/> call
        self.files = self.bytes = self.elements = 0

    @contextlib.contextmanager
    def guarded(self):
        xacro = self.xacro
        saved = {name: getattr(xacro, name) for name in ("parse", "safe_eval", "eval_extension", "get_include_files",
                                                         "eval_all", "handle_macro_call")}
        original_parse, original_eval_all, original_call = xacro.parse, xacro.eval_all, xacro.handle_macro_call

        def parse(inp, filename=None):
            if inp is None:
                document = original_parse(self.read(filename))
                self.adopt_ros1_tags(document, Path(filename).resolve())
                return document
            return original_parse(inp, filename)

        def handle_macro_call(node, macros, symbols):
            if ":" not in node.tagName and node.tagName.rsplit(".", 1)[-1] in self.ros1_macros \
                    and self.is_macro(node.tagName, macros, symbols):
                self.note_ros1_call(node.tagName)  # ROS 1: <name/> calls the macro name
                node.tagName = node.nodeName = "xacro:" + node.tagName
            return original_call(node, macros, symbols)

        def eval_all(node, macros, symbols):
            self.elements += 1
            if self.elements > MAX_ELEMENTS:
                raise UserError(f"the expansion passes {MAX_ELEMENTS:,} elements (a macro that calls itself, or "
                                "doubles at each level?)", Location(str(self.top)))
            if len(xacro.macrostack or []) > MAX_MACRO_DEPTH:
                raise UserError(f"macros nest deeper than {MAX_MACRO_DEPTH} calls (a macro that calls itself?)",
                                Location(str(self.top)))
            return original_eval_all(node, macros, symbols)

        xacro.parse, xacro.eval_all, xacro.handle_macro_call = parse, eval_all, handle_macro_call
        xacro.safe_eval = lambda expr, symbols, locals=None: self.evaluate(expr, symbols)
        xacro.eval_extension = self.extension
        xacro.get_include_files = self.include_files
        try:
            with contextlib.redirect_stderr(io.StringIO()):  # xacro's own chatter; its errors are raised
                yield
        finally:
            for name, value in saved.items():
                setattr(xacro, name, value)

    def read(self, filename: str) -> str:
        """One file's text, checked: inside the tree, a kind xacro includes, within the limits,
        and every expression and substitution in it of an allowed form."""
        path = Path(filename).resolve()
        written = self.written.get(filename, filename)
        shown = str(self.top) if path == self.top.resolve() else self.shown(path)
        if path != self.top.resolve():
            if path.suffix.lower() not in INCLUDABLE:
                raise self.refuse(f"xacro:include of {written}: only .xacro, .urdf and .xml files are included",
                                  written)
            if not path.is_relative_to(self.tree):
                raise self.refuse(f"xacro:include of {written}: outside the robot's folder {self.shown(self.tree)}",
                                  written)
        self.files += 1
        if self.files > MAX_FILES:
            raise self.refuse(f"more than {MAX_FILES} files included")
        data = read_regular_file(path, MAX_XML_BYTES, "xacro files")
        self.bytes += len(data)
        if self.bytes > MAX_TOTAL_BYTES:
            raise self.refuse("the included files pass 8 MiB in all")
        text = decode_xml(data, shown)
        self.names[path], self.texts[path] = shown, text
        _check_text(text, shown)
        blank = _NOT_MARKUP.sub(lambda m: " " * len(m.group(0)), text)
        self.starts[path] = [(m.group(1), m.start()) for m in _START_TAG.finditer(blank)]
        return re.sub(r"^\s*<\?xml[^>]*\?>", "", text)

    def adopt_ros1_tags(self, document, path: Path) -> None:
        """Rename the tags ROS 1's xacro took without the prefix to xacro:NAME, as it read them:
        `include` only when it holds no element (Gazebo's <include><uri>… is not xacro's)."""
        elements = [document.documentElement, *document.documentElement.getElementsByTagName("*")]
        starts = self.starts.get(path, [])
        placed = len(starts) == len(elements) and all(e.tagName == name for e, (name, _) in zip(elements, starts))
        for index, element in enumerate(elements):
            name = element.tagName
            children = element.childNodes
            only_text = not children or (len(children) == 1 and children[0].nodeType == children[0].TEXT_NODE)
            if name in ROS1_TAGS or (name == "include" and only_text):
                element.tagName = element.nodeName = "xacro:" + name
                self.ros1.setdefault(path, {})[starts[index][1] if placed else -1] = name
                if name == "macro":
                    self.ros1_macros.add(element.getAttribute("name"))

    def is_macro(self, name: str, macros, symbols) -> bool:
        try:
            self.xacro.resolve_macro(name, macros, symbols)
        except (KeyError, TypeError, AttributeError):
            return False
        return True

    def note_ros1_call(self, name: str) -> None:
        """Remember where the unprefixed macro call <name> is written: in the file that defines
        the macro being expanded, else in the file being read."""
        stack = self.xacro.macrostack or []
        written = stack[-1].history[-1][-1] if stack and stack[-1].history and stack[-1].history[-1] \
            else (self.xacro.filestack or [None])[-1]
        current = Path(written).resolve() if written else self.top.resolve()
        for path in sorted(self.starts, key=lambda path: path != current):
            offset = next((offset for tag, offset in self.starts[path] if tag == name), None)
            if offset is not None:
                self.ros1.setdefault(path, {})[offset] = name
                return
        self.ros1.setdefault(current, {})[-1] = name

    def ros1_warnings(self) -> list[str]:
        """One line per file with unprefixed xacro tags, at the first of them."""
        lines = []
        for path, found in self.ros1.items():
            names = list(dict.fromkeys(found[offset] for offset in sorted(found)))
            first = min(found)
            where = _place(self.texts[path], self.names[path], first) if first >= 0 \
                else Location(self.names.get(path, str(self.top)))
            one = len(names) == 1
            lines.append(f"{where}: {', '.join(f'<{name}>' for name in names)} without the xacro: prefix "
                         f"{'is read as a xacro tag' if one else 'are read as xacro tags'}, as ROS 1's xacro "
                         f"read {'it' if one else 'them'} (deprecated there; ROS 2's xacro leaves "
                         f"{'it' if one else 'them'} as plain XML)")
        return lines

    def evaluate(self, expression: str, symbols):
        try:
            return evaluate(str(expression), symbols)
        except Refused as refusal:
            raise self.refuse(f"${{{expression}}}: {refusal}", expression) from None

    def extension(self, text: str) -> str:
        """`$(arg NAME)` and `$(find PKG)`; the other kinds never get here (see _check_text)."""
        match = _EXTENSION.fullmatch(text.strip())
        kind, argument = (match.group(1), match.group(2).strip()) if match else ("", "")
        if kind == "arg":
            arguments = self.xacro.substitution_args_context.get("arg", {})
            if argument not in arguments:
                raise self.refuse(f"$(arg {argument}): no xacro:arg of that name", f"$(arg {argument}")
            return arguments[argument]
        if kind == "find":
            return str(self.find(argument))
        raise self.refuse(f"{text}: only $(arg NAME) and $(find PACKAGE) are allowed", text)

    def find(self, package: str) -> Path:
        names = {package, package + "_description", package.removesuffix("_support"),
                 package.removesuffix("_description")}
        for folder in [self.tree, *sorted(self.tree.iterdir()), *sorted(self.tree.glob("*/*"))]:
            if folder.is_dir() and folder.name in names:
                return folder
        raise self.refuse(f"$(find {package}): the ROS package {package} is not in the robot's folder "
                          f"{self.shown(self.tree)} "
                          "(dhsym does not search ROS_PACKAGE_PATH)", f"$(find {package}")

    def include_files(self, spec: str, symbols):
        name = str(self.xacro.eval_text(spec, symbols))
        if re.search(r"[*?\[]", name):
            raise self.refuse(f"xacro:include {name}: wildcards are not allowed", spec)
        resolved = self.xacro.abs_filename_spec(name)
        self.written[resolved] = name
        yield resolved

    def shown(self, path: Path) -> str:
        """A path as the user would write it: from the folder of the file they named."""
        relative = os.path.relpath(path, self.top.resolve().parent)
        shown = os.path.normpath(os.path.join(self.top.parent, relative))
        return f"{shown} (the folder of {self.top.name})" if relative == "." else shown

    def refuse(self, message: str, needle: str | None = None) -> UserError:
        """A UserError at the place of `needle` in the file being expanded (else at the file)."""
        current = Path(self.xacro.filestack[-1]).resolve() if self.xacro.filestack and self.xacro.filestack[-1] \
            else self.top.resolve()
        for path in sorted(self.texts, key=lambda path: path != current):  # the current file first
            offset = _COMMENT.sub(lambda m: " " * len(m.group(0)), self.texts[path]).find(needle) if needle else -1
            if offset >= 0:
                return UserError(message, _place(self.texts[path], self.names[path], offset))
        return UserError(message, Location(self.names.get(current, str(self.top))))

    def user_error(self, error: Exception) -> UserError:
        """A UserError for an error xacro raised (one line), or the UserError it wraps."""
        cause = error
        while cause is not None:
            if isinstance(cause, UserError):
                return cause
            cause = getattr(cause, "exc", None) or cause.__cause__ or cause.__context__
        message = " ".join(str(error).split())
        return self.refuse(f"xacro: {message[:300]}")


def _check_text(text: str, shown: str) -> None:
    """Refuse, with its place, a declaration, a `${…}` of a form not allowed, or a `$(…)` other
    than arg and find, anywhere outside comments."""
    blank = _COMMENT.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)
    declaration = _DECLARATION.search(blank)
    if declaration:
        raise UserError("DOCTYPE and entity declarations are not allowed in a xacro file",
                        _place(text, shown, declaration.start()))
    for match in _EXPRESSION.finditer(blank):
        reason = check_syntax(match.group(1))
        if reason:
            raise UserError(reason, _place(text, shown, match.start()))
    for match in _EXTENSION.finditer(blank):
        if match.group(1) not in ("arg", "find"):
            raise UserError(f"$({match.group(1)} …) is not allowed in a xacro file read by dhsym; only $(arg NAME) "
                            "and $(find PACKAGE)", _place(text, shown, match.start()))


def _place(text: str, shown: str, offset: int) -> Location:
    line = text.count("\n", 0, offset) + 1
    return Location(shown, line, offset - (text.rfind("\n", 0, offset) + 1) + 1)
