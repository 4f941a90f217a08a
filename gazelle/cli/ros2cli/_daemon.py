"""``ros2 daemon start | stop | status``, with ros2cli Jazzy's output (ros2cli/command/daemon.py and its
verbs): the graph daemon the listing verbs ask (see ``_daemon_link``)."""

from __future__ import annotations

import argparse
import time

from ._daemon_link import private_dir, request, socket_name, start_daemon

START_WAIT_SEC = 10.0


def main(argv: list[str]) -> int:
    """``ros2 daemon VERB``; returns the exit status."""
    p = argparse.ArgumentParser(prog="ros2 daemon", description="Various daemon related sub-commands")
    sub = p.add_subparsers(dest="cmd", required=True)
    sub.add_parser("start", help="Start the daemon if it isn't running")
    sub.add_parser("status", help="Output the status of the daemon")
    sub.add_parser("stop", help="Stop the daemon if it is running")
    args = p.parse_args(argv)
    running = request({"op": "status"}) is not None
    if args.cmd == "status":
        print("The daemon is running" if running else "The daemon is not running")
        return 0
    if args.cmd == "stop":
        if not running:
            print("The daemon is not running")
            return 0
        request({"op": "stop"})
        deadline = time.monotonic() + START_WAIT_SEC
        while request({"op": "status"}) is not None and time.monotonic() < deadline:
            time.sleep(0.05)
        print("The daemon has been stopped")
        return 0
    if running:
        print("The daemon is already running")
        return 0
    if not start_daemon():
        return 1
    deadline = time.monotonic() + START_WAIT_SEC  # answering: it has its node (not yet the whole graph)
    while request({"op": "status"}) is None:
        if time.monotonic() > deadline:
            folder = private_dir(create=False)
            print(f"The daemon did not answer within {START_WAIT_SEC:g} s on {folder}/{socket_name()}")
            return 1
        time.sleep(0.05)
    print("The daemon has been started")
    return 0
