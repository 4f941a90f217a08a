"""``from launch_yaml.launch_description_sources import YAMLLaunchDescriptionSource``, as in Jazzy."""

from launch.launch_description_sources import YAMLLaunchDescriptionSource

__all__ = ["YAMLLaunchDescriptionSource"]
