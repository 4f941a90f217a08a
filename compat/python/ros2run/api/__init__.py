"""ros2run.api (ros2cli Jazzy): a package's executable by name, and running it as ``ros2 run`` does."""

from __future__ import annotations

import os
import signal
import subprocess
from collections.abc import Iterable
from typing import Any

from ros2pkg.api import PackageNotFound, get_executable_paths

ROS2RUN_MSG_PREFIX = "[ros2run]:"


class MultipleExecutables(Exception):
    """More than one executable of the package has that name (in different sub-folders of its ``lib``)."""

    def __init__(self, paths: Iterable[str]) -> None:
        self.paths = list(paths)
        super().__init__(self.paths)


def get_executable_path(*, package_name: str, executable_name: str) -> str | None:
    """The path of ``executable_name`` of ``package_name``, or None when it has none of that name.

    Raises:
        PackageNotFound: the package is not in the ament index.
        MultipleExecutables: several of its executables have that name.
    """
    matches = [p for p in get_executable_paths(package_name=package_name) if os.path.basename(p) == executable_name]
    if len(matches) > 1:
        raise MultipleExecutables(matches)
    return matches[0] if matches else None


def run_executable(*, path: str, argv: list[str], prefix: list[str] | None = None) -> int:
    """Run ``path`` with ``argv`` (after ``prefix``, a command as a list, when given) until it ends, Ctrl-C
    reaching it as well; a failure is said in one line (``[ros2run]: Segmentation fault``, ``[ros2run]: Process
    exited with failure 2``). Returns its exit status (negative: the signal that ended it)."""
    cmd = [*(prefix or []), path, *argv]
    process = subprocess.Popen(cmd)
    while process.returncode is None:
        try:
            process.communicate()
        except KeyboardInterrupt:
            pass  # the child got the Ctrl-C too, and ends on its own
    code = process.returncode
    if code != 0:
        if code < 0 and -code in {int(s) for s in signal.valid_signals()}:
            print(ROS2RUN_MSG_PREFIX, signal.strsignal(-code))
        else:
            print(ROS2RUN_MSG_PREFIX, f"Process exited with failure {code}")
    return code


class ExecutableNameCompleter:
    """argcomplete's completer of executable names, for the package the parsed argument ``package_name_key``
    names."""

    def __init__(self, *, package_name_key: str | None = None) -> None:
        self.package_name_key = package_name_key

    def __call__(self, prefix: str, parsed_args: Any, **kwargs: Any) -> list[str]:
        try:
            paths = get_executable_paths(package_name=getattr(parsed_args, str(self.package_name_key)))
        except PackageNotFound:
            return []
        return [os.path.basename(p) for p in paths]


__all__ = [
    "ROS2RUN_MSG_PREFIX",
    "ExecutableNameCompleter",
    "MultipleExecutables",
    "PackageNotFound",
    "get_executable_path",
    "run_executable",
]
