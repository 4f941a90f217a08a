# gazelle test stand-in (see ../../SOURCES.md): the launch actions of nav2_minimal_tb4_sim's spawn_tb4.launch.py,
# written anew: parameter_bridge given its YAML through parameters=[{...}], two ros_gz_image image_bridges, and
# ros_gz_sim's create reading the robot_description topic.
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    sim_dir = get_package_share_directory('nav2_minimal_tb4_sim')
    namespace = LaunchConfiguration('namespace')
    use_sim_time = LaunchConfiguration('use_sim_time')
    pose = {axis: LaunchConfiguration(f'{axis}_pose', default=value)
            for axis, value in (('x', '-8.00'), ('y', '-0.50'), ('z', '0.01'))}

    bridge = Node(
        package='ros_gz_bridge',
        executable='parameter_bridge',
        name='bridge_ros_gz',
        namespace=namespace,
        parameters=[{'config_file': os.path.join(sim_dir, 'configs', 'tb4_bridge.yaml'),
                     'use_sim_time': use_sim_time}],
        output='screen')
    images = [
        Node(package='ros_gz_image', executable='image_bridge', name=f'bridge_gz_ros_camera_{kind}',
             namespace=namespace, output='screen', parameters=[{'use_sim_time': use_sim_time}],
             arguments=[topic])
        for kind, topic in (('image', '/rgbd_camera/image'), ('depth', '/rgbd_camera/depth_image'))]
    spawn = Node(
        condition=IfCondition(LaunchConfiguration('use_simulator')),
        package='ros_gz_sim',
        executable='create',
        namespace=namespace,
        output='screen',
        arguments=['-name', LaunchConfiguration('robot_name'), '-topic', 'robot_description',
                   '-x', pose['x'], '-y', pose['y'], '-z', pose['z']],
        parameters=[{'use_sim_time': use_sim_time}])

    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value=''),
        DeclareLaunchArgument('use_simulator', default_value='True'),
        DeclareLaunchArgument('use_sim_time', default_value='true'),
        DeclareLaunchArgument('robot_name', default_value='turtlebot4'),
        bridge,
        *images,
        spawn,
    ])
