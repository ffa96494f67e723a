"""Inverse kinematics in closed form: the structure of the axes, the sub-problems a course
teaches, every branch named, and numeric evaluation of all branches at once.

>>> import dhsym
>>> from dhsym.inverse import solve
>>> len(solve(dhsym.load("puma560")).branches)
8
"""
from .evaluate import evaluate
from .solve import free_variables, solve

__all__ = ["evaluate", "free_variables", "solve"]
