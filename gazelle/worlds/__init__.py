"""Worlds shipped with gazelle."""

from __future__ import annotations

from ..description import (
    Collision,
    ConfigElement,
    Light,
    Link,
    Material,
    Model,
    Plane,
    Plugin,
    Pose,
    Surface,
    Visual,
    World,
)

DEFAULT_WORLD_SYSTEMS = (
    Plugin("gz::sim::systems::Sensors", "gz-sim-sensors-system", ConfigElement("plugin")),
    Plugin("gz::sim::systems::Imu", "gz-sim-imu-system", ConfigElement("plugin")),
    Plugin("gz::sim::systems::Contact", "gz-sim-contact-system", ConfigElement("plugin")),
    Plugin("gz::sim::systems::NavSat", "gz-sim-navsat-system", ConfigElement("plugin")),
    Plugin("gz::sim::systems::ForceTorque", "gz-sim-forcetorque-system", ConfigElement("plugin")),
    Plugin("gz::sim::systems::Magnetometer", "gz-sim-magnetometer-system", ConfigElement("plugin")),
    Plugin("gz::sim::systems::Altimeter", "gz-sim-altimeter-system", ConfigElement("plugin")),
)
"""gz-sim's sensor systems, on in the embedded default world: a sensor with no gazebo_ros plugin
(a gz-sim model such as TurtleBot3's model.sdf) publishes as it would in TurtleBot3's own gz world.
A user's world file gets exactly the systems it lists, as in gz-sim."""


def default_world() -> World:
    """The embedded default world: a ground plane, a sun and Earth gravity (as Gazebo's empty world),
    and gz-sim's sensor systems (:data:`DEFAULT_WORLD_SYSTEMS`)."""
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
        name="default",
        gravity=(0.0, 0.0, -9.8),
        models=(ground,),
        lights=(sun,),
        plugins=DEFAULT_WORLD_SYSTEMS,
        source_file="<builtin:default>",
    )
