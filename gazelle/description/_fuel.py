"""Gazebo Fuel URIs without a network: built-in equivalents and the local Fuel cache.

Gazebo downloads ``https://fuel.gazebosim.org/1.0/<owner>/models/<name>[/<version>]`` on first
use; here nothing is fetched. TurtleBot3's worlds (and most gz-sim worlds) include Fuel's
"Ground Plane" and "Sun": those resolve to built-in equivalents with Fuel's own values. Any
other Fuel model is looked up in the local cache Gazebo keeps (``GZ_FUEL_CACHE_PATH``, else
``~/.gz/fuel``, and Ignition's ``IGN_FUEL_CACHE_PATH`` / ``~/.ignition/fuel``); if it is not
there, the include is skipped with a warning naming the model and saying nothing was fetched.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass
from pathlib import Path
from urllib.parse import unquote, urlsplit

FUEL_HOSTS = ("fuel.gazebosim.org", "fuel.ignitionrobotics.org", "app.gazebosim.org")

GROUND_PLANE_SDF = """<?xml version="1.0"?>
<sdf version="1.6">
  <model name="ground_plane">
    <static>true</static>
    <link name="link">
      <collision name="collision">
        <geometry><plane><normal>0 0 1</normal><size>100 100</size></plane></geometry>
        <surface><friction><ode><mu>100</mu><mu2>50</mu2></ode></friction></surface>
      </collision>
      <visual name="visual">
        <geometry><plane><normal>0 0 1</normal><size>100 100</size></plane></geometry>
        <material>
          <ambient>0.8 0.8 0.8 1</ambient><diffuse>0.8 0.8 0.8 1</diffuse><specular>0.8 0.8 0.8 1</specular>
        </material>
      </visual>
    </link>
  </model>
</sdf>
"""
"""Fuel's OpenRobotics "Ground Plane" (a static 100 m plane, friction 100/50)."""

SUN_SDF = """<?xml version="1.0"?>
<sdf version="1.6">
  <light type="directional" name="sun">
    <cast_shadows>true</cast_shadows>
    <pose>0 0 10 0 0 0</pose>
    <diffuse>0.8 0.8 0.8 1</diffuse>
    <specular>0.2 0.2 0.2 1</specular>
    <attenuation><range>1000</range><constant>0.9</constant><linear>0.01</linear><quadratic>0.001</quadratic></attenuation>
    <direction>-0.5 0.1 -0.9</direction>
  </light>
</sdf>
"""
"""Fuel's OpenRobotics "Sun" (a directional light)."""

BUILTIN = {"ground plane": GROUND_PLANE_SDF, "sun": SUN_SDF}

CLASSIC_GROUND_PLANE_SDF = GROUND_PLANE_SDF.replace(
    "<ambient>0.8 0.8 0.8 1</ambient><diffuse>0.8 0.8 0.8 1</diffuse><specular>0.8 0.8 0.8 1</specular>",
    "<script><name>Gazebo/Grey</name></script>",
)
"""Gazebo Classic's stock ``model://ground_plane`` (osrf/gazebo_models' ground_plane/model.sdf: the same
static 100 m plane and friction 100/50 as Fuel's, drawn in ``Gazebo/Grey``)."""

CLASSIC_BUILTIN = {"ground_plane": CLASSIC_GROUND_PLANE_SDF, "sun": SUN_SDF}
"""``model://`` names that Gazebo Classic installs with itself (``/usr/share/gazebo-11/models``), so every
Classic world includes them and no package ships them: built in, used when no model of that name is on
the resource paths (``sun`` is the same light as Fuel's)."""


@dataclass(frozen=True)
class FuelModel:
    """A Fuel model URI taken apart."""

    host: str
    owner: str
    name: str
    version: str | None

    def label(self) -> str:
        """``owner/name`` (and the version), as messages name the model."""
        return f"{self.owner}/{self.name}" + (f" (version {self.version})" if self.version else "")


_PATH = re.compile(r"^/(?:[\d.]+/)?(?P<owner>[^/]+)/models/(?P<name>[^/]+)(?:/(?P<version>\d+|tip))?(?:/.*)?$", re.I)


def parse_fuel_uri(uri: str) -> FuelModel | None:
    """The Fuel model a URI names, or None when it is not a Fuel model URI.

    The forms worlds use: ``https://fuel.gazebosim.org/1.0/<owner>/models/<name>``, with or without the API
    version, with a version number or ``tip`` after the name, and with a file path after that (a mesh inside
    the model). Owner and name are percent-decoded (Fuel's names have spaces: ``Construction Cone``); ``tip``
    means the newest version, as gz-fuel-tools reads it. Only the Fuel hosts are models; any other
    ``https://`` URI is not one, and is never fetched."""
    uri = uri.strip()
    if not uri.lower().startswith(("https://", "http://")):
        return None
    parts = urlsplit(uri.replace(" ", "%20"))
    host = (parts.hostname or "").lower()
    if host not in FUEL_HOSTS:
        return None
    m = _PATH.match(parts.path)
    if m is None:
        return None
    version = m.group("version")
    return FuelModel(
        host, unquote(m.group("owner")), unquote(m.group("name")), None if version in (None, "tip") else version
    )


def cache_roots(environ: dict[str, str] | os._Environ[str] = os.environ) -> list[Path]:
    """The folders Gazebo keeps downloaded Fuel models in, that exist."""
    home = Path(environ.get("HOME", "~")).expanduser()
    cands = [
        *(Path(p) for p in (environ.get("GZ_FUEL_CACHE_PATH"), environ.get("IGN_FUEL_CACHE_PATH")) if p),
        home / ".gz" / "fuel",
        home / ".ignition" / "fuel",
    ]
    return [c for c in dict.fromkeys(cands) if c.is_dir()]


def find_cached(model: FuelModel, roots: list[Path]) -> Path | None:
    """The folder of ``model`` in a local Fuel cache (the newest version unless one is named), or None.

    gz-fuel-tools keeps a download as ``<cache>/<host>/<owner>/models/<name>/<version>/``; the owner and
    name are matched without regard to case, and a name's folder may be percent-encoded, so a cache written by
    either spelling is found. Only numbered version folders count; the highest wins when the URI names none,
    which is what a world that says ``tip`` (or nothing) got when it was downloaded."""
    want_owner, want_name = model.owner.lower(), model.name.lower()
    for root in roots:
        host_dir = root / model.host
        if not host_dir.is_dir():
            continue
        for owner in _children(host_dir):
            if owner.name.lower() != want_owner:
                continue
            for name in _children(owner / "models"):
                if unquote(name.name).lower() != want_name:
                    continue
                versions = [v for v in _children(name) if v.name.isdigit()]
                if model.version is not None:
                    versions = [v for v in versions if v.name == model.version]
                if versions:
                    return max(versions, key=lambda v: int(v.name))
    return None


def _children(folder: Path) -> list[Path]:
    try:
        return [p for p in folder.iterdir() if p.is_dir()]
    except OSError:
        return []
