"""Every inverse-kinematics branch that reaches one pose, drawn side by side: the PUMA's eight
configurations, the planar arm's elbow up and elbow down.

The pose is the one the joint values `values` give (default: every joint 0), with any of its
elements replaced by `target` ({"px": 0.4, ...}, the names `dhsym ik` uses); each branch is
evaluated by the generated numpy code of the solution (dhsym.inverse.solve, or the one given) and
drawn with `draw`; a branch that does not exist at the pose gets a panel that says so.

    from dhsym.plot.branches import draw_branches
    figure = draw_branches(dhsym.load("puma560"), values={"theta_2": "-30deg", "theta_3": "45deg"})
"""
from __future__ import annotations

import math
import textwrap

import numpy as np

from ..errors import UserError
from ..inverse import evaluate, solve
from ..inverse.solution import TARGET_NAMES
from .draw import draw
from .poses import as_number, frame_poses, is_planar

PANEL_INCHES = (3.8, 4.0)  # width, height of one branch's picture
TITLE_CHARACTERS = 30  # a branch's name wraps to stay over its own picture
MAX_COLUMNS = 4
TARGET_COLOUR = "#ff7f0e"


def target_pose(chain, values=None, target=None) -> np.ndarray:
    """The 4×4 pose at joint values `values` (missing ones 0, constants from the sample), with
    the elements named in `target` (r11 … r33, px, py, pz) replaced.

    >>> from dhsym.io.library import load
    >>> target_pose(load("planar2r"), target={"px": 0.6})[:2, 3].tolist()
    [0.6, 0.0]
    """
    pose = np.array(frame_poses(chain, values)[-1][1], dtype=float)
    for name, value in (target or {}).items():
        if name not in TARGET_NAMES:
            raise UserError(f"{name} is not an element of the target; the elements are {', '.join(TARGET_NAMES)}")
        row, column = divmod(TARGET_NAMES.index(name), 4)
        pose[row, column] = as_number(value, name)
    return pose


def branch_values(robot, pose, constants=None, free=(), values=None, solution=None) -> tuple[list[str], np.ndarray]:
    """(branch names, joint values (B, n) of every joint of the robot, in joint order) of its
    inverse kinematics (`solution`, else solved with `free` kept as parameters) at `pose`; NaN where
    a branch does not exist. Free joints keep their values from `values` (default 0), constants come
    from `constants` or the sample."""
    chain = robot.chain
    if solution is None:
        solution = solve(chain, free, sample=robot.sample, numbers=robot.numbers, name=robot.name, path=robot.path)
    given = {str(k): as_number(v, str(k)) for k, v in (constants or {}).items()}
    for variable in solution.free:
        given[variable.name] = as_number((values or {}).get(variable.name, 0), variable.name)
    solved = evaluate(solution, pose, given, robot.name)  # by the robot's own names (the module renames len, float …)
    joints = np.empty((len(solution.branches), chain.n))
    for k, variable in enumerate(chain.joint_variables):
        if variable in solution.joint_variables:
            joints[:, k] = solved[:, list(solution.joint_variables).index(variable)]
        else:
            joints[:, k] = given[variable.name]
    return [branch.name for branch in solution.branches], joints


def draw_branches(robot, values=None, target=None, constants=None, free=(), figure=None, show_frames=False,
                  solution=None, triad_scale=None):
    """A figure with one picture per branch of the inverse kinematics (`solution`, else solved with
    `free` kept as parameters) at the pose of `values` (with `target`'s elements replaced), side by
    side; returns the Figure. The pose's origin is marked on every picture."""
    pose = target_pose(robot, {**(constants or {}), **(values or {})}, target)
    names, joints = branch_values(robot, pose, constants, free, values, solution)
    if figure is None:
        import matplotlib.pyplot as plt  # only here: library users in notebooks want pyplot's figures

        figure = plt.figure()
    columns = min(len(names), MAX_COLUMNS)
    rows = math.ceil(len(names) / columns)
    figure.set_size_inches(PANEL_INCHES[0] * columns, PANEL_INCHES[1] * rows)
    variables = [v.name for v in robot.chain.joint_variables]
    existing = [k for k in range(len(names)) if np.isfinite(joints[k]).all()]
    planar = is_planar(robot, {**(constants or {}), **dict(zip(variables, joints[existing[0]]))}) if existing \
        else False
    drawn = []
    for k, name in enumerate(names):
        ax = figure.add_subplot(rows, columns, k + 1, **({} if planar else {"projection": "3d"}))
        title = "\n".join(textwrap.wrap(f"{k + 1}. {name}", TITLE_CHARACTERS))
        if k not in existing:
            ax.set_title(title + "\n(does not reach this pose)", fontsize=9)
            ax.set_axis_off()
            continue
        shown = {**(constants or {}), **dict(zip(variables, joints[k]))}
        _picture(ax, robot, shown, title + "\n" + _joint_values(robot.chain, joints[k]), show_frames, triad_scale)
        ax.scatter(*(pose[:2, 3] if planar else pose[:3, 3]), marker="*", s=140, color=TARGET_COLOUR, zorder=5)
        drawn.append(ax)
    _same_limits(drawn, planar)
    figure.subplots_adjust(hspace=0.45, wspace=0.3)
    figure.suptitle(f"{robot.name}: {len(existing)} of {len(names)} branches reach the pose", fontsize=11)
    return figure


def _picture(ax, robot, values: dict, title: str, show_frames, triad_scale) -> None:
    """One branch's picture: the arm at `values`, no legend (the joint symbols need no key on
    every picture, and it would cover the next)."""
    draw(robot, values, ax=ax, show_frames=show_frames, title=title, triad_scale=triad_scale)
    ax.title.set_fontsize(9)
    if ax.get_legend():
        ax.get_legend().remove()


def _same_limits(axes, planar: bool) -> None:
    """One scale for every picture, so that the configurations compare at a glance."""
    if not axes:
        return
    for axis in ("x", "y") if planar else ("x", "y", "z"):
        limits = np.array([getattr(ax, f"get_{axis}lim")() for ax in axes])
        for ax in axes:
            getattr(ax, f"set_{axis}lim")(limits[:, 0].min(), limits[:, 1].max())


def _joint_values(chain, values) -> str:
    """θ in degrees, d in the robot's length unit, on at most two lines."""
    parts = [f"{round(math.degrees(v))}°" if row.joint == "R" else f"{v:.3g}"  # round(): never −0°
             for row, v in zip(chain.rows, values)]
    parts = [part.replace("-", "−") for part in parts]
    half = (len(parts) + 1) // 2 if len(parts) > 3 else len(parts)
    return ", ".join(parts[:half]) + ("\n" + ", ".join(parts[half:]) if parts[half:] else "")
