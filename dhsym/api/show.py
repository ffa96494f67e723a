r"""`dhsym.show`: DH tables, transforms, matrices and expressions that Jupyter renders as LaTeX,
laid out by the documents' rule for a notebook's line (dhsym.latex.display). Each takes a robot,
what `import_urdf` gives, or a plain chain, and names frames as the robot prints them.

>>> import dhsym
>>> arm = dhsym.load("planar2r")
>>> print(dhsym.show.transform(arm, 0, 2).latex.splitlines()[:2])
['\\begin{array}{l}', '{}^{0}T_{2} =']
>>> "r_{11} & r_{12}" in dhsym.show.transform(dhsym.load("puma560"), 0, 6).latex  # too wide: named elements
True
>>> print(dhsym.show.transform(dhsym.load("spherical_wrist"), 3, 6).latex.splitlines()[1])
{}^{3}T_{6} =
"""
from __future__ import annotations

from ..latex import display
from ..latex.display import Latex
from ..printing.render import transform_title
from .robot import notebook_robot

__all__ = ["Latex", "expression", "matrix", "table", "transform"]


def table(robot, page: str = "notebook") -> Latex:
    """The DH table in its convention's column order, rows numbered as the robot's joints; joint
    variables starred. A table too wide for the `page` is split into tables of columns."""
    return display.table(notebook_robot(robot), page)


def transform(robot, i, j, raw: bool = False, page: str = "notebook") -> Latex:
    """{i}T_{j}, simplified unless `raw`; frames numbered as the robot prints them."""
    robot = notebook_robot(robot)
    return display.matrix(robot, robot.transform(i, j, raw=raw), transform_title(i, j, "latex"), page=page)


def matrix(robot, value, name: str = "", legend: bool = True, page: str = "notebook") -> Latex:
    """Any matrix (or vector) of a robot in c/s notation, with its name and legend."""
    return display.matrix(notebook_robot(robot), value, name, legend, page)


def expression(robot, value, name: str = "") -> Latex:
    """One expression in c/s notation, e.g. a position component."""
    return display.expression(notebook_robot(robot), value, name)
