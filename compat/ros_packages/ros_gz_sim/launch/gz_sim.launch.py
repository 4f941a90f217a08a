"""ros_gz_sim's gz_sim.launch.py for gazelle: `gazelle sim` from gz_args (a world file, found where gz sim
finds it: as given, on GZ_SIM_RESOURCE_PATH, then the installed worlds, where gz's empty.sdf is gazelle's
default world; -r to run; -s for no GUI: the server still serves its viewer, which -g shows; -g, the GUI
alone: gzclient's stand-in)."""

import os
import shlex

from gazelle.cli import gz_sim_args
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess, LogInfo, OpaqueFunction, Shutdown

GAZELLE = "@GAZELLE@"


def _server(context):
    cfg = context.launch_configurations
    tokens = shlex.split(cfg.get("gz_args", ""))
    shutdown = cfg.get("on_exit_shutdown", "false").lower() in ("true", "1")
    if "-g" in tokens:
        # `gz sim -g`: the GUI alone, joining the server another include started (TurtleBot3's jazzy
        # launches include this file twice, `-r -s WORLD` and `-g`). gazelle's GUI is the server's browser
        # viewer, so this is gzclient's stand-in, which says where to look: a second `gazelle sim` here
        # was a second server on the domain, and the two stopped each other
        client = os.path.join(os.path.dirname(GAZELLE), "gzclient")
        return [ExecuteProcess(cmd=[client], name="gazebo", output="screen", on_exit=Shutdown() if shutdown else None)]
    parsed = gz_sim_args(tokens, viewer=os.environ.get("GAZELLE_GZSERVER_VIEWER", "1") != "0")
    # `-s` serves the viewer, as gzserver does: gazelle's GUI is the server's browser viewer, which a `-g` include
    # (with -s and -g in two includes there was none) or gzclient points at; GAZELLE_GZSERVER_VIEWER=0 turns it off
    cmd, ignored = [GAZELLE, "sim", *parsed.sim_args], parsed.ignored
    actions = []
    if ignored:
        actions.append(LogInfo(msg=f"gz_args {' '.join(ignored)} have no meaning for gazelle sim"))
    actions.append(ExecuteProcess(cmd=cmd, name="gazebo", output="screen", on_exit=Shutdown() if shutdown else None))
    return actions


def generate_launch_description():
    return LaunchDescription(
        [
            DeclareLaunchArgument("gz_args", default_value="", description="Arguments to be passed to Gazebo Sim"),
            DeclareLaunchArgument("gz_version", default_value="8", description="Gazebo Sim's major version"),
            DeclareLaunchArgument("ign_args", default_value="", description="Deprecated: use gz_args"),
            DeclareLaunchArgument("on_exit_shutdown", default_value="false", description="Shutdown on gz-sim exit"),
            OpaqueFunction(function=_server),
        ]
    )
