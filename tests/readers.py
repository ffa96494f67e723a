"""The robot-file readers as a notebook sees a robot: `load_robot_text` and `load_robot_file` of
dhsym.io.robotfile, each robot given as the notebook `Robot` (dhsym.api.robot: `fk()`, `rows`,
frames as printed), as `dhsym.load` gives it. The readers' errors are theirs, unchanged."""
from dhsym.api.robot import Robot, notebook_robot
from dhsym.io import robotfile


def load_robot_text(text: str, filename: str = "robot.yaml") -> Robot:
    return notebook_robot(robotfile.load_robot_text(text, filename))


def load_robot_file(path) -> Robot:
    return notebook_robot(robotfile.load_robot_file(path))
