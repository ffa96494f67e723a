"""Robot files that are not built in, for the tests: they exercise notation and layout.

Two-digit joints, Greek names, text to escape, mixed families of angles, a wrist numbered
from 3, and constant twists and offsets of π/6 with prismatic joints, whose elements hold
long fractions and roots.
"""

TEN_JOINTS = """name: "Ten-link planar arm & co: 100% planar_test, θ"
source: "made up for the tests; names with # and ~ and {braces}"
convention: standard
joints:
""" + "".join(f"  - {{joint: R, alpha: 0, a: l_{i}, d: 0, theta: theta_{i}}}\n" for i in range(1, 11))

GREEK_PRISMATIC = """name: Greek names
convention: modified
joints:
  - {joint: R, alpha: 0, a: 0, d: 0, theta: phi_1}
  - {joint: R, alpha: pi, a: lambda_1, d: 0, theta: psi_2}
  - {joint: P, alpha: -pi/2, a: 0, d: d_3, theta: 0}
"""

MIXED_FAMILIES = """name: Mixed angle names
source: "made up: theta_1, phi_2 and psi_3 on parallel axes, as in 3T_Tool of a finger"
notes: "c_{phi 2} must not read as the c2 of another chain; 0T3 and a_2 are set as math"
convention: standard
joints:
  - {joint: R, alpha: 0, a: a_1, d: 0, theta: theta_1}
  - {joint: R, alpha: 0, a: a_2, d: 0, theta: phi_2}
  - {joint: R, alpha: pi/2, a: a_3, d: 0, theta: psi_3}
"""

NUMBERED_WRIST = """name: Wrist numbered as in the lecture
convention: standard
first_frame: 3
joints:
  - {joint: R, alpha: -pi/2, a: 0, d: 0, theta: theta_4}
  - {joint: R, alpha: pi/2, a: 0, d: 0, theta: theta_5}
  - {joint: R, alpha: 0, a: 0, d: d_6, theta: theta_6}
"""

SIXTH_TWISTS = """name: Prismatic joints with offsets and twists of pi/6
convention: standard
joints:
  - {joint: R, alpha: pi/6, a: a_1, d: d_1, theta: theta_1 + pi/6}
  - {joint: P, alpha: pi/6, a: a_2, d: d_2 + l_2, theta: pi/6, var: d_2}
  - {joint: R, alpha: -pi/6, a: a_3, d: d_3, theta: theta_3 - pi/3}
  - {joint: P, alpha: pi/6, a: 0, d: d_4 + l_4, theta: pi/4, var: d_4}
"""

SIXTH_TWISTS_AND_ROOT = """name: Prismatic offsets, twists of pi/6 and a root
convention: modified
joints:
  - {joint: P, alpha: 0, a: 0, d: d_1 + l_1, theta: pi/6, var: d_1}
  - {joint: R, alpha: pi/6, a: sqrt(a_1^2 + b_1^2), d: h_2, theta: theta_2 - pi/6}
  - {joint: P, alpha: pi/6, a: a_2, d: d_3 - l_3, theta: pi/3, var: d_3}
  - {joint: R, alpha: -pi/6, a: a_3, d: 0, theta: theta_4 + pi/6}
  - {joint: P, alpha: pi/6, a: 0, d: d_5 + l_5/2, theta: 0, var: d_5}
"""

TEST_ROBOTS = {"ten-joints": TEN_JOINTS, "greek": GREEK_PRISMATIC, "mixed": MIXED_FAMILIES, "wrist": NUMBERED_WRIST,
               "sixth-twists": SIXTH_TWISTS, "sixth-twists-root": SIXTH_TWISTS_AND_ROOT}

# A waist and three pitch joints (Trossen's PincherX 100, Lynxmotion's AL5D)
PITCH_ARM = """name: pitch arm
convention: standard
joints:
  - {joint: R, theta: theta_1, d: d_1, a: 0, alpha: pi/2}
  - {joint: R, theta: theta_2, d: 0, a: a_2, alpha: 0}
  - {joint: R, theta: theta_3, d: 0, a: a_3, alpha: 0}
  - {joint: R, theta: theta_4, d: 0, a: a_4, alpha: 0}
sample: {d_1: 0.09, a_2: 0.106, a_3: 0.1, a_4: 0.114}
"""
