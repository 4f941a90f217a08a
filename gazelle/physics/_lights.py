"""What the world's cameras see besides the entities: the world's lights in MuJoCo's spec, and the background
colour where nothing is drawn."""

from __future__ import annotations

import mujoco
import numpy as np

from ..description import Light, World, rotation_matrix


def background_of(world: World) -> tuple[int, ...]:
    """What cameras see where nothing is drawn (the world's ``background``, 8-bit RGB): the world's ``<scene>
    <background>`` (SDFormat's default 0.7 grey), or the gz-sim Sensors system's ``<background_color>``,
    which wins over it, as gz-sim's sensors render (``src/systems/sensors/Sensors.cc``:
    ``background_color``, else ``src/rendering/RenderUtil.cc``: ``scene->SetBackgroundColor(
    scene.Background())``)."""
    colour = world.scene.background[:3]
    for plugin in world.plugins:
        if "sensors" not in (plugin.filename or "").lower() and not plugin.name.endswith("::Sensors"):
            continue
        el = plugin.config.find("background_color")
        try:
            values = [float(v) for v in (el.text or "").split()] if el is not None else []
        except ValueError:
            values = []
        if len(values) in (3, 4):
            colour = (values[0], values[1], values[2])
    return tuple(int(round(255 * min(max(float(c), 0.0), 1.0))) for c in colour)


def add_light(spec: mujoco.MjSpec, light: Light) -> None:
    """A world light for cameras (its direction is in the light's frame, as SDF gives it)."""
    kinds = {"directional": mujoco.mjtLightType.mjLIGHT_DIRECTIONAL, "spot": mujoco.mjtLightType.mjLIGHT_SPOT}
    R = rotation_matrix(light.pose.orientation)
    direction = R @ np.asarray(light.direction, dtype=float)
    n = float(np.linalg.norm(direction))
    spec.worldbody.add_light(
        name=f"light::{light.name}",
        type=kinds.get(light.type, mujoco.mjtLightType.mjLIGHT_POINT),
        pos=list(light.pose.position),
        dir=list(direction / n) if n > 0 else [0.0, 0.0, -1.0],
        diffuse=list(light.diffuse[:3]),
        specular=list(light.specular[:3]),
        castshadow=bool(light.cast_shadows),
    )
