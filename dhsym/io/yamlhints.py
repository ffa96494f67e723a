"""Plain words for YAML syntax errors: what is probably wrong, and where.

The YAML parser says what it expected (`expected <block end>, but found '?'`); a student needs
to hear that a key is indented by one space too many, that `-{` needs a space, or that a `{`
is never closed. `explain` looks at the parser's marks and the lines around them and returns
the message and the place (0-based line and column) to report; an error it does not know is
passed on in the parser's words.

>>> text = "convention: standard\\njoints:\\n  - {joint: R}\\n  base: []\\n"
>>> try:
...     yaml.compose(text, Loader=yaml.SafeLoader)
... except yaml.MarkedYAMLError as error:
...     message, line, column = explain(error, text)
>>> print(line + 1, column + 1, message[:58])
4 3 key 'base' starts in column 3, but the keys above it start
"""
from __future__ import annotations

import re

import yaml

_GLUED_COLON = re.compile(r"(?:^|(?<=[\s{,\[]))([^\W\d]\w*):(?=[^\s/:])")  # convention:standard
_CLOSING = {"{": "}", "[": "]"}
_LINE_BREAKS = re.compile("\r\n|[\r\n\x85\u2028\u2029]")


def explain(error: yaml.MarkedYAMLError, text: str) -> tuple[str, int, int]:
    """(message, line, column) for a YAML syntax error in `text`; line and column count from 0."""
    lines = _LINE_BREAKS.split(text)  # as YAML counts lines: \r and \u2028 end one too
    mark = error.problem_mark or error.context_mark
    line, column = (mark.line, mark.column) if mark else (0, 0)
    problem = " ".join((error.problem or error.context or "unreadable YAML").split())
    for rule in (_tab, _first_line, _block_end, _glued, _flow, _simple_key, _open_quote):
        try:
            found = rule(error, problem, lines, line, column)
        except (IndexError, ValueError):  # a mark where hostile text has no such line or column
            found = None
        if found:
            return found
    return _plain_tokens(problem), line, column


_TOKENS = {"<block mapping start>": "a key", "<block sequence start>": "a list item",
           "<block end>": "the end of a block",
           "<stream end>": "the end of the file", "<document start>": "a new document (---)",
           "<block collection start>": "a block", "<flow mapping start>": "'{'", "<flow sequence start>": "'['",
           "<scalar>": "a value", "<document end>": "'...'", "<flow mapping end>": "'}'",
           "<flow sequence end>": "']'", "<flow entry>": "','", "<block entry>": "'-'", "?": "a key"}


def _plain_tokens(problem: str) -> str:
    """The parser's words with its token names said plainly: expected the end of a block, but found a key.

    >>> _plain_tokens("expected <block end>, but found '<block mapping start>'")
    'expected the end of a block here, but found a key; check the indentation of this line and the one above'
    """
    text = problem
    for token, plain in _TOKENS.items():
        text = text.replace(f"'{token}'", plain).replace(token, plain)
    text = text.replace("while scanning a simple key", "while reading a key")
    if text.startswith("expected the end of a block"):
        text = text.replace("block,", "block here,") + "; check the indentation of this line and the one above"
    return text


def _indent(text: str) -> int:
    return len(text) - len(text.lstrip(" "))


def _content_above(lines: list[str], line: int):
    """(number, text) of the lines above `line` that hold YAML, nearest first."""
    for number in range(min(line, len(lines)) - 1, -1, -1):
        stripped = lines[number].strip()
        if stripped and not stripped.startswith("#"):
            yield number, lines[number]


def _key_column(text: str) -> int | None:
    """Where the key of a `key: value` line starts, after any `- `; None for other lines."""
    column = _indent(text)
    while text.startswith("- ", column):
        column += 2 + _indent(text[column + 2:])
    return column if re.match(r"[^\s#{\[\-'\"][^:#]*:(\s|$)", text[column:]) else None


def _columns(numbers) -> str:
    return " or ".join(str(number + 1) for number in numbers)


def _tab(error, problem, lines, line, column):
    if "'\\t'" in problem:
        return "a tab character; YAML indentation must use spaces", line, column
    return None


def _first_line(error, problem, lines, line, column):
    """The first key indented, the next ones not: ` name: arm` then `convention: …`."""
    if not problem.startswith("expected '<document start>'"):
        return None
    first = next(((n, text) for n, text in enumerate(lines) if text.strip() and not text.lstrip().startswith("#")),
                 None)
    if first is None or _indent(first[1]) == 0 or first[0] >= line:
        return None
    return (f"the first line starts in column {_indent(first[1]) + 1}, but line {line + 1} in column {column + 1}; "
            f"the keys of the file start in the same column, best column 1"), first[0], _indent(first[1])


def _block_end(error, problem, lines, line, column):
    """A line that starts at a column no list or mapping above it uses."""
    if not problem.startswith("expected <block end>") or line >= len(lines):
        return None
    text = lines[line]
    if text.startswith("-", column) and text[column + 1:column + 2] not in ("", " "):
        return f"put a space after '-': write '- {text[column + 1]}', not '-{text[column + 1]}'", line, column
    if text.startswith("-", column):
        for number, above in _content_above(lines, line):
            if above.lstrip().startswith("- ") and _indent(above) != column:
                return (f"this list item starts in column {column + 1}, but the item on line {number + 1} in "
                        f"column {_indent(above) + 1}; the items of one list start in the same column"), line, column
        return None
    levels: list[int] = []
    for _, above in _content_above(lines, line):
        key = _key_column(above)
        if key is not None and (not levels or key < levels[-1]):
            levels.append(key)
    name = text[column:].split(":")[0].strip()
    if not levels or not re.fullmatch(r"[^\s,{}\[\]'\"#&*!|>%@`]+", name):
        return None
    return (f"key {name!r} starts in column {column + 1}, but the keys above it start in column "
            f"{_columns(sorted(levels, reverse=True))}; line it up with the keys of its own mapping"), line, column


def _glued(error, problem, lines, line, column):
    """`mapping values are not allowed here`: a missing space after - or :, or a line indented
    under a value as if it continued it."""
    if not problem.startswith("mapping values are not allowed") or line >= len(lines):
        return None
    text = lines[line]
    start = _indent(text)
    if text.startswith("-", start) and text[start + 1:start + 2] not in ("", " "):
        return f"put a space after '-': write '- {text[start + 1:start + 2]}', not '-{text[start + 1:start + 2]}'", \
            line, start
    for number, above in [(line, text[:column])] + list(_content_above(lines, line))[:1]:
        glued = _glued_colon(above, number)
        if glued:
            return glued
    previous = next(_content_above(lines, line), None)
    if previous and _key_column(previous[1]) is not None and start > _key_column(previous[1]):
        name = text[start:column].strip()
        return (f"{name!r} is indented more than the key on line {previous[0] + 1}, so YAML reads it as part of "
                f"that key's value; start {name + ':'!r} in column {_key_column(previous[1]) + 1}"), line, start
    return None


def _glued_colon(text: str, line: int):
    """`convention:standard`: a key and its value without the space YAML needs after ':'."""
    glued = _GLUED_COLON.search(text.split("#")[0])
    if not glued:
        return None
    key, rest = glued.group(1), text[glued.end():].split()
    value = rest[0] if rest else ""
    return f"a key needs a space after its ':': write '{key}: {value}', not '{key}:{value}'", line, glued.end() - 1


def _flow(error, problem, lines, line, column):
    """A {…} or […] that is never closed, or closed by the other bracket."""
    opening = error.context_mark
    if not problem.startswith("expected ','") or opening is None:
        return None
    bracket = "{" if "mapping" in (error.context or "") else "["
    got = problem.rsplit("but got ", 1)[-1].strip("'")
    if got in ("}", "]") and got != _CLOSING[bracket]:
        return (f"this {got!r} closes the {bracket!r} of column {opening.column + 1}; close it with "
                f"{_CLOSING[bracket]!r}"), line, column
    if got in ("<stream end>", "{", "[") or line > opening.line:
        before = "the end of the file" if got == "<stream end>" else f"line {line + 1}, column {column + 1}"
        return (f"this {bracket!r} is never closed: {before} comes before its {_CLOSING[bracket]!r} (or a ',' "
                f"between its entries)"), opening.line, opening.column
    return None


def _simple_key(error, problem, lines, line, column):
    """A line of a mapping with no `:` in it: `alpha 0`."""
    start = error.context_mark
    if not problem.startswith("could not find expected ':'") or start is None or start.line >= len(lines):
        return None
    glued = _glued_colon(lines[start.line], start.line)
    if glued:
        return glued
    words = lines[start.line][start.column:].split("#")[0].split(None, 1)
    example = f"'{words[0]}: {words[1].strip()}'" if len(words) == 2 else f"'{words[0]}: VALUE'" if words else ""
    return f"this line of a mapping has no ':'; write a key and its value as {example}", start.line, start.column


def _open_quote(error, problem, lines, line, column):
    start = error.context_mark
    if "quoted scalar" not in (error.context or "") or start is None:
        return None
    quote = lines[start.line][start.column] if start.line < len(lines) else '"'
    return f"this {quote} is never closed; end the text with {quote}", start.line, start.column


def node_kind(node: yaml.Node) -> str:
    """What a node is, in words, for messages: a list, a mapping, a single value."""
    if isinstance(node, yaml.SequenceNode):
        return "a list"
    if isinstance(node, yaml.MappingNode):
        return "a mapping"
    return "a single value" if node.value else "an empty value"


def glued_key(node: yaml.ScalarNode) -> str:
    """`; write 'alpha: 0' ...` for a value that is a key and its value without the space."""
    key, colon, value = node.value.partition(":")
    if node.style is None and colon and key.strip() and value and not value[0].isspace():
        return f"; a key needs a space after its ':': write '{key.strip()}: {value}'"
    return ""
