"""The Python that bring-ups import beside launch itself: ``launch.utilities``, ``nav2_common.launch``
(RewrittenYaml, ReplaceString, ParseMultiRobotPose, HasNodeParams) and ``ros2run.api``. One missing module
aborted the whole launch at its import; a Nav2-style bring-up now runs unchanged."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from .test_launch import prefix, ros2, write  # noqa: F401 - prefix: the fixture

NAV2_PARAMS = """\
amcl:
  ros__parameters:
    use_sim_time: False
    base_frame_id: "base_footprint"
    scan_topic: scan
bt_navigator:
  ros__parameters:
    use_sim_time: False
    global_frame: map
local_costmap:
  local_costmap:
    ros__parameters:
      use_sim_time: False
      plugins: ["voxel_layer", "inflation_layer"]
      voxel_layer:
        observation_sources: scan
        scan:
          topic: <robot_namespace>/scan
"""

# in the style of nav2_bringup Jazzy's bringup_launch.py and navigation_launch.py, and of launch files that
# run a package's executable themselves
BRINGUP = """
import json
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo, OpaqueFunction
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions
from launch_ros.actions import Node
from launch_ros.descriptions import ParameterFile
from launch_ros.substitutions import FindPackageShare
from nav2_common.launch import HasNodeParams, ParseMultiRobotPose, ReplaceString, RewrittenYaml
from ros2run.api import get_executable_path


def opaque(context):
    ns = perform_substitutions(context, normalize_to_list_of_substitutions(LaunchConfiguration("namespace")))
    return [LogInfo(msg="opaque namespace " + ns)]


def generate_launch_description():
    namespace = LaunchConfiguration("namespace")
    robots = ParseMultiRobotPose("robots").value()
    params_file = PathJoinSubstitution([FindPackageShare("demo_pkg"), "config", "nav2_params.yaml"])
    params_file = ReplaceString(source_file=params_file, replacements={"<robot_namespace>": ("/", namespace)},
                                condition=IfCondition(LaunchConfiguration("use_namespace")))
    configured = ParameterFile(RewrittenYaml(
        source_file=params_file, root_key=namespace, convert_types=True,
        param_rewrites={"use_sim_time": LaunchConfiguration("use_sim_time"), "autostart": "true",
                        "amcl.ros__parameters.base_frame_id": "base_link",
                        "bt_navigator.ros__parameters.server_timeout": "20",
                        "local_costmap.local_costmap.ros__parameters.plugins.1": "obstacle_layer"},
        key_rewrites={"scan_topic": "laser_topic"}), allow_substs=True)
    return LaunchDescription([
        DeclareLaunchArgument("namespace", default_value=""),
        DeclareLaunchArgument("use_namespace", default_value="false"),
        DeclareLaunchArgument("use_sim_time", default_value="false"),
        DeclareLaunchArgument("robots", default_value=""),
        LogInfo(msg="robots " + json.dumps(robots, sort_keys=True)),
        LogInfo(msg="echo at " + str(get_executable_path(package_name="demo_pkg", executable_name="echo_args"))),
        LogInfo(msg=["has amcl ", HasNodeParams(source_file=params_file, node_name="amcl"),
                     " has planner ", HasNodeParams(source_file=params_file, node_name="planner_server")]),
        OpaqueFunction(function=opaque),
        Node(package="demo_pkg", executable="echo_args", name="nav", parameters=[configured], output="screen"),
    ])
"""


def _params_of(text: str) -> dict:
    line = next(x for x in text.splitlines() if "PARAMS " in x)
    return yaml.safe_load(line.split("PARAMS ", 1)[1].replace("|", "\n"))


def test_a_nav2_style_bringup_runs_with_its_rewritten_parameters(prefix: Path) -> None:
    (prefix / "share" / "demo_pkg" / "config").mkdir()
    (prefix / "share" / "demo_pkg" / "config" / "nav2_params.yaml").write_text(NAV2_PARAMS)
    write(prefix / "share" / "demo_pkg" / "launch" / "bringup.launch.py", BRINGUP)
    robots = "robots:=r1={x: 1.0, y: 2.0};r2={yaw: 1.57};junk"
    args = ["launch", "demo_pkg", "bringup.launch.py", "namespace:=r1", "use_namespace:=true", "use_sim_time:=True"]
    out = ros2([*args, robots], prefix)
    text = out.stdout + out.stderr
    assert out.returncode == 0, text
    pose = {"roll": 0.0, "pitch": 0.0, "z": 0.0}
    expected = {"r1": {**pose, "x": 1.0, "y": 2.0, "yaw": 0.0}, "r2": {**pose, "x": 0.0, "y": 0.0, "yaw": 1.57}}
    line = next(x for x in text.splitlines() if "robots " in x)
    assert yaml.safe_load(line.split("robots ", 1)[1]) == expected
    assert f"echo at {prefix / 'lib' / 'demo_pkg' / 'echo_args'}" in text
    assert "has amcl True has planner False" in text
    assert "opaque namespace r1" in text
    params = _params_of(text)
    assert list(params) == ["r1"]  # root_key: the namespace
    p = params["r1"]
    assert p["amcl"]["ros__parameters"] == {"use_sim_time": True, "base_frame_id": "base_link", "laser_topic": "scan"}
    assert p["bt_navigator"]["ros__parameters"] == {"use_sim_time": True, "global_frame": "map", "server_timeout": 20}
    costmap = p["local_costmap"]["local_costmap"]["ros__parameters"]
    assert costmap["use_sim_time"] is True
    assert costmap["plugins"] == ["voxel_layer", "obstacle_layer"]
    assert costmap["voxel_layer"]["scan"]["topic"] == "/r1/scan"  # ReplaceString's ("/", namespace)
    assert "autostart" not in yaml.safe_dump(p)  # a plain name that is nowhere in the file is not added


def test_without_its_condition_replace_string_is_the_file_itself(prefix: Path) -> None:
    (prefix / "share" / "demo_pkg" / "config").mkdir()
    (prefix / "share" / "demo_pkg" / "config" / "nav2_params.yaml").write_text(NAV2_PARAMS)
    write(prefix / "share" / "demo_pkg" / "launch" / "bringup.launch.py", BRINGUP)
    out = ros2(["launch", "demo_pkg", "bringup.launch.py"], prefix)
    text = out.stdout + out.stderr
    assert out.returncode == 0, text
    params = _params_of(text)
    assert "<robot_namespace>/scan" in yaml.safe_dump(params)  # use_namespace false: nothing replaced
    assert "amcl" in params  # an empty root_key: no wrapping
    assert "robots {}" in text


def test_a_missing_parameter_file_is_one_line_naming_it(prefix: Path) -> None:
    write(prefix / "share" / "demo_pkg" / "launch" / "bringup.launch.py", BRINGUP)
    out = ros2(["launch", "demo_pkg", "bringup.launch.py"], prefix)
    text = out.stdout + out.stderr
    assert out.returncode != 0
    assert "Traceback" not in text
    assert "RewrittenYaml: cannot read '" in text or "HasNodeParams: cannot read '" in text
    assert "nav2_params.yaml': No such file or directory" in text


def test_parse_multi_robot_pose_says_which_robot_is_not_a_pose() -> None:
    from nav2_common.launch import ParseMultiRobotPose

    with pytest.raises(ValueError, match=r"robots: robot 'r2': '\[1, 2\]' is not a pose"):
        ParseMultiRobotPose("robots", argv=["launch", "f.py", "robots:=r1={x: 1};r2=[1, 2]"]).value()
    assert ParseMultiRobotPose("robots", argv=["launch", "f.py"]).value() == {}


def test_launch_utilities_as_launch_has_them() -> None:
    import launch
    from launch.actions import LogInfo
    from launch.substitutions import TextSubstitution
    from launch.utilities import (
        ensure_argument_type,
        is_a,
        is_a_subclass,
        normalize_to_list_of_entities,
        normalize_to_list_of_substitutions,
        perform_substitutions,
    )

    subs = normalize_to_list_of_substitutions(["a", TextSubstitution(text="b")])
    assert perform_substitutions(launch.LaunchContext(), subs) == "ab"
    assert launch.utilities.perform_substitutions is perform_substitutions  # after `import launch` alone
    ensure_argument_type("x", [str, int], "name")
    with pytest.raises(TypeError, match=r"^'Node' expected 'name' to be one of \[<class 'str'>\], but got '1'"):
        ensure_argument_type(1, str, "name", "Node")
    log = LogInfo(msg="m")
    assert normalize_to_list_of_entities([log, [log, log]]) == [log, log, log]
    assert is_a(log, LogInfo) and is_a_subclass(LogInfo, launch.Action) and not is_a_subclass(3, launch.Action)


def test_ros2run_api_finds_and_runs_a_packages_executable(prefix: Path) -> None:
    """ros2cli Jazzy's ros2run/api: None for a name the package lacks, PackageNotFound for no package,
    MultipleExecutables for one name in two sub-folders, and run_executable's status and failure line."""
    (prefix / "lib" / "demo_pkg" / "tools").mkdir()
    twin = prefix / "lib" / "demo_pkg" / "tools" / "twin"
    for path in (twin, prefix / "lib" / "demo_pkg" / "twin"):
        path.write_text("#!/bin/sh\nexit 4\n")
        path.chmod(0o755)
    code = f"""
import sys
from ros2run.api import MultipleExecutables, get_executable_path, run_executable
from ros2pkg.api import PackageNotFound
print(get_executable_path(package_name="demo_pkg", executable_name="echo_args"))
print(get_executable_path(package_name="demo_pkg", executable_name="nope"))
try:
    get_executable_path(package_name="no_such_pkg", executable_name="x")
except PackageNotFound as err:
    print("not found", err.package_name)
try:
    get_executable_path(package_name="demo_pkg", executable_name="twin")
except MultipleExecutables as err:
    print("several", len(err.paths))
print("status", run_executable(path={str(twin)!r}, argv=[]))
"""
    env = dict(os.environ, AMENT_PREFIX_PATH=f"{prefix}{os.pathsep}{sys.prefix}")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=60)
    assert out.returncode == 0, out.stderr
    assert out.stdout.splitlines() == [
        str(prefix / "lib" / "demo_pkg" / "echo_args"),
        "None",
        "not found no_such_pkg",
        "several 2",
        "[ros2run]: Process exited with failure 4",
        "status 4",
    ]
