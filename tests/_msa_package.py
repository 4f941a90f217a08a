"""A MoveIt Setup Assistant–style configuration package for the Panda, installed into a prefix as colcon would, for
the tests of moveit_configs_utils (issue 51 item 2).

Its config/ is moveit_resources_panda_moveit_config's (the real files, copied from tests' fixtures), beside the
``.setup_assistant`` file and the launch files Setup Assistant writes for Jazzy: each is three lines calling a
``moveit_configs_utils.launches.generate_*_launch`` with ``MoveItConfigsBuilder("panda", package_name=...)``.
"""

from __future__ import annotations

import shutil
from pathlib import Path

from _paths import REAL

PANDA = REAL / "moveit_panda"
PACKAGE = "panda_moveit_config"

SETUP_ASSISTANT = """moveit_setup_assistant_config:
  urdf:
    package: moveit_resources_panda_description
    relative_path: urdf/panda.urdf
  srdf:
    relative_path: config/panda.srdf
  package_settings:
    author_name: gazelle tests
    author_email: tests@example.com
    generated_timestamp: 1700000000
  control_xacro:
    command:
      - position
    state:
      - position
      - velocity
"""

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>panda_moveit_config</name>
  <version>0.3.0</version>
  <description>An automatically generated package with all the configuration and launch files for using the panda with the MoveIt Motion Planning Framework</description>
  <maintainer email="tests@example.com">gazelle tests</maintainer>
  <license>BSD-3-Clause</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <exec_depend>moveit_ros_move_group</exec_depend>
  <exec_depend>moveit_configs_utils</exec_depend>
  <exec_depend>moveit_resources_panda_description</exec_depend>
  <exec_depend>robot_state_publisher</exec_depend>
  <exec_depend>rviz2</exec_depend>
  <exec_depend>controller_manager</exec_depend>
  <export><build_type>ament_cmake</build_type></export>
</package>
"""

LAUNCH = """from moveit_configs_utils import MoveItConfigsBuilder
from moveit_configs_utils.launches import generate_{what}_launch


def generate_launch_description():
    moveit_config = MoveItConfigsBuilder("panda", package_name="panda_moveit_config").to_moveit_configs()
    return generate_{what}_launch(moveit_config)
"""

LAUNCHES = ("move_group", "demo", "rsp", "moveit_rviz", "spawn_controllers", "static_virtual_joint_tfs", "warehouse_db")


def install_panda_config(prefix: Path) -> Path:
    """The package (and moveit_resources_panda_description, which its URDF includes) under ``prefix/share``,
    registered in ``prefix``'s ament index; returns the package's share folder."""
    index = prefix / "share" / "ament_index" / "resource_index" / "packages"
    index.mkdir(parents=True, exist_ok=True)
    (prefix / "share" / "moveit_resources_panda_description").symlink_to(PANDA / "moveit_resources_panda_description")
    (index / "moveit_resources_panda_description").write_text("")
    share = prefix / "share" / PACKAGE
    shutil.copytree(PANDA / "moveit_resources_panda_moveit_config" / "config", share / "config")
    for f in share.rglob("*"):
        f.chmod(0o755 if f.is_dir() else 0o644)  # the fixtures are read-only
    (share / ".setup_assistant").write_text(SETUP_ASSISTANT)
    (share / "package.xml").write_text(PACKAGE_XML)
    (share / "launch").mkdir()
    for what in LAUNCHES:
        (share / "launch" / f"{what}.launch.py").write_text(LAUNCH.format(what=what))
    (index / PACKAGE).write_text("")
    return share
