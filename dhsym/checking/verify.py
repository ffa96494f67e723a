"""Equality by algebra and by numbers, under the name notebooks and scripts know:
`dhsym.checking.verify.check` (and `dhsym.verify.check`). The code is plain math and lives in
`dhsym.core.verify`, below every layer that uses it.

>>> import sympy
>>> t = sympy.Symbol("t", real=True)
>>> bool(check(sympy.sin(t) ** 2, 1 - sympy.cos(t) ** 2))
True
"""
from ..core.verify import Verdict, algebraically_equal, check, numeric_error, trig_canonical

__all__ = ["Verdict", "algebraically_equal", "check", "numeric_error", "trig_canonical"]
