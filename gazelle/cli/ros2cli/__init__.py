"""The ``ros2`` command for a venv without ROS 2's ros2cli: ``launch``, ``run``, ``pkg``, and the first
introspection verbs: ``topic`` (list, echo, hz, info, type, pub), ``service`` (list, type, find, call),
``node`` (list, info), ``interface`` (show, list, package) and ``bag`` (record, play, info: MCAP).

Same arguments and output as ros2cli Jazzy for what it covers; an unknown verb lists the verbs that
exist. ``gazelle launch`` and ``gazelle run`` are the same commands. ``param`` and ``action`` are not
here yet.
"""

from __future__ import annotations

import argparse
import os
import sys

VERBS = ("bag", "interface", "launch", "node", "pkg", "run", "service", "topic")


def ensure_ament_prefix() -> None:
    """Put this environment's prefix (the venv: gazelle's packages and our interfaces) on
    AMENT_PREFIX_PATH, after what a sourced workspace already put there."""
    prefix = sys.prefix
    paths = [p for p in os.environ.get("AMENT_PREFIX_PATH", "").split(os.pathsep) if p]
    if prefix not in paths:
        paths.append(prefix)
        os.environ["AMENT_PREFIX_PATH"] = os.pathsep.join(paths)


def main(argv: list[str] | None = None) -> int:
    """``ros2 VERB ...``; returns the exit status."""
    argv = list(sys.argv[1:] if argv is None else argv)
    ensure_ament_prefix()
    if not argv or argv[0] in ("-h", "--help"):
        print("usage: ros2 [-h] Call `ros2 <command> -h` for more detailed usage. ...\n")
        print("ros2 is an extensible command-line tool for ROS 2 (gazelle's subset).\n")
        print(
            "Commands:\n  bag        Various rosbag related sub-commands\n"
            "  interface  Show information about ROS interfaces\n  launch     Run a launch file"
        )
        print("  node       Various node related sub-commands\n  pkg        Various package related sub-commands")
        print("  run        Run a package specific executable\n  service    Various service related sub-commands")
        print("  topic      Various topic related sub-commands\n")
        print("  Call `ros2 <command> -h` for more detailed usage.")
        return 0 if argv else 2
    verb, rest = argv[0], argv[1:]
    if verb == "launch":
        from ._launch import main as launch_main

        return launch_main(rest)
    if verb == "run":
        from ._run import main as run_main

        return run_main(rest)
    if verb == "pkg":
        from ._pkg import main as pkg_main

        return pkg_main(rest)
    if verb == "bag":
        from ._bag import main as bag_main

        return bag_main(rest)
    if verb == "topic":
        from ._topic import main as topic_main

        return topic_main(rest)
    if verb in ("service", "node", "interface"):
        from . import _service

        verbs = {"service": _service.service_main, "node": _service.node_main, "interface": _service.interface_main}
        return verbs[verb](rest)
    print(
        f"usage: ros2 [-h] Call `ros2 <command> -h` for more detailed usage. ...\n"
        f"ros2: error: argument Call `ros2 <command> -h` for more detailed usage.: invalid choice: '{verb}' "
        f"(choose from {', '.join(repr(v) for v in VERBS)}); param and action are not in gazelle's ros2 yet",
        file=sys.stderr,
    )
    return 2


def console_main() -> None:
    raise SystemExit(main())


__all__ = ["VERBS", "console_main", "ensure_ament_prefix", "main"]
_ = argparse
