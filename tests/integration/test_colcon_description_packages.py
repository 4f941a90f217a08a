"""Issue 26: `colcon build` of ordinary ament_cmake description, gazebo and launch packages failed on
configs that only exist with a full ROS install: urdf (turtlebot3_description, husky_description),
ament_lint_auto (`ros2 pkg create`'s template, articubot_one), xacro and gazebo_ros (husky_gazebo).
Three packages of our own with those repositories' CMakeLists patterns build unchanged here."""

from __future__ import annotations

from pathlib import Path

import pytest

from .test_blog_workspace import shell

pytestmark = pytest.mark.slow

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>{name}</name><version>1.0.0</version><description>test</description>
  <maintainer email="dev@example.com">dev</maintainer><license>BSD</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  {depends}
  <test_depend>ament_lint_auto</test_depend><test_depend>ament_lint_common</test_depend>
  <export><build_type>ament_cmake</build_type></export>
</package>
"""

DESCRIPTION = """cmake_minimum_required(VERSION 3.5)
project(my_description)
find_package(ament_cmake REQUIRED)
find_package(urdf REQUIRED)
install(DIRECTORY urdf meshes DESTINATION share/${PROJECT_NAME}/)
ament_package()
"""

TEMPLATE = """cmake_minimum_required(VERSION 3.8)
project(my_bot)
if(CMAKE_COMPILER_IS_GNUCXX OR CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  add_compile_options(-Wall -Wextra -Wpedantic)
endif()
find_package(ament_cmake REQUIRED)
install(DIRECTORY launch description config worlds DESTINATION share/${PROJECT_NAME})
if(BUILD_TESTING)
  find_package(ament_lint_auto REQUIRED)
  set(ament_cmake_copyright_FOUND TRUE)
  set(ament_cmake_cpplint_FOUND TRUE)
  ament_lint_auto_find_test_dependencies()
endif()
ament_package()
"""

GAZEBO = """cmake_minimum_required(VERSION 3.5)
project(my_gazebo)
find_package(ament_cmake REQUIRED)
find_package(xacro REQUIRED)
find_package(gazebo_ros REQUIRED)
find_package(robot_state_publisher REQUIRED)
install(DIRECTORY launch worlds DESTINATION share/${PROJECT_NAME})
ament_package()
"""


def _package(src: Path, name: str, cmake: str, depends: list[str], folders: list[str]) -> None:
    pkg = src / name
    for folder in folders:
        (pkg / folder).mkdir(parents=True)
        (pkg / folder / "keep.txt").write_text(folder)
    deps = "".join(f"<depend>{d}</depend>" for d in depends)
    (pkg / "package.xml").write_text(PACKAGE_XML.format(name=name, depends=deps))
    (pkg / "CMakeLists.txt").write_text(cmake)


def test_colcon_builds_description_template_and_gazebo_packages_unchanged(tmp_path: Path) -> None:
    src = tmp_path / "ws" / "src"
    _package(src, "my_description", DESCRIPTION, ["urdf"], ["urdf", "meshes"])
    _package(src, "my_bot", TEMPLATE, ["xacro", "robot_state_publisher"], ["launch", "description", "config", "worlds"])
    _package(src, "my_gazebo", GAZEBO, ["xacro", "gazebo_ros", "robot_state_publisher"], ["launch", "worlds"])
    ws = tmp_path / "ws"
    build = shell(f"cd {ws} && colcon build --event-handlers console_direct+", "colcon")
    assert build.wait(300) == 0, build.output
    for pkg, folder in (("my_description", "urdf"), ("my_bot", "worlds"), ("my_gazebo", "launch")):
        assert (ws / "install" / pkg / "share" / pkg / folder / "keep.txt").is_file(), pkg
    log = (ws / "log" / "latest_build" / "my_bot" / "stdout_stderr.log").read_text()
    assert "lint tests are skipped" in log, log
