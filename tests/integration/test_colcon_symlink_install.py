"""Issue 49: `colcon build --symlink-install`, as nearly every ROS 2 README says, then the workspace's worlds and
robots load with every mesh.

colcon links each installed file back into the workspace (ament_cmake_symlink_install: one link per file of an
``install(DIRECTORY ...)``). gazelle followed the links out of the install prefix and refused the meshes as
outside the folders it may read: TurtleBot3's world lost its walls and pillars to twelve MESH_NOT_FOUND warnings
and the burger four more. Two packages are built here with the real colcon: the TurtleBot3 stand-in of
test_turtlebot3_e2e, and a description package whose URDF takes a ``package://`` mesh from a sibling folder of
its repository (outside the package's own source folder) and another through a link that leads out of the
workspace, which must stay refused. Each file is loaded by the real ``gazelle check`` in a shell that sourced
``install/setup.bash``.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from .test_blog_workspace import shell
from .test_turtlebot3 import TB3

pytestmark = pytest.mark.slow

TB3_CMAKELISTS = """cmake_minimum_required(VERSION 3.8)
project(turtlebot3_gazebo)
find_package(ament_cmake REQUIRED)
install(DIRECTORY models urdf worlds DESTINATION share/${PROJECT_NAME}/)
ament_package()
"""

ARENA_CMAKELISTS = """cmake_minimum_required(VERSION 3.8)
project(arena_description)
find_package(ament_cmake REQUIRED)
install(DIRECTORY urdf DESTINATION share/${PROJECT_NAME}/)
install(DIRECTORY ../common/meshes DESTINATION share/${PROJECT_NAME}/)
ament_package()
"""

ARENA_PACKAGE = """<?xml version="1.0"?>
<package format="3">
  <name>arena_description</name><version>1.0.0</version><description>test</description>
  <maintainer email="dev@example.com">dev</maintainer><license>BSD</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <export><build_type>ament_cmake</build_type></export>
</package>
"""


def _urdf(mesh: str) -> str:
    return (
        '<robot name="r"><link name="base"><inertial><mass value="1"/>'
        '<inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial>'
        f'<visual><geometry><mesh filename="package://arena_description/meshes/{mesh}"/></geometry></visual>'
        f'<collision><geometry><mesh filename="package://arena_description/meshes/{mesh}"/></geometry></collision>'
        "</link></robot>"
    )


def _workspace(root: Path) -> Path:
    ws = root / "ws"
    tb3 = ws / "src" / "turtlebot3_gazebo"
    tb3.mkdir(parents=True)
    shutil.copy(TB3 / "turtlebot3_gazebo" / "package.xml", tb3 / "package.xml")
    for folder in ("models", "urdf", "worlds"):
        shutil.copytree(TB3 / "turtlebot3_gazebo" / folder, tb3 / folder)
    (tb3 / "CMakeLists.txt").write_text(TB3_CMAKELISTS)
    repo = ws / "src" / "arena"
    meshes, pkg = repo / "common" / "meshes", repo / "arena_description"
    (pkg / "urdf").mkdir(parents=True)
    meshes.mkdir(parents=True)
    stl = TB3 / "turtlebot3_gazebo" / "models" / "turtlebot3_common" / "meshes" / "bases" / "burger_base.stl"
    shutil.copy(stl, meshes / "base.stl")
    secret = root / "outside" / "secret.stl"  # a mesh, so that it would load if it were read
    secret.parent.mkdir()
    shutil.copy(stl, secret)
    (meshes / "leak.stl").symlink_to(secret)
    (pkg / "package.xml").write_text(ARENA_PACKAGE)
    (pkg / "CMakeLists.txt").write_text(ARENA_CMAKELISTS)
    (pkg / "urdf" / "robot.urdf").write_text(_urdf("base.stl"))
    (pkg / "urdf" / "leak.urdf").write_text(_urdf("leak.stl"))
    return ws


def test_a_symlink_installed_workspace_loads_every_mesh_and_no_link_out_of_it(tmp_path: Path) -> None:
    ws = _workspace(tmp_path)
    build = shell(f"cd {ws} && colcon build --symlink-install", "colcon")
    assert build.wait(240) == 0, build.output
    share = ws / "install" / "turtlebot3_gazebo" / "share" / "turtlebot3_gazebo"
    assert (share / "worlds" / "turtlebot3_world.world").is_symlink()  # colcon linked, not copied
    arena = ws / "install" / "arena_description" / "share" / "arena_description"
    checks = {
        "world": share / "worlds" / "turtlebot3_world.world",
        "burger": share / "models" / "turtlebot3_burger" / "model.sdf",
        "robot": arena / "urdf" / "robot.urdf",
        "leak": arena / "urdf" / "leak.urdf",
    }
    script = " && ".join(f"echo '== {name}' && (gazelle check {path} 2>&1; true)" for name, path in checks.items())
    # the models folder on GZ_SIM_RESOURCE_PATH, as turtlebot3_world.launch.py appends it
    run = shell(
        f"cd {ws} && source install/setup.bash && export GZ_SIM_RESOURCE_PATH={share / 'models'} && {script}", "check"
    )
    assert run.wait(120) == 0, run.output
    parts = dict(p.split("\n", 1) for p in run.output.split("== ")[1:])
    for name in ("world", "burger", "robot"):
        assert "MESH_NOT_FOUND" not in parts[name] and "outside the folders" not in parts[name], parts[name]
        assert "0 errors" in parts[name], parts[name]
    assert "0 errors, 0 warnings" in parts["robot"], parts["robot"]
    assert (
        "'package://arena_description/meshes/leak.stl' is outside the folders files may be read from" in parts["leak"]
    ), parts["leak"]
