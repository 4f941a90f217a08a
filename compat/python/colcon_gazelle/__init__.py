"""gazelle's colcon extension: every CMake package colcon builds in a gazelle venv includes
``gazelle_cpp_targets.cmake`` (beside this file) in its first ``project()``, through CMake's
``CMAKE_PROJECT_TOP_LEVEL_INCLUDES`` (CMake 3.24+).

That file lets a package whose compiled targets need C++ ROS 2 or Gazebo libraries (``rclcpp``, ``gz-sim``,
Gazebo Classic, ``hardware_interface``, ...), which a gazelle venv does not have, configure and install
everything else: each such target is one line saying it is not built and what it needs, and its installed
file is a placeholder (an executable that says so and exits 1). See the CMake file for the rules.

The argument is added to the package's ``cmake_args`` metadata, which colcon's build verb appends to the
command line's ``--cmake-args`` (``colcon_core.verb.build.BuildPackageArguments``), so a user's own CMake
arguments are kept.
"""

from __future__ import annotations

from pathlib import Path

from colcon_core.package_augmentation import PackageAugmentationExtensionPoint
from colcon_core.plugin_system import satisfies_version

CMAKE_FILE = Path(__file__).resolve().parent / "gazelle_cpp_targets.cmake"
"""The file every CMake package includes."""
CMAKE_TYPES = ("ros.ament_cmake", "ros.cmake", "cmake")
"""The colcon package types that colcon-cmake and colcon-ros configure with CMake."""


class GazelleCppTargetsAugmentation(PackageAugmentationExtensionPoint):
    """Adds ``-DCMAKE_PROJECT_TOP_LEVEL_INCLUDES=<gazelle_cpp_targets.cmake>`` to every CMake package's
    ``cmake_args``."""

    def __init__(self) -> None:
        super().__init__()
        satisfies_version(PackageAugmentationExtensionPoint.EXTENSION_POINT_VERSION, "^1.0")

    def augment_package(self, desc, *, additional_argument_names=None) -> None:
        if desc.type not in CMAKE_TYPES or not CMAKE_FILE.is_file():
            return
        args = desc.metadata.setdefault("cmake_args", [])
        flag = f"-DCMAKE_PROJECT_TOP_LEVEL_INCLUDES={CMAKE_FILE}"
        if flag not in args:
            args.append(flag)
