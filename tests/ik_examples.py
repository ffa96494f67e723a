"""Closed-form solutions written by hand, as the solver's contract (dhsym/inverse/solution.py)
describes them: the surfaces are tested on these whatever the solver finds.

The planar 2R is Spong's elbow manipulator: D = cos θ2 by the law of cosines, two branches."""
import sympy

from dhsym import load
from dhsym.inverse.sentences import Subproblem
from dhsym.inverse.solution import Branch, DerivationStep, Solution


def planar2r() -> Solution:
    robot = load("planar2r")
    t1, t2 = robot.chain.joint_variables
    px, py, a1, a2, D = sympy.symbols("px py a_1 a_2 D", real=True)
    cosine = (px**2 + py**2 - a1**2 - a2**2) / (2 * a1 * a2)
    branches = []
    for name, sign in (("elbow down", 1), ("elbow up", -1)):
        elbow = sympy.atan2(sign * sympy.sqrt(1 - D**2), D)
        shoulder = sympy.atan2(py, px) - sympy.atan2(a2 * sympy.sin(t2), a1 + a2 * sympy.cos(t2))
        branches.append(Branch(name, ((t2, elbow), (t1, shoulder))))
    steps = (DerivationStep(px**2 + py**2, a1**2 + a2**2 + 2 * a1 * a2 * sympy.cos(t2), Subproblem("law of cosines"),
                            (t2,), "the distance from the base to the tip fixes the elbow angle"),
             DerivationStep(sympy.atan2(py, px), t1 + sympy.atan2(a2 * sympy.sin(t2), a1 + a2 * sympy.cos(t2)),
                            Subproblem("atan2 of a pair"), (t1,),
                            "the direction to the tip, less the angle the forearm adds"))
    reach = "D² ≤ 1: the tip within reach, |a1 − a2| ≤ r ≤ a1 + a2"
    return Solution(robot.chain, "planar arm: the law of cosines for the elbow, then the shoulder", (t1, t2),
                    ((D, cosine),), tuple(branches), conditions=(reach,),
                    degenerate=("px = py = 0 with a1 = a2: θ1 is arbitrary",), steps=steps, sample=dict(robot.sample),
                    numbers=robot.numbers)


def puma560() -> Solution:
    """Craig's solution of the PUMA 560 (Introduction to Robotics, section 4.7): θ1 from px, py;
    θ3 from the constant K; θ2 from θ23; the wrist angles from 3R6; eight branches."""
    robot = load("puma560")
    t1, t2, t3, t4, t5, t6 = robot.chain.joint_variables
    r11, r12, r13, px, r21, r22, r23, py, r31, r32, r33, pz = sympy.symbols(
        "r11 r12 r13 px r21 r22 r23 py r31 r32 r33 pz", real=True)
    a2, a3, d3, d4, K = sympy.symbols("a_2 a_3 d_3 d_4 K", real=True)
    cos, sin, atan2, sqrt = sympy.cos, sympy.sin, sympy.atan2, sympy.sqrt
    c1, s1, c3, s3 = cos(t1), sin(t1), cos(t3), sin(t3)
    c23, s23, c4, s4, c5, s5 = cos(t2 + t3), sin(t2 + t3), cos(t4), sin(t4), cos(t5), sin(t5)
    k = (px**2 + py**2 + pz**2 - a2**2 - a3**2 - d3**2 - d4**2) / (2 * a2)
    reach = c1 * px + s1 * py
    branches = []
    for shoulder, first in (("left", 1), ("right", -1)):
        for elbow, second in (("up", 1), ("down", -1)):
            for wrist, flip in (("not flipped", 1), ("flipped", -1)):
                theta1 = atan2(py, px) - atan2(d3, first * sqrt(px**2 + py**2 - d3**2))
                theta3 = atan2(a3, d4) - atan2(K, second * sqrt(a3**2 + d4**2 - K**2))
                theta2 = atan2((-a3 - a2 * c3) * pz - reach * (d4 - a2 * s3),
                               (a2 * s3 - d4) * pz + (a3 + a2 * c3) * reach) - t3
                theta4 = atan2(flip * (-r13 * s1 + r23 * c1), flip * (-r13 * c1 * c23 - r23 * s1 * c23 + r33 * s23))
                theta5 = atan2(-(r13 * (c1 * c23 * c4 + s1 * s4) + r23 * (s1 * c23 * c4 - c1 * s4) - r33 * s23 * c4),
                               -r13 * c1 * s23 - r23 * s1 * s23 - r33 * c23)
                theta6 = atan2(-r11 * (c1 * c23 * s4 - s1 * c4) - r21 * (s1 * c23 * s4 + c1 * c4) + r31 * s23 * s4,
                               r11 * ((c1 * c23 * c4 + s1 * s4) * c5 - c1 * s23 * s5)
                               + r21 * ((s1 * c23 * c4 - c1 * s4) * c5 - s1 * s23 * s5)
                               - r31 * (s23 * c4 * c5 + c23 * s5))
                branches.append(Branch(f"shoulder {shoulder}, elbow {elbow}, wrist {wrist}",
                                       ((t1, theta1), (t3, theta3), (t2, theta2), (t4, theta4), (t5, theta5),
                                        (t6, theta6))))
    steps = (DerivationStep(-s1 * px + c1 * py, d3, Subproblem("a cos θ + b sin θ = c"), (t1,),
                            "the second row of 1T6 = 1T0 0T6"),
             DerivationStep(K, a3 * c3 - d4 * s3, Subproblem("a cos θ + b sin θ = c"), (t3,),
                            "the sum of the squares of the position"),)
    return Solution(robot.chain, "kinematic decoupling: axes 4, 5, 6 meet at the wrist centre",
                    tuple(robot.chain.joint_variables), ((K, k),), tuple(branches),
                    conditions=("px² + py² ≥ d3²", "K² ≤ a3² + d4²"),
                    degenerate=("s5 = 0: axes 4 and 6 line up; only θ4 + θ6 is determined",), steps=steps,
                    sample=dict(robot.sample), numbers=robot.numbers)
