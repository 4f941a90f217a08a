import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    package_name = 'articubot_like'
    share = get_package_share_directory(package_name)
    use_ros2_control = LaunchConfiguration('use_ros2_control')

    # robot_state_publisher with sim time forced on
    rsp = IncludeLaunchDescription(
        PythonLaunchDescriptionSource([os.path.join(share, 'launch', 'rsp.launch.py')]),
        launch_arguments={'use_sim_time': 'true', 'use_ros2_control': use_ros2_control}.items(),
    )

    joystick = IncludeLaunchDescription(
        PythonLaunchDescriptionSource([os.path.join(share, 'launch', 'joystick.launch.py')]),
        launch_arguments={'use_sim_time': 'true'}.items(),
    )

    twist_mux = Node(
        package='twist_mux',
        executable='twist_mux',
        parameters=[os.path.join(share, 'config', 'twist_mux.yaml'), {'use_sim_time': True}],
        remappings=[('/cmd_vel_out', '/diff_cont/cmd_vel_unstamped')],
    )

    gazebo_params_file = os.path.join(share, 'config', 'gazebo_params.yaml')
    gazebo = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(
            [os.path.join(get_package_share_directory('gazebo_ros'), 'launch', 'gazebo.launch.py')]),
        launch_arguments={'extra_gazebo_args': '--ros-args --params-file ' + gazebo_params_file}.items(),
    )

    spawn_entity = Node(
        package='gazebo_ros',
        executable='spawn_entity.py',
        arguments=['-topic', 'robot_description', '-entity', 'my_bot'],
        output='screen',
    )

    diff_drive_spawner = Node(
        package='controller_manager', executable='spawner', arguments=['diff_cont'],
        condition=IfCondition(use_ros2_control))
    joint_broad_spawner = Node(
        package='controller_manager', executable='spawner', arguments=['joint_broad'],
        condition=IfCondition(use_ros2_control))

    return LaunchDescription([
        DeclareLaunchArgument('use_ros2_control', default_value='true', description='Use ros2_control if true'),
        rsp,
        joystick,
        twist_mux,
        gazebo,
        spawn_entity,
        diff_drive_spawner,
        joint_broad_spawner,
    ])
