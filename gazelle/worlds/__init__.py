"""Worlds shipped with gazelle."""

from __future__ import annotations

from ..description import Collision, Light, Link, Material, Model, Plane, Pose, Surface, Visual, World


def default_world() -> World:
    """The embedded default world: a ground plane, a sun and Earth gravity (as Gazebo's empty world)."""
    plane = Plane(normal=(0.0, 0.0, 1.0), size=(100.0, 100.0))
    ground = Model(
        name="ground_plane",
        static=True,
        links=(
            Link(
                name="link",
                collisions=(Collision("collision", Pose(), plane, Surface(mu=100.0, mu2=50.0)),),
                visuals=(Visual("visual", Pose(), plane, Material("ground", diffuse=(0.8, 0.8, 0.8, 1.0))),),
            ),
        ),
        source_format="builtin",
    )
    sun = Light(
        name="sun",
        type="directional",
        pose=Pose((0.0, 0.0, 10.0)),
        diffuse=(0.8, 0.8, 0.8, 1.0),
        specular=(0.2, 0.2, 0.2, 1.0),
        direction=(-0.5, 0.1, -0.9),
        cast_shadows=True,
    )
    return World(
        name="default", gravity=(0.0, 0.0, -9.8), models=(ground,), lights=(sun,), source_file="<builtin:default>"
    )
