"""The parts of a robot description about planning and control rather than bodies: an SRDF's semantics
(groups, named states, end effectors, disabled collision pairs) and a URDF's ``<ros2_control>`` blocks.
Frozen dataclasses like the rest of the model (see :mod:`._model`)."""

from __future__ import annotations

from dataclasses import dataclass

from ._diagnostics import SourceLocation


# --------------------------------------------------------------------------- semantics (SRDF)
@dataclass(frozen=True, slots=True)
class Chain:
    """SRDF ``<chain base_link tip_link>`` inside a group."""

    base_link: str
    """The chain's first link."""
    tip_link: str
    """The chain's last link (usually the tool flange)."""


@dataclass(frozen=True, slots=True)
class Group:
    """SRDF ``<group>``: the joints, links, chains and subgroups a planner moves together."""

    name: str
    """The group's name (panda_arm, hand, ...), as a MoveIt client names it."""
    links: tuple[str, ...] = ()
    """Links listed directly."""
    joints: tuple[str, ...] = ()
    """Joints listed directly."""
    chains: tuple[Chain, ...] = ()
    """Chains: every joint between each base and tip."""
    subgroups: tuple[str, ...] = ()
    """Other groups this one contains, by name."""


@dataclass(frozen=True, slots=True)
class GroupState:
    """SRDF ``<group_state>``: a named joint configuration of a group (``home``, ``ready``)."""

    name: str
    """The state's name (home, ready, open, ...)."""
    group: str
    """The group it positions."""
    joint_values: tuple[tuple[str, tuple[float, ...]], ...] = ()
    """(joint, values) pairs: one value per degree of freedom, rad or m."""


@dataclass(frozen=True, slots=True)
class EndEffector:
    """SRDF ``<end_effector>``: a group attached to a parent link (and parent group)."""

    name: str
    """The end effector's name."""
    parent_link: str
    """The link the end effector is attached to."""
    group: str
    """The group that forms the end effector (the hand)."""
    parent_group: str | None = None
    """The group the parent link belongs to (the arm), when given."""


@dataclass(frozen=True, slots=True)
class VirtualJoint:
    """SRDF ``<virtual_joint>``: how the robot's root attaches to the world frame."""

    name: str
    """The virtual joint's name."""
    type: str
    """fixed, floating or planar."""
    parent_frame: str
    """The fixed frame it attaches to (world, odom)."""
    child_link: str
    """The robot's root link."""


@dataclass(frozen=True, slots=True)
class DisabledCollision:
    """SRDF ``<disable_collisions>``: a link pair a planner never checks, and why."""

    link1: str
    """First link of the pair."""
    link2: str
    """Second link of the pair."""
    reason: str = ""
    """Adjacent, Never, Default, ... as the MoveIt Setup Assistant wrote it."""


@dataclass(frozen=True, slots=True)
class Semantics:
    """The content of an SRDF."""

    robot_name: str
    """The SRDF's <robot name>, which must match the URDF's."""
    groups: tuple[Group, ...] = ()
    """Planning groups."""
    group_states: tuple[GroupState, ...] = ()
    """Named joint configurations."""
    end_effectors: tuple[EndEffector, ...] = ()
    """End effectors."""
    virtual_joints: tuple[VirtualJoint, ...] = ()
    """How the root attaches to the world."""
    passive_joints: tuple[str, ...] = ()
    """Joints a planner does not move."""
    disabled_collisions: tuple[DisabledCollision, ...] = ()
    """Link pairs never checked for collision."""


# --------------------------------------------------------------------------- ros2_control
SIMULATED_HARDWARE = frozenset(
    {
        "gazebo_ros2_control/GazeboSystem",
        "gz_ros2_control/GazeboSimSystem",
        "ign_ros2_control/IgnitionSystem",
        "mujoco_ros2_control/MujocoSystem",
        "mock_components/GenericSystem",
    }
)
"""``<hardware><plugin>`` names that mean "the simulator is the hardware"."""


@dataclass(frozen=True, slots=True)
class ControlInterface:
    """A ``<command_interface>`` or ``<state_interface>`` of a ros2_control component, with its
    ``<param>`` s (``min``, ``max``, ``initial_value``, ``data_type``...) as written."""

    name: str
    """position, velocity, effort, or a custom name."""
    params: tuple[tuple[str, str], ...] = ()
    """(name, value) pairs of its <param>s, as written."""
    location: SourceLocation | None = None
    """Where the interface is written (file:line)."""

    def param(self, name: str) -> str | None:
        """A ``<param name=...>`` value as written, or None."""
        return next((v for k, v in self.params if k == name), None)


@dataclass(frozen=True, slots=True)
class ControlComponent:
    """A ``<joint>``, ``<sensor>`` or ``<gpio>`` of a ``<ros2_control>`` block."""

    name: str
    """The joint's (or sensor's, gpio's) name."""
    command_interfaces: tuple[ControlInterface, ...] = ()
    """What controllers may write."""
    state_interfaces: tuple[ControlInterface, ...] = ()
    """What controllers may read."""
    params: tuple[tuple[str, str], ...] = ()
    """(name, value) pairs of the component's <param>s, as written."""
    location: SourceLocation | None = None
    """Where the component is written (file:line)."""


@dataclass(frozen=True, slots=True)
class Ros2Control:
    """A URDF ``<ros2_control name type>`` block: its hardware and what it exposes to controllers."""

    name: str
    """The block's name attribute."""
    type: str
    """``system``, ``actuator`` or ``sensor``."""
    hardware_plugin: str = ""
    """``<hardware><plugin>``; see :data:`SIMULATED_HARDWARE` and :attr:`simulated`."""
    hardware_params: tuple[tuple[str, str], ...] = ()
    """(name, value) pairs of <hardware><param>s, as written."""
    joints: tuple[ControlComponent, ...] = ()
    """The joints it exposes."""
    sensors: tuple[ControlComponent, ...] = ()
    """Its sensors (force/torque, IMU) with their state interfaces."""
    gpios: tuple[ControlComponent, ...] = ()
    """Its GPIOs."""
    location: SourceLocation | None = None
    """Where the block is written (file:line)."""

    @property
    def simulated(self) -> bool:
        """Whether the hardware plugin is a simulator's (else a real driver, which the simulator stands in for)."""
        return self.hardware_plugin in SIMULATED_HARDWARE
