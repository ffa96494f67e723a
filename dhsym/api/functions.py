"""The command line's commands, for Python: `dhsym.load`, `fk`, `jacobian`, `convert`, `check`,
`screws`, `import_urdf` and `ik`. Each takes a robot (what `load` gives), what `import_urdf`
gives, or a plain chain (frames 0..n), and names frames as the robot prints them.

>>> import dhsym
>>> arm = dhsym.load("planar2r")
>>> dhsym.fk(arm)[0, 3]
a_1*cos(theta_1) + a_2*cos(theta_1 + theta_2)
>>> dhsym.load("spherical_wrist").frames
[3, 4, 5, 6]
"""
from __future__ import annotations

import dataclasses
import os

from .robot import Robot, notebook_robot


def load(name_or_path: str | os.PathLike) -> Robot:
    """A built-in robot by name, or a robot file by path (a str, or a `pathlib.Path` or any
    os.PathLike, which is always a path), with the warnings of its reading (`robot.warnings`).

    >>> load("planar2r")
    Robot('Planar elbow manipulator (2R)', standard DH, 2 joints: RR, frames 0..2)
    """
    from ..io.library import load as read

    return Robot.of(read(name_or_path))


def fk(robot, start=None, end=None, raw: bool = False):
    """ⁱTⱼ, the transform from frame `start` (default: the first) to frame `end` (default: the
    last), simplified into textbook form unless `raw`, as `dhsym fk ROBOT --from I --to J`.

    >>> import dhsym
    >>> dhsym.fk(dhsym.load("planar2r"))[:2, 3]
    Matrix([
    [a_1*cos(theta_1) + a_2*cos(theta_1 + theta_2)],
    [a_1*sin(theta_1) + a_2*sin(theta_1 + theta_2)]])
    """
    robot = notebook_robot(robot)
    return robot.transform(robot.first_frame if start is None else start,
                           robot.last_frame if end is None else end, raw=raw)


def jacobian(robot, frame=None, point=None):
    """The 6×n geometric Jacobian of the origin of frame `point` (default: the last), expressed
    in frame `frame` (default: the first), as `dhsym jacobian`; the robot's `determinant()`,
    `singularities()` and `propagate()` give the rest.

    >>> import dhsym
    >>> dhsym.jacobian(dhsym.load("planar2r"))[:2, :]
    Matrix([
    [-a_1*sin(theta_1) - a_2*sin(theta_1 + theta_2), -a_2*sin(theta_1 + theta_2)],
    [ a_1*cos(theta_1) + a_2*cos(theta_1 + theta_2),  a_2*cos(theta_1 + theta_2)]])
    """
    return notebook_robot(robot).jacobian(frame, point)


def convert(robot, convention: str) -> Robot:
    """The same robot in the other DH convention ("standard" or "modified"), as `dhsym convert`.

    >>> import dhsym
    >>> arm = dhsym.convert(dhsym.load("puma560"), "standard")
    >>> arm.convention, dhsym.check(arm, "puma560").same
    ('standard', True)
    """
    from ..geometry.convert import convert_robot

    return Robot.of(convert_robot(notebook_robot(robot), convention))


def check(a, b):
    """Are `a` and `b` the same? Two robots (the second may be a built-in name or a file's path): the
    same kinematics from base to tool for every joint value, as `dhsym check A --against B`,
    and if not, what to fix (`.same`, `.message`). Two expressions or matrices: equal, proven
    by algebra and by numbers at random points (a verdict that is true or false).

    >>> import dhsym, sympy
    >>> print(dhsym.check(dhsym.load("spatial3r"), "inline6"))
    the tables have 3 and 6 joints; they cannot describe the same robot
    >>> t = sympy.Symbol("t", real=True)
    >>> print(dhsym.check(sympy.sin(2*t), 2*sympy.sin(t)*sympy.cos(t)))  # doctest: +ELLIPSIS
    equal: by algebra, and numerically (max error ...)
    """
    from ..core.chain import Chain
    from ..core.robot import Robot as Record

    if isinstance(getattr(a, "robot", a), (Record, Chain)):
        from ..geometry.compare import compare

        reference = load(b) if isinstance(b, (str, os.PathLike)) else b
        return compare(notebook_robot(a), notebook_robot(reference))
    from ..checking.verify import check as equal

    return equal(a, b)


def screws(robot):
    """The screw axes of the joints (the columns of a 6×n matrix, ω over v) and the home pose M,
    in the first frame with every joint at zero, as `dhsym screws`.

    >>> import dhsym
    >>> dhsym.screws(dhsym.load("planar2r")).matrix.T
    Matrix([
    [0, 0, 1, 0,    0, 0],
    [0, 0, 1, 0, -a_1, 0]])
    """
    from ..geometry.screws import screw_axes

    return screw_axes(notebook_robot(robot).chain)


def import_urdf(path, base: str | None = None, tip: str | None = None, convention: str = "standard",
                variables: str = "q", xacro_args: dict | None = None, package_paths=()):
    """A DH robot derived from a URDF (or .xacro) file's base → tip path, as `dhsym import`:
    `.robot` (its notes name each variable's URDF joint, its warnings are the reader's) and
    `.joint_names`; `variables="urdf"` names the joint variables after the URDF's joints;
    `xacro_args` ({"ur_type": "ur5e"}) and `package_paths` as `--xacro-arg` and `--package-path`.

    >>> import dhsym, pathlib, tempfile
    >>> urdf = pathlib.Path(tempfile.mkdtemp(), "arm.urdf")
    >>> _ = urdf.write_text('''<robot name="arm"> <link name="base"/> <link name="upper"/> <link name="tip"/>
    ...   <joint name="shoulder" type="revolute"> <parent link="base"/> <child link="upper"/>
    ...     <axis xyz="0 0 1"/> <limit lower="-3" upper="3" effort="1" velocity="1"/> </joint>
    ...   <joint name="hand" type="fixed"> <parent link="upper"/> <child link="tip"/>
    ...     <origin xyz="0.5 0 0"/> </joint> </robot>''')
    >>> dhsym.fk(dhsym.import_urdf(urdf))[:2, 3].T
    Matrix([[cos(q_1)/2, sin(q_1)/2]])
    """
    from ..io.urdfimport import import_urdf as imported

    result = imported(path, base, tip, convention, variables, xacro_args, package_paths)
    return dataclasses.replace(result, robot=Robot.of(result.robot))


def ik(robot, free=(), numeric: bool = False, constants=None):
    """The closed-form inverse kinematics, every branch named, as `dhsym ik`: `.branches`,
    `.evaluate(T)` (all branches at once, numpy), `.latex()`, `.text()`, `.code()`; the joint
    variables `free` stay parameters (a redundant arm). With `numeric`, as `dhsym ik --numeric`:
    every real solution in numbers, for any arm (dhsym.inverse.numeric), its constants from
    `constants` or the robot file's sample values.

    >>> import dhsym
    >>> [branch.name for branch in dhsym.ik(dhsym.load("planar2r")).branches]
    ['elbow down', 'elbow up']
    >>> dhsym.ik(dhsym.load("ur5"), numeric=True)
    NumericInverse('Universal Robots UR5', 6 joints)
    """
    if numeric:
        from .ik import numeric_inverse_kinematics

        return numeric_inverse_kinematics(notebook_robot(robot), free, constants)
    return notebook_robot(robot).ik(free)


def equations_of_motion(robot, to: int | None = None):
    """The dynamics τ = M(q) q̈ + C(q, q̇) q̇ + g(q) in textbook form, as `dhsym dynamics`: `.M`, `.C`,
    `.g`, `.christoffel`, `.tau(...)` (symbolic, or numbers for states), `.regressor()`, `.steps()`,
    `.latex()`, `.text()`, `.code()`; of the links up to frame `to` (as printed) only (`dhsym dynamics --to`).
    (`dhsym.dynamics` is the package of the math, so this function has the name of what it gives.)

    >>> import dhsym
    >>> dhsym.equations_of_motion(dhsym.load("spong_elbow")).M[1, 1]
    I_2 + l_c2**2*m_2
    """
    return notebook_robot(robot).dynamics(to)
