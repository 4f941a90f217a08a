"""gazebo_ros's gzserver.launch.py for gazelle: runs `gazelle sim [world]` (named gzserver), paused
with pause:=true, the viewer on unless gui:=false."""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess, LogInfo, OpaqueFunction, Shutdown

GAZELLE = "@GAZELLE@"


def _server(context):
    cfg = context.launch_configurations
    cmd = [GAZELLE, "sim"]
    world = cfg.get("world", "")
    if world:
        cmd.append(world)
    if cfg.get("pause", "false").lower() in ("true", "1"):
        cmd.append("--paused")
    if cfg.get("gui", "true").lower() not in ("true", "1"):
        cmd.append("--no-viewer")
    ignored = [a for a in ("extra_gazebo_args", "params_file") if cfg.get(a)]
    actions = []
    if ignored:
        actions.append(LogInfo(msg=f"gazelle sim does not use {', '.join(ignored)} (Gazebo's own options)"))
    required = cfg.get("server_required", "false").lower() in ("true", "1")
    actions.append(ExecuteProcess(cmd=cmd, name="gzserver", output="screen", on_exit=Shutdown() if required else None))
    return actions


def generate_launch_description():
    declared = [
        DeclareLaunchArgument(name, default_value=default, description=description)
        for name, default, description in (
            ("world", "", "Specify world file name"),
            ("pause", "false", "Start paused"),
            ("verbose", "false", "More messages"),
            ("extra_gazebo_args", "", "Extra arguments to be passed to Gazebo"),
            ("params_file", "", "Path to ROS 2 yaml parameter file"),
            ("server_required", "false", "Shut down launch when the server ends"),
        )
    ]
    return LaunchDescription([*declared, OpaqueFunction(function=_server)])
