"""Closing a loop: the joint values that make two serial chains of a cut mechanism meet.

>>> from dhsym.io.library import load
>>> left, right = close_loop(load("fourbar_left"), load("fourbar_right"), {"phi_1": sympy.pi / 2},
...                          ["theta_1", "phi_2"])
>>> round(float(np.degrees(left[sympy.Symbol("theta_1", real=True)])), 1)  # the other branch: 59.9
11.1
"""
from __future__ import annotations

import numpy as np
import sympy

from ..core.robot import Robot
from ..errors import UserError
from .poses import as_number, frame_poses, resolve_values


def close_loop(first: Robot, second: Robot, known: dict, unknowns, guess=None,
               tolerance=1e-10) -> tuple[dict, dict]:
    """Values of `unknowns` that bring the last frame origins of two robots' chains together.

    A closed mechanism cut at a revolute joint gives two chains from one fixed frame (their base
    steps place them); closing the loop means both cut ends meet. Solved by Gauss-Newton from
    `guess` (default 0.5 for every unknown; another guess finds another assembly branch).
    Returns the full values of each chain, ready for `draw_closed`.
    """
    names = [_name(u) for u in unknowns]
    guess = {_name(k): as_number(v, str(k)) for k, v in (guess or {}).items()}
    known = {_name(k): v for k, v in known.items()}
    own = [{s.name for s in robot.chain.symbols} for robot in (first, second)]
    strangers = [n for n in list(known) + names if not any(n in symbols for symbols in own)]
    if strangers:
        raise UserError(f"{', '.join(strangers)} belong to neither chain")
    unknown_values = np.array([guess.get(n, 0.5) for n in names], dtype=float)

    def gap(x):
        given = {**known, **dict(zip(names, x, strict=True))}
        ends = [frame_poses(chain, {n: v for n, v in given.items() if n in symbols})[-1][1][:3, 3]
                for chain, symbols in zip((first, second), own, strict=True)]
        return ends[0] - ends[1]

    for _ in range(60):
        residual = gap(unknown_values)
        if np.linalg.norm(residual) < tolerance:
            break
        step = 1e-7
        jacobian = np.column_stack([(gap(unknown_values + step * e) - gap(unknown_values - step * e)) / (2 * step)
                                    for e in np.eye(len(names))])
        unknown_values = unknown_values + np.linalg.lstsq(jacobian, -residual, rcond=None)[0]
    if np.linalg.norm(gap(unknown_values)) > 1e3 * tolerance:
        raise UserError(f"the loop does not close for these values (gap {np.linalg.norm(gap(unknown_values)):.3g}); "
                        "the mechanism cannot be assembled there, or try another guess")
    solved = {**known, **dict(zip(names, unknown_values.tolist(), strict=True))}
    return tuple(resolve_values(chain, {n: v for n, v in solved.items() if n in symbols})
                 for chain, symbols in zip((first, second), own, strict=True))


def _name(key) -> str:
    return key.name if isinstance(key, sympy.Symbol) else str(key)
