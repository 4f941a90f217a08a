"""moveit_configs_utils (MoveIt 2 Jazzy's), gazelle's stand-in written from its behaviour: the builder that reads a
MoveIt configuration package laid out as MoveIt Setup Assistant lays it out, and the ``generate_*_launch``
functions its launch files call. The parameters it gathers are the keys MoveIt's are; the nodes the launch
descriptions start are gazelle's stand-ins where gazelle has them (``moveit_ros_move_group move_group``,
``robot_state_publisher``, ``rviz2``, ``controller_manager spawner``)."""

from .moveit_configs_builder import MoveItConfigs, MoveItConfigsBuilder

__all__ = ["MoveItConfigs", "MoveItConfigsBuilder"]
