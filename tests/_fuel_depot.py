"""A stand-in for Fuel's OpenRobotics/Depot in a Fuel cache laid out as gz-fuel-tools lays it out
(``<cache>/fuel.gazebosim.org/openrobotics/models/depot/<version>/``: ModelIdentifier::UniqueName, lowercased). The
real Depot is not downloadable here (no network at test time) and is large; the stand-in has its structure: a
static model whose meshes are named by Fuel file URLs."""

from __future__ import annotations

from pathlib import Path

import trimesh

DEPOT_URI = "https://fuel.gazebosim.org/1.0/OpenRobotics/models/Depot"


def fuel_depot(cache: Path, size: tuple[float, float] = (10.0, 6.0), version: int = 7) -> Path:
    """A stand-in Depot where gz-fuel-tools would have put the real one: a hall of ``size`` (a 0.1 m floor slab
    whose top is at z = 0, and 2 m walls 0.1 m thick inside that size) as one STL named by a Fuel file URL, as
    Fuel models name their meshes; its link is ``main`` and its roof a visual ``ROOF_visual``, as the Depot's."""
    folder = cache / "fuel.gazebosim.org" / "openrobotics" / "models" / "depot" / str(version)
    (folder / "meshes").mkdir(parents=True)
    sx, sy = size
    parts = [trimesh.creation.box(extents=(sx, sy, 0.1), transform=_at(0, 0, -0.05))]
    hx, hy = sx / 2 - 0.05, sy / 2 - 0.05
    for x, y, ex, ey in ((hx, 0, 0.1, sy), (-hx, 0, 0.1, sy), (0, hy, sx, 0.1), (0, -hy, sx, 0.1)):
        parts.append(trimesh.creation.box(extents=(ex, ey, 2.0), transform=_at(x, y, 1.0)))
    trimesh.util.concatenate(parts).export(folder / "meshes" / "depot.stl")
    (folder / "model.config").write_text(
        '<?xml version="1.0"?><model><name>Depot</name><version>1.0</version><sdf version="1.6">model.sdf</sdf></model>'
    )
    mesh = f"<mesh><uri>{DEPOT_URI}/tip/files/meshes/depot.stl</uri></mesh>"
    (folder / "model.sdf").write_text(
        f"""<?xml version="1.0"?><sdf version="1.6"><model name="Depot"><static>true</static>
<link name="main"><collision name="collision"><geometry>{mesh}</geometry></collision>
<visual name="ROOF_visual"><geometry>{mesh}</geometry></visual></link></model></sdf>"""
    )
    return folder


def _at(x: float, y: float, z: float):
    return trimesh.transformations.translation_matrix((x, y, z))
