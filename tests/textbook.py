"""Matrices as textbooks print them, for comparison with dhsym's results.

c(2, 3) is cos(θ2 + θ3); names match the built-in robot files.
"""
import sympy

from dhsym import real_symbol


def theta(i):
    return real_symbol(f"theta_{i}")


def c(*joints):
    return sympy.cos(sum(theta(i) for i in joints))


def s(*joints):
    return sympy.sin(sum(theta(i) for i in joints))


def syms(names):
    return [real_symbol(n) for n in names.split()]


def _with_bottom(rows):
    return sympy.Matrix(rows + [[0, 0, 0, 1]])


def craig_puma_0T6():
    """Craig, Introduction to Robotics, eq. (3.14)."""
    a2, a3, d3, d4 = syms("a_2 a_3 d_3 d_4")
    w1 = c(4) * c(5) * c(6) - s(4) * s(6)
    w2 = -c(4) * c(5) * s(6) - s(4) * c(6)
    return _with_bottom([
        [c(1) * (c(2, 3) * w1 - s(2, 3) * s(5) * c(6)) + s(1) * (s(4) * c(5) * c(6) + c(4) * s(6)),
         c(1) * (c(2, 3) * w2 + s(2, 3) * s(5) * s(6)) + s(1) * (c(4) * c(6) - s(4) * c(5) * s(6)),
         -c(1) * (c(2, 3) * c(4) * s(5) + s(2, 3) * c(5)) - s(1) * s(4) * s(5),
         c(1) * (a2 * c(2) + a3 * c(2, 3) - d4 * s(2, 3)) - d3 * s(1)],
        [s(1) * (c(2, 3) * w1 - s(2, 3) * s(5) * c(6)) - c(1) * (s(4) * c(5) * c(6) + c(4) * s(6)),
         s(1) * (c(2, 3) * w2 + s(2, 3) * s(5) * s(6)) - c(1) * (c(4) * c(6) - s(4) * c(5) * s(6)),
         -s(1) * (c(2, 3) * c(4) * s(5) + s(2, 3) * c(5)) + c(1) * s(4) * s(5),
         s(1) * (a2 * c(2) + a3 * c(2, 3) - d4 * s(2, 3)) + d3 * c(1)],
        [-s(2, 3) * w1 - c(2, 3) * s(5) * c(6),
         -s(2, 3) * w2 + c(2, 3) * s(5) * s(6),
         s(2, 3) * c(4) * s(5) - c(2, 3) * c(5),
         -a3 * s(2, 3) - a2 * s(2) - d4 * c(2, 3)],
    ])


def spong_stanford_0T6():
    """Spong, Hutchinson & Vidyasagar, Robot Modeling and Control, Stanford manipulator."""
    d2, d3, d6 = syms("d_2 d_3 d_6")
    w1 = c(4) * c(5) * c(6) - s(4) * s(6)
    w2 = c(4) * c(5) * s(6) + s(4) * c(6)
    return _with_bottom([
        [c(1) * (c(2) * w1 - s(2) * s(5) * c(6)) - s(1) * (s(4) * c(5) * c(6) + c(4) * s(6)),
         c(1) * (-c(2) * w2 + s(2) * s(5) * s(6)) - s(1) * (-s(4) * c(5) * s(6) + c(4) * c(6)),
         c(1) * (c(2) * c(4) * s(5) + s(2) * c(5)) - s(1) * s(4) * s(5),
         c(1) * s(2) * d3 - s(1) * d2 + d6 * (c(1) * c(2) * c(4) * s(5) + c(1) * c(5) * s(2) - s(1) * s(4) * s(5))],
        [s(1) * (c(2) * w1 - s(2) * s(5) * c(6)) + c(1) * (s(4) * c(5) * c(6) + c(4) * s(6)),
         s(1) * (-c(2) * w2 + s(2) * s(5) * s(6)) + c(1) * (-s(4) * c(5) * s(6) + c(4) * c(6)),
         s(1) * (c(2) * c(4) * s(5) + s(2) * c(5)) + c(1) * s(4) * s(5),
         s(1) * s(2) * d3 + c(1) * d2 + d6 * (c(1) * s(4) * s(5) + c(2) * c(4) * s(1) * s(5) + c(5) * s(1) * s(2))],
        [-s(2) * w1 - c(2) * s(5) * c(6),
         s(2) * w2 + c(2) * s(5) * s(6),
         -s(2) * c(4) * s(5) + c(2) * c(5),
         c(2) * d3 + d6 * (c(2) * c(5) - c(4) * s(2) * s(5))],
    ])


def spong_scara_0T4():
    """Spong et al., SCARA (RRPR) 0T4, as printed with products of c12 and c4."""
    a1, a2, d3, d4 = syms("a_1 a_2 d_3 d_4")
    return _with_bottom([
        [c(1, 2) * c(4) + s(1, 2) * s(4), -c(1, 2) * s(4) + s(1, 2) * c(4), 0, a1 * c(1) + a2 * c(1, 2)],
        [s(1, 2) * c(4) - c(1, 2) * s(4), -c(1, 2) * c(4) - s(1, 2) * s(4), 0, a1 * s(1) + a2 * s(1, 2)],
        [0, 0, -1, -d3 - d4],
    ])


def planar3r_0Ttool():
    """Lecture 000 (Ghosal): X = l1 c1 + l2 c12 + l3 c123."""
    l1, l2, l3 = syms("l_1 l_2 l_3")
    return _with_bottom([
        [c(1, 2, 3), -s(1, 2, 3), 0, l1 * c(1) + l2 * c(1, 2) + l3 * c(1, 2, 3)],
        [s(1, 2, 3), c(1, 2, 3), 0, l1 * s(1) + l2 * s(1, 2) + l3 * s(1, 2, 3)],
        [0, 0, 1, 0],
    ])


def spatial3r_0T3():
    """Lecture 002 (Udai), Example 1."""
    d1, a2, a3 = syms("d_1 a_2 a_3")
    reach = a2 * c(2) + a3 * c(2, 3)
    return _with_bottom([
        [c(1) * c(2, 3), -c(1) * s(2, 3), s(1), reach * c(1)],
        [s(1) * c(2, 3), -s(1) * s(2, 3), -c(1), reach * s(1)],
        [s(2, 3), c(2, 3), 0, d1 + a2 * s(2) + a3 * s(2, 3)],
    ])


def spherical_wrist_3T6():
    """Spong et al. eq. for the spherical wrist; lecture 002 Example 2."""
    (d6,) = syms("d_6")
    return _with_bottom([
        [c(4) * c(5) * c(6) - s(4) * s(6), -c(4) * c(5) * s(6) - s(4) * c(6), c(4) * s(5), c(4) * s(5) * d6],
        [s(4) * c(5) * c(6) + c(4) * s(6), -s(4) * c(5) * s(6) + c(4) * c(6), s(4) * s(5), s(4) * s(5) * d6],
        [-s(5) * c(6), s(5) * s(6), c(5), c(5) * d6],
    ])


def craig_puma_3J6():
    """Craig, Introduction to Robotics, eq. (5.66): the PUMA 560 Jacobian in frame 3."""
    a2, a3, d3, d4 = syms("a_2 a_3 d_3 d_4")
    return sympy.Matrix([
        [-d3 * c(2, 3), a2 * s(3) - d4, -d4, 0, 0, 0],
        [d3 * s(2, 3), a2 * c(3) + a3, a3, 0, 0, 0],
        [a2 * c(2) + a3 * c(2, 3) - d4 * s(2, 3), 0, 0, 0, 0, 0],
        [-s(2, 3), 0, 0, 0, s(4), -c(4) * s(5)],
        [-c(2, 3), 0, 0, 1, 0, c(5)],
        [0, 1, 1, 0, c(4), s(4) * s(5)],
    ])


def planar2r_0J():
    """Spong et al., planar elbow manipulator: J = [−a1 s1 − a2 s12, −a2 s12; a1 c1 + a2 c12, a2 c12]."""
    a1, a2 = syms("a_1 a_2")
    return sympy.Matrix([[-a1 * s(1) - a2 * s(1, 2), -a2 * s(1, 2)], [a1 * c(1) + a2 * c(1, 2), a2 * c(1, 2)],
                         [0, 0], [0, 0], [0, 0], [1, 1]])


def planar3r_3J():
    """Craig, Example 5.3 extended to three links: the planar arm's Jacobian in its last link frame."""
    l1, l2 = syms("l_1 l_2")
    return sympy.Matrix([[l1 * s(2, 3) + l2 * s(3), l2 * s(3), 0], [l1 * c(2, 3) + l2 * c(3), l2 * c(3), 0],
                         [0, 0, 0], [0, 0, 0], [0, 0, 0], [1, 1, 1]])


def spong_scara_0J():
    """Spong et al., SCARA Jacobian (rows vx, vy, vz, ωx, ωy, ωz)."""
    a1, a2 = syms("a_1 a_2")
    return sympy.Matrix([[-a1 * s(1) - a2 * s(1, 2), -a2 * s(1, 2), 0, 0],
                         [a1 * c(1) + a2 * c(1, 2), a2 * c(1, 2), 0, 0],
                         [0, 0, -1, 0], [0, 0, 0, 0], [0, 0, 0, 0], [1, 1, 0, -1]])


def spong_stanford_0J_columns_3_to_6():
    """Spong et al., Stanford manipulator: J3 = (z2; 0) and the angular parts z3, z4, z5 of J4..J6."""
    return sympy.Matrix([
        [c(1) * s(2), 0, 0, 0], [s(1) * s(2), 0, 0, 0], [c(2), 0, 0, 0],
        [0, c(1) * s(2), -c(1) * c(2) * s(4) - s(1) * c(4),
         c(1) * c(2) * c(4) * s(5) - s(1) * s(4) * s(5) + c(1) * s(2) * c(5)],
        [0, s(1) * s(2), c(1) * c(4) - s(1) * c(2) * s(4),
         s(1) * c(2) * c(4) * s(5) + c(1) * s(4) * s(5) + s(1) * s(2) * c(5)],
        [0, c(2), s(2) * s(4), -s(2) * c(4) * s(5) + c(2) * c(5)],
    ])
