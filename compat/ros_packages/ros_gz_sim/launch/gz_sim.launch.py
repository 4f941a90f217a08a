"""ros_gz_sim's gz_sim.launch.py for gazelle: `gazelle sim` from gz_args (a world file, found where gz sim
finds it: as given, on GZ_SIM_RESOURCE_PATH, then the installed worlds, where gz's empty.sdf is gazelle's
default world; -r to run; -s for no GUI: the server still serves its viewer, which -g shows; -g, the GUI
alone: gzclient's stand-in)."""

import os
import shlex

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
    cmd, world, run, ignored = [GAZELLE, "sim"], "", False, []
    skip = False
    for i, tok in enumerate(tokens):
        if skip:
            skip = False
            continue
        if tok == "-r":
            run = True
        elif tok in ("-s", "--headless-rendering"):
            # `-s`: gz's server without its GUI, which a `gz sim -g` may join later. gazelle's GUI is the
            # server's browser viewer, so the server serves it (as gzserver does; GAZELLE_GZSERVER_VIEWER=0
            # turns it off) and `-g` prints where it is: with `-s` and `-g` in two includes there was none
            if os.environ.get("GAZELLE_GZSERVER_VIEWER", "1") == "0":
                cmd.append("--no-viewer")
        elif tok in ("-v", "--verbose", "--render-engine", "--physics-engine", "--gui-config"):
            skip = i + 1 < len(tokens) and not tokens[i + 1].startswith("-")
            ignored.append(tok)
        elif tok.startswith("-v") and tok[2:].isdigit():
            ignored.append(tok)
        elif not tok.startswith("-"):
            world = tok
        else:
            ignored.append(tok)
    if world:
        cmd.insert(2, world)
    if not run:
        cmd.append("--paused")  # gz sim starts paused without -r
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
