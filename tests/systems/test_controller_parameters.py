"""A controller's own node's parameters (issue 50 item 5), in-process: what the node holds (ros2_control's base
parameters, the YAML's values, the defaults the controller read) and what setting one does: refused where
ros2_control refuses it (read-only, another type, not declared), else the controller's from its next configure, and
at once for the JTC's tolerances, as its ``update()`` reads them again. gazelle's controllers had no such node."""

from __future__ import annotations

import pytest
from _paths import REAL
from _sim import new_simulation

from gazelle.description import load
from gazelle.systems.ros2_control import ControlError, ControllerManager, ControllerParameters, load_params

DIFFBOT = REAL / "ros2_control_diffbot"
DIFFBOT_URDF = DIFFBOT / "_xacro_expanded" / "diffbot.urdf"
DIFFBOT_YAML = DIFFBOT / "ros2_control_demo_example_2" / "config" / "diffbot_controllers.yaml"


class _Components:
    """A bus listener that keeps the components announced and withdrawn."""

    def __init__(self) -> None:
        self.added: list = []
        self.removed: list = []

    def endpoint_added(self, ep, /) -> None: ...

    def endpoint_removed(self, ep, /) -> None: ...

    def component_added(self, owner, component) -> None:
        self.added.append(component)

    def component_removed(self, component) -> None:
        self.removed.append(component)


@pytest.fixture
def diffbot():
    sim = new_simulation()
    entity = sim.spawn(load(DIFFBOT_URDF).model, name="diffbot")
    cm = next(s for s in entity.systems if isinstance(s, ControllerManager))
    cm.files.append(load_params(DIFFBOT_YAML))
    seen = _Components()
    sim.bus.add_listener(seen)
    for n in ("joint_state_broadcaster", "diffbot_base_controller"):
        cm.load_controller(n)
        cm.configure_controller(n)
    cm.switch_controller(["joint_state_broadcaster", "diffbot_base_controller"], [])
    nodes = {c.name: c for c in seen.added if isinstance(c, ControllerParameters)}
    return sim, cm, nodes, seen


def test_each_loaded_controller_announces_its_nodes_parameters(diffbot):
    sim, cm, nodes, seen = diffbot
    assert set(nodes) == {"joint_state_broadcaster", "diffbot_base_controller"}
    values = nodes["diffbot_base_controller"].values()
    assert values["wheel_separation"] == 0.10  # the YAML's
    assert values["tf_frame_prefix_enable"] is True  # a default it read, the YAML silent
    assert (values["update_rate"], values["is_async"], values["thread_priority"]) == (cm.update_rate, False, -100)
    assert "type" not in values  # the manager's, not a parameter of the node


def test_a_parameter_set_on_the_node_is_read_at_the_next_configure_and_refusals_name_why(diffbot):
    sim, cm, nodes, seen = diffbot
    node = nodes["diffbot_base_controller"]
    ctrl = cm.controllers["diffbot_base_controller"].controller
    node.set({"wheel_separation": 0.2})
    assert node.values()["wheel_separation"] == 0.2
    assert ctrl.separation == pytest.approx(0.10)  # read in on_configure, as diff_drive_controller reads it
    cm.switch_controller([], ["diffbot_base_controller"])
    cm.configure_controller("diffbot_base_controller")
    assert ctrl.separation == pytest.approx(0.2)
    node.set({"wheel_radius": 1})  # an integer for a double is taken as the double
    assert node.values()["wheel_radius"] == 1.0 and isinstance(node.values()["wheel_radius"], float)
    with pytest.raises(ControlError, match="'wheel_separation' is a double; a string cannot be set"):
        node.set({"wheel_separation": "wide"})
    with pytest.raises(ControlError, match="'no_such' is not declared"):
        node.set({"no_such": 1.0})
    with pytest.raises(ControlError, match="'joints' cannot be set: it is read-only"):
        nodes["joint_state_broadcaster"].set({"joints": ["left_wheel_joint"]})
    assert node.values()["wheel_separation"] == 0.2  # a refused set changed nothing


def test_unloading_withdraws_the_node_and_forgets_what_was_set(diffbot):
    sim, cm, nodes, seen = diffbot
    nodes["diffbot_base_controller"].set({"wheel_separation": 0.3})
    cm.switch_controller([], ["diffbot_base_controller"])
    cm.unload_controller("diffbot_base_controller")
    assert nodes["diffbot_base_controller"] in seen.removed
    cm.load_controller("diffbot_base_controller")
    cm.configure_controller("diffbot_base_controller")
    assert cm.controllers["diffbot_base_controller"].controller.separation == pytest.approx(0.10)
