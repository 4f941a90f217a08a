"""Where ``gazelle sim WORLD`` finds ``WORLD``: where ``gz sim WORLD`` finds it, so that a bring-up's
``gz_args: "-r warehouse.sdf"`` (ros_gz_sim's gz_sim.launch.py) names the same file under gazelle.

gz-sim Harmonic's command line (src/cmd/cmdsim.rb.in; the server's ``resolveSdfWorldFile`` in src/Util.cc
searches the same places) tries, in order:

1. the path as given (absolute, or relative to the current folder);
2. each folder of ``GZ_SIM_RESOURCE_PATH`` (``:``-separated), or, only when that variable is not set at all,
   of the deprecated ``IGN_GAZEBO_RESOURCE_PATH`` (with gz's notice);
3. the worlds installed with gz-sim. gazelle installs one: its embedded empty world, gz's ``empty.sdf``
   (and Classic's ``empty.world``).

gz's last resort, a download from Gazebo Fuel, is not taken: nothing is fetched from the network.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Mapping
from pathlib import Path

from ..description import Diagnostic, ErrorCode, ModelLoadError, Severity, SourceLocation

INSTALLED_WORLDS = ("empty.sdf", "empty.world")
"""The worlds installed with gazelle (step 3): each is its embedded default world."""

GZ_RESOURCE_VARIABLE = "GZ_SIM_RESOURCE_PATH"
IGN_RESOURCE_VARIABLE = "IGN_GAZEBO_RESOURCE_PATH"


def find_world_file(path: Path, env: Mapping[str, str] | None = None) -> Path | None:
    """The world file ``path`` names, in gz sim's order (see the module docstring); None for an installed
    world (gazelle's embedded default).

    Raises:
        ModelLoadError: a FILE_NOT_FOUND diagnostic naming what was searched, when no place has it.
    """
    env = os.environ if env is None else env
    if path.exists():
        return path
    variable, folders = _resource_folders(env)
    if not path.is_absolute():
        for folder in folders:
            candidate = Path(folder) / path
            if candidate.exists():
                return candidate
        if str(path) in INSTALLED_WORLDS:
            return None
    searched = (
        f"{variable} ({len(folders)} folder{'s' if len(folders) != 1 else ''})" if variable else "no resource path"
    )
    message = (
        f"no such world file: {path} (searched the path as given, {searched} and gazelle's installed worlds: "
        f"{', '.join(INSTALLED_WORLDS)})"
    )
    raise ModelLoadError([Diagnostic(ErrorCode.FILE_NOT_FOUND, Severity.ERROR, message, SourceLocation(str(path)))])


def _resource_folders(env: Mapping[str, str]) -> tuple[str, list[str]]:
    """The variable gz sim reads the world folders from, and its non-empty folders: GZ_SIM_RESOURCE_PATH when
    it is set (even empty), else IGN_GAZEBO_RESOURCE_PATH when that is (said to be deprecated, as gz says)."""
    if GZ_RESOURCE_VARIABLE in env:
        variable = GZ_RESOURCE_VARIABLE
    elif IGN_RESOURCE_VARIABLE in env:
        variable = IGN_RESOURCE_VARIABLE
        print(
            f"Using deprecated environment variable [{IGN_RESOURCE_VARIABLE}]. Please use [{GZ_RESOURCE_VARIABLE}] "
            "instead.",
            file=sys.stderr,
        )
    else:
        return "", []
    return variable, [f for f in env[variable].split(os.pathsep) if f]
