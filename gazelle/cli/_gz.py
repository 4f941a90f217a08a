"""``gz``: gz-sim's command line for what gazelle serves, as ``gzserver``/``gzclient`` are for Gazebo Classic.

Launch files and users type ``gz sim -r -s world.sdf``, ``gz sim -g``, ``gz topic -l`` and ``gz service -l``.

* ``gz sim [options] [WORLD]`` is ``gazelle sim``: ``-r`` runs (gz sim starts paused without it), ``-s`` the
  server without a GUI (gazelle's server still serves its browser viewer, which ``-g`` or gzclient points at),
  ``-g`` the GUI alone (gzclient's stand-in: it prints the running server's viewer address), a WORLD found
  where gz sim finds it (``gazelle sim`` looks it up), ``empty.sdf`` the default world. Options with no meaning
  for gazelle (``-v4``, ``--render-engine ogre2``, ...) are named in one line. ros_gz_sim's
  ``gz_sim.launch.py`` stand-in reads its ``gz_args`` with the same function.
* ``gz topic -l``, ``-e -t TOPIC``, ``-i -t TOPIC`` and ``gz service -l``: gz-transport's topics are ROS
  topics in gazelle, under the gz name (``gazelle.ros``'s ``gz_topic_on_ros``), so these are ``ros2 topic
  list|echo|info`` and ``ros2 service list``.
* Everything else (``gz topic -p``, ``gz service -s``, ``gz model``, ``gz log``, ``gz fuel``) is one line saying
  what to use instead, exit 1.
"""

from __future__ import annotations

import re
import sys
from dataclasses import dataclass, field

_WITH_VALUE = ("--render-engine", "--render-engine-gui", "--render-engine-server", "--physics-engine", "--gui-config")
_SEEDED = ("-z", "--iterations", "--seed", "--playback", "--record-path", "--network-role", "--network-secondaries")


@dataclass
class GzSim:
    """What ``gz sim``'s arguments ask for, in gazelle's terms."""

    gui_only: bool = False
    """``-g``: the GUI alone, joining a running server (gzclient's stand-in)."""
    sim_args: list[str] = field(default_factory=list)
    """``gazelle sim`` arguments (the world, ``--paused`` without ``-r``, ``--no-viewer``)."""
    ignored: list[str] = field(default_factory=list)
    """The options gazelle has no use for, for one line."""


def gz_sim_args(tokens: list[str], viewer: bool = True) -> GzSim:
    """``gz sim``'s ``tokens`` (a launch file's ``gz_args``, split as a shell splits them) for ``gazelle sim``.
    ``viewer`` False is ``--no-viewer`` with ``-s`` (``GAZELLE_GZSERVER_VIEWER=0``)."""
    out = GzSim(gui_only="-g" in tokens)
    run, world, skip = False, "", False
    for i, tok in enumerate(tokens):
        if skip:
            skip = False
            continue
        if tok == "-r":
            run = True
        elif tok == "-g":
            continue
        elif tok == "-s":
            if not viewer:
                out.sim_args.append("--no-viewer")
        elif tok in ("-v", "--verbose", *_WITH_VALUE, *_SEEDED):
            skip = i + 1 < len(tokens) and not tokens[i + 1].startswith("-")
            out.ignored.append(f"{tok} {tokens[i + 1]}" if skip else tok)
        elif re.fullmatch(r"-v\d", tok) or tok in ("--headless-rendering", "--levels", "--record", "-h"):
            out.ignored.append(tok)
        elif not tok.startswith("-"):
            world = tok
        else:
            out.ignored.append(tok)
    if world:
        out.sim_args.insert(0, world)
    if not run:
        out.sim_args.append("--paused")  # gz sim starts paused without -r
    return out


def _ros2(argv: list[str]) -> int:
    from .ros2cli import main

    return main(argv)


def _topic(argv: list[str]) -> int:
    """``gz topic -l | -e -t T | -i -t T``, as the ``ros2 topic`` verb of the same use."""
    from ..ros import gz_topic_on_ros

    topic = argv[argv.index("-t") + 1] if "-t" in argv and argv.index("-t") + 1 < len(argv) else ""
    if "-l" in argv:
        return _ros2(["topic", "list"])
    if "-e" in argv and topic:
        return _ros2(["topic", "echo", gz_topic_on_ros(topic)])
    if "-i" in argv and topic:
        return _ros2(["topic", "info", "-v", gz_topic_on_ros(topic)])
    print(
        "gz topic (gazelle): gz-transport's topics are ROS topics here, under the gz name: `gz topic -l`, "
        "`-e -t TOPIC` and `-i -t TOPIC` work; to publish use `ros2 topic pub TOPIC ROS_TYPE VALUES`",
        file=sys.stderr,
    )
    return 1


def _service(argv: list[str]) -> int:
    """``gz service -l``, as ``ros2 service list``; a call names the ROS service that does the same."""
    if "-l" in argv:
        return _ros2(["service", "list"])
    print(
        "gz service (gazelle): gazelle serves gazebo_ros's and simulation_interfaces' ROS services instead of "
        "gz-transport's (`gz service -l` lists them): spawn with `gazelle spawn` or /spawn_entity, control the world "
        "with /pause_physics, /unpause_physics, /reset_world or /gazelle/step_simulation",
        file=sys.stderr,
    )
    return 1


def gz_main(argv: list[str] | None = None) -> int:
    """The ``gz`` console script."""
    args = list(sys.argv[1:] if argv is None else argv)
    verb, rest = (args[0], args[1:]) if args else ("", [])
    if verb == "sim":
        import os

        parsed = gz_sim_args(rest, viewer=os.environ.get("GAZELLE_GZSERVER_VIEWER", "1") != "0")
        if parsed.ignored:
            print(f"gz sim (gazelle sim): not used: {' '.join(parsed.ignored)}", file=sys.stderr, flush=True)
        if parsed.gui_only:
            from ..ros import gui_stand_in_main

            return gui_stand_in_main("gz_sim_gui", "the simulation is drawn in the browser by gazelle sim's viewer", [])
        from ._main import main

        main(["sim", *parsed.sim_args])
        return 0
    if verb == "topic":
        return _topic(rest)
    if verb == "service":
        return _service(rest)
    print(
        f"gz {verb or '(no command)'}: not part of gazelle, which provides `gz sim`, `gz topic -l|-e|-i` and "
        "`gz service -l`; see `gazelle --help` and `ros2 --help`",
        file=sys.stderr,
    )
    return 1


def console_main() -> None:
    sys.exit(gz_main())
