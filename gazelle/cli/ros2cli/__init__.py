"""The ``ros2`` command for a venv without ROS 2's ros2cli: ``launch``, ``run``, ``pkg`` and the
introspection verbs: ``topic`` (list, echo, hz, bw, delay, info, type, find, pub), ``service`` (list,
type, find, call), ``action`` (list, info, type, send_goal), ``node`` (list, info), ``param`` (list, get,
set, describe, dump, load), ``interface`` (show, list, package, packages, proto), ``bag`` (record, play,
info: rosbag2's MCAP), ``daemon`` (start, stop, status) and ``control`` (ros2controlcli's verbs over a
controller manager's services).

Same arguments and output as ros2cli Jazzy for what it covers (each verb's module names the upstream file
it follows); an unknown verb lists the verbs that exist. Where gazelle differs it says so in the verb's
docstring: the listing verbs ask gazelle's graph daemon (``ros2 daemon``: a Unix socket only its user may
use, see ``_daemon_link``) or, with ``--no-daemon``, discover the graph themselves; and a few waits that
upstream leaves unbounded are bounded where a wedged peer would otherwise hang a script (parameter
services, 5 s). ``gazelle launch`` and ``gazelle run`` are the same commands.
"""

from __future__ import annotations

import importlib
import os
import signal
import sys

from ._graph import ShutDown, matching_qos  # the Foxglove bridge subscribes the same way

COMMANDS = {
    "action": ("_action", "main", "Various action related sub-commands"),
    "bag": ("_bag", "main", "Various rosbag related sub-commands"),
    "control": ("_control", "main", "Various control related sub-commands"),
    "daemon": ("_daemon", "main", "Various daemon related sub-commands"),
    "interface": ("_interface", "main", "Show information about ROS interfaces"),
    "launch": ("_launch", "main", "Run a launch file"),
    "node": ("_node", "main", "Various node related sub-commands"),
    "param": ("_param", "main", "Various param related sub-commands"),
    "pkg": ("_pkg", "main", "Various package related sub-commands"),
    "run": ("_run", "main", "Run a package specific executable"),
    "service": ("_service", "service_main", "Various service related sub-commands"),
    "topic": ("_topic", "main", "Various topic related sub-commands"),
}
"""verb -> (module, function, help line); a module is imported only when its verb runs."""
VERBS = tuple(COMMANDS)


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
        print("Commands:")
        for verb, (_m, _f, text) in COMMANDS.items():
            print(f"  {verb:<10} {text}")
        print("\n  Call `ros2 <command> -h` for more detailed usage.")
        return 0 if argv else 2
    verb, rest = argv[0], argv[1:]
    if verb in COMMANDS:
        module, function, _text = COMMANDS[verb]
        try:
            return getattr(importlib.import_module(f"{__name__}.{module}"), function)(rest)
        except KeyboardInterrupt:  # Ctrl-C: ros2cli's cli.py returns signal.SIGINT, with no traceback
            return int(signal.SIGINT)
        except ShutDown:  # rclpy's own SIGINT/SIGTERM handler shut the context down under the verb
            return 0
        except BrokenPipeError:  # `ros2 interface list | head`: the reader has gone, as any Unix tool's would
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # nothing more to say, and no traceback
            return 128 + int(signal.SIGPIPE)
        except Exception as err:
            if type(err).__name__ == "ExternalShutdownException":
                return 0
            raise
    print(
        f"usage: ros2 [-h] Call `ros2 <command> -h` for more detailed usage. ...\n"
        f"ros2: error: argument Call `ros2 <command> -h` for more detailed usage.: invalid choice: '{verb}' "
        f"(choose from {', '.join(repr(v) for v in VERBS)})",
        file=sys.stderr,
    )
    return 2


def console_main() -> None:
    code = main()
    # The verb has said everything: end without the interpreter's finalisation, where a DDS participant's
    # threads have held a finished verb's process (as ros2cli's users see with Ctrl-\ now and then)
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code if isinstance(code, int) else 1)


__all__ = ["COMMANDS", "VERBS", "matching_qos", "console_main", "ensure_ament_prefix", "main"]
