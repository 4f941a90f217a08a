"""xacro loading: the real xacro package, $(find) through our resolver, errors located in included files."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
import xacro
import xacro.substitution_args as xacro_subst
from _paths import REAL, TEST_DATA

from description.test_urdf import _fuzz, formatted
from gazelle.description import Mesh, Model, ModelLoadError, ResourceResolver, load, load_string

DATA = TEST_DATA / "urdf"
XACRO = DATA / "xacro"

SEED_ROBOT = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="simple_robot">
  <xacro:property name="PI" value="3.1415926535897931"/>
  <xacro:property name="robot_width" value="0.3"/>
  <xacro:property name="robot_length" value="0.3"/>
  <xacro:property name="robot_height" value="0.1"/>
  <xacro:property name="wheel_radius" value="0.05"/>
  <xacro:property name="wheel_width" value="0.04"/>
  <material name="blue"><color rgba="0 0 1 1"/></material>
  <material name="black"><color rgba="0 0 0 1"/></material>
  <link name="base_link">
    <visual><geometry><box size="${robot_length} ${robot_width} ${robot_height}"/></geometry><material name="blue"/></visual>
    <collision><geometry><box size="${robot_length} ${robot_width} ${robot_height}"/></geometry></collision>
    <inertial><mass value="1.0"/><inertia ixx="0.0083" ixy="0" ixz="0" iyy="0.0083" iyz="0" izz="0.015"/></inertial>
  </link>
  <xacro:macro name="wheel" params="side y">
    <link name="${side}_wheel">
      <visual><geometry><cylinder radius="${wheel_radius}" length="${wheel_width}"/></geometry><material name="black"/></visual>
      <collision><geometry><cylinder radius="${wheel_radius}" length="${wheel_width}"/></geometry></collision>
      <inertial><mass value="0.1"/><inertia ixx="0.0001" ixy="0" ixz="0" iyy="0.0001" iyz="0" izz="0.000125"/></inertial>
    </link>
    <joint name="base_${side}_wheel_joint" type="continuous">
      <parent link="base_link"/><child link="${side}_wheel"/>
      <origin xyz="0 ${y} 0" rpy="${PI/2} 0 0"/><axis xyz="0 0 1"/>
    </joint>
  </xacro:macro>
  <xacro:wheel side="left" y="${robot_width/2 + wheel_width/2}"/>
  <xacro:wheel side="right" y="${-(robot_width/2 + wheel_width/2)}"/>
  <gazebo>
    <plugin name="differential_drive" filename="libgazebo_ros_diff_drive.so">
      <left_joint>base_left_wheel_joint</left_joint><right_joint>base_right_wheel_joint</right_joint>
      <wheel_separation>0.34</wheel_separation><wheel_diameter>0.1</wheel_diameter>
      <publish_odom>true</publish_odom><publish_odom_tf>true</publish_odom_tf>
      <odometry_frame>odom</odometry_frame><robot_base_frame>base_link</robot_base_frame>
    </plugin>
  </gazebo>
</robot>
"""


def test_seed_robot_loads() -> None:
    result = load_string(SEED_ROBOT, source="<seed>.urdf.xacro", expand_xacro=True)
    model = result.value
    assert isinstance(model, Model)
    assert result.diagnostics == ()
    assert [lk.name for lk in model.links] == ["base_link", "left_wheel", "right_wheel"]
    assert [j.type.value for j in model.joints] == ["continuous", "continuous"]
    for joint in model.joints:
        assert joint.origin.rpy == pytest.approx((math.pi / 2, 0.0, 0.0))
        assert joint.axis is not None and joint.axis.xyz == (0.0, 0.0, 1.0)
    assert model.joint("base_left_wheel_joint").origin.position == pytest.approx((0.0, 0.17, 0.0))
    (plugin,) = model.plugins
    assert plugin.filename == "libgazebo_ros_diff_drive.so" and plugin.name == "differential_drive"
    assert plugin.config.find("left_joint").text == "base_left_wheel_joint"  # type: ignore[union-attr]
    assert [c.tag for c in plugin.config.children][:2] == ["left_joint", "right_joint"]
    assert plugin.config.attr("filename") == "libgazebo_ros_diff_drive.so"
    assert "gazelle_source" not in dict(plugin.config.attributes)
    material = model.link("base_link").visuals[0].material
    assert material is not None and material.name == "blue" and material.diffuse == (0.0, 0.0, 1.0, 1.0)
    # elements expanded from the macro point at the macro's lines
    assert model.link("left_wheel").location.line == 17  # type: ignore[union-attr]
    assert model.joint("base_right_wheel_joint").location.line == 22  # type: ignore[union-attr]
    assert plugin.location is not None and plugin.location.line == 30


# --------------------------------------------------------------------------- real robots
_REAL_CASES = [
    ("turtlebot3", "turtlebot3_description/urdf/turtlebot3_burger.urdf.xacro", 7, 6, set()),
    ("turtlebot3", "turtlebot3_description/urdf/turtlebot3_burger.urdf", 7, 6, set()),
    # Panda's <dynamics> carries Franka's D/K/mu_coulomb/mu_viscous, which gazelle ignores
    ("moveit_panda", "moveit_resources_panda_description/urdf/panda.urdf.xacro", 12, 11, {"ATTRIBUTE_UNSUPPORTED"}),
    (
        "moveit_panda",
        "moveit_resources_panda_moveit_config/config/panda.urdf.xacro",
        12,
        11,
        {"ATTRIBUTE_UNSUPPORTED"},
    ),
    (
        "moveit_panda",
        "dual_arm_panda_moveit_config/config/panda.urdf.xacro",
        25,
        24,
        {"INERTIA_MISSING"},
    ),
    ("ros2_control_diffbot", "ros2_control_demo_example_2/urdf/diffbot.urdf.xacro", 5, 4, set()),
    ("ros2_control_r6bot", "ros2_control_demo_example_7/urdf/r6bot.urdf.xacro", 10, 9, set()),
]


@pytest.mark.parametrize(("case", "path", "n_links", "n_joints", "warning_codes"), _REAL_CASES)
def test_real_robot_loads_through_xacro(
    monkeypatch: pytest.MonkeyPatch, case: str, path: str, n_links: int, n_joints: int, warning_codes: set[str]
) -> None:
    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", str(REAL / case))
    file = REAL / case / path
    # turtlebot3_burger.urdf is xacro in disguise (xacro:arg, ${namespace}): load it as xacro
    result = load_string(file.read_text(), format="xacro", source=str(file), expand_xacro=True)
    model = result.value
    assert isinstance(model, Model)
    assert (len(model.links), len(model.joints)) == (n_links, n_joints)
    assert {d.code.value for d in result.diagnostics} == warning_codes, formatted(result.diagnostics)
    meshes = [g.geometry for lk in model.links for g in (*lk.visuals, *lk.collisions) if isinstance(g.geometry, Mesh)]
    assert all(m.path is not None and Path(m.path).is_file() for m in meshes)


def test_ros2_control_location_points_into_included_file(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", str(REAL / "ros2_control_diffbot"))
    result = load(REAL / "ros2_control_diffbot/ros2_control_demo_example_2/urdf/diffbot.urdf.xacro")
    (rc,) = result.model.ros2_control
    assert rc.location is not None and rc.location.line == 6
    assert str(rc.location.file).endswith("diffbot.ros2_control.xacro")


def test_turtlebot3_gazebo_blocks_are_applied(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", str(REAL / "turtlebot3"))
    model = load(REAL / "turtlebot3/turtlebot3_description/urdf/turtlebot3_burger.urdf.xacro").value
    assert isinstance(model, Model)
    assert len(model.gazebo) == 8
    wheel = model.link("wheel_left_link")
    assert wheel.collisions[0].surface.mu == 0.1 and wheel.collisions[0].surface.kp == 500000.0
    assert [s.type for s in model.link("imu_link").sensors] == ["imu"]
    (lidar,) = model.link("base_scan").sensors
    assert lidar.update_rate_hz == 5 and [p.filename for p in lidar.plugins] == ["libgazebo_ros_laser.so"]
    assert {p.filename for p in model.plugins} == {"libgazebo_ros_diff_drive.so", "libgazebo_ros_imu.so"}
    assert model.link("base_footprint").inertial is None


def test_args_override_xacro_arg_defaults() -> None:
    result = load(XACRO / "packages.urdf.xacro", args={"prefix": "my_"}, resolver=ResourceResolver([DATA / "packages"]))
    model = result.value
    assert isinstance(model, Model)
    (link,) = model.links
    assert link.name == "my_base"
    mesh = link.visuals[0].geometry
    assert isinstance(mesh, Mesh) and mesh.path == str((DATA / "packages/gazelle_test_pkg/meshes/cube.stl").resolve())
    assert link.collisions[0].geometry.path == mesh.path  # type: ignore[union-attr]
    # the derived-inertia warning points into the package's macro file
    assert "gazelle_test_pkg/urdf/parts.xacro:4: warning: [INERTIA_MISSING] link 'my_base'" in formatted(
        result.diagnostics
    )


# --------------------------------------------------------------------------- errors
@pytest.mark.parametrize(
    ("name", "expected"),
    [
        (
            "included_undefined_property.urdf.xacro",
            "inc/undefined_property.xacro:5: error: [XACRO_ERROR] xacro: name 'QQQ_undefined' is not defined",
        ),
        (
            "missing_include.urdf.xacro",
            "missing_include.urdf.xacro:5: error: [XACRO_ERROR] xacro: No such file or directory: ",
        ),
        (
            "macro_error.urdf.xacro",
            "inc/macros.xacro:6: error: [XACRO_ERROR] xacro: ZeroDivisionError: division by zero (when evaluating expression '1 / 0') (in macro 'leg')",
        ),
        (
            "included_urdf_error.urdf.xacro",
            "inc/bad_joint.xacro:5: error: [JOINT_PARENT_INVALID] joint 'shoulder' has unknown parent link 'base_QQQ'",
        ),
        ("included_malformed.urdf.xacro", "inc/malformed.xacro:4: error: [XML_PARSE_ERROR] malformed XML"),
        (
            "unknown_package.urdf.xacro",
            "unknown_package.urdf.xacro:4: error: [XACRO_ERROR] xacro: package 'QQQ_no_such_pkg' not found",
        ),
    ],
)
def test_xacro_error_names_file_and_line(name: str, expected: str) -> None:
    with pytest.raises(ModelLoadError) as info:
        load(XACRO / name, resolver=ResourceResolver(env={}))
    text = formatted(info.value.diagnostics)
    assert expected in text
    assert text.count("error:") == 1, text


def test_undefined_arg_is_a_xacro_error() -> None:
    text = '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n<link name="$(arg QQQ)"/></robot>'
    with pytest.raises(ModelLoadError) as info:
        load_string(text, expand_xacro=True)
    assert "<string>.xacro:2: error: [XACRO_ERROR] xacro: Undefined substitution argument QQQ" in formatted(
        info.value.diagnostics
    )


def test_xacro_globals_are_restored() -> None:
    # the in-process expansion (what the bounded child runs) restores xacro's module globals
    from gazelle.description import DiagnosticSink
    from gazelle.description._xacro import expand

    before = (xacro_subst._eval_find, xacro_subst._eval_dict["find"], xacro.parse, xacro.eval_all, xacro.warning)
    bad = XACRO / "macro_error.urdf.xacro"
    assert expand(bad.read_text(), source=str(bad), args={}, sink=DiagnosticSink(), resolver=ResourceResolver()) is None
    assert expand(SEED_ROBOT, "<seed>.xacro", {}, sink=DiagnosticSink(), resolver=ResourceResolver()) is not None
    after = (xacro_subst._eval_find, xacro_subst._eval_dict["find"], xacro.parse, xacro.eval_all, xacro.warning)
    assert before == after
    assert xacro.substitution_args_context.get("arg") == {}


def test_fuzzed_xacro_only_raises_model_load_error() -> None:
    _fuzz(SEED_ROBOT, "xacro", seed=3, rounds=300)
    urdf = (REAL / "turtlebot3/turtlebot3_description/urdf/turtlebot3_burger.urdf").read_text()
    _fuzz(urdf, "xacro", seed=4, rounds=200)


def test_the_venvs_xacro_command_finds_packages_on_gazelle_resource_path(tmp_path):
    """Issue 27 item 12: `xacro robot.urdf.xacro` in the venv found `$(find pkg)` through the ament index only,
    where `gazelle spawn -file` also reads GAZELLE_RESOURCE_PATH: a moveit_resources clone on it failed with
    "package not found". The venv's xacro now finds packages there too, by their package.xml name."""
    import os
    import subprocess
    import sys
    from pathlib import Path

    pkg = tmp_path / "clones" / "panda_moveit_config"  # the folder's name is not the package's
    (pkg / "config").mkdir(parents=True)
    (pkg / "package.xml").write_text(
        '<?xml version="1.0"?><package format="3"><name>moveit_resources_panda_moveit_config</name>'
        "<version>1.0.0</version><description>d</description><maintainer email='a@b.c'>a</maintainer>"
        "<license>BSD</license></package>"
    )
    (pkg / "config" / "part.xacro").write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="from_the_package"/></robot>'
    )
    top = tmp_path / "robot.urdf.xacro"
    top.write_text(
        '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
        '<xacro:include filename="$(find moveit_resources_panda_moveit_config)/config/part.xacro"/></robot>'
    )
    env = {k: v for k, v in os.environ.items() if k != "AMENT_PREFIX_PATH"}
    env["GAZELLE_RESOURCE_PATH"] = str(tmp_path / "clones")
    out = subprocess.run(
        [str(Path(sys.prefix) / "bin" / "xacro"), str(top)], capture_output=True, text=True, env=env, timeout=60
    )
    assert out.returncode == 0, out.stderr
    assert '<link name="from_the_package"/>' in out.stdout
    # a package that is nowhere gets xacro's own error, not a traceback of gazelle's
    top.write_text('<robot name="r"><link name="$(find no_such_package)"/></robot>')
    out = subprocess.run(
        [str(Path(sys.prefix) / "bin" / "xacro"), str(top)], capture_output=True, text=True, env=env, timeout=60
    )
    assert out.returncode != 0 and "no_such_package" in out.stderr and "Traceback" not in out.stderr, out.stderr
