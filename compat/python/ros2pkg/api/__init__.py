"""ros2pkg.api (ros2cli Jazzy): packages of the ament index and their executables, as ``ros2 pkg`` and
``ros2 run`` find them."""

from __future__ import annotations

import os
from collections.abc import Iterable

from ament_index_python.packages import PackageNotFoundError, get_package_prefix, get_packages_with_prefixes


class PackageNotFound(Exception):
    """No package of that name is in the ament index."""

    def __init__(self, package_name: str) -> None:
        super().__init__(package_name)
        self.package_name = package_name


def get_package_names() -> Iterable[str]:
    """Every package of the ament index."""
    return get_packages_with_prefixes().keys()


def get_prefix_path(package_name: str) -> str | None:
    """The install prefix of ``package_name``, or None (also when no AMENT_PREFIX_PATH is set at all, where
    ament_index_python raises an OSError)."""
    try:
        return get_package_prefix(package_name)
    except (PackageNotFoundError, ValueError, OSError):
        return None


def get_executable_paths(*, package_name: str) -> list[str]:
    """The executable files under ``<prefix>/lib/<package_name>`` (sub-folders too, hidden ones not, in name
    order), then, for a package colcon installed alone in its prefix, its ``bin`` (an ament_python package
    without a setup.cfg puts its scripts there, and gazelle's ``ros2 run`` finds them).

    Raises:
        PackageNotFound: the package is not in the ament index.
    """
    prefix = get_prefix_path(package_name)
    if prefix is None:
        raise PackageNotFound(package_name)
    paths: list[str] = []
    for folder, subfolders, files in os.walk(os.path.join(prefix, "lib", package_name)):
        subfolders[:] = sorted(d for d in subfolders if not d.startswith("."))
        paths.extend(os.path.join(folder, f) for f in sorted(files) if os.access(os.path.join(folder, f), os.X_OK))
    bin_folder = os.path.join(prefix, "bin")
    if os.path.basename(os.path.normpath(prefix)) == package_name and os.path.isdir(bin_folder):
        for f in sorted(os.listdir(bin_folder)):
            path = os.path.join(bin_folder, f)
            if os.path.isfile(path) and os.access(path, os.X_OK):
                paths.append(path)
    return paths


__all__ = ["PackageNotFound", "get_executable_paths", "get_package_names", "get_prefix_path"]
