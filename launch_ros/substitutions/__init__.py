"""launch_ros.substitutions: FindPackageShare, FindPackagePrefix, ExecutableInPackage."""

from __future__ import annotations

import os
from typing import Any

from launch.substitution import Substitution
from launch.substitutions import SubstitutionFailure
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions


class PackageNotFoundError(SubstitutionFailure):
    pass


def package_prefix(name: str) -> str:
    """The install prefix of ROS package ``name`` (the ament index); "Package 'x' not found" else."""
    from ament_index_python.packages import PackageNotFoundError as _NotFound
    from ament_index_python.packages import get_package_prefix

    try:
        return get_package_prefix(name)
    except (_NotFound, LookupError, OSError):
        raise PackageNotFoundError(f"Package '{name}' not found") from None


class FindPackagePrefix(Substitution):
    def __init__(self, package: Any) -> None:
        self.package = normalize_to_list_of_substitutions(package)

    def perform(self, context: Any) -> str:
        return package_prefix(perform_substitutions(context, self.package))


class FindPackageShare(FindPackagePrefix):
    def perform(self, context: Any) -> str:
        name = perform_substitutions(context, self.package)
        return os.path.join(package_prefix(name), "share", name)

    def find(self, *parts: Any) -> Any:
        from launch.substitutions import PathJoinSubstitution

        return PathJoinSubstitution([self, *parts])


def find_executable(package: str, executable: str) -> str:
    """``<prefix>/lib/<package>/<executable>``, or colcon's ``<prefix>/bin/<executable>`` for an
    ament_python package installed without a setup.cfg (as the seed blog's is)."""
    prefix = package_prefix(package)
    candidates = [os.path.join(prefix, "lib", package, executable), os.path.join(prefix, "bin", executable)]
    for c in candidates:
        if os.path.isfile(c) and os.access(c, os.X_OK):
            return c
    raise SubstitutionFailure(
        f"executable '{executable}' not found on the libexec directory '{os.path.join(prefix, 'lib', package)}'"
    )


class ExecutableInPackage(Substitution):
    def __init__(self, executable: Any, package: Any) -> None:
        self.executable = normalize_to_list_of_substitutions(executable)
        self.package = normalize_to_list_of_substitutions(package)

    def perform(self, context: Any) -> str:
        return find_executable(
            perform_substitutions(context, self.package), perform_substitutions(context, self.executable)
        )


__all__ = ["ExecutableInPackage", "FindPackagePrefix", "FindPackageShare", "find_executable", "package_prefix"]
