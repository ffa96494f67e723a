"""`dhsym latex`: the DH table, the link matrices, the derivation and the result as beamer
slides, an article or a snippet of math, laid out so that everything fits its page.

This module assembles the three documents. The parts: `sections` decides what is shown,
`layout` how math is set on a line (a matrix, or its named elements with long ones broken),
`width` how wide the math prints, and `packing` how the blocks of a section fill beamer
frames (a full frame continues on the next, titled "(cont.)"). Nothing is ever shrunk.

>>> from dhsym.io.library import load
>>> tex = document(load("planar2r"), "snippet")
>>> "{}^{0}T_{2} = {}^{0}T_{1}\\\\,{}^{1}T_{2} =" in tex and "a_{1} c_{1} + a_{2} c_{12}" in tex
True
"""
from __future__ import annotations

from pathlib import Path
from typing import Callable

from ..core.chain import Frame
from ..core.robot import Robot
from ..errors import UserError
from ..io.library import ROBOTS_DIR
from ..printing.printers import LatexPrinter, chain_settings
from .ik import PART as IK_PART
from .ik import ik_sections, typeset
from .layout import PAGES, Block, Page, flat
from .packing import pack
from .prose import tex_prose, tex_text
from .sections import Section, sections
from .velocity import velocity_sections

DOCUMENTS = ("slides", "article", "snippet")


# ---------------------------------------------------------------- the three documents

def document(robot: Robot, kind: str = "slides", steps: bool = False, start: Frame | None = None,
             end: Frame | None = None, jacobian: bool = False, ik: Callable | None = None,
             dynamics: bool = False) -> str:
    """The LaTeX text of a document of `kind` for `robot`, about the transform from the chain's frame
    `start` (default: the first) to `end` (default: the last); `jacobian` adds velocity kinematics,
    `ik` the closed-form inverse kinematics: a function that gives the solution (dhsym.inverse), called
    after the rest is laid out (a surface above this layer solves it, as `robot.ik()` does);
    `dynamics` the equations of motion (a chain too large to print raises TooLargeToPrint)."""
    chain = robot.chain
    start = chain.frames[0] if start is None else start
    end = chain.frames[-1] if end is None else end
    if start == end:
        raise UserError(f"--from and --to name the same frame ({robot.numbering.frame(start)}); choose two "
                        "different frames")
    page = PAGES[kind]
    content = sections(robot, start, end, steps, page, LatexPrinter(chain_settings(robot)))
    if jacobian:
        content += velocity_sections(robot, page, steps=steps)
    if ik is not None:
        content += ik_sections(ik(), robot, page)
    if dynamics:
        from .dynamics import document_sections  # the dynamics layer only for documents that show it

        content += document_sections(robot, page, steps)
    return {"slides": _slides, "article": _article, "snippet": _snippet}[kind](robot, content, page)


def _subtitle(robot: Robot) -> str:
    return f"Forward kinematics, {robot.chain.convention} DH convention"


def robot_file(robot: Robot) -> str:
    """Which robot file the robot comes from: a built-in's name, else the path as given.

    >>> from dhsym.io.library import load
    >>> robot_file(load("puma560"))
    'puma560.yaml (built into dhsym)'
    """
    if not robot.file:
        return "none (built in Python)"
    path = Path(robot.file)
    return f"{path.name} (built into dhsym)" if path.parent == ROBOTS_DIR else robot.file


def _slides(robot: Robot, content: list[Section], page: Page) -> str:
    out = [SLIDES_PREAMBLE, "\\begin{document}\n",
           "\\begin{frame}[plain]\n\\centering\n{\\usebeamerfont{title}\\usebeamercolor[fg]{title}"
           f"{tex_text(robot.name)}\\par}}\n\\bigskip\n{tex_text(_subtitle(robot))}\\par\n"
           f"\\vfill\n{{\\small\\raggedright Source: {tex_prose(robot.source or 'not given')}\\par\n"
           f"Robot file: {tex_text(robot_file(robot))}\\par}}\n"
           "\\end{frame}\n"]
    for section in content:
        title = section.title
        for number, blocks in enumerate(pack(section.items, page.height_pt)):
            shows = [name for block in blocks for name in block.shows]
            if shows:  # link matrices: the frame says which
                title = f"{section.title}: ${shows[0]}$" + (f" to ${shows[-1]}$" if len(shows) > 1 else "")
            elif number:
                title = blocks[0].alone[0] if blocks[0].alone else title.removesuffix(" (cont.)") + " (cont.)"
            out.append(f"\\begin{{frame}}{{{title}}}\n" + _join(blocks) + "\n\\end{frame}\n")
    out.append("\\end{document}\n")
    return "\n".join(out)


def _article(robot: Robot, content: list[Section], page: Page) -> str:
    out = [ARTICLE_PREAMBLE, "\\begin{document}\n", f"\\section*{{{tex_text(robot.name)}}}\n",
           f"{tex_text(_subtitle(robot))}.\n\nSource: {tex_prose(robot.source or 'not given')}\n",
           f"Robot file: {tex_text(robot_file(robot))}\n"]
    if robot.notes:  # ragged right: an imported robot's notes hold long names that justify badly
        out.append(f"{{\\raggedright Notes: {tex_prose(robot.notes)}\\par}}\n")
    part = None
    for section in content:
        if section.part != part:
            part = section.part
            out.append(f"\\subsection*{{{part}}}\n")
        if section.headed:
            out.append(f"\\subsubsection*{{{section.title}}}\n")
        out.extend([_join(flat(section.items)), ""])
    out.append("\\end{document}\n")
    return "\n".join(out)


def _snippet(robot: Robot, content: list[Section], page: Page) -> str:
    """Only the math; titles and text become comments, except in the inverse kinematics, whose
    steps, branches and conditions are typeset as `dhsym ik --format latex` sets them."""
    out = [f"% dhsym latex: {_comment(robot.name)} ({robot.chain.convention} DH); needs \\usepackage{{amsmath}}",
           f"% Source: {_comment(robot.source or 'not given')}", f"% Robot file: {_comment(robot_file(robot))}"]
    inverse = [section for section in content if section.part == IK_PART]
    for section in content:
        if section.part == IK_PART:
            if section is inverse[0]:  # the part's sections as one run of text and displays
                out.append("\n" + typeset([item for part in inverse for item in part.items]).rstrip("\n"))
            continue
        out.append(f"\n% {_comment(section.title)}")
        out.extend(block.latex if block.is_display else f"% {_comment(block.latex)}" for block in flat(section.items))
    return "\n".join(out) + "\n"


def _join(blocks: list[Block]) -> str:
    return "\n".join(b.latex if b.is_display else b.latex + "\\par" for b in blocks)


SLIDES_PREAMBLE = r"""% Made by dhsym latex. Compile with pdflatex (beamer, lmodern).
\documentclass[11pt,aspectratio=169]{beamer}
\usepackage[T1]{fontenc}
\usepackage{lmodern}
\usefonttheme[onlymath]{serif}
\setbeamertemplate{navigation symbols}{}
\setbeamertemplate{footline}{\hfill\usebeamerfont{page number in head/foot}\insertframenumber\hspace{2em}\vspace{1ex}}
"""

ARTICLE_PREAMBLE = r"""% Made by dhsym latex. Compile with pdflatex.
\documentclass[11pt,a4paper]{article}
\usepackage[T1]{fontenc}
\usepackage{lmodern}
\usepackage{amsmath}
\usepackage[margin=25mm]{geometry}
\setlength{\parindent}{0pt}
\setlength{\parskip}{0.5\baselineskip}
"""


# ---------------------------------------------------------------- text from robot files

def _comment(text: str) -> str:
    """Text for a LaTeX comment: one line (a newline would end the comment)."""
    return " ".join(text.split())
