"""Pictures: numeric frame poses equal the symbolic kinematics; drawings and the `plot` command."""
import shutil

import matplotlib
import numpy as np
import pytest
import sympy
from matplotlib.colors import to_rgb
from matplotlib.figure import Figure

from dhsym import Chain, DHRow, Robot, load, plot
from dhsym.cli import main
from dhsym.errors import UserError
from dhsym.io.library import ROBOTS_DIR

matplotlib.use("Agg")
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def _origins(robot, values):
    return {frame: pose[:3, 3] for frame, pose in plot.frame_poses(robot, values)}


def test_planar2r_origins_are_the_hand_computed_ones():
    origins = _origins(load("planar2r"), {"theta_1": "30deg", sympy.Symbol("theta_2", real=True): sympy.pi / 3})
    elbow = 0.5 * np.array([np.cos(np.pi / 6), np.sin(np.pi / 6), 0])
    assert np.allclose(origins[0], 0)
    assert np.allclose(origins[1], elbow)
    assert np.allclose(origins[2], elbow + 0.4 * np.array([0, 1, 0]))  # θ1 + θ2 = 90°


@pytest.mark.parametrize("name", ["puma560", "stanford", "fourbar_right", "planar3r"])
def test_every_pose_equals_the_symbolic_transform(name):
    robot = load(name)
    rng = np.random.default_rng(7)
    angles = {v: float(rng.uniform(-2, 2)) for v in robot.joint_variables}
    numbers = {**{s: float(v) for s, v in robot.sample.items()}, **angles}
    for frame, pose in plot.frame_poses(robot, angles):
        exact = robot.transform(robot.first_frame, frame, raw=True).xreplace(numbers)
        assert np.allclose(pose, np.array(exact.evalf(), dtype=float)), frame


def test_missing_and_unknown_symbols_are_user_errors():
    a_1, l_1, theta_1 = sympy.symbols("a_1 l_1 theta_1", real=True)
    arm = Robot(Chain([DHRow.revolute(theta_1, a=a_1)], "standard"))  # a robot without a file has no sample values
    assert plot.frame_poses(arm, {"a_1": 2})[-1][1][0, 3] == pytest.approx(2)  # joint variable defaults to 0
    with pytest.raises(UserError, match="no value for a_1"):
        plot.frame_poses(arm, {theta_1: 1})
    with pytest.raises(UserError, match="l_1 is not a symbol.*a_1, theta_1"):
        plot.frame_poses(arm, {l_1: 1, "a_1": 1})


def test_planar_arms_are_recognised_numerically():
    assert plot.is_planar(load("planar3r"), {"theta_2": 1})
    assert not plot.is_planar(load("scara"))  # all axes parallel, but the prismatic joint leaves the plane
    assert not plot.is_planar(load("spatial3r"))


def test_planar3r_is_drawn_flat_and_puma560_in_equal_3d():
    assert plot.draw(load("planar3r"), ax=Figure()).name == "rectilinear"
    ax = plot.draw(load("puma560"), {"theta_2": "-30deg"}, ax=Figure())
    assert ax.name == "3d"
    spans = [np.ptp(limits) for limits in (ax.get_xlim(), ax.get_ylim(), ax.get_zlim())]
    assert np.allclose(spans, spans[0])
    assert np.allclose(ax.get_box_aspect() / ax.get_box_aspect()[0], 1)


def _artists(ax, prefix):
    return [a for a in ax.get_children() if (a.get_gid() or "").startswith(prefix)]


def _colour(artist):
    if hasattr(artist, "arrow_patch"):
        return to_rgb(artist.arrow_patch.get_edgecolor())
    return to_rgb(np.atleast_2d(artist.get_color())[0] if hasattr(artist, "get_segments") else artist.get_color())


@pytest.mark.parametrize("name", ["planar2r", "spatial3r"])
def test_triads_are_red_green_blue(name):
    ax = plot.draw(load(name), {"theta_1": 0.3}, ax=Figure())
    for channel, letter in enumerate("xyz"):
        artists = _artists(ax, f"{letter} axis")
        assert artists, letter
        for artist in artists:
            rgb = _colour(artist)
            assert rgb[channel] == max(rgb) and rgb[channel] > 0.4, (letter, rgb)


def test_frames_sharing_an_origin_and_axis_share_one_labelled_arrow():
    ax = plot.draw(load("planar3r"), ax=Figure())  # frames 0 and 1 coincide at θ1 = 0
    labels = [t.get_text() for t in ax.texts if t.get_text()]
    assert "$x_{0,1}$" in labels and "$x_{0}$" not in labels
    assert not plot.draw(load("planar3r"), ax=Figure(), show_frames=False).texts


def test_joints_are_circles_and_squares():
    ax = plot.draw(load("scara"), ax=Figure())
    assert [a.get_marker() for a in _artists(ax, "R joint")] == ["o", "o", "o"]
    assert [a.get_marker() for a in _artists(ax, "P joint")] == ["s"]


def test_fourbar_loop_closes_and_is_drawn_with_its_cut_joint():
    left, right = load("fourbar_left"), load("fourbar_right")
    left_values, right_values = plot.close_loop(left, right, {"phi_1": "120deg"}, ["theta_1", "phi_2"],
                                                guess={"theta_1": 1, "phi_2": -1})
    assert np.allclose(plot.frame_poses(left, left_values)[-1][1][:3, 3],
                       plot.frame_poses(right, right_values)[-1][1][:3, 3])
    ax = plot.draw_closed([(left, left_values, "black", "left"), (right, right_values, "brown", "right")], ax=Figure())
    assert ax.name == "rectilinear"
    assert len(_artists(ax, "R joint")) == 4  # left 2, right 1, and the cut joint
    assert "$x_{LT}$" in [t.get_text() for t in ax.texts]
    with pytest.raises(UserError, match="does not close"):
        plot.close_loop(left, right, {"phi_1": 0}, ["theta_1", "phi_2"])  # the rocker cannot reach 0°


def test_save_writes_png_and_never_over_an_input(tmp_path):
    ax = plot.draw(load("planar2r"), ax=Figure())
    plot.save(ax, tmp_path / "arm.png")
    assert (tmp_path / "arm.png").read_bytes().startswith(PNG_MAGIC)
    with pytest.raises(UserError, match="refusing to overwrite"):
        plot.save(ax.figure, tmp_path / "arm.png", inputs=[tmp_path / "arm.png"])


def test_cli_writes_png_to_the_robot_name_by_default(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert main(["plot", "planar2r", "--q", "theta_1=30deg", "theta_2=-pi/4", "--set", "a_1=1"]) == 0
    assert capsys.readouterr().out.strip() == "planar2r.png"
    assert (tmp_path / "planar2r.png").read_bytes().startswith(PNG_MAGIC)


@pytest.mark.parametrize("arguments, message", [
    (["--q", "theta_1=30dg"], "--q 'theta_1=30dg': write 30deg (or 30°) for degrees"),
    (["--q", "l_9=1"], "no symbol l_9; its symbols are a_1, a_2, theta_1, theta_2"),
    (["--set", "theta_1=1"], "theta_1 is a joint variable; use --q"),
    (["--q", "theta_1"], "expected NAME=EXPR"),
    (["--q", "theta_1=a_1"], "must be a number"),
    (["-o", "arm.jpg"], "cannot write .jpg"),
])
def test_cli_bad_values_give_one_error_line_and_exit_2(arguments, message, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert main(["plot", "planar2r", *arguments]) == 2
    error = capsys.readouterr().err
    assert error.count("\n") == 1 and error.startswith("dhsym: error: ") and message in error
    assert not list(tmp_path.iterdir())


def test_cli_refuses_to_overwrite_the_robot_file(tmp_path, capsys):
    robot_file = tmp_path / "arm.png"  # an odd name for a robot file, but a readable one
    shutil.copy(ROBOTS_DIR / "planar2r.yaml", robot_file)
    before = robot_file.read_bytes()
    assert main(["plot", str(robot_file), "-o", str(tmp_path / "picture.png")]) == 0
    assert main(["plot", str(robot_file), "--3d", "-o", str(robot_file)]) == 2
    assert "refusing to overwrite" in capsys.readouterr().err
    assert robot_file.read_bytes() == before


def test_frame_offset_renumbers_the_picture_only():
    from matplotlib.figure import Figure

    from dhsym import load
    renumbered = plot.draw(load("spherical_wrist"), ax=Figure(), frame_offset=3)
    plain = plot.draw(load("spherical_wrist"), ax=Figure(), frame_offset=0)
    by_the_robot_file = plot.draw(load("spherical_wrist"), ax=Figure())  # first_frame: 3
    assert [t.get_text() for t in by_the_robot_file.texts] == [t.get_text() for t in renumbered.texts]
    assert sorted(t.get_text() for t in renumbered.texts) == [
        "$x_{3,4,5}$", "$x_{6}$", "$y_{3,5}$", "$y_{4}$", "$y_{6}$", "$z_{3,5}$", "$z_{4}$", "$z_{6}$"]
    assert sorted(t.get_text() for t in plain.texts) == [
        "$x_{0,1,2}$", "$x_{3}$", "$y_{0,2}$", "$y_{1}$", "$y_{3}$", "$z_{0,2}$", "$z_{1}$", "$z_{3}$"]
    positions = [[t.get_position() for t in sorted(ax.texts, key=lambda t: t.get_text()[1:])]
                 for ax in (renumbered, plain)]
    assert positions[0] == positions[1]  # the same picture, only the names differ


def _tips(ax) -> dict:
    """Each drawn axis label and the 3D point it names (the tip of its arrow)."""
    return {t.get_text(): np.array(t.get_position_3d()) for t in ax.texts if t.get_text()}


def test_chosen_frames_alone_show_the_wrist_flipped_twin():
    # The PUMA's wrist-flipped twin (θ4 + π, −θ5, θ6 + π) has the same links and reaches the same
    # frame 6; drawn with frames 5 and 6 only, frame 6 is the same and frame 5's x and z are not.
    puma = load("puma560")
    q = {"theta_1": 0.3, "theta_2": -0.5, "theta_3": 0.6, "theta_4": 0.5, "theta_5": 0.7, "theta_6": 0.2}
    twin = dict(q, theta_4=0.5 + np.pi, theta_5=-0.7, theta_6=0.2 + np.pi)
    pictures = [plot.draw(puma, values, ax=Figure(), show_frames=[5, 6]) for values in (q, twin)]
    for ax in pictures:
        axes = {a.get_gid() for a in ax.get_children() if " axis of frame " in (a.get_gid() or "")}
        assert axes == {f"{letter} axis of frame {frame}" for letter in "xyz" for frame in (5, 6)}
    links = [next(line for line in ax.lines if line.get_gid() == "links").get_data_3d() for ax in pictures]
    assert np.allclose(links[0], links[1])
    tips = [_tips(ax) for ax in pictures]
    assert sorted(tips[0]) == sorted(tips[1]) == ["$x_{5}$", "$x_{6}$", "$y_{5}$", "$y_{6}$", "$z_{5}$", "$z_{6}$"]
    assert all(np.allclose(tips[0][name], tips[1][name]) for name in ("$x_{6}$", "$y_{6}$", "$z_{6}$"))
    assert not np.allclose(tips[0]["$x_{5}$"], tips[1]["$x_{5}$"])
    assert not np.allclose(tips[0]["$z_{5}$"], tips[1]["$z_{5}$"])


def test_one_frame_by_its_printed_name_and_an_unknown_frame_is_a_user_error():
    wrist = load("spherical_wrist")  # first_frame: 3, frames printed 3..6
    ax = plot.draw(wrist, ax=Figure(), show_frames=6)
    assert sorted(_tips(ax)) == ["$x_{6}$", "$y_{6}$", "$z_{6}$"]
    with pytest.raises(UserError, match="no frame 2 to draw; the frames are 3, 4, 5, 6"):
        plot.draw(wrist, ax=Figure(), show_frames=[2])
    assert not _tips(plot.draw(wrist, ax=Figure(), show_frames=[]))


def test_branches_drawn_with_the_last_frames():
    from dhsym.plot.branches import draw_branches

    arm = load("planar2r")
    figure = draw_branches(arm, values={"theta_2": "60deg"}, show_frames=[2], figure=Figure(), triad_scale=0.2)
    for ax in figure.axes:
        assert sorted(filter(None, (t.get_text() for t in ax.texts))) == ["$x_{2}$", "$y_{2}$"]
        x2 = next(a for a in ax.get_children() if a.get_gid() == "x axis of frame 2")
        assert np.isclose(np.linalg.norm(np.subtract(x2.xy, x2.xyann)), 0.2)
