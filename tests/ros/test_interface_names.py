"""The one checked resolver from a type name to a class (:func:`gazelle.ros.resolve_interface`, issue 48):
rosidl's name rules, a package the ament index lists as an interface package, and only its ``msg``,
``srv`` or ``action`` module imported. Every other way in (the Foxglove bridge's ``message_class``, the
schema text of ``message_definition``, the ros_gz bridge stand-in's YAML types) goes through it."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from _planted import PAYLOADS, imported, plant

from gazelle.ros import InterfaceError, interface_file, message_class, message_definition, resolve_interface
from gazelle.ros._gz_compat import _message_class as bridge_message_class


@pytest.fixture
def planted(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """The planted packages first on ``sys.path`` (the real ``venv`` and ``unittest`` set aside for the test,
    so that an import would reach the planted ones); their markers' folder."""
    path, markers = plant(tmp_path / "planted")
    monkeypatch.syspath_prepend(str(path))
    for name in ("venv", "unittest", "gz_planted"):
        for module in [m for m in sys.modules if m == name or m.startswith(f"{name}.")]:
            monkeypatch.delitem(sys.modules, module)
    return markers


@pytest.mark.parametrize("payload", PAYLOADS)
def test_every_way_from_a_name_to_a_class_refuses_a_crafted_name_and_imports_nothing(planted: Path, payload: str):
    for resolve in (resolve_interface, message_class, message_definition, interface_file, bridge_message_class):
        with pytest.raises(InterfaceError) as err:
            resolve(payload)
        assert repr(payload) in str(err.value) and "\n" not in str(err.value), str(err.value)
    for kind in ("srv", "action"):
        with pytest.raises(InterfaceError):
            resolve_interface(payload, kind)
    assert imported(planted) == []


@pytest.mark.parametrize(
    ("name", "kind", "why"),
    [
        ("std_msgs/msg/String/Extra", "msg", "expected pkg/msg|srv|action/Name"),
        ("std_msgs", "msg", "expected pkg/msg|srv|action/Name"),
        ("Std_msgs/msg/String", "msg", "is not a ROS package name"),
        ("std__msgs/msg/String", "msg", "is not a ROS package name"),
        ("std_msgs_/msg/String", "msg", "is not a ROS package name"),
        ("std_msgs\n/msg/String", "msg", "is not a ROS package name"),
        ("std_msgs/msg/string", "msg", "is not the name of a msg type"),
        ("std_msgs/msg/String_", "msg", "is not the name of a msg type"),
        ("std_msgs/msg/String_Request", "msg", "is not the name of a msg type"),
        ("std_srvs/srv/SetBool", "msg", "'SetBool' is not the name of a msg type derived from a srv"),
        ("std_msgs/msg/String", "srv", "is not the name of a srv type derived from a msg"),
        ("std_msgs/msg/Nope", "msg", "std_msgs has no msg Nope"),
        ("no_such_msgs/msg/Nope", "msg", "'no_such_msgs' is not an interface package in the ament index"),
        ("rclpy/msg/Nope", "msg", "'rclpy' is not an interface package in the ament index"),
        ("std_msgs/msg/" + "A" * 300, "msg", "of at most 256 characters"),
    ],
)
def test_names_that_break_a_rule_are_one_line_saying_which(name: str, kind: str, why: str) -> None:
    with pytest.raises(InterfaceError) as err:
        resolve_interface(name, kind)
    text = str(err.value)
    assert why in text and "\n" not in text and len(text) < 600, text


def test_the_names_ros2cli_takes_still_resolve() -> None:
    """``pkg/msg/Name`` and ``pkg/Name``; a service's request, response and event and an action's goal,
    feedback message and send-goal service (the types of an action's and a service's hidden topics and
    services), each only by rosidl's suffixes."""
    from control_msgs.action import GripperCommand
    from std_msgs.msg import String
    from std_srvs.srv import SetBool

    assert resolve_interface("std_msgs/msg/String") is String
    assert resolve_interface("std_msgs/String") is String
    assert resolve_interface("std_srvs/srv/SetBool", "srv") is SetBool
    assert resolve_interface("std_srvs/SetBool", "srv") is SetBool
    assert resolve_interface("std_srvs/srv/SetBool_Event") is SetBool.Event
    assert resolve_interface("std_srvs/srv/SetBool_Request") is SetBool.Request
    assert resolve_interface("control_msgs/action/GripperCommand", "action") is GripperCommand
    assert resolve_interface("control_msgs/action/GripperCommand_Goal") is GripperCommand.Goal
    assert (
        resolve_interface("control_msgs/action/GripperCommand_FeedbackMessage") is GripperCommand.Impl.FeedbackMessage
    )
    assert (
        resolve_interface("control_msgs/action/GripperCommand_SendGoal", "srv") is GripperCommand.Impl.SendGoalService
    )
    assert resolve_interface("control_msgs/action/GripperCommand_SendGoal_Request").__name__.endswith("_Request")
    assert interface_file("std_srvs/srv/SetBool").endswith("share/std_srvs/srv/SetBool.srv")


def test_a_package_the_ament_index_lists_is_imported_as_its_kind_module_only(
    tmp_path: Path, planted: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The index decides which packages are interfaces: listed under a prefix of AMENT_PREFIX_PATH, the
    planted ``gz_planted`` resolves (its ``msg`` module imported, which imports its package), and its
    ``__main__`` is still never imported."""
    prefix = tmp_path / "prefix"
    resource = prefix / "share" / "ament_index" / "resource_index" / "rosidl_interfaces" / "gz_planted"
    resource.parent.mkdir(parents=True)
    resource.write_text("msg/Clock.msg\nmsg/Clock.idl\n")
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(prefix))
    with pytest.raises(InterfaceError, match="'__main__' is not msg, srv or action"):
        resolve_interface("gz_planted/__main__/Clock")
    with pytest.raises(InterfaceError, match="gz_planted has no msg Other"):
        resolve_interface("gz_planted/msg/Other")
    assert imported(planted) == []
    with pytest.raises(InterfaceError, match="gz_planted.msg has no Clock"):  # a plain class, not generated
        resolve_interface("gz_planted/msg/Clock")
    assert imported(planted) == ["gz_planted.__init__", "gz_planted.msg.__init__"]
