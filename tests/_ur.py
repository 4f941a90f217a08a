"""Universal Robots' own packages for the UR5e tests (issue 51 item 3), installed into a prefix as colcon would.

``tests/data/ur`` holds, byte for byte, what the tests need of UniversalRobots/Universal_Robots_ROS2_Description
(``ur_description``: the macro, its includes, the UR5e's parameter files and collision meshes),
UniversalRobots/Universal_Robots_ROS2_GZ_Simulation (``ur_simulation_gz``: its launch files, controllers file and
URDF) and UniversalRobots/Universal_Robots_ROS2_Driver (``ur_moveit_config``: its launch file, SRDF and MoveIt
configuration; ``ur_robot_driver``: its ``wait_for_robot_description`` script, which ur_moveit.launch.py starts),
each with its LICENSE (BSD-3-Clause); ``tests/data/ur/SOURCES.md`` names the commits. The UR5e's visual
meshes (9 MB of COLLADA) are left out: the tests run without a viewer.
"""

from __future__ import annotations

from pathlib import Path

from _paths import REPO

UR = REPO / "tests" / "data" / "ur"
PACKAGES = ("ur_description", "ur_simulation_gz", "ur_moveit_config", "ur_robot_driver")
# what ur_robot_driver's CMakeLists.txt installs as programs (``install(PROGRAMS ... DESTINATION lib/${PROJECT_NAME})``)
# and the tests run
PROGRAMS = {"ur_robot_driver": ("scripts/wait_for_robot_description",)}


def install_ur(prefix: Path) -> Path:
    """Each package under ``prefix/share`` (a link to tests/data/ur's folder), registered in ``prefix``'s ament
    index, its programs under ``prefix/lib/<package>``; returns ``prefix``."""
    index = prefix / "share" / "ament_index" / "resource_index" / "packages"
    index.mkdir(parents=True, exist_ok=True)
    for name in PACKAGES:
        (prefix / "share" / name).symlink_to(UR / name)
        (index / name).write_text("")
    for name, programs in PROGRAMS.items():
        lib = prefix / "lib" / name
        lib.mkdir(parents=True, exist_ok=True)
        for program in programs:
            (lib / Path(program).name).symlink_to(UR / name / program)
    return prefix
