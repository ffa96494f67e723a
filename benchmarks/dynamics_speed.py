"""Dynamics: how fast, and how short, against the peers' published figures and baselines measured in
the same run.

1. The fully symbolic PUMA 560 (ten standard parameters per link, about each frame's origin, as
   SymPyBotics takes them; and dhsym's own default, mass, centre of mass and inertia about it):
   the time to derive M, C and g as code, and what that code costs. SymPyBotics: 6.3 s, M 773
   operations, C 6,556 (measured on this kind of machine when the issue was filed; it does not
   install from PyPI). Target: 10× faster and smaller.
2. τ as code, against OpenSYMORO's customized Newton–Euler for the PUMA: 381 multiplications,
   326 additions, 0.58 s.
3. The PUMA with numeric parameters (Armstrong, Khatib and Burdick, as the Robotics Toolbox gives
   them in Spong's frames): M, C, g and the Christoffel symbols in textbook form, against the time
   of `import sympy` in a fresh process (the issue's target: no longer).
4. The generated tau of the UR5 (example-robot-data's URDF) over 100,000 states at once, against
   Pinocchio's RNEA called in a Python loop, when both are installed.

dhsym's times are the best of three cold runs (SymPy's cache emptied). Run with `make bench`.
"""
from __future__ import annotations

import gc
import resource
import subprocess
import sys
import time
from pathlib import Path

import numpy
import sympy
from sympy.core.cache import clear_cache

from dhsym.core.chain import Chain, DHRow
from dhsym.core.inertia import LinkInertia, MassModel
from dhsym.dynamics.codegen import module_text
from dhsym.dynamics.composite import mass_matrix
from dhsym.dynamics.coriolis import coriolis_matrix
from dhsym.dynamics.derive import derive
from dhsym.dynamics.model import rigid_model, standard_parameters
from dhsym.dynamics.newton_euler import newton_euler
from dhsym.dynamics.program import dynamics_program
from dhsym.dynamics.tape import Tape, operations
from dhsym.io.library import load

sys.path.insert(0, str(Path(__file__).parent.parent / "tests"))
from packages import EXAMPLE_ROBOT_DATA  # noqa: E402  (tests/ holds where the data packages keep their files)

SYMPYBOTICS = {"seconds": 6.3, "M": 773, "C": 6556}
OPENSYMORO = {"seconds": 0.58, "multiplications": 381, "additions": 326}
STATES = 100_000


def best_of(runs: int, function):
    results = []
    for _ in range(runs):
        clear_cache()
        start = time.perf_counter()
        value = function()
        results.append((time.perf_counter() - start, value))
    return min(results, key=lambda pair: pair[0])


def import_sympy_seconds() -> tuple[float, float]:
    """`import sympy` in a fresh interpreter, less the interpreter's own start-up: best of three,
    (wall-clock seconds, CPU seconds). On a loaded machine the CPU time is the steadier figure."""
    def run(code: str) -> tuple[float, float]:
        cpu, start = _children_cpu(), time.perf_counter()
        subprocess.run([sys.executable, "-c", code], check=True)
        return time.perf_counter() - start, _children_cpu() - cpu
    pairs = [(run("import sympy"), run("pass")) for _ in range(3)]
    return min(a[0] - b[0] for a, b in pairs), min(a[1] - b[1] for a, b in pairs)


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def symbolic_puma(parameters: str):
    """M, C and g of the fully symbolic PUMA as code: (tape, M, C, g)."""
    chain = load("puma560").chain
    tape = Tape()
    masses = MassModel().filled(chain.n)
    about = [standard_parameters(k) for k in range(1, chain.n + 1)] if parameters == "origin" else None
    model = rigid_model(chain, masses, about)
    M = mass_matrix(tape, model)
    C = coriolis_matrix(tape, model, M)
    g = newton_euler(tape, model, [0] * chain.n, [0] * chain.n).torques
    return tape, M, C, g


def upper(M) -> list:
    return [M[i, j] for i in range(M.rows) for j in range(i, M.cols)]


def count_ops(tape, outputs) -> int:
    """SymPy's count_ops of the code: every name the outputs need once, then the outputs."""
    return sum(sympy.count_ops(tape.definitions[s]) for s in tape.used(outputs)) + \
        sum(sympy.count_ops(x) for x in outputs)


def report_symbolic() -> None:
    print("Fully symbolic PUMA 560: M, C, g as code")
    print(f"{'parameters':<22} {'seconds':>8} {'×SymPyBotics':>13} {'M ops':>7} {'C ops':>7} {'g ops':>6}"
          f" {'M count_ops':>12} {'C count_ops':>12}")
    for label, parameters in (("about the origin", "origin"), ("m, com, I about com", "com")):
        seconds, (tape, M, C, g) = best_of(3, lambda p=parameters: symbolic_puma(p))
        ops = [operations(tape, x).multiplications + operations(tape, x).additions for x in (upper(M), list(C), g)]
        print(f"{label:<22} {seconds:8.3f} {SYMPYBOTICS['seconds'] / seconds:13.1f} {ops[0]:7d} {ops[1]:7d}"
              f" {ops[2]:6d} {count_ops(tape, upper(M)):12d} {count_ops(tape, list(C)):12d}")
    print(f"{'SymPyBotics':<22} {SYMPYBOTICS['seconds']:8.3f} {1:13.1f} {SYMPYBOTICS['M']:>7} {SYMPYBOTICS['C']:>7}")


def report_torque() -> None:
    chain = load("puma560").chain
    masses = MassModel().filled(chain.n)

    def torque():
        tape = Tape()
        model = rigid_model(chain, masses, [standard_parameters(k) for k in range(1, chain.n + 1)])
        return tape, newton_euler(tape, model).torques

    seconds, (tape, torques) = best_of(3, torque)
    counted = operations(tape, torques)
    print("\nFully symbolic PUMA 560: τ as code (Newton–Euler)")
    print(f"dhsym       {seconds:6.3f} s  {counted.multiplications} multiplications, {counted.additions} additions,"
          f" {counted.functions} cos/sin")
    print(f"OpenSYMORO  {OPENSYMORO['seconds']:6.3f} s  {OPENSYMORO['multiplications']} multiplications, "
          f"{OPENSYMORO['additions']} additions")


def numeric_puma() -> tuple:
    """The PUMA 560 with Armstrong, Khatib and Burdick's parameters, in Spong's frames as the Robotics
    Toolbox gives them (link 1's mass is not measured; its centre is on its axis, so it does not matter)."""
    r = sympy.Rational
    q = [sympy.Symbol(f"q_{k}", real=True) for k in range(1, 7)]
    table = [(0, 0, sympy.pi / 2), (0, r("0.4318"), 0), (r("0.15005"), r("0.0203"), -sympy.pi / 2),
             (r("0.4318"), 0, sympy.pi / 2), (0, 0, -sympy.pi / 2), (0, 0, 0)]
    chain = Chain([DHRow.revolute(v, d, a, alpha) for v, (d, a, alpha) in zip(q, table)], "standard")
    values = [(0, (0, 0, 0), ("0", "0.35", "0")), ("17.4", ("-0.3638", "0.006", "0.2275"), ("0.13", "0.524", "0.539")),
              ("4.8", ("-0.0203", "-0.0141", "0.070"), ("0.066", "0.086", "0.0125")),
              ("0.82", (0, "0.019", 0), ("1.8e-3", "1.3e-3", "1.8e-3")),
              ("0.34", (0, 0, 0), ("0.3e-3", "0.4e-3", "0.3e-3")),
              ("0.09", (0, 0, "0.032"), ("0.15e-3", "0.15e-3", "0.04e-3"))]
    links = tuple(LinkInertia(r(m), tuple(r(x) for x in c), (*[r(x) for x in i], 0, 0, 0)) for m, c, i in values)
    return chain, MassModel(links, (0, 0, -r("9.81")))


def report_numeric(import_seconds: tuple[float, float]) -> None:
    chain, masses = numeric_puma()
    gc.freeze()  # as the dhsym process does after its imports (dhsym/cli/__main__.py)
    seconds, result = best_of(3, lambda: derive(chain, masses))
    cpu = min(_cpu_seconds(lambda: derive(chain, masses)) for _ in range(3))
    size = sum(sympy.count_ops(x) for x in [*result.M, *result.C, *result.g])
    print("\nPUMA 560 with numeric parameters: M, C, g and Christoffel symbols in textbook form")
    print(f"dhsym {seconds:.3f} s, `import sympy` {import_seconds[0]:.3f} s: ratio {seconds / import_seconds[0]:.2f}"
          f"  ({size} operations in M, C, g; {len(result.christoffel)} Christoffel symbols not zero)")
    print(f"CPU time: dhsym {cpu:.3f} s, `import sympy` {import_seconds[1]:.3f} s: ratio {cpu / import_seconds[1]:.2f}")


def _cpu_seconds(function) -> float:
    clear_cache()
    start = time.process_time()
    function()
    return time.process_time() - start


def report_code() -> None:
    urdf = EXAMPLE_ROBOT_DATA / "ur_description/urdf/ur5_robot.urdf"
    try:
        import pinocchio
    except ImportError:
        print("\nGenerated tau against Pinocchio: skipped (pin is not installed)")
        return
    if not urdf.exists():
        print("\nGenerated tau against Pinocchio: skipped (example-robot-data is not installed)")
        return
    from dhsym.io.urdfimport import import_urdf

    robot = import_urdf(urdf, tip="ee_link").robot
    program = dynamics_program(robot.chain, robot.filled_masses())
    namespace: dict = {}
    exec(compile(module_text(program, robot.name, robot.sample), "ur5_dynamics.py", "exec"), namespace)
    rng = numpy.random.default_rng(0)
    q, qd, qdd = (rng.uniform(-3, 3, (STATES, robot.n)) for _ in range(3))
    ours, torques = best_of(3, lambda: namespace["tau"](q, qd, qdd))
    model = pinocchio.buildModelFromUrdf(str(urdf))
    data = model.createData()
    rnea = pinocchio.rnea

    def loop():
        return numpy.array([rnea(model, data, a, b, c) for a, b, c in zip(q, qd, qdd)])

    theirs, reference = best_of(1, loop)
    print(f"\nUR5: tau of {STATES:,} states (max difference {numpy.abs(torques - reference).max():.1e})")
    print(f"dhsym module, all at once {ours:.3f} s; Pinocchio RNEA in a Python loop {theirs:.3f} s;"
          f" ratio {theirs / ours:.1f}")


def main() -> int:
    import_seconds = import_sympy_seconds()
    report_symbolic()
    report_torque()
    report_numeric(import_seconds)
    report_code()
    return 0


if __name__ == "__main__":
    sys.exit(main())
