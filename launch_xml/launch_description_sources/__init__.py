"""``from launch_xml.launch_description_sources import XMLLaunchDescriptionSource``, as in Jazzy."""

from launch.launch_description_sources import XMLLaunchDescriptionSource

__all__ = ["XMLLaunchDescriptionSource"]
