"""``[LEVEL] [name]: text`` lines on the screen, as ros2 launch prints them."""

from __future__ import annotations

import sys
import threading

_lock = threading.Lock()


def log(level: str, name: str, text: str) -> None:
    with _lock:
        for line in text.splitlines() or [""]:
            print(f"[{level}] [{name}]: {line}", file=sys.stderr, flush=True)


def output(prefix: str, line: str) -> None:
    with _lock:
        print(f"[{prefix}] {line}", flush=True)
