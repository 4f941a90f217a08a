"""``gzserver`` and ``gzclient``: Gazebo Classic's two executables, for launch files that run them directly
(Husky's, many Clearpath and tutorial launches: ``ExecuteProcess(cmd=['gzserver', world, '-s',
'libgazebo_ros_init.so', ...])``).

``gzserver [options] [WORLD]`` is ``gazelle sim [WORLD] --no-viewer``: ``-u``/``--pause`` starts it paused;
``-s``/``--server-plugin`` of gazebo_ros's system plugins (``libgazebo_ros_init.so``,
``libgazebo_ros_factory.so``, ``libgazebo_ros_force_system.so``) are what ``gazelle sim`` always serves;
every other option (``--verbose``, ``-e ode``, ``--seed``, ``-r``, ``--record_path``, ...) is named in one
warning line and not used. ``gzclient`` is Gazebo's GUI: here the browser viewer, served by a
``gazelle sim`` of its own with the same world is not what a launch file wants (two servers on one
domain stop each other), so gzclient says where to look (``gazelle sim``'s viewer, started by gzserver
when ``GAZELLE_GZSERVER_VIEWER`` is not 0) and stays up until it is stopped, as the GUI would.
"""

from __future__ import annotations

import os
import sys

GAZEBO_ROS_SYSTEM_PLUGINS = ("libgazebo_ros_init.so", "libgazebo_ros_factory.so", "libgazebo_ros_force_system.so")
"""gazebo_ros's system plugins: /clock, the spawn and state services, the force services; gazelle sim serves
them without being asked."""
_WITH_VALUE = {"-e", "--physics", "--seed", "--iters", "--record_path", "--record_period", "--record_filter",
               "--record_encoding", "-p", "--play", "-o", "--profile", "--minimal_comms"}  # fmt: skip


def gzserver_args(argv: list[str]) -> tuple[list[str], list[str]]:
    """``gazelle sim`` arguments for gzserver's ``argv``, and the options that are not used (for a warning)."""
    out: list[str] = []
    world: str | None = None
    ignored: list[str] = []
    it = iter(argv)
    for arg in it:
        if arg in ("-u", "--pause"):
            out.append("--paused")
        elif arg in ("-s", "--server-plugin", "-g", "--gui-plugin"):
            plugin = next(it, "")
            if os.path.basename(plugin) not in GAZEBO_ROS_SYSTEM_PLUGINS:
                ignored.append(f"{arg} {plugin}")
        elif arg.startswith("--ros-args"):
            ignored.extend([arg, *it])
        elif arg in _WITH_VALUE:
            ignored.append(f"{arg} {next(it, '')}")
        elif arg.startswith("-"):
            ignored.append(arg)
        elif world is None:
            world = arg
        else:
            ignored.append(arg)
    if world:
        out.insert(0, world)
    if os.environ.get("GAZELLE_GZSERVER_VIEWER", "1") == "0":
        out.append("--no-viewer")
    return out, ignored


def gzserver_main() -> None:
    """The ``gzserver`` console script."""
    args, ignored = gzserver_args(sys.argv[1:])
    if ignored:
        print(f"gzserver (gazelle sim): not used: {' '.join(ignored)}", file=sys.stderr, flush=True)
    from ._main import main

    main(["sim", *args])


def gzclient_main() -> None:
    """The ``gzclient`` console script (and ``gz sim -g``): says where the running server's viewer is, by the
    address that server announced, and waits to be stopped."""
    from ..ros import gui_stand_in_main

    sys.exit(
        gui_stand_in_main("gzclient", "the simulation is drawn in the browser by gazelle sim's viewer", sys.argv[1:])
    )
