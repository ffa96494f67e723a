"""The generated module's one-pose path (`math` on plain floats, dhsym.inverse.onepose) gives the
values of its batch path (numpy) on random poses, unreachable ones (NaN) included, for arms of
every kind; a pose where plain floats raise falls back to numpy."""
import numpy as np
import pytest
from ik_checks import numeric_fk, random_joints, sample_constants

from dhsym import load

SIX_JOINTS = ("puma560", "stanford", "ur5", "iiwa7")  # seconds of derivation each
ARMS = {"planar2r": (), "planar3r": (), "spherical_wrist": (), "scara": (), "cylindrical_rpp": (),
        "puma560": (), "stanford": (), "ur5": (), "iiwa7": ("theta_3",)}


def _module(name, free):
    robot = load(name)
    code = robot.ik(free=list(free)).code()
    namespace: dict = {}
    exec(compile(code, f"{name}_ik.py", "exec"), namespace)
    return robot, code, namespace


def _poses(robot, count: int, seed: int):
    """Random reachable poses by FK, then the same poses moved 100 m away (out of a revolute arm's reach)."""
    joints = random_joints(robot, np.random.default_rng(seed), count)
    fk = numeric_fk(robot, sample_constants(robot))
    poses = np.array([np.array(fk(*q), dtype=float) for q in joints])
    far = poses.copy()
    far[:, :3, 3] += 100.0
    return joints, np.concatenate([poses, far])


@pytest.mark.parametrize("name", [pytest.param(name, marks=pytest.mark.slow) if name in SIX_JOINTS else name
                                  for name in ARMS])
def test_one_pose_in_plain_floats_gives_the_batch_values(name):
    free = ARMS[name]
    robot, code, namespace = _module(name, free)
    assert "def one_pose(T" in code and "import math" in code
    joints, poses = _poses(robot, 12, 27)
    names = [v.name for v in robot.joint_variables]
    values = {k: np.tile(joints[:, names.index(k)], 2) for k in free}  # a --free joint: its value at each pose
    batch = namespace["ik"](poses, **values)
    alone = np.array([namespace["ik"](pose, **{k: float(v[i]) for k, v in values.items()})
                      for i, pose in enumerate(poses)])
    assert alone.shape == batch.shape == (len(poses), len(namespace["BRANCHES"]), len(namespace["JOINTS"]))
    assert np.array_equal(np.isnan(alone), np.isnan(batch))
    assert np.isfinite(batch[:12]).any(axis=(1, 2)).all()
    if all(row.joint == "R" for row in robot.chain.rows) and "= elements[3]" in code:  # revolute, reads px
        assert np.isnan(batch[12:]).all()
    assert np.allclose(alone, batch, atol=1e-9, equal_nan=True)
    angles = [k for k, joint in enumerate(namespace["JOINTS"]) if k in namespace["REVOLUTE"]]
    finite = alone[..., angles][np.isfinite(alone[..., angles])]
    assert ((-np.pi <= finite) & (finite < np.pi)).all()


def test_one_pose_is_the_plain_float_path_and_a_division_by_zero_falls_back_to_numpy():
    robot, _, namespace = _module("planar2r", ())
    _, poses = _poses(robot, 3, 5)
    direct = namespace["one_pose"](poses[0], 0.5, 0.4)  # what ik() returns for one pose of plain numbers
    assert np.array_equal(direct, namespace["ik"](poses[0]))
    with pytest.raises(ZeroDivisionError):
        namespace["one_pose"](poses[0], 0.0, 0.4)  # D divides by a_1 a_2
    alone = namespace["ik"](poses[0], a_1=0.0)
    assert alone.shape == (2, 2) and np.array_equal(alone, namespace["ik"](poses[:1], a_1=0.0)[0], equal_nan=True)
    constants = np.array([0.5])  # an array for a constant: numpy decides, as for many poses
    assert np.allclose(namespace["ik"](poses[0], a_1=constants), direct, equal_nan=True)


def test_a_batch_of_wrists_some_lined_up_gives_each_poses_own_values_and_reaches_them():
    # the member (θ6 through θ4) is taken only by the poses whose |s5| < LINED_UP, in a batch as alone
    robot, code, namespace = _module("spherical_wrist", ())
    assert "if lined_up.any():" in code and "< LINED_UP:  # the wrist's axes line up" in code
    joints = random_joints(robot, np.random.default_rng(5), 6)
    joints[:, 1] = (0.7, 0.0, 1e-8, np.pi, -0.3, -1e-9)
    fk = numeric_fk(robot, sample_constants(robot))
    poses = np.array([np.array(fk(*q), dtype=float) for q in joints])
    batch = namespace["ik"](poses)
    alone = np.array([namespace["ik"](pose) for pose in poses])
    assert np.allclose(alone, batch, atol=1e-9)
    for pose, branches in zip(poses, batch):
        for branch in branches:
            assert np.allclose(np.array(fk(*branch), dtype=float), pose, atol=1e-7)  # √(1 − r33²) near s5 = 0


def test_a_batch_larger_than_a_chunk_gives_the_values_of_all_poses_at_once():
    # CHUNK poses at a time (their arrays stay in cache); a constant per pose takes all poses at once
    robot, _, namespace = _module("planar2r", ())
    _, poses = _poses(robot, 40, 9)
    many = np.tile(poses, (namespace["CHUNK"] // len(poses) + 2, 1, 1))
    chunked = namespace["ik"](many)
    at_once = namespace["ik"](many, a_1=np.full(len(many), 0.5))
    assert chunked.shape == at_once.shape == (len(many), 2, 2) and len(many) > namespace["CHUNK"]
    assert np.array_equal(chunked, at_once, equal_nan=True)
    assert np.array_equal(chunked[: len(poses)], namespace["ik"](poses), equal_nan=True)
