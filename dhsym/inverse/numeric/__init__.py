"""Inverse kinematics in numbers, for every arm, with or without a closed form: every real solution
of a six-joint arm at a pose (revolute and prismatic joints, any geometry), a redundant arm's with
joints given (and swept over a given joint's values), and the one solution nearest a configuration
for any arm.

    ik = numeric_inverse(arm.chain, sample=arm.sample)   # the arm's numbers; constants= to set them
    ik.solve(T)                                          # (16, 6): every real solution, NaN after the last
    ik.solutions(T)                                      # (k, 6): the real ones only
    numeric_inverse(chain7, free=["q_3"]).sweep(T)       # q_3 from −π in 5° steps, the solutions at each
    numeric_inverse(chain7).nearest(T, seed)             # damped least squares, every joint moving
    print(ik.code())                                     # the standalone numpy module, ik(T)

How: `arm` puts the robot in numbers; `variants` chooses, once per arm, how the elimination reads
the arm's loop; `runtime` does the numbers (the generated module holds a copy of it); `solver` is
what the facade calls (dhsym.api.ik: a robot file's chain, sample values and name); `answer` is
what `dhsym ik --numeric` shows; `codegen` writes the module.

>>> import dhsym
>>> ur5 = dhsym.load("ur5")
>>> ik = numeric_inverse(ur5.chain, sample=ur5.sample)
>>> T = ik.pose([0.3, -0.4, 0.5, -0.6, 0.7, -0.8])
>>> ik.solutions(T).shape
(4, 6)
"""
from .solver import numeric_inverse

__all__ = ["numeric_inverse"]
