"""Closed-form solutions written by hand, as the solver's contract (dhsym/inverse/solution.py)
describes them: the surfaces are tested on these whatever the solver finds.

The planar 2R is Spong's elbow manipulator: D = cos θ2 by the law of cosines, two branches."""
import sympy

from dhsym.inverse.solution import Branch, Solution, Step
from dhsym.io.library import load


def planar2r() -> Solution:
    chain = load("planar2r")
    t1, t2 = chain.joint_variables
    px, py, a1, a2, D = sympy.symbols("px py a_1 a_2 D", real=True)
    cosine = (px**2 + py**2 - a1**2 - a2**2) / (2 * a1 * a2)
    branches = []
    for name, sign in (("elbow down", 1), ("elbow up", -1)):
        elbow = sympy.atan2(sign * sympy.sqrt(1 - D**2), D)
        shoulder = sympy.atan2(py, px) - sympy.atan2(a2 * sympy.sin(t2), a1 + a2 * sympy.cos(t2))
        branches.append(Branch(name, ((t2, elbow), (t1, shoulder))))
    steps = (Step(px**2 + py**2, a1**2 + a2**2 + 2 * a1 * a2 * sympy.cos(t2), "law of cosines", (t2,),
                  "the distance from the base to the tip fixes the elbow angle"),
             Step(sympy.atan2(py, px), t1 + sympy.atan2(a2 * sympy.sin(t2), a1 + a2 * sympy.cos(t2)),
                  "atan2 of a pair", (t1,), "the direction to the tip, less the angle the forearm adds"))
    reach = "D² ≤ 1: the tip within reach, |a1 − a2| ≤ r ≤ a1 + a2"
    return Solution(chain, "planar arm: the law of cosines for the elbow, then the shoulder", (t1, t2),
                    ((D, cosine),), tuple(branches), conditions=(reach,),
                    degenerate=("px = py = 0 with a1 = a2: θ1 is arbitrary",), steps=steps)
