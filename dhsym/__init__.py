"""dhsym: Denavit–Hartenberg tables to textbook-form symbolic kinematics.

A notebook or a script needs one import:

>>> import dhsym
>>> arm = dhsym.load("planar2r")
>>> dhsym.fk(arm)[0, 3]
a_1*cos(theta_1) + a_2*cos(theta_1 + theta_2)
>>> arm.determinant().value
a_1*a_2*sin(theta_2)
>>> dhsym.velocity.determinant(arm.chain).value   # the layers below take the plain chain, frames 0..n
a_1*a_2*sin(theta_2)

Every name is imported on first use (`__getattr__` below), so that `import dhsym`, and each
command of the command line, loads only what it uses: numpy comes with `dhsym.plot`
(matplotlib with the first picture), the velocity layer with `dhsym.jacobian`, and so on.
`dhsym.show` renders tables and matrices in Jupyter; it is not called `display`, so that
`from dhsym import *` leaves IPython's `display` alone. `dir(dhsym)` lists the names.
"""
from __future__ import annotations

from importlib import import_module

# Each exported name and where it lives: (module, attribute), or (module, None) for a module. The
# notebook surface (dhsym.api) translates the robot file's frame numbers; the layers below it take
# plain chains, frames 0..n.
_LAZY = {
    "load": ("dhsym.api.functions", "load"),
    "builtin_names": ("dhsym.io.library", "builtin_names"),
    "Robot": ("dhsym.api.robot", "Robot"),
    "Chain": ("dhsym.core.chain", "Chain"),
    "DHRow": ("dhsym.core.chain", "DHRow"),
    "Step": ("dhsym.core.transforms", "Step"),
    "Numbering": ("dhsym.core.numbering", "Numbering"),
    "show": ("dhsym.api.show", None),
    "plot": ("dhsym.plot", None),  # numpy and matplotlib only when pictures are wanted
    "velocity": ("dhsym.velocity", None),
    "errata": ("dhsym.checking.errata", None),
    "verify": ("dhsym.checking.verify", None),
    "real_symbol": ("dhsym.io.expr", "real_symbol"),
    "parse_expression": ("dhsym.io.expr", "parse_expression"),
    "UserError": ("dhsym.errors", "UserError"),
    "Location": ("dhsym.errors", "Location"),
    # the command line's commands, for Python
    **{name: ("dhsym.api.functions", name) for name in ("fk", "jacobian", "convert", "check", "screws",
                                                          "import_urdf", "ik", "equations_of_motion")},
}

__all__ = sorted(_LAZY)


def __getattr__(name: str):
    if name not in _LAZY:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    module, attribute = _LAZY[name]
    value = import_module(module) if attribute is None else getattr(import_module(module), attribute)
    globals()[name] = value  # the next use is a plain lookup
    return value


def __dir__() -> list[str]:
    return list(__all__)
