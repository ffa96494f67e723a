"""Inverse kinematics in closed form: the structure of the axes, the sub-problems a course
teaches, every branch named, and numeric evaluation of all branches at once. Every function here
takes a plain `Chain` (frames 0..n) and what the robot file says as explicit arguments; the
notebook's `robot.ik()` (dhsym.api.ik) and the printers number the frames as the file does.

>>> import dhsym
>>> from dhsym.inverse import solve
>>> len(solve(dhsym.load("puma560").chain).branches)
8
"""
from .evaluate import evaluate
from .solve import free_variables, solve

__all__ = ["evaluate", "free_variables", "solve"]
