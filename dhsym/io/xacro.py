"""`.xacro` files expanded to URDF by the `xacro` package (an optional extra: pip install
'dhsym[xacro]'), with everything that could run code, read other files or run without end
taken out of its hands.

- `${…}` is worked out by `xacroexpr` (numbers, property names, arithmetic, a few math
  functions, YAML data), never by xacro's eval; each expression of each file is checked, with
  its FILE:LINE:COL, before anything is expanded.
- `$(…)`: only `$(arg NAME)` and `$(find PKG)`; `$(eval …)`, `$(env …)`, `$(optenv …)`,
  `$(dirname)`, `$(cwd)` and `$(anon …)` are refused. Arguments come from the caller
  (`--xacro-arg NAME:=VALUE`) or from `<xacro:arg>` defaults, in document order as xacro reads
  them. Packages are found as ROS finds them (see `packages`): the package that holds the file,
  its workspace, and the folders given as `package_paths`, never elsewhere.
- `xacro:include` reads only .xacro, .urdf and .xml files, and `load_yaml` only .yaml and .yml
  files, inside those trees, each a regular file of at most 2 MiB (YAML: 1 MiB), no DOCTYPE, at
  most 200 files and 8 MiB in all; no wildcards.
- Expansion stops after 50,000 elements, 64 nested macro calls, 16 MiB of text worked through
  (a macro that copies a long text at each level), 20,000 substitutions worked out (a macro that
  repeats `${p}` many times) or 100,000 expression parts evaluated, and a text whose length
  times its `$` signs passes 50 million (xacro's lexer copies the rest of the text at each) is
  refused before xacro reads it: every bound a count made as the expansion goes.
- Tags written without the `xacro:` prefix are read as ROS 1's xacro read them (`xacroros1`).
  `expand_xacro(path, warnings)` appends the warnings of the expansion to `warnings`.

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

from lxml import etree

from ..errors import Location, UserError
from .packages import Packages
from .xacroexpr import Refused, Work, check_syntax, evaluate
from .xacroros1 import Ros1Tags, blank_markup, place
from .xacroyaml import yaml_data
from .xmlsource import MAX_XML_BYTES, decode_xml, read_regular_file
from .yamlsafe import MAX_FILE_BYTES as MAX_YAML_BYTES
from .yamlsafe import decode_utf8

MAX_FILES = 200
MAX_TOTAL_BYTES = 8 << 20
MAX_ELEMENTS = 50_000
MAX_MACRO_DEPTH = 64
MAX_TEXT_WORK = 16 << 20
MAX_SUBSTITUTIONS = 20_000  # ${…} and $(…) worked out in one expansion; a UR5e's takes 639
MAX_LEX_WORK = 50_000_000  # a text's length times its `$` signs: xacro's lexer copies the rest at each one
INCLUDABLE = (".xacro", ".urdf", ".xml")
YAML_SUFFIXES = (".yaml", ".yml")
_EXPRESSION = re.compile(r"(?<!\$)\$\{([^}]*)\}")
_EXTENSION = re.compile(r"(?<!\$)\$\(\s*(\S*)([^)]*)\)")
_DECLARATION = re.compile(r"<!(DOCTYPE|ENTITY)", re.IGNORECASE)
_COMMENT = re.compile(r"<!--.*?-->", re.DOTALL)


def expand_xacro(path: str | Path, warnings: list | None = None, arguments: dict | None = None,
                 package_paths=()) -> bytes:
    """The URDF that xacro makes of the file, as UTF-8 bytes; see the module's docstring.
    `arguments` are the xacro arguments NAME → VALUE (`xacro FILE NAME:=VALUE`)."""
    try:
        import xacro
    except ImportError:
        raise UserError("reading .xacro files needs the xacro package (pip install 'dhsym[xacro]'); or expand "
                        "the file yourself: xacro FILE.xacro > FILE.urdf", Location(str(path))) from None
    top = Path(path)
    read_regular_file(top)  # a folder, pipe, missing or huge file: one clear line before xacro sees it
    expander = _Expander(xacro, top, Packages(top, package_paths))
    with expander.guarded():
        try:
            document = xacro.process_file(str(top.resolve()), mappings=dict(arguments or {}))
        except UserError:
            raise
        except Exception as error:  # xacro's own errors (XacroException, ExpatError, NameError…)
            raise expander.user_error(error) from None
        text = document.toprettyxml(indent="  ")
    if len(text) > 4 * MAX_XML_BYTES:
        raise UserError("the expanded URDF is larger than 8 MiB", Location(str(path)))
    if warnings is not None:
        warnings.extend(expander.ros1.warnings(expander.texts, expander.names, str(top)))
    return text.encode("utf-8")


class _Expander:
    """Stands between xacro and the files, the expressions and the substitutions."""

    def __init__(self, xacro, top: Path, packages: Packages):
        self.xacro, self.top, self.packages = xacro, top, packages
        self.names = {}  # resolved path -> the name the user knows it by
        self.written = {}  # the path xacro opens -> the include's filename as written
        self.texts = {}
        self.ros1 = Ros1Tags()
        self.work = Work(self.load_yaml)
        self.original = {}  # xacro's own functions, while the hooks stand in for them
        self.files = self.bytes = self.elements = self.text_work = self.substitutions = 0

    @contextlib.contextmanager
    def guarded(self):
        xacro = self.xacro
        hooked = ("parse", "safe_eval", "eval_extension", "get_include_files", "eval_all", "eval_text",
                  "handle_macro_call")
        saved = self.original = {name: getattr(xacro, name) for name in hooked}
        xacro.parse, xacro.eval_all, xacro.eval_text = self.parse, self.eval_all, self.eval_text
        xacro.handle_macro_call = self.handle_macro_call
        xacro.safe_eval = lambda expr, symbols, locals=None: self.evaluate(expr, symbols)
        xacro.eval_extension = self.extension
        xacro.get_include_files = self.include_files
        try:
            with contextlib.redirect_stderr(io.StringIO()):  # xacro's own chatter; its errors are raised
                yield
        finally:
            for name, value in saved.items():
                setattr(xacro, name, value)

    def parse(self, inp, filename=None):
        if inp is None:
            document = self.original["parse"](self.read(filename))
            self.ros1.adopt(document, Path(filename).resolve())
            return document
        return self.original["parse"](inp, filename)

    def handle_macro_call(self, node, macros, symbols):
        if self.ros1.is_call(node.tagName) and self.is_macro(node.tagName, macros, symbols):
            self.ros1.note_call(node.tagName, self.current_file())  # ROS 1: <name/> calls the macro name
            node.tagName = node.nodeName = "xacro:" + node.tagName
        return self.original["handle_macro_call"](node, macros, symbols)

    def eval_all(self, node, macros, symbols):
        self.elements += 1
        if self.elements > MAX_ELEMENTS:
            raise UserError(f"the expansion passes {MAX_ELEMENTS:,} elements (a macro that calls itself, or "
                            "doubles at each level?)", Location(str(self.top)))
        if len(self.xacro.macrostack or []) > MAX_MACRO_DEPTH:
            raise UserError(f"macros nest deeper than {MAX_MACRO_DEPTH} calls (a macro that calls itself?)",
                            Location(str(self.top)))
        return self.original["eval_all"](node, macros, symbols)

    def eval_text(self, text, symbols):
        """xacro's evaluation of a text, counting the characters read and made and the
        substitutions worked out, before the work."""
        if isinstance(text, str) and "$" in text:
            dollars = text.count("$")
            if len(text) * dollars > MAX_LEX_WORK:
                raise UserError(f"a text of {len(text):,} characters with {dollars:,} substitutions is more than a "
                                "robot file needs", Location(str(self.top)))
            self.substitutions += text.count("${") + text.count("$(")
            if self.substitutions > MAX_SUBSTITUTIONS:
                raise UserError(f"the expansion works out more than {MAX_SUBSTITUTIONS:,} ${{…}} and $(…) "
                                "substitutions (a macro that repeats one many times?)", Location(str(self.top)))
        self.count_text(text)
        result = self.original["eval_text"](text, symbols)
        self.count_text(result)
        return result

    def count_text(self, text) -> None:
        if isinstance(text, str):
            self.text_work += len(text)
            if self.text_work > MAX_TEXT_WORK:
                raise UserError(f"the expansion works through more than {MAX_TEXT_WORK >> 20} MiB of text (a macro "
                                "that copies a long text at each level?)", Location(str(self.top)))

    def current_file(self) -> Path:
        """The file being read: where the macro being expanded is defined, else the open file."""
        stack = self.xacro.macrostack or []
        written = stack[-1].history[-1][-1] if stack and stack[-1].history and stack[-1].history[-1] \
            else (self.xacro.filestack or [None])[-1]
        return Path(written).resolve() if written else self.top.resolve()

    def read(self, filename: str) -> str:
        """One file's text, checked: inside the trees, a kind xacro includes, within the limits,
        and every expression and substitution in it of an allowed form."""
        path = Path(filename).resolve()
        written = self.written.get(filename, filename)
        if path != self.top.resolve():
            if path.suffix.lower() not in INCLUDABLE:
                raise self.refuse(f"xacro:include of {written}: only .xacro, .urdf and .xml files are included",
                                  written)
            self.check_inside(path, f"xacro:include of {written}", written)
            if not path.exists():
                raise self.refuse(f"xacro:include of {written}: no such file", written)
        data = self.take(path, MAX_XML_BYTES, "xacro files")
        shown = str(self.top) if path == self.top.resolve() else self.shown(path)
        text = decode_xml(data, shown)
        self.names[path], self.texts[path] = shown, text
        _check_text(text, shown)
        self.ros1.note_text(path, text)
        return re.sub(r"^\s*<\?xml[^>]*\?>", "", text)

    def take(self, path: Path, limit: int, what: str) -> bytes:
        """A file's bytes, counted against the limits on files and bytes in all."""
        self.files += 1
        if self.files > MAX_FILES:
            raise self.refuse(f"more than {MAX_FILES} files included")
        data = read_regular_file(path, limit, what)
        self.bytes += len(data)
        if self.bytes > MAX_TOTAL_BYTES:
            raise self.refuse("the included files pass 8 MiB in all")
        return data

    def check_inside(self, path: Path, what: str, needle: str) -> None:
        if not self.packages.contains(path):
            folders = " and ".join(self.shown(root) for root in self.packages.roots)
            raise self.refuse(f"{what}: outside the robot's folder {folders}", needle)

    def load_yaml(self, name: str):
        """The data of a YAML file in the trees (`load_yaml` in an expression)."""
        path = Path(self.xacro.abs_filename_spec(name)).resolve()
        if path.suffix.lower() not in YAML_SUFFIXES:
            raise Refused(f"load_yaml of {name}: only .yaml and .yml files are read")
        self.check_inside(path, f"load_yaml of {name}", name)
        shown = self.shown(path)
        if not path.exists():
            raise Refused(f"load_yaml of {shown}: no such file")
        return yaml_data(decode_utf8(self.take(path, MAX_YAML_BYTES, "YAML files"), shown), shown)

    def is_macro(self, name: str, macros, symbols) -> bool:
        try:
            self.xacro.resolve_macro(name, macros, symbols)
        except (KeyError, TypeError, AttributeError):
            return False
        return True

    def evaluate(self, expression: str, symbols):
        try:
            return evaluate(str(expression), symbols, self.work)
        except Refused as refusal:
            raise self.refuse(f"${{{expression}}}: {refusal}", expression) from None

    def extension(self, text: str) -> str:
        """`$(arg NAME)` and `$(find PKG)`; the other kinds never get here (see _check_text)."""
        match = _EXTENSION.fullmatch(text.strip())
        kind, argument = (match.group(1), match.group(2).strip()) if match else ("", "")
        if kind == "arg":
            arguments = self.xacro.substitution_args_context.get("arg", {})
            if argument not in arguments:
                raise self.refuse(self.unknown_argument(argument), f"$(arg {argument}")
            return arguments[argument]
        if kind == "find":
            folder = self.packages.find(argument)
            if folder is None:
                raise self.refuse(self.packages.missing(argument, self.shown), f"$(find {argument}")
            return str(folder)
        raise self.refuse(f"{text}: only $(arg NAME) and $(find PACKAGE) are allowed", text)

    def unknown_argument(self, name: str) -> str:
        """Why $(arg name) has no value: declared later (xacro reads in document order), or never."""
        declared = re.compile(rf"""<(?:xacro:)?arg\s[^>]*?name\s*=\s*["']{re.escape(name)}["']""")
        for path, text in self.texts.items():
            found = declared.search(blank_markup(text))
            if found:
                return (f"$(arg {name}) is used before <xacro:arg name=\"{name}\"> declares it at "
                        f"{place(text, self.names[path], found.start())} (xacro reads arguments in document order); "
                        f"give it with --xacro-arg {name}:=VALUE")
        return f"$(arg {name}): no <xacro:arg name=\"{name}\"> declares it; give it with --xacro-arg {name}:=VALUE"

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
                return UserError(message, place(self.texts[path], self.names[path], offset))
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
    than arg and find, anywhere outside comments, CDATA and processing instructions; and any
    DOCTYPE the XML parser sees (entities must never expand)."""
    blank = blank_markup(text)
    declaration = _DECLARATION.search(blank)
    if declaration is None and _has_doctype(text):
        declaration = _DECLARATION.search(text) or re.match("", text)
    if declaration:
        raise UserError("DOCTYPE and entity declarations are not allowed in a xacro file",
                        place(text, shown, declaration.start()))
    for match in _EXPRESSION.finditer(blank):
        reason = check_syntax(match.group(1))
        if reason:
            raise UserError(reason, place(text, shown, match.start()))
    for match in _EXTENSION.finditer(blank):
        if match.group(1) not in ("arg", "find"):
            raise UserError(f"$({match.group(1)} …) is not allowed in a xacro file read by dhsym; only $(arg NAME) "
                            "and $(find PACKAGE)", place(text, shown, match.start()))


def _has_doctype(text: str) -> bool:
    """Whether an XML parser that expands nothing finds a document type declaration."""
    parser = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False, huge_tree=False, recover=True)
    try:
        tree = etree.fromstring(re.sub(r"^\s*<\?xml[^>]*\?>", "", text).encode("utf-8"), parser)
    except etree.XMLSyntaxError:
        return False
    if tree is None:
        return False
    info = tree.getroottree().docinfo
    return info.internalDTD is not None or bool(info.doctype)
