"""dhsym: Denavit–Hartenberg tables to textbook-form symbolic kinematics.

A notebook starts with one import:

>>> import dhsym
>>> arm = dhsym.load("planar2r")
>>> arm.fk()[0, 3]
a_1*cos(theta_1) + a_2*cos(theta_1 + theta_2)
>>> dhsym.velocity.determinant(arm).value
a_1*a_2*sin(theta_2)

`dhsym.plot` (pictures) is imported on first use, so that the math and the command line
never load numpy or matplotlib.
"""
from importlib import import_module

from . import velocity
from .checking import errata, verify
from .checking.verify import check
from .core.chain import Chain, DHRow
from .core.robot import Robot
from .core.transforms import Step
from .errors import Location, UserError
from .io.expr import parse_expression, real_symbol
from .io.library import builtin_names, load
from .latex import display

__all__ = ["Chain", "DHRow", "Location", "Robot", "Step", "UserError", "builtin_names", "check", "display", "errata",
           "load", "parse_expression", "plot", "real_symbol", "velocity", "verify"]


def __getattr__(name):
    if name == "plot":  # numpy and matplotlib only when pictures are wanted
        return import_module(".plot", __name__)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
