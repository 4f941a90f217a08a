"""Issue 49 item 2: an ament_cmake package that compiles C++ against libraries a gazelle venv does not have
(rclcpp, gz-sim, Gazebo Classic, hardware_interface/pluginlib, a vendor SDK) stopped `colcon build`, and with
it the launch files, worlds and models of the whole repository.

The packages here have the CMakeLists patterns of turtlebot3_gazebo (jazzy: a rclcpp node through
target_link_libraries, gz-sim plugins through `gz-sim::gz-sim`), ros_gz_project_template's
ros_gz_example_gazebo (`gz-sim8::gz-sim8`, its version taken from `gz-sim8_VERSION_MAJOR`),
gz_ros2_control_demos (ament_target_dependencies(rclcpp rclcpp_action)), husky_base (a hardware_interface
plugin, pluginlib_export_plugin_description_file), turtlebot3 humble's Classic plugin (`${GAZEBO_LIBRARIES}`),
turtlebot3_node (dynamixel_sdk, which nothing here provides), a component (rclcpp_components_register_node)
and a library with no ROS dependency, which is still compiled for real."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from .test_blog_workspace import shell

pytestmark = pytest.mark.slow

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>{name}</name><version>1.0.0</version><description>test</description>
  <maintainer email="dev@example.com">dev</maintainer><license>BSD</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <depend>rclcpp</depend>
  <export><build_type>ament_cmake</build_type></export>
</package>
"""

SIM_CMAKE = """cmake_minimum_required(VERSION 3.8)
project(my_sim)
if(NOT CMAKE_CXX_STANDARD)
  set(CMAKE_CXX_STANDARD 17)
endif()
add_compile_options(-Wall -Wextra -Wpedantic)
find_package(ament_cmake REQUIRED)
find_package(ros_gz_sim REQUIRED)
find_package(geometry_msgs REQUIRED)
find_package(rclcpp REQUIRED)
find_package(tf2 REQUIRED)
find_package(gz-cmake3 REQUIRED)
find_package(gz-plugin2 REQUIRED COMPONENTS register)
set(GZ_PLUGIN_VER ${gz-plugin2_VERSION_MAJOR})
find_package(gz-sim8 REQUIRED)
set(GZ_SIM_VER ${gz-sim8_VERSION_MAJOR})
find_package(gz-sim REQUIRED)
find_package(gazebo REQUIRED)
find_package(gazebo_ros REQUIRED)
include_directories(include ${GAZEBO_INCLUDE_DIRS})
link_directories(${GAZEBO_LIBRARY_DIRS})

add_executable(drive src/drive.cpp)
target_link_libraries(drive ${geometry_msgs_TARGETS} rclcpp::rclcpp tf2::tf2)
add_library(obstacles SHARED src/plugin.cpp)
target_link_libraries(obstacles PUBLIC gz-sim::gz-sim)
add_library(BasicSystem SHARED src/plugin.cpp)
target_link_libraries(BasicSystem PRIVATE gz-sim${GZ_SIM_VER}::gz-sim${GZ_SIM_VER})
add_library(classic_plugin SHARED src/plugin.cpp)
target_link_libraries(classic_plugin ${GAZEBO_LIBRARIES})
ament_target_dependencies(classic_plugin rclcpp gazebo_ros)

add_library(geometry SHARED src/geometry.cpp)
add_executable(plain src/plain.cpp)
target_link_libraries(plain geometry)

install(TARGETS drive obstacles BasicSystem classic_plugin geometry plain DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch worlds models DESTINATION share/${PROJECT_NAME}/)
ament_package()
"""

ROBOT_CMAKE = """cmake_minimum_required(VERSION 3.5)
project(my_robot)
find_package(ament_cmake REQUIRED)
find_package(hardware_interface REQUIRED)
find_package(pluginlib REQUIRED)
find_package(rclcpp REQUIRED)
find_package(rclcpp_action REQUIRED)
find_package(rclcpp_components REQUIRED)
find_package(dynamixel_sdk REQUIRED)
find_package(std_msgs REQUIRED)

add_library(robot_hardware SHARED src/hardware.cpp)
target_include_directories(robot_hardware PRIVATE include)
ament_target_dependencies(robot_hardware hardware_interface pluginlib rclcpp)
pluginlib_export_plugin_description_file(hardware_interface robot_hardware.xml)

add_library(node_lib SHARED src/node.cpp)
ament_target_dependencies(node_lib rclcpp rclcpp_action std_msgs dynamixel_sdk)
add_executable(robot_node src/main.cpp)
target_link_libraries(robot_node node_lib)

add_library(component SHARED src/component.cpp)
ament_target_dependencies(component rclcpp rclcpp_components)
rclcpp_components_register_node(component PLUGIN "my_robot::Component" EXECUTABLE component_node)

install(TARGETS robot_hardware node_lib component LIBRARY DESTINATION lib RUNTIME DESTINATION lib/${PROJECT_NAME})
install(TARGETS robot_node DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})
ament_export_dependencies(hardware_interface pluginlib rclcpp)
ament_package()
"""

SOURCES = {
    "my_sim": {
        "src/drive.cpp": '#include "rclcpp/rclcpp.hpp"\nint main() { return 0; }\n',
        "src/plugin.cpp": '#include <gz/sim/System.hh>\n#include "gazebo/gazebo.hh"\n',
        "src/geometry.cpp": "int twice(int x) { return 2 * x; }\n",
        "src/plain.cpp": '#include <cstdio>\nint twice(int);\nint main() { std::printf("plain %d\\n", twice(21)); }\n',
    },
    "my_robot": {
        "src/hardware.cpp": '#include "hardware_interface/system_interface.hpp"\n',
        "src/node.cpp": '#include "dynamixel_sdk/dynamixel_sdk.h"\n',
        "src/main.cpp": "int main() { return 0; }\n",
        "src/component.cpp": '#include "rclcpp_components/register_node_macro.hpp"\n',
        "robot_hardware.xml": "<library path='robot_hardware'/>\n",
    },
}


def _workspace(root: Path) -> Path:
    for name, cmake, folders in (
        ("my_sim", SIM_CMAKE, ("launch", "worlds", "models")),
        ("my_robot", ROBOT_CMAKE, ("launch", "config")),
    ):
        pkg = root / "ws" / "src" / name
        for folder in folders:
            (pkg / folder).mkdir(parents=True)
            (pkg / folder / "keep.txt").write_text(folder)
        for rel, text in SOURCES[name].items():
            (pkg / rel).parent.mkdir(parents=True, exist_ok=True)
            (pkg / rel).write_text(text)
        (pkg / "package.xml").write_text(PACKAGE_XML.format(name=name))
        (pkg / "CMakeLists.txt").write_text(cmake)
    return root / "ws"


def test_colcon_skips_each_cpp_target_it_cannot_build_and_installs_the_rest(tmp_path: Path) -> None:
    ws = _workspace(tmp_path)
    build = shell(f"cd {ws} && colcon build --symlink-install", "colcon")
    assert build.wait(300) == 0, build.output
    assert "Summary: 2 packages finished" in build.output, build.output
    skipped = {
        "my_sim: drive ": "rclcpp, tf2",
        "my_sim: obstacles ": "gz-sim",
        "my_sim: BasicSystem ": "gz-sim8",  # the version from gz-sim8_VERSION_MAJOR, as the template's CMakeLists takes it
        "my_sim: classic_plugin ": "gazebo, rclcpp, gazebo_ros",
        "my_robot: robot_hardware ": "hardware_interface, pluginlib, rclcpp",
        "my_robot: node_lib ": "rclcpp, rclcpp_action, dynamixel_sdk",
        "my_robot: robot_node ": "node_lib (not built)",
        "my_robot: component ": "rclcpp, rclcpp_components",
        "my_robot: component_node ": "rclcpp_components, component (not built)",
    }
    lines = [line for line in build.output.splitlines() if line.startswith("gazelle: ")]
    for target, needs in skipped.items():
        said = [line for line in lines if f"gazelle: {target}is not built" in line]
        assert len(said) == 1, (target, lines)
        assert f"(it needs {needs}, not available in a gazelle venv)" in said[0], said[0]
    assert len(lines) == len(skipped), lines
    install = ws / "install"
    for pkg, folder in (("my_sim", "worlds"), ("my_sim", "models"), ("my_robot", "config")):
        assert (install / pkg / "share" / pkg / folder / "keep.txt").is_file(), (pkg, folder)
    # what needs nothing missing is compiled for real
    plain = subprocess.run([install / "my_sim" / "lib" / "my_sim" / "plain"], capture_output=True, text=True)
    assert plain.stdout == "plain 42\n", plain
    # a placeholder says what it is when run, and fails
    run = shell(f"cd {ws} && source install/setup.bash && ros2 run my_sim drive", "ros2 run")
    assert run.wait(60) == 1, run.output
    assert "gazelle: my_sim's drive is a compiled program gazelle did not build: it needs rclcpp, tf2" in run.output
