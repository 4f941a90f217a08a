"""controller_manager's ``ros2_control_node`` as a stand-in (the real one is C++ and not on PyPI): it runs the robot's
controller manager in the simulation, with the robot_description and the parameters files it is given.

MoveIt's demo launch files (``generate_demo_launch``, moveit_resources' demo.launch.py) start it with
``ros2_controllers.yaml`` as its parameters and ``/controller_manager/robot_description`` remapped to
``/robot_description`` (robot_state_publisher's latched topic), and ros2_control Jazzy's node takes the URDF from
that topic (controller_manager.cpp ``robot_description_callback``) and runs the ``<ros2_control>`` hardware the URDF
names (there: mock_components/GenericSystem). Here the robot runs in gazelle instead:

* the URDF comes from that topic (the remap applies), else from a ``robot_description`` in the parameters files;
* a gazelle server already running (its ``/spawn_entity``) is used, else one is started (``gazelle sim
  --no-viewer``, stopped with this node);
* the robot is spawned as ``gazelle spawn`` spawns it, its controller manager given the parameters files in its
  plugin tag (read before it serves anything) and without gazelle's own robot_state_publisher (the launch runs
  one); a robot whose root link is not fixed to a ``world`` link is fixed there first, as MoveIt's configurations
  run it on mock hardware, which has no dynamics: the arm stays on its base (MoveIt's static transform from
  ``world`` says where the base is);
* the controller manager is ``/controller_manager`` (the spawners' default); Ctrl-C deletes the robot.
"""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from xml.sax.saxutils import escape

import rclpy
import yaml
from gazebo_msgs.srv import DeleteEntity
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from rclpy.utilities import ok, try_shutdown
from std_msgs.msg import String

from ..description import load_string
from ._rsp_node import spin_until_interrupted

WAIT_DESCRIPTION_SEC = 60.0
"""How long the robot_description may take to come (robot_state_publisher starting beside it)."""
WAIT_SERVER_SEC = 2.0
"""How long a running gazelle server has to answer before one is started: short, as the demo's spawners give the
manager 10 s (gazelle's spawner's --controller-manager-timeout; Jazzy's waits for ever) and the server must still
start and spawn the robot within them."""
ENTITY = "ros2_control_robot"


def _params_files(args: list[str]) -> list[str]:
    """The ``--params-file F`` of the ROS arguments."""
    return [args[i + 1] for i, a in enumerate(args[:-1]) if a == "--params-file"]


def _description_in(files: list[str]) -> str | None:
    """A ``robot_description`` parameter given in the parameters files (any node's section), or None."""
    for f in files:
        try:
            data = yaml.safe_load(Path(f).read_text())
        except (OSError, yaml.YAMLError):
            continue
        for section in (data or {}).values() if isinstance(data, dict) else ():
            params = section.get("ros__parameters") if isinstance(section, dict) else None
            if isinstance(params, dict) and isinstance(params.get("robot_description"), str):
                return params["robot_description"]
    return None


def prepared(urdf: str, files: list[str]) -> str:
    """The URDF as gazelle runs it for ros2_control_node: its root link fixed to a ``world`` link (unless a ``world``
    link is its root already), and, unless it names a ros2_control plugin of its own, gz_ros2_control's plugin tag
    with the parameters files, so that the manager has them when it starts, as ros2_control_node has its
    parameters before it serves anything (given after the spawn, a spawner could ask first)."""
    extra = ""
    try:
        model = load_string(urdf, format="urdf").model
    except Exception:  # a description gazelle cannot read: the spawn names what is wrong with it
        model = None
    if model is not None:
        children = {j.child for j in model.joints}
        roots = [link.name for link in model.links if link.name not in children]
        if roots and roots[0] != "world":
            extra += (
                '<link name="world"/><joint name="ros2_control_node_fixed_base" type="fixed">'
                f'<parent link="world"/><child link="{escape(roots[0])}"/></joint>'
            )
    if "ros2_control" not in "".join(re.findall(r"<plugin[^>]*>", urdf)):
        given = "".join(f"<parameters>{escape(str(Path(f).resolve()))}</parameters>" for f in files)
        extra += (
            '<gazebo><plugin filename="gz_ros2_control-system" name="gz_ros2_control::GazeboSimROS2ControlPlugin">'
            f"{given}</plugin></gazebo>"
        )
    head, sep, _tail = urdf.rpartition("</robot>")
    return head + extra + "</robot>" if sep else urdf


class Ros2ControlNode(Node):
    """Waits for the robot_description, then has gazelle run the robot and its controller manager."""

    def __init__(self) -> None:
        super().__init__("ros2_control_node_standin")
        self.description: str | None = None
        latched = QoSProfile(
            depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE
        )
        # the absolute name, so that the launch's remap of /controller_manager/robot_description applies
        self.create_subscription(String, "/controller_manager/robot_description", self._take, latched)
        self.server: subprocess.Popen | None = None

    def _take(self, msg: String) -> None:
        self.description = self.description or msg.data

    def wait_description(self, files: list[str]) -> str | None:
        given = _description_in(files)
        if given:
            return given
        deadline = time.monotonic() + WAIT_DESCRIPTION_SEC
        while self.description is None and time.monotonic() < deadline:
            rclpy.spin_once(self, timeout_sec=0.1)
        return self.description

    def ensure_server(self, gazelle: str) -> bool:
        """A gazelle server answering ``/spawn_entity``: the running one, else one this node starts."""
        from gazebo_msgs.srv import SpawnEntity

        client = self.create_client(SpawnEntity, "/spawn_entity")
        if client.wait_for_service(timeout_sec=WAIT_SERVER_SEC):
            return True
        self.get_logger().info("no gazelle server is running: starting one (gazelle sim --no-viewer)")
        self.server = subprocess.Popen([gazelle, "sim", "--no-viewer"], env=os.environ.copy())
        return client.wait_for_service(timeout_sec=120.0)


def main(argv: list[str] | None = None) -> int:
    """Run until Ctrl-C; 1 when the robot could not be brought up (the reason in one line)."""
    args = sys.argv if argv is None else argv
    ros_args = args[args.index("--ros-args") :] if "--ros-args" in args else []
    files = _params_files(ros_args)
    rclpy.init(args=args)
    node = Ros2ControlNode()
    log = node.get_logger()
    gazelle = str(Path(sys.executable).parent / "gazelle")
    urdf = node.wait_description(files)
    if urdf is None:
        log.error(f"no robot_description within {WAIT_DESCRIPTION_SEC:.0f} s (its topic, or a parameter)")
        node.destroy_node()
        try_shutdown()
        return 1
    if not node.ensure_server(gazelle):
        log.error("the gazelle server did not come up")
        return _stop(node, 1)
    with tempfile.NamedTemporaryFile("w", suffix=".urdf", delete=False) as f:
        f.write(prepared(urdf, files))
    cmd = [gazelle, "spawn", "-entity", ENTITY, "-file", f.name, "-no_robot_state_publisher"]
    spawned = subprocess.run(cmd, env=os.environ.copy(), check=False)
    os.unlink(f.name)
    if spawned.returncode != 0:
        log.error("the robot could not be spawned (gazelle spawn said why above)")
        return _stop(node, 1)
    log.info("the robot and its controller manager /controller_manager run in gazelle")
    try:
        spin_until_interrupted(node)
    finally:
        _cleanup(node)
    return 0


def _cleanup(node: Ros2ControlNode) -> None:
    """Delete the robot (when the server is still there) and stop the server this node started."""
    if not ok():
        rclpy.init()
    try:
        deleter = Node("ros2_control_node_standin_exit")
        client = deleter.create_client(DeleteEntity, "/delete_entity")
        if client.wait_for_service(timeout_sec=2.0):
            future = client.call_async(DeleteEntity.Request(name=ENTITY))
            rclpy.spin_until_future_complete(deleter, future, timeout_sec=5.0)
        deleter.destroy_node()
    finally:
        try_shutdown()
    if node.server is not None:
        node.server.send_signal(signal.SIGINT)
        try:
            node.server.wait(20)
        except subprocess.TimeoutExpired:
            node.server.kill()


def _stop(node: Ros2ControlNode, status: int) -> int:
    server = node.server
    node.destroy_node()
    try_shutdown()
    if server is not None:
        server.terminate()
        server.wait(20)
    return status
