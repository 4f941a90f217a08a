"""Gazebo Fuel URIs without a network: built-in equivalents and the local Fuel cache.

Gazebo downloads ``https://fuel.gazebosim.org/1.0/<owner>/models/<name>[/<version>]`` on first
use; here nothing is fetched. TurtleBot3's worlds (and most gz-sim worlds) include Fuel's
"Ground Plane" and "Sun": those resolve to built-in equivalents with Fuel's own values. Any
other Fuel model is looked up in the local cache Gazebo keeps, where gz-fuel-tools' ClientConfig puts it
(src/ClientConfig.cc): ``GZ_FUEL_CACHE_PATH`` if set, else the ``cache: path:`` of ``~/.gz/fuel/config.yaml``
(or ``config.yml``), else ``~/.gz/fuel``; and Ignition's ``IGN_FUEL_CACHE_PATH`` / ``~/.ignition/fuel``. Its
layout is ``<cache>/<host>/<owner>/models/<name>/<version>/`` with owner and name lowercased
(ModelIdentifier::SetName/SetOwner, UniqueName). A file inside a Fuel model
(``.../<owner>/models/<name>/<version>/files/<path>``, FuelClient's model file URLs) is read from the same
folder. If the model is not there, the include is skipped with one error-level line naming the model and
saying how to get it (nothing is ever fetched).
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
    file: str | None = None
    """The path of a file inside the model (``.../files/<path>``), percent-decoded, or None."""

    def label(self) -> str:
        """``owner/name`` (and the version), as messages name the model."""
        return f"{self.owner}/{self.name}" + (f" (version {self.version})" if self.version else "")


_PATH = re.compile(
    r"^/(?:[\d.]+/)?(?P<owner>[^/]+)/models/(?P<name>[^/]+)(?:/(?P<version>\d+|tip))?(?:/files/(?P<file>.+)|/.*)?$",
    re.I,
)


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
    file = m.group("file")
    return FuelModel(
        host,
        unquote(m.group("owner")),
        unquote(m.group("name")),
        None if version in (None, "tip") else version,
        unquote(file) if file else None,
    )


def cache_roots(environ: dict[str, str] | os._Environ[str] = os.environ) -> list[Path]:
    """The folders Gazebo keeps downloaded Fuel models in, that exist: gz-fuel-tools' cache location
    (``GZ_FUEL_CACHE_PATH``, else the config file's ``cache: path:``, else ``~/.gz/fuel``), then Ignition's."""
    home = Path(environ.get("HOME", "~")).expanduser()
    gz = environ.get("GZ_FUEL_CACHE_PATH") or configured_cache(home / ".gz" / "fuel")
    cands = [
        *(Path(p) for p in (gz, environ.get("IGN_FUEL_CACHE_PATH")) if p),
        home / ".gz" / "fuel",
        home / ".ignition" / "fuel",
    ]
    return [c for c in dict.fromkeys(cands) if c.is_dir()]


MAX_CONFIG_BYTES = 64 * 1024
"""The largest Fuel config file read (gz-fuel-tools' own lists one cache and a few servers: under 1 KiB)."""


def configured_cache(folder: Path) -> str | None:
    """The ``cache: path:`` that ``folder/config.yaml`` (else ``config.yml``) sets, as ClientConfig::LoadConfig
    reads it, or None (no file, not YAML, no such key: gz-fuel-tools then keeps its default)."""
    import yaml

    for name in ("config.yaml", "config.yml"):
        path = folder / name
        try:
            if not path.is_file() or path.stat().st_size > MAX_CONFIG_BYTES:
                continue
            data = yaml.safe_load(path.read_text(encoding="utf-8"))
        except (OSError, UnicodeDecodeError, yaml.YAMLError):
            return None
        cache = data.get("cache") if isinstance(data, dict) else None
        value = cache.get("path") if isinstance(cache, dict) else None
        return str(Path(value).expanduser()) if isinstance(value, str) and value else None
    return None


def cached_file(model: FuelModel, roots: list[Path]) -> tuple[Path, Path] | None:
    """(the model's cache folder, the file) for a Fuel model file URL (``.../files/<path>``) whose model is in a
    local Fuel cache, or None. The file must stay inside the model's folder."""
    if model.file is None:
        return None
    folder = find_cached(model, roots)
    if folder is None:
        return None
    path = (folder / model.file).resolve()
    real = folder.resolve()
    return (folder, path) if real in path.parents and path.is_file() else None


def how_to_get(model: FuelModel, uri: str, roots: list[Path]) -> str:
    """The one line that says a Fuel model is not here and how to get it."""
    where = ", ".join(str(r) for r in roots) or "no cache folder exists: ~/.gz/fuel, GZ_FUEL_CACHE_PATH"
    return (
        f"Fuel model '{model.label()}' is not built in and not in a local Fuel cache ({where}); nothing was "
        f'fetched (gazelle never downloads): get it with `gz fuel download -u "{uri}"` where Gazebo is installed '
        "and copy ~/.gz/fuel here (or set GZ_FUEL_CACHE_PATH), or put the model folder on GZ_SIM_RESOURCE_PATH "
        "and include it as model://; include skipped, the world loads without it"
    )


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
