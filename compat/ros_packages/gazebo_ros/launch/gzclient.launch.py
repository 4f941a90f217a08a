"""gazebo_ros's gzclient.launch.py for gazelle: the client is the browser viewer that `gazelle sim`
serves; this prints where it is."""

from launch import LaunchDescription
from launch.actions import LogInfo


def generate_launch_description():
    return LaunchDescription(
        [LogInfo(msg="gzclient: the scene is in your browser at http://127.0.0.1:8080 (served by gazelle sim)")]
    )
