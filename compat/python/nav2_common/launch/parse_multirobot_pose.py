"""ParseMultiRobotPose: the robots and their poses of a ``robots:=`` launch argument, read from the command line
when the launch file is loaded (nav2_common Jazzy, parse_multirobot_pose.py: what it does, in our own code).

``ros2 launch nav2_bringup cloned_multi_tb3_simulation_launch.py robots:="robot1={x: 1.0, y: 1.0, yaw: 0.0};
robot2={x: -1.0, y: 1.0, z: 0.1, yaw: 1.5707}"``: ``ParseMultiRobotPose('robots').value()`` is
``{'robot1': {'x': 1.0, 'y': 1.0, 'yaw': 0.0, 'z': 0.0, 'roll': 0.0, 'pitch': 0.0}, 'robot2': {...}}``, each
missing coordinate 0.0. Robots are separated by ``;``; an entry without exactly one ``=`` is skipped, as
nav2_common skips it. nav2_common reads the arguments after ``ros2 launch PKG FILE``; here every ``NAME:=VALUE``
of the command line counts, so ``ros2 launch FILE robots:=...`` works too.
"""

from __future__ import annotations

import sys

import yaml

POSE_KEYS = ("x", "y", "z", "roll", "pitch", "yaw")


class ParseMultiRobotPose:
    """See the module docstring."""

    def __init__(self, target_argument: str, argv: list[str] | None = None) -> None:
        self._name = target_argument
        prefix = target_argument + ":="
        given = [a[len(prefix) :] for a in (sys.argv[1:] if argv is None else argv) if a.startswith(prefix)]
        self._text = given[-1] if given else ""

    def value(self) -> dict[str, dict[str, float]]:
        """Robot name -> pose (``x y z roll pitch yaw``, 0.0 where not given).

        Raises:
            ValueError: a robot's pose is not a YAML mapping of numbers (the message names the argument and
                the robot).
        """
        robots: dict[str, dict[str, float]] = {}
        for entry in (e for e in self._text.split(";") if e.strip()):
            parts = entry.strip().split("=")
            if len(parts) != 2:
                continue
            name, text = parts[0].strip(), parts[1].strip()
            try:
                pose = yaml.safe_load(text)
            except yaml.YAMLError:
                pose = None
            if not isinstance(pose, dict):
                raise ValueError(
                    f"{self._name}: robot '{name}': '{text}' is not a pose like {{x: 1.0, y: 2.0, yaw: 0.0}}"
                )
            for key in POSE_KEYS:
                pose.setdefault(key, 0.0)
            robots[name] = pose
        return robots
