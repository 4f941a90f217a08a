"""``ur_controllers/ScaledJointTrajectoryController``: Universal Robots' JTC, whose trajectory time runs at the robot's
speed scaling (ur_controllers, jazzy: ``scaled_joint_trajectory_controller.cpp``).

Upstream's ``update()`` reads the scaling factor from the state interface its ``speed_scaling_interface_name``
parameter names (default ``speed_scaling/speed_scaling_factor``; ``value_or(1.0)``), sets the trajectory's time to the
controller's time on a new trajectory's first sample (``traj_time_ = time``) and afterwards advances it by
``period * scaling_factor_`` each cycle: every sample, the tolerance checks and the goal's end are taken at that
trajectory time. Everything else is joint_trajectory_controller's (the parameters, the action, the topics), so
this is :class:`~._trajectory.JointTrajectoryController` run at a shifted time: ``t - lag``, the lag growing by
``(1 - factor) * period`` per cycle and reset by a new trajectory. A factor of 1.0 leaves the lag at exactly 0: the
controller then runs exactly as the JTC (and in planned blocks).

One difference, said at configure: upstream adds the scaling interface to the state interfaces it claims, so
ros2_control refuses to activate it on hardware without one (gz_ros2_control's GazeboSimSystem, which UR's Gazebo
simulation runs, has none). UR's driver reports a factor of 1.0 when nothing slows the robot (its mock hardware's
``speed_scaling`` GPIO starts at 1.0), and so does this controller where the hardware has no such interface, with
a warning naming it; ``speed_scaling_interface_name: ""`` (upstream: "This controller will not use speed
scaling") silences it.
"""

from __future__ import annotations

import math

import numpy as np

from ._trajectory import JointTrajectoryController, TrajectoryBlock

DEFAULT_SCALING_INTERFACE = "speed_scaling/speed_scaling_factor"
"""``speed_scaling_interface_name``'s default (ur_controllers' scaled_joint_trajectory_controller_parameters.yaml)."""


class ScaledJointTrajectoryController(JointTrajectoryController):
    """See the module docstring."""

    type_name = "ur_controllers/ScaledJointTrajectoryController"

    def on_configure(self) -> None:
        """JTC's parameters, and ``speed_scaling_interface_name``: the state interface read as the factor when the
        hardware has it (else the factor stays 1.0, with one warning)."""
        super().on_configure()
        name = self.param("speed_scaling_interface_name", DEFAULT_SCALING_INTERFACE, str)
        self._scaling_key = name if name in self.ctx.state_names else ""
        self.lag = 0.0
        """Controller time minus trajectory time (s): what the factor has held the trajectory back by."""
        self.scaling_factor = 1.0
        if not name:
            self.log.info("No scaling interface set. This controller will not use speed scaling.")
        elif not self._scaling_key:
            self.log.warning(
                f"{self.name}: the hardware has no state interface '{name}' (speed_scaling_interface_name): the speed "
                "scaling stays 1.0, as UR's driver reports it when nothing slows the robot (ros2_control would refuse "
                'to activate ur_controllers\' controller here; speed_scaling_interface_name: "" says no scaling)'
            )
        else:
            self.log.info(f"Using scaling state from the hardware from interface {name}.")

    def state_interfaces(self) -> list[str] | None:
        """JTC's, and the scaling interface when the hardware has it (upstream's state_interface_configuration)."""
        own = super().state_interfaces() or []
        return [*own, self._scaling_key] if self._scaling_key else own

    def _factor(self, states: dict[str, float]) -> float:
        """The scaling factor this cycle: the interface's value (1.0 without one, or for a value that is not a finite
        number; never below 0: the trajectory's time does not run backwards)."""
        if not self._scaling_key:
            return 1.0
        value = states.get(self._scaling_key, 1.0)
        return max(0.0, value) if math.isfinite(value) else 1.0

    def update(self, t: float, period: float, states: dict[str, float], commands: dict[str, float]) -> None:
        """One cycle at trajectory time ``t - lag``: a trajectory taken in this cycle starts at the controller's time
        (lag 0, upstream's ``traj_time_ = time``); while one runs, each later cycle advances it by ``period`` times
        the factor."""
        self.scaling_factor = factor = self._factor(states)
        if self._incoming is not None:
            self.lag = 0.0
        elif self._traj is not None and factor != 1.0:
            self.lag += (1.0 - factor) * period
        super().update(t - self.lag, period, states, commands)

    def plan_block(self, times: np.ndarray, states: dict[str, float]) -> TrajectoryBlock | None:
        """Planned blocks only while the trajectory time is the controller's (no scaling interface, no lag): a factor
        read each cycle is a Python cycle."""
        if self._scaling_key or self.lag != 0.0:
            return None
        return super().plan_block(times, states)
