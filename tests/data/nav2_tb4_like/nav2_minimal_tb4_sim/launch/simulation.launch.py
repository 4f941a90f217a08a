# gazelle test stand-in (see ../../SOURCES.md): the launch actions of nav2_minimal_tb4_sim's simulation.launch.py,
# written anew: the world xacro'd into a temporary file by an ExecuteProcess started beside gz sim, ros_gz_sim's
# gz_sim.launch.py for the server (and the client unless headless), robot_state_publisher given the xacro output,
# rviz2, and spawn_tb4.launch.py for the bridges and the robot.
import os
import tempfile

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import (
    AppendEnvironmentVariable,
    DeclareLaunchArgument,
    ExecuteProcess,
    IncludeLaunchDescription,
    OpaqueFunction,
    RegisterEventHandler,
)
from launch.conditions import IfCondition
from launch.event_handlers import OnShutdown
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import Command, LaunchConfiguration, PythonExpression
from launch_ros.actions import Node


def generate_launch_description():
    sim_dir = get_package_share_directory('nav2_minimal_tb4_sim')
    desc_dir = get_package_share_directory('nav2_minimal_tb4_description')
    gz_sim_launch = os.path.join(get_package_share_directory('ros_gz_sim'), 'launch', 'gz_sim.launch.py')

    use_sim_time = LaunchConfiguration('use_sim_time')
    use_rviz = LaunchConfiguration('use_rviz')
    headless = LaunchConfiguration('headless')
    world = LaunchConfiguration('world')
    robot_sdf = LaunchConfiguration('robot_sdf')
    pose = {axis: LaunchConfiguration(f'{axis}_pose', default=value)
            for axis, value in (('x', '-8.00'), ('y', '-0.50'), ('z', '0.01'))}

    arguments = [
        DeclareLaunchArgument('namespace', default_value=''),
        DeclareLaunchArgument('use_sim_time', default_value='True'),
        DeclareLaunchArgument('rviz_config_file', default_value=os.path.join(desc_dir, 'rviz', 'config.rviz')),
        DeclareLaunchArgument('use_rviz', default_value='True'),
        DeclareLaunchArgument('use_simulator', default_value='True'),
        DeclareLaunchArgument('headless', default_value='False'),
        DeclareLaunchArgument('world', default_value=os.path.join(sim_dir, 'worlds', 'depot.sdf')),
        DeclareLaunchArgument('robot_name', default_value='nav2_turtlebot4'),
        DeclareLaunchArgument(
            'robot_sdf', default_value=os.path.join(desc_dir, 'urdf', 'standard', 'turtlebot4.urdf.xacro')),
    ]

    world_sdf = tempfile.mktemp(prefix='nav2_', suffix='.sdf')
    world_sdf_xacro = ExecuteProcess(cmd=['xacro', '-o', world_sdf, ['headless:=', headless], world])
    gazebo_server = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(gz_sim_launch),
        launch_arguments={'gz_args': ['-r -s ', world_sdf]}.items(),
        condition=IfCondition(LaunchConfiguration('use_simulator')))
    gazebo_client = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(gz_sim_launch),
        launch_arguments={'gz_args': ['-v4 -g ']}.items(),
        condition=IfCondition(PythonExpression([LaunchConfiguration('use_simulator'), ' and not ', headless])))
    remove_world_sdf = RegisterEventHandler(OnShutdown(on_shutdown=[
        OpaqueFunction(function=lambda _: os.remove(world_sdf))]))

    robot_state_publisher = Node(
        package='robot_state_publisher',
        executable='robot_state_publisher',
        name='robot_state_publisher',
        namespace=LaunchConfiguration('namespace'),
        output='screen',
        parameters=[{'use_sim_time': use_sim_time, 'robot_description': Command(['xacro', ' ', robot_sdf])}],
        remappings=[('/tf', 'tf'), ('/tf_static', 'tf_static')])
    rviz = Node(
        condition=IfCondition(use_rviz),
        package='rviz2',
        executable='rviz2',
        name='rviz2',
        output='screen',
        arguments=['-d', LaunchConfiguration('rviz_config_file')],
        parameters=[{'use_sim_time': use_sim_time}])
    robot = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(sim_dir, 'launch', 'spawn_tb4.launch.py')),
        launch_arguments={'namespace': LaunchConfiguration('namespace'),
                          'use_simulator': LaunchConfiguration('use_simulator'),
                          'use_sim_time': use_sim_time,
                          'robot_name': LaunchConfiguration('robot_name'),
                          'x_pose': pose['x'], 'y_pose': pose['y'], 'z_pose': pose['z']}.items())

    return LaunchDescription([
        *arguments,
        AppendEnvironmentVariable('GZ_SIM_RESOURCE_PATH', os.path.join(sim_dir, 'worlds')),
        world_sdf_xacro,
        remove_world_sdf,
        robot,
        gazebo_server,
        gazebo_client,
        robot_state_publisher,
        rviz,
    ])
