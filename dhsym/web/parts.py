r"""The documents' blocks as parts of a web page: a heading, a paragraph of text with inline math,
or displayed math. The page sets text as text (it reflows with the window) and hands each piece
of math to MathJax; the same parts give back the LaTeX that `--format latex` prints.

A paragraph of the documents is LaTeX text (`latex.prose.tex_text`: escaped characters, math
between dollars); here it becomes segments, ("text", plain text) and ("math", TeX), which the
page puts into the DOM as text nodes, never as HTML.

>>> from dhsym.latex.layout import Block
>>> part = paragraph_part(Block("Step 1 (law of cosines), for $\\theta_{2}$: 50\\% \\& more.", 0.0, False))
>>> part["segments"]
[['text', 'Step 1 (law of cosines), for '], ['math', '\\theta_{2}'], ['text', ': 50% & more.']]
>>> latex_of([heading("Branch 1: elbow up"), part])
'% Branch 1: elbow up\n% Step 1 (law of cosines), for $\\theta_{2}$: 50\\% \\& more.\n'
"""
from __future__ import annotations

import re

from ..latex.layout import Block, aligned_display, lines_under

# LaTeX text as the documents write it, and the plain text it stands for.
_TEXT_MACROS = {"\\textbackslash{}": "\\", "\\textasciitilde{}": "~", "\\textasciicircum{}": "^",
                "\\textdegree{}": "°", "\\dots{}": "…", "\\allowbreak{}": "", "\\&": "&", "\\%": "%",
                "\\$": "$", "\\#": "#", "\\_": "_", "\\{": "{", "\\}": "}", "---": "—", "--": "–",
                "``": "“", "''": "”", "\\,": "\u2009", "~": "\u00a0"}
_TEXT_TOKEN = re.compile("|".join(re.escape(macro) for macro in sorted(_TEXT_MACROS, key=len, reverse=True)))
_MATH = re.compile(r"(?<!\\)\$((?:[^$\\]|\\.)*)\$")
_BOLD = re.compile(r"\\textbf\{((?:[^{}]|\{[^{}]*\})*)\}")
# TeX that MathJax does not know and a page does not need: where a printed page may break
_PAGE_ONLY = re.compile(r"\\displaybreak\[\d\]|\\allowbreak(?:\{\})?")


def heading(title: str) -> dict:
    """A section title (LaTeX text with math in dollars) as a heading part."""
    return {"kind": "heading", "segments": segments(title), "latex": title}


def paragraph_part(block: Block) -> dict:
    """A paragraph of a document; a paragraph set in bold is a subheading."""
    bold = _BOLD.fullmatch(block.latex.strip())
    if bold:
        return {"kind": "heading", "segments": segments(bold.group(1)), "latex": block.latex}
    return {"kind": "text", "segments": segments(block.latex), "latex": " ".join(block.latex.split())}


def math_part(block: Block) -> dict:
    r"""A display, as MathJax reads it (no page breaks) and as the document writes it.

    >>> from dhsym.latex.layout import display
    >>> math_part(display("x = 1", 10.0))["tex"]
    'x = 1'
    """
    tex = block.latex.strip()
    if tex.startswith("\\[") and tex.endswith("\\]"):
        tex = tex[2:-2].strip()
    return {"kind": "math", "tex": _PAGE_ONLY.sub("", tex).strip(), "latex": block.latex}


def item_parts(items) -> list[dict]:
    """Blocks and `Rows` of a section, in order; rows become one align*, as in a snippet."""
    parts = []
    for item in items:
        block = item if isinstance(item, Block) else aligned_display(lines_under(item.columns, 0), "align*")
        parts.append(math_part(block) if block.is_display else paragraph_part(block))
    return parts


def section_parts(sections) -> list[dict]:
    """Each section's title as a heading, then its items."""
    return [part for section in sections for part in [heading(section.title), *item_parts(section.items)]]


def snippet_parts(latex: str) -> list[dict]:
    r"""A snippet of displays and lines of text (`results_latex`, `table_latex`) as parts.

    >>> [part["kind"] for part in snippet_parts("\\[\nx = 1\n\\]\nwhere\n\\begin{align*}\nc &= d\n\\end{align*}\n")]
    ['math', 'text', 'math']
    """
    parts, lines = [], latex.splitlines()
    while lines:
        line = lines.pop(0)
        ends = {"\\[": "\\]", "\\begin{align*}": "\\end{align*}"}.get(line.strip())
        if ends:
            body = [line]
            while lines and body[-1].strip() != ends:
                body.append(lines.pop(0))
            parts.append(math_part(Block("\n".join(body), 0.0)))
        elif line.strip():
            parts.append(paragraph_part(Block(line.strip().removeprefix("% "), 0.0, is_display=False)))
    return parts


def segments(latex: str) -> list[list[str]]:
    r"""LaTeX text cut into ["text", plain text] and ["math", TeX] pieces.

    >>> segments("arm--base: $a_{2}$ of 3\\,m")
    [['text', 'arm–base: '], ['math', 'a_{2}'], ['text', ' of 3\u2009m']]
    """
    out, position = [], 0
    for match in _MATH.finditer(latex):
        out += [["text", plain_text(latex[position:match.start()])], ["math", match.group(1)]]
        position = match.end()
    out.append(["text", plain_text(latex[position:])])
    return [piece for piece in out if piece[1]]


def plain_text(latex: str) -> str:
    r"""LaTeX text (no math) as the characters it prints, spaces collapsed.

    >>> plain_text("a\\_b \\textbackslash{} 90\\textdegree{}")
    'a_b \\ 90°'
    """
    text = _TEXT_TOKEN.sub(lambda match: _TEXT_MACROS[match.group(0)], latex)
    return re.sub(r"[ \t\r\n]+", " ", text)


def latex_of(parts) -> str:
    """The parts as a snippet for a document with amsmath: text as comments, math as displays,
    as `dhsym jacobian --format latex` writes them."""
    return "".join((part["latex"] if part["kind"] == "math" else f"% {part['latex']}") + "\n" for part in parts)
