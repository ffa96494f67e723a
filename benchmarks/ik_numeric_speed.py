"""The numeric inverse kinematics (dhsym.inverse.numeric): solutions per second over a batch of
poses, against a plain numpy FK of the same poses and against EAIK's batch call, in the same run.

- dhsym: `numeric_inverse_kinematics(robot).solve(T)` on POSES poses at once (every real solution of each).
- plain numpy FK: the arm's constant transforms and its joints' turns (built with numpy.cos and
  numpy.sin) multiplied with `@` over the same batch, base and tool included: what the poses cost
  to make.
- EAIK 1.2 (its C++ sub-problem solver, analytic where it knows a decomposition of the arm):
  `Robot.calculate_IK_batched` with one worker thread (dhsym uses one core as well), run in a
  process of a Python that has it: this one when `import eaik` works, else the venv
  build/peers/eaik (installed there once, unless --no-install). Only its solutions that reach the
  pose (within 1e-8) are counted; EAIK does not solve the offset-wrist arm at all.

Each time is the least CPU time of RUNS runs (on a shared machine the wall clock waits for other
jobs), with numpy's BLAS on one thread; the ratios are what this benchmark is for.

Run: python benchmarks/ik_numeric_speed.py [--no-install] [--poses N]
"""
from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # before numpy loads: one core, as EAIK's one worker
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy
from peer_venv import peer_python

import dhsym
from dhsym.api.ik import numeric_inverse_kinematics

ROOT = Path(__file__).resolve().parent.parent
PEER_VENV = ROOT / "build" / "peers" / "eaik"
PEER_PACKAGE = "EAIK==1.2.2"
RUNS = 3
ARMS = (("offset-wrist cobot (no closed form)", str(ROOT / "tests" / "data" / "numeric" / "offset_wrist_cobot.yaml")),
        ("PUMA 560", "puma560"), ("UR5", "ur5"))
EAIK_SCRIPT = """
import sys, time, numpy
import eaik.pybindings.EAIK as binding
data = numpy.load(sys.argv[1])
robot = binding.Robot(data["axes"].T, data["offsets"].T, data["rotation"], [], True)
if not robot.has_known_decomposition():
    print("none"); sys.exit()
poses = [pose for pose in data["poses"]]
best = float("inf")
for _ in range(int(sys.argv[2])):
    start = time.process_time()
    answers = robot.calculate_IK_batched(poses, 1)
    best = min(best, time.process_time() - start)
numpy.save(sys.argv[1] + ".q.npy", numpy.array([numpy.array(a.Q).reshape(-1, 6) for a in answers], dtype=object),
           allow_pickle=True)
print(best)
"""


def best_of(work, runs: int = RUNS) -> float:
    times = []
    for _ in range(runs):
        start = time.process_time()
        work()
        times.append(time.process_time() - start)
    return min(times)


def plain_fk(arm, values):
    """numpy FK of a batch: each joint's turn built with numpy.cos/numpy.sin, multiplied with @."""
    result = numpy.broadcast_to(arm.frames[0], (len(values), 4, 4))
    for k, kind in enumerate(arm.kinds):
        amount = values[:, k] * arm.slopes[k]
        motion = numpy.zeros((len(values), 4, 4))
        motion[:, 2, 2] = motion[:, 3, 3] = 1.0
        if kind == "R":
            cosine, sine = numpy.cos(amount), numpy.sin(amount)
            motion[:, 0, 0], motion[:, 0, 1], motion[:, 1, 0], motion[:, 1, 1] = cosine, -sine, sine, cosine
        else:
            motion[:, 0, 0] = motion[:, 1, 1] = 1.0
            motion[:, 2, 3] = amount
        result = result @ motion @ arm.frames[k + 1]
    return result


def eaik_python(install: bool):
    """A Python that has EAIK, and why not when there is none."""
    try:
        import eaik  # noqa: F401

        return Path(sys.executable), ""
    except ImportError:
        pass
    return peer_python(PEER_VENV, PEER_PACKAGE, install)


def eaik_batch(python, arm, poses):
    """(EAIK's best time, its solutions that reach each pose) or (None, None) where EAIK has no decomposition."""
    frame, axes, points = arm.frames[0], [], []
    for k in range(len(arm.kinds)):
        axes.append(frame[:3, 2] * numpy.sign(arm.slopes[k]))
        points.append(frame[:3, 3].copy())
        frame = frame @ arm.frames[k + 1]
    offsets = [points[0]] + [b - a for a, b in zip(points, points[1:])] + [frame[:3, 3] - points[-1]]
    with tempfile.TemporaryDirectory() as folder:
        data = Path(folder) / "arm.npz"
        numpy.savez(data, axes=numpy.array(axes), offsets=numpy.array(offsets), rotation=frame[:3, :3], poses=poses)
        done = subprocess.run([str(python), "-c", EAIK_SCRIPT, str(data), str(RUNS)], capture_output=True, text=True,
                              check=True)
        if done.stdout.strip() == "none":
            return None, None
        solutions = numpy.load(str(data) + ".q.npy", allow_pickle=True)
    solutions = [numpy.asarray(q, dtype=float).reshape(-1, 6) / numpy.abs(arm.slopes) for q in solutions]
    reached = [q[numpy.abs(plain_fk(arm, q) - pose).max(axis=(1, 2)) < 1e-8] for q, pose in zip(solutions, poses)]
    return float(done.stdout.split()[-1]), reached


def measure(name: str, count: int):
    """(the arm, the poses, dhsym's time, the solutions it finds, the plain FK's time) at `count` random poses."""
    inverse = numeric_inverse_kinematics(dhsym.load(name))
    rng = numpy.random.default_rng(1)
    values = rng.uniform(-numpy.pi, numpy.pi, (count, len(inverse.arm.kinds)))
    poses = plain_fk(inverse.arm, values)
    ours = best_of(lambda: inverse.solve(poses))
    found = numpy.isfinite(inverse.solve(poses)[:, :, 0]).sum()
    return inverse.arm, poses, ours, found, best_of(lambda: plain_fk(inverse.arm, values))


def main() -> None:
    install = "--no-install" not in sys.argv[1:]
    count = int(sys.argv[sys.argv.index("--poses") + 1]) if "--poses" in sys.argv else 2000
    python, reason = eaik_python(install)
    print(f"{count} random poses per arm; least of {RUNS} runs; EAIK: {reason or f'run by {python}'}")
    for label, name in ARMS:
        arm, poses, ours, found, fk = measure(name, count)
        print(f"{label}: dhsym {ours:.3f} s, {found / count:.1f} solutions per pose, {found / ours:,.0f} solutions/s, "
              f"{ours / count * 1e6:.0f} µs per pose; plain numpy FK {fk * 1e3:.1f} ms: dhsym takes {ours / fk:.0f}x "
              "FK")
        if python is None:
            continue
        theirs, reached = eaik_batch(python, arm, poses)
        if theirs is None:
            print("  EAIK: no decomposition of this arm is known to it (it refuses the arm)")
            continue
        their_found = sum(len(q) for q in reached)
        print(f"  EAIK batch (1 thread): {theirs:.3f} s, {their_found / count:.1f} solutions per pose, "
              f"{their_found / theirs:,.0f} solutions/s: dhsym takes {ours / theirs:.0f}x EAIK")


if __name__ == "__main__":
    main()
