"""The controller types a controller manager can load, by their ``package/Class`` name: what ros2_control finds
through pluginlib (each controller package's plugin XML), here one table. A new controller registers here."""

from __future__ import annotations

from ._ackermann import AckermannSteeringController
from ._broadcasters import (
    ForceTorqueSensorBroadcaster,
    ForwardCommandController,
    ImuSensorBroadcaster,
    JointGroupEffortController,
    JointGroupPositionController,
    JointGroupVelocityController,
    JointStateBroadcaster,
)
from ._controller import Controller
from ._diff_drive import DiffDriveController
from ._gripper import EffortGripperActionController, GripperActionController
from ._scaled_trajectory import ScaledJointTrajectoryController
from ._trajectory import JointTrajectoryController
from ._tricycle import TricycleController

CONTROLLER_TYPES: dict[str, type[Controller]] = {
    c.type_name: c
    for c in (
        JointStateBroadcaster,
        DiffDriveController,
        JointTrajectoryController,
        ScaledJointTrajectoryController,
        ForwardCommandController,
        JointGroupPositionController,
        JointGroupVelocityController,
        JointGroupEffortController,
        GripperActionController,
        EffortGripperActionController,
        ImuSensorBroadcaster,
        ForceTorqueSensorBroadcaster,
        TricycleController,
        AckermannSteeringController,
    )
}
"""Controller types a manager can load, by their ``package/Class`` name."""
