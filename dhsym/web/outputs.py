r"""What the page shows: the DH table, the link matrices, a transform ⁱTⱼ, the Jacobian with its
determinant and singularities, the inverse kinematics with its branches, and the slide deck, laid
out for a line of `width_pt` (the documents' one layout rule: a matrix too wide for the line is
written element by element). Each result is a title, the page's parts and the LaTeX a lecturer
pastes into a document: the same text `dhsym fk --format latex --text-width W` prints.

The command line's size limits apply before any work (`cli.limits`), so an arm too large to
print is refused with the same advice, instead of freezing the browser's tab.

>>> import dhsym
>>> result = output(dhsym.load("planar2r"), "fk", 345.0)
>>> result.title
'Planar elbow manipulator (2R): ${}^{0}T_{2}$  (standard DH)'
>>> [part["kind"] for part in result.parts]
['math', 'text', 'math', 'math']
>>> result.latex.startswith("\\[\n{}^{0}T_{2} =\n\\begin{bmatrix}")
True
"""
from __future__ import annotations

from dataclasses import dataclass

from ..api.robot import notebook_robot
from ..cli.limits import LATEX_MAX_NODES, refuse_if_too_large, refuse_jacobian_if_too_large, refuse_long_entries
from ..core.robot import Robot
from ..errors import UserError
from ..latex.layout import Block, Page
from ..latex.prose import tex_text
from ..latex.results import results_latex, table_latex
from ..latex.sections import CONVENTION_LATEX
from ..printing.render import transform_title
from .parts import heading, item_parts, latex_of, paragraph_part, section_parts, snippet_parts

SHOWS = ("table", "links", "fk", "jacobian", "ik")
FONT_PT = 10.0  # the page's math is laid out as for 10 pt type, the size of `--format latex`
MIN_WIDTH_PT, MAX_WIDTH_PT = 100.0, 2000.0  # as `--text-width` accepts


@dataclass(frozen=True)
class Output:
    """A result for the page: its title (LaTeX text), its parts, and its LaTeX."""

    title: str
    parts: list
    latex: str

    def json(self) -> dict:
        return {"title": heading(self.title)["segments"], "parts": self.parts, "latex": self.latex}


def output(robot: Robot, show: str, width_pt: float, start=None, end=None, frame=None, point=None,
           free=()) -> Output:
    """The result of one tab; frames are numbered as the robot prints them (None: first and last)."""
    if show not in SHOWS:
        raise UserError(f"unknown output {show!r}; the page shows {', '.join(SHOWS)}")
    page = Page(min(max(float(width_pt), MIN_WIDTH_PT), MAX_WIDTH_PT), FONT_PT)
    if show == "table":
        return _table(robot, page)
    if show == "links":
        chain = robot.chain
        latex = results_latex(robot, [(i - 1, i, chain.link(i)) for i in range(1, chain.n + 1)], page.width_pt)
        return Output(_title(robot, "link matrices"), snippet_parts(latex), latex)
    if show == "fk":
        return _transform(robot, start, end, page)
    if show == "jacobian":
        return _jacobian(robot, frame, point, page)
    return _inverse(robot, free, page)


def slides(robot: Robot, start=None, end=None, jacobian: bool = False, ik: bool = False, free=()) -> str:
    """The beamer deck of `dhsym latex ROBOT [--jacobian] [--ik]`, with that command's limits; frames
    as printed."""
    from ..latex.document import document  # the documents only for a deck

    chain = robot.chain
    first, last = robot.numbering.chain_frames(chain, start, end)
    refuse_if_too_large(robot, first, last, limit=LATEX_MAX_NODES, others=False)
    if jacobian:
        refuse_long_entries(robot)
        refuse_jacobian_if_too_large(robot, chain.first_frame, chain.last_frame, LATEX_MAX_NODES, option="")
    solved = (lambda: notebook_robot(robot).ik(free).solution) if ik else None
    return document(robot, "slides", start=first, end=last, jacobian=jacobian, ik=solved)


def _title(robot: Robot, what: str) -> str:
    return f"{tex_text(' '.join(robot.name.split()))}: {what}  ({robot.chain.convention} DH)"


def _table(robot: Robot, page: Page) -> Output:
    latex = table_latex(robot, page.width_pt)
    note = paragraph_part(Block(CONVENTION_LATEX[robot.chain.convention] + " ${}^{*}$ marks the joint variables.",
                                0.0, is_display=False))
    return Output(_title(robot, "DH table"), [note, *snippet_parts(latex)], latex)


def _transform(robot: Robot, start, end, page: Page) -> Output:
    chain, numbering = robot.chain, robot.numbering
    first, last = numbering.chain_frames(chain, start, end)
    if first == last:
        raise UserError(f"from and to name the same frame ({numbering.frame(first)}); choose two different frames")
    refuse_if_too_large(robot, first, last, limit=LATEX_MAX_NODES)
    with numbering.printed():
        matrix = chain.transform(first, last)
    latex = results_latex(robot, [(first, last, matrix)], page.width_pt)
    title = transform_title(numbering.frame(first), numbering.frame(last), "latex")
    return Output(_title(robot, f"${title}$"), snippet_parts(latex), latex)


def _jacobian(robot: Robot, frame, point, page: Page) -> Output:
    from ..latex.velocity import velocity_sections  # the velocity layer only when the Jacobian is asked for

    own_frame, own_point = robot.numbering.chain_frames(robot.chain, frame, point)
    refuse_long_entries(robot)
    refuse_jacobian_if_too_large(robot, own_frame, own_point, LATEX_MAX_NODES)
    parts = section_parts(velocity_sections(robot, page, own_frame, own_point))
    return Output(_title(robot, "Jacobian, determinant and singularities"), parts, latex_of(parts))


def _inverse(robot: Robot, free, page: Page) -> Output:
    from ..latex.ik import ik_sections, typeset

    solution = notebook_robot(robot).ik(free).solution  # solved once per robot read and choice of free
    items = [item for section in ik_sections(solution, robot, page, headings=True) for item in section.items]
    return Output(_title(robot, "inverse kinematics"), item_parts(items), typeset(items))  # headings in bold
