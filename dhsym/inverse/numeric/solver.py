"""The numeric inverse kinematics of an arm with numbers, for notebooks, programs and the command
line: every real solution at a pose (a six-joint arm, or a redundant one with joints given), the
solutions over a range of a given joint's values, and the one solution nearest a configuration
(any arm, by damped least squares).

>>> import numpy, dhsym
>>> puma = dhsym.load("puma560")
>>> ik = numeric_inverse(puma.chain, sample=puma.sample, name=puma.name)
>>> q = [0.3, -0.4, 0.5, -0.6, 0.7, -0.8]
>>> solutions = ik.solutions(ik.pose(q))
>>> len(solutions), bool(numpy.abs(solutions - q).max(axis=1).min() < 1e-9)
(8, True)
"""
from __future__ import annotations

import numpy

from ...core.chain import Chain
from ...errors import UserError
from .arm import numeric_arm
from .runtime.chain import nearest_amounts, pose_and_jacobian, wrapped
from .runtime.solve import solve
from .variants import SIZE, choose, runtime_arm, tolerance

UNKNOWNS = 6  # a pose fixes six numbers
SWEEP_STEPS = 72  # a turning joint swept in 5° steps


def numeric_inverse(chain: Chain, free=(), constants=None, *, sample=None, name: str = "") -> "NumericInverse":
    """The numeric inverse kinematics of `chain` with the joint variables `free` (symbols or names)
    given as parameters; `constants` maps the chain's constants (symbols or names) to numbers, else
    `sample` (the robot file's sample values) gives them; `name`: the robot's, for messages."""
    arm = numeric_arm(chain, constants, sample=sample, name=name)
    positions = free_positions(arm, free)
    unknowns = len(arm.kinds) - len(positions)
    if unknowns < UNKNOWNS:
        raise UserError(f"the numeric inverse kinematics lists the solutions of six unknown joints; "
                        f"{name or 'the arm'} has {unknowns}: a pose fixes six numbers, more than its "
                        "joints can meet in general")
    choice = choose(arm, positions) if unknowns == UNKNOWNS else None
    return NumericInverse(arm, positions, choice)


def free_positions(arm, free) -> tuple[int, ...]:
    """The positions of the joint variables `free` (symbols or names), checked, in joint order."""
    positions = []
    for item in free:
        name = getattr(item, "name", str(item)).strip()
        if name not in arm.variables:
            raise UserError(f"--free {name}: {arm.name or 'the robot'} has no joint variable {name}; its joint "
                            f"variables are {', '.join(arm.variables)}")
        positions.append(arm.variables.index(name))
    return tuple(sorted(set(positions)))


class NumericInverse:
    """`arm` (dhsym.inverse.numeric.arm.NumericArm), the positions of the `free` joints, and the
    elimination's `choice` (None for an arm with more than six unknown joints: only `nearest`)."""

    def __init__(self, arm, free, choice):
        self.arm, self.free, self.choice = arm, tuple(free), choice

    def __repr__(self) -> str:
        given = f", {', '.join(self.free_variables)} given" if self.free else ""
        return f"NumericInverse({self.arm.name!r}, {len(self.arm.kinds)} joints{given})"

    @property
    def joint_variables(self) -> tuple[str, ...]:
        return self.arm.variables

    @property
    def free_variables(self) -> tuple[str, ...]:
        return tuple(self.arm.variables[k] for k in self.free)

    @property
    def hidden_variable(self) -> str:
        """The joint whose polynomial the elimination solves (the first reading's)."""
        order, _ = self.choice.variants[0]
        unknown = [k for k in range(len(self.arm.kinds)) if k not in self.free]
        return self.arm.variables[unknown[order[2]]]

    def runtime(self) -> dict:
        """The data the runtime (and the generated module) works with."""
        self._need_choice()
        return runtime_arm(self.arm, self.free, self.choice.variants, SIZE)

    def pose(self, values):
        """The end pose (4, 4) at joint values (n,), or poses (N, 4, 4) at (N, n)."""
        return self.arm.pose(values)

    def solve(self, T, **free):
        """Every real solution at pose T (4, 4) → (16, n), or poses (N, 4, 4) → (N, 16, n): each
        solution once, in order of its joint values, NaN after the last; a given joint's value is
        a keyword argument (a number, or one per pose)."""
        self._need_choice()
        target = numpy.asarray(T, dtype=float)
        if target.ndim not in (2, 3) or target.shape[-2:] != (4, 4):
            raise UserError(f"T must be one pose (4, 4) or many (N, 4, 4), not an array of shape {target.shape}")
        poses = target.reshape(-1, 4, 4)
        values = self._free_values(free, len(poses))
        result = solve(self.runtime(), poses, values)
        return result[0] if target.ndim == 2 else result

    def solutions(self, T, **free):
        """The real solutions at one pose, (k, n): `solve` without the NaN rows."""
        result = self.solve(numpy.asarray(T, dtype=float).reshape(4, 4), **free)
        return result[numpy.isfinite(result[:, 0])]

    def sweep(self, T, values=None):
        """The solutions at pose T for each value of the one given joint: (its values (V,), the
        solutions (V, 16, n)); by default a turning joint's values from −π in 5° steps."""
        if len(self.free) != 1:
            raise UserError("a sweep varies one given joint: make exactly one joint variable free")
        name = self.free_variables[0]
        if values is None:
            if self.arm.kinds[self.free[0]] != "R":
                raise UserError(f"{name} slides: give the values to sweep it over")
            values = -numpy.pi + 2 * numpy.pi * numpy.arange(SWEEP_STEPS) / SWEEP_STEPS
        values = numpy.asarray(values, dtype=float).reshape(-1)
        target = numpy.broadcast_to(numpy.asarray(T, dtype=float).reshape(4, 4), (len(values), 4, 4))
        return values, self.solve(target, **{name: values})

    def nearest(self, T, seed, limits=None):
        """The joint values nearest `seed` (n,) that reach pose T, by damped least squares on the
        Jacobian (every joint moves, a redundant arm's too); `limits` (n, 2), the lower and upper
        value of each joint, keeps them within. Refused when the pose is not reached."""
        slopes = numpy.asarray(self.arm.slopes)
        bounds = None if limits is None else numpy.sort(numpy.asarray(limits, dtype=float) * slopes[:, None], axis=1)
        target = numpy.asarray(T, dtype=float).reshape(4, 4)
        seed = numpy.asarray(seed, dtype=float) * slopes
        amounts, missed = nearest_amounts(self.arm.frames, self.arm.kinds, target, seed, bounds)
        if not missed < tolerance(self.arm):
            raise UserError(f"no solution reaches the pose from this seed (the nearest pose found misses it by "
                            f"{missed:.2g}): the pose may be out of reach" + (" or of the limits" if bounds is not None
                                                                               else ""))
        return wrapped(amounts / slopes, self.arm.kinds)

    def singular(self, values) -> bool:
        """Whether the Jacobian at joint values (n,) has rank below six (the solutions there are not isolated)."""
        _, jacobian = pose_and_jacobian(self.arm.frames, self.arm.kinds,
                                        numpy.asarray(values, dtype=float) * numpy.asarray(self.arm.slopes))
        sizes = numpy.linalg.svd(jacobian, compute_uv=False)
        return bool(sizes[-1] < 1e-9 * sizes[0])

    def code(self, command: str = "") -> str:
        """The standalone numpy module (`dhsym ik --format python` for an arm solved numerically)."""
        from .codegen import module_text

        return module_text(self, command)

    def _free_values(self, given, count):
        names = self.free_variables
        unknown = sorted(set(given) - set(names))
        if unknown:
            raise UserError(f"{unknown[0]} is not a given joint of this solution; the given joints are "
                            f"{', '.join(names) or 'none'}")
        missing = [name for name in names if name not in given]
        if missing:
            raise UserError(f"no value for {missing[0]}: a given joint needs one")
        columns = [numpy.broadcast_to(numpy.asarray(given[name], dtype=float).reshape(-1), (count,)) for name in names]
        return numpy.stack(columns, axis=1) if columns else numpy.zeros((count, 0))

    def _need_choice(self):
        if self.choice is None:
            unknowns = len(self.arm.kinds) - len(self.free)
            extra = unknowns - UNKNOWNS
            left = [name for k, name in enumerate(self.arm.variables) if k not in self.free]
            middle = (len(left) - extra) // 2  # an elbow joint, as the closed form's advice chooses
            raise UserError(f"{self.arm.name or 'the arm'} has {unknowns} unknown joints, but a pose fixes only six: "
                            f"its solutions are not isolated; give {extra} of them with --free (e.g. --free "
                            f"{' '.join(left[middle:middle + extra])}) for every solution at the given values "
                            "(in Python, nearest() finds the solution nearest a configuration)")
