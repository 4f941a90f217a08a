"""Parameters files' node keys as rcl matches them (``/**`` zero or more namespace levels, ``/*`` exactly one),
in the one matcher every reader of such a file uses: the controller manager's files, the spawner's."""

from __future__ import annotations

import pytest
from _paths import REAL, REPO

from gazelle.description import Pose, load_string
from gazelle.systems.ros2_control import ControllerManager, parse_params, section_matches

DIFFBOT = REAL / "ros2_control_diffbot"
DIFFBOT_URDF = DIFFBOT / "_xacro_expanded" / "diffbot.urdf"
WILDCARD_YAML = REPO / "tests" / "data" / "ros2_control" / "diffbot_wildcard_controllers.yaml"


@pytest.mark.parametrize(
    ("key", "fq", "matches"),
    [
        # rclcpp parameter_map.cpp is_node_name_matched: "/*" -> one (/token), "/**" -> any number of them
        ("/**/controller_manager", "/controller_manager", True),
        ("/**/controller_manager", "/r1/controller_manager", True),
        ("/**/controller_manager", "/a/b/controller_manager", True),
        ("/**/controller_manager", "/r1/other", False),
        ("/*/controller_manager", "/controller_manager", False),
        ("/*/controller_manager", "/r1/controller_manager", True),
        ("/*/controller_manager", "/a/b/controller_manager", False),
        ("/**", "/controller_manager", True),
        ("/**", "/r1/diff", True),
        ("/*", "/diff", True),
        ("/*", "/r1/diff", False),
        ("/r1/*", "/r1/diff", True),
        ("/r1/*", "/r2/diff", False),
        ("r1/diff", "/r1/diff", True),  # a key without a leading '/' gets one
        ("/r1/diff", "/r1/diffx", False),
        ("/r1.diff", "/r1/diff", False),  # every other character stands for itself
        ("/r*", "/r1", False),  # a stray '*' is no wildcard
    ],
)
def test_section_keys_match_a_nodes_fully_qualified_name_as_rcl_does(key, fq, matches):
    namespace, _, name = fq.rpartition("/")
    assert section_matches(key, name, namespace) is matches


def test_a_name_without_a_namespace_still_applies_to_namespaced_copies():
    """gazelle's one addition to rcl: controller files written for one robot serve its namespaced copies."""
    assert section_matches("diff", "diff", "/r1")
    assert section_matches("/diff", "diff", "/r1")
    assert not section_matches("/r2/diff", "diff", "/r1")


def test_sections_merge_in_the_files_order_the_later_winning_as_rclcpp_merges_them():
    pf = parse_params(
        "/**:\n  ros__parameters: {a: 1, b: 1}\n"
        "/**/diff:\n  ros__parameters: {a: 2, c: 2}\n"
        "/r1/diff:\n  ros__parameters: {c: 3}\n"
        "/**/diff_again_later:\n  ros__parameters: {d: 4}\n"
    )
    assert pf.for_node("diff") == {"a": 2, "b": 1, "c": 2}
    assert pf.for_node("diff", "/r1") == {"a": 2, "b": 1, "c": 3}
    assert pf.for_node("diff", "r1/") == {"a": 2, "b": 1, "c": 3}


def test_the_names_a_file_spells_out_include_wildcard_namespaced_ones():
    """What ``spawn --ros-args --params-file`` hands the manager a ``params_file`` for."""
    pf = parse_params(WILDCARD_YAML.read_text())
    assert pf.names_in("") == {"controller_manager", "diffbot_base_controller"}
    assert pf.names_in("/bot") == pf.names_in("")
    two = parse_params("/r1/a:\n  ros__parameters: {x: 1}\n/*/b:\n  ros__parameters: {x: 1}\n")
    assert two.names_in("/r1") == {"a", "b"}
    assert two.names_in("") == set()


@pytest.mark.parametrize("namespace", ["", "bot"])
def test_a_controller_manager_finds_its_rate_and_the_controllers_types_under_double_star(tmp_path, make_sim, namespace):
    """The issue's bring-up: with every key under ``/**/`` and no namespace, the manager ran at 100 Hz and
    no controller had a type ("the 'type' of controller ... is not set")."""
    cfg = tmp_path / "controllers.yaml"
    cfg.write_text(WILDCARD_YAML.read_text())
    ns = f"<ros><namespace>{namespace}</namespace></ros>" if namespace else ""
    urdf = DIFFBOT_URDF.read_text().replace(
        "</robot>",
        '<gazebo><plugin filename="gz_ros2_control-system" name="gz_ros2_control::GazeboSimROS2ControlPlugin">'
        f"<parameters>{cfg}</parameters>{ns}</plugin></gazebo></robot>",
    )
    sim = make_sim()
    entity = sim.spawn(
        load_string(urdf, source=str(tmp_path / "robot.urdf")).model, name="diffbot", pose=Pose((0, 0, 0.05))
    )
    (cm,) = [s for s in entity.systems if isinstance(s, ControllerManager)]
    assert cm.update_rate == 20
    for name in ("joint_state_broadcaster", "diffbot_base_controller"):
        cm.load_controller(name)
        cm.configure_controller(name)
    cm.switch_controller(["joint_state_broadcaster", "diffbot_base_controller"], [])
    drive = cm.controllers["diffbot_base_controller"]
    assert drive.type_name == "diff_drive_controller/DiffDriveController"
    assert drive.controller.radius == pytest.approx(0.015)  # type: ignore[attr-defined] - from /**/diffbot_base_controller
    sim.step(10)
