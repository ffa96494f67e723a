"""Inverse kinematics in closed form: the structure of the axes, the sub-problems a course
teaches, every branch named, and numeric evaluation of all branches at once."""
