"""gazelle's `launch` / `launch_ros` and the `ros2` command, on launch files of our own written in the
style of TurtleBot3's and articubot_one's Gazebo launch files. Real processes, no ROS graph needed."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

ROS2 = [sys.executable, "-c", "import sys; from gazelle.cli.ros2cli import main; sys.exit(main(sys.argv[1:]))"]

ECHO_ARGS = """#!{python}
import json, sys, os
print("ARGS " + json.dumps(sys.argv[1:]))
for i, a in enumerate(sys.argv):
    if a == "--params-file":
        print("PARAMS " + open(sys.argv[i + 1]).read().replace("\\n", "|"))
print("ENV " + os.environ.get("GREETING", "-"))
"""


@pytest.fixture
def prefix(tmp_path: Path) -> Path:
    """An install prefix with package demo_pkg: share/demo_pkg/launch and lib/demo_pkg/echo_args."""
    root = tmp_path / "install"
    (root / "share" / "ament_index" / "resource_index" / "packages").mkdir(parents=True)
    (root / "share" / "ament_index" / "resource_index" / "packages" / "demo_pkg").write_text("")
    (root / "share" / "demo_pkg" / "launch").mkdir(parents=True)
    (root / "lib" / "demo_pkg").mkdir(parents=True)
    exe = root / "lib" / "demo_pkg" / "echo_args"
    exe.write_text(ECHO_ARGS.format(python=sys.executable))
    exe.chmod(0o755)
    return root


def ros2(args: list[str], prefix: Path | None = None, timeout: float = 60) -> subprocess.CompletedProcess:
    env = dict(os.environ)
    if prefix is not None:
        env["AMENT_PREFIX_PATH"] = f"{prefix}{os.pathsep}{sys.prefix}"
    return subprocess.run([*ROS2, *args], capture_output=True, text=True, env=env, timeout=timeout)


def write(path: Path, text: str) -> Path:
    path.write_text(textwrap.dedent(text))
    return path


INCLUDED = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo
from launch.substitutions import LaunchConfiguration


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument("robot", default_value="burger", description="Which robot"),
        LogInfo(msg=["included with robot=", LaunchConfiguration("robot")]),
    ])
"""

MAIN = """
import os
from launch import LaunchDescription
from launch.actions import (DeclareLaunchArgument, ExecuteProcess, GroupAction, IncludeLaunchDescription, LogInfo,
    OpaqueFunction, RegisterEventHandler, SetEnvironmentVariable, AppendEnvironmentVariable, TimerAction)
from launch.conditions import IfCondition, UnlessCondition
from launch.event_handlers import OnProcessExit
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import (Command, EnvironmentVariable, FindExecutable, LaunchConfiguration,
    PathJoinSubstitution, PythonExpression, TextSubstitution, ThisLaunchFileDir)
from launch_ros.actions import Node, PushRosNamespace, SetParameter, SetRemap
from launch_ros.parameter_descriptions import ParameterValue
from launch_ros.substitutions import FindPackageShare


def say(context, word):
    return [LogInfo(msg="opaque says " + word + " with use_sim_time=" + context.launch_configurations["use_sim_time"])]


def generate_launch_description():
    use_sim_time = LaunchConfiguration("use_sim_time")
    first = ExecuteProcess(cmd=[FindExecutable(name="python3"), "-c", "print('first ran')"], name="first", output="screen")
    description = ParameterValue(Command(["echo ", "<robot name='r'/>"]), value_type=str)
    return LaunchDescription([
        DeclareLaunchArgument("use_sim_time", default_value="false", description="Use simulation (Gazebo) clock if true"),
        DeclareLaunchArgument("namespace", default_value="r1", description="Robot namespace"),
        SetEnvironmentVariable("GREETING", "hello"),
        AppendEnvironmentVariable("GREETING", "world", separator=" "),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(PathJoinSubstitution([ThisLaunchFileDir(), "included.launch.py"])),
            launch_arguments={"robot": "waffle"}.items(),
        ),
        LogInfo(msg="sim time on", condition=IfCondition(use_sim_time)),
        LogInfo(msg="sim time off", condition=UnlessCondition(use_sim_time)),
        LogInfo(msg=["twice two is ", PythonExpression(["2 * ", "2"])]),
        LogInfo(msg=["share is ", FindPackageShare("demo_pkg")]),
        LogInfo(msg=["home is ", EnvironmentVariable("HOME")]),
        OpaqueFunction(function=say, args=["hi"]),
        first,
        RegisterEventHandler(OnProcessExit(target_action=first, on_exit=[LogInfo(msg="after first exited")])),
        GroupAction([
            PushRosNamespace(LaunchConfiguration("namespace")),
            SetParameter(name="use_sim_time", value=use_sim_time),
            SetRemap(src="/cmd_vel", dst="cmd_vel_nav"),
            Node(package="demo_pkg", executable="echo_args", name="talker", output="screen",
                 parameters=[{"robot_description": description, "rate": 10.5}],
                 remappings=[("/odom", "odom_raw")], arguments=["--flag"]),
        ]),
        Node(package="demo_pkg", executable="echo_args", name="outside", output="screen"),
        TimerAction(period=0.5, actions=[LogInfo(msg="timer fired")]),
    ])
"""


def test_a_launch_file_with_includes_conditions_events_groups_and_nodes(tmp_path, prefix):
    launch_dir = prefix / "share" / "demo_pkg" / "launch"
    write(launch_dir / "included.launch.py", INCLUDED)
    write(launch_dir / "main.launch.py", MAIN)
    out = ros2(["launch", "demo_pkg", "main.launch.py", "use_sim_time:=true"], prefix)
    text = out.stdout + out.stderr
    assert out.returncode == 0, text
    for line in (
        "[INFO] [launch.user]: included with robot=waffle",
        "[INFO] [launch.user]: sim time on",
        "[INFO] [launch.user]: twice two is 4",
        f"[INFO] [launch.user]: share is {prefix / 'share' / 'demo_pkg'}",
        "[INFO] [launch.user]: opaque says hi with use_sim_time=true",
        "[first-1] first ran",
        "[INFO] [launch.user]: after first exited",
        "[INFO] [launch.user]: timer fired",
    ):
        assert line in text, f"missing {line!r} in:\n{text}"
    assert "sim time off" not in text
    # the output prefix is the executable's name, as ros2 launch prints it ([echo_args-2])
    talker = [ln for ln in text.splitlines() if ln.startswith("[echo_args-") and "__node:=talker" in ln]
    args = json.loads(talker[0].split("ARGS ", 1)[1])
    assert args[0] == "--flag" and args[1] == "--ros-args"
    ros = " ".join(args[2:])
    assert "-r __node:=talker" in ros and "-r __ns:=/r1" in ros
    assert "-r /cmd_vel:=cmd_vel_nav" in ros and "-r /odom:=odom_raw" in ros
    proc = talker[0].split("]", 1)[0] + "]"
    params = " ".join(ln for ln in text.splitlines() if ln.startswith(proc) and "PARAMS" in ln)
    assert "use_sim_time: true" in params and "rate: 10.5" in params
    assert "robot_description: '<robot name=r/>" in params  # the Command's output (shlex-split), a string
    assert f"{proc} ENV hello world" in text
    outside = [ln for ln in text.splitlines() if "__node:=outside" in ln]
    assert "__ns" not in outside[0]  # the group's namespace stayed inside the group


GZ_ROS2_CONTROL_DEMO = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    # Launch Arguments
    use_sim_time = LaunchConfiguration('use_sim_time', default=True)
    params = {'robot_description': '<robot name="r"/>', 'use_sim_time': use_sim_time}
    node_robot_state_publisher = Node(
        package='demo_pkg', executable='echo_args', output='screen', parameters=[params])
    return LaunchDescription([
        node_robot_state_publisher,
        LogInfo(msg=['use_sim_time=', use_sim_time, ' gui=', LaunchConfiguration('gui', default=False),
                     ' mixed=', LaunchConfiguration('mixed', default=[1, '-', 2.5])]),
        LogInfo(msg='sim clock', condition=IfCondition(use_sim_time)),
        # Launch Arguments
        DeclareLaunchArgument(
            'use_sim_time',
            default_value=use_sim_time,
            description='If true, use simulated clock'),
    ])
"""


def test_a_launch_configuration_default_that_is_not_text_is_its_text_as_in_launch(prefix):
    """gz_ros2_control's demos write ``LaunchConfiguration('use_sim_time', default=True)`` and declare the
    argument with it as its own default: launch turns the bool into the text ``True``
    (launch/substitutions/launch_configuration.py)."""
    write(prefix / "share" / "demo_pkg" / "launch" / "demo.launch.py", GZ_ROS2_CONTROL_DEMO)
    out = ros2(["launch", "demo_pkg", "demo.launch.py"], prefix)
    text = out.stdout + out.stderr
    assert out.returncode == 0, text
    assert "Traceback" not in text
    for line in (
        "[INFO] [launch.user]: use_sim_time=True gui=False mixed=1-2.5",
        "[INFO] [launch.user]: sim clock",
    ):
        assert line in text, f"missing {line!r} in:\n{text}"
    params = " ".join(ln for ln in text.splitlines() if ln.startswith("[echo_args-") and "PARAMS" in ln)
    assert "use_sim_time: true" in params, text
    # the argument it declares still takes a value from the command line
    out = ros2(["launch", "demo_pkg", "demo.launch.py", "use_sim_time:=false"], prefix)
    text = out.stdout + out.stderr
    assert out.returncode == 0 and "use_sim_time=false gui=False" in text and "sim clock" not in text, text
    params = " ".join(ln for ln in text.splitlines() if ln.startswith("[echo_args-") and "PARAMS" in ln)
    assert "use_sim_time: false" in params, text


def test_equals_substitutions_take_bools_numbers_and_none_as_in_launch(prefix):
    """launch's EqualsSubstitution (launch/substitutions/equals_substitution.py) writes a bool operand as
    ``true``/``false``, None as ``''``, anything else with ``str()``, and compares two bools as bools and two
    numbers as numbers; NotEqualsSubstitution is its negation (``IfCondition(EqualsSubstitution(
    LaunchConfiguration('use_sim_time'), True))`` in Jazzy launch files)."""
    write(
        prefix / "share" / "demo_pkg" / "launch" / "equals.launch.py",
        """
        from launch import LaunchDescription
        from launch.actions import DeclareLaunchArgument, LogInfo
        from launch.conditions import IfCondition
        from launch.substitutions import EqualsSubstitution, LaunchConfiguration, NotEqualsSubstitution


        def generate_launch_description():
            sim = LaunchConfiguration('use_sim_time')
            return LaunchDescription([
                DeclareLaunchArgument('use_sim_time', default_value='1'),
                LogInfo(msg='sim clock', condition=IfCondition(EqualsSubstitution(sim, True))),
                LogInfo(msg=['equals ', EqualsSubstitution('1.0', 1), ' ', EqualsSubstitution(None, ''), ' ',
                             EqualsSubstitution('a', 'b'), ' ', NotEqualsSubstitution(sim, False)]),
            ])
        """,
    )
    out = ros2(["launch", "demo_pkg", "equals.launch.py"], prefix)
    text = out.stdout + out.stderr
    assert out.returncode == 0, text
    assert "[INFO] [launch.user]: sim clock" in text and "[INFO] [launch.user]: equals true true false true" in text


def test_a_bool_where_launch_takes_only_text_is_refused_as_in_launch_with_the_line(prefix):
    """``DeclareLaunchArgument(default_value=True)`` fails in ROS 2's launch too (its
    normalize_to_list_of_substitutions takes text and substitutions only): refused, the user's line and
    what was given named."""
    write(
        prefix / "share" / "demo_pkg" / "launch" / "bool.launch.py",
        """
        from launch import LaunchDescription
        from launch.actions import DeclareLaunchArgument


        def generate_launch_description():
            return LaunchDescription([DeclareLaunchArgument('use_sim_time', default_value=True)])
        """,
    )
    out = ros2(["launch", "demo_pkg", "bool.launch.py"], prefix)
    assert out.returncode == 1
    assert 'bool.launch.py", line 7, in generate_launch_description' in out.stderr, out.stderr
    assert "expected a string, a substitution or a list of them, got bool: True" in out.stderr, out.stderr


def test_show_args_lists_the_arguments_of_the_file_and_its_includes(prefix):
    launch_dir = prefix / "share" / "demo_pkg" / "launch"
    write(launch_dir / "included.launch.py", INCLUDED)
    write(launch_dir / "main.launch.py", MAIN)
    out = ros2(["launch", "demo_pkg", "main.launch.py", "--show-args"], prefix)
    assert out.returncode == 0, out.stderr
    assert "'use_sim_time':" in out.stdout and "Use simulation (Gazebo) clock if true" in out.stdout
    assert "(default: 'false')" in out.stdout and "'robot':" in out.stdout


@pytest.mark.parametrize(
    "args, expected",
    [
        (["launch", "no_such_pkg", "x.launch.py"], "Package 'no_such_pkg' not found"),
        (["launch", "demo_pkg", "missing.launch.py"], "file 'missing.launch.py' was not found in the share directory"),
        (["run", "no_such_pkg", "x"], "Package 'no_such_pkg' not found"),
        (["run", "demo_pkg", "no_such_exe"], "No executable found"),
        (
            ["doctor"],
            "invalid choice: 'doctor' (choose from 'action', 'bag', 'control', 'daemon', 'interface', 'launch', 'node', 'param'",
        ),
    ],
)
def test_bad_input_is_a_clear_error_without_a_traceback_of_ours(prefix, args, expected):
    write(prefix / "share" / "demo_pkg" / "launch" / "main.launch.py", INCLUDED)
    out = ros2(args, prefix)
    assert out.returncode != 0
    assert expected in out.stdout + out.stderr
    assert "Traceback" not in out.stderr


def test_an_argument_the_launch_file_does_not_declare_is_taken_as_ros2_launch_takes_it(prefix):
    """ros2launch (Jazzy api.py ``launch_a_launch_file``) includes the file with every argument, and launch's
    IncludeLaunchDescription sets each as a launch configuration, checking only that the declared ones without a
    default are given: ``launch_rviz:=false`` to a file that declares no ``launch_rviz`` runs, and a substitution
    of an undeclared one reads its value. gazelle refused it ("not declared by ...") and exited 1 (issue 51)."""
    write(
        prefix / "share" / "demo_pkg" / "launch" / "main.launch.py",
        INCLUDED.replace(
            'LogInfo(msg=["included',
            'LogInfo(msg=["colour=", LaunchConfiguration("colour")]),\n        LogInfo(msg=["included',
        ),
    )
    out = ros2(["launch", "demo_pkg", "main.launch.py", "launch_rviz:=false", "colour:=red"], prefix)
    assert out.returncode == 0, out.stdout + out.stderr
    said = out.stdout + out.stderr
    assert "colour=red" in said and "included with robot=burger" in said, said


MOVEIT_LIKE = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess, LogInfo, RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch.substitutions import FindExecutable, LaunchConfiguration


def generate_launch_description():
    ld = LaunchDescription()
    ld.add_entity(LaunchDescription([DeclareLaunchArgument("warehouse_path", default_value="/tmp/w.sqlite")]))
    wait = ExecuteProcess(cmd=[FindExecutable(name="python3"), "-c", "print('waited')"], output="screen")
    ld.add_action(wait)
    ld.add_action(RegisterEventHandler(OnProcessExit(target_action=wait, on_exit=[
        LogInfo(msg=["after the wait: warehouse=", LaunchConfiguration("warehouse_path"),
                     " use_sim_time=", LaunchConfiguration("use_sim_time")]),
    ])))
    return ld
"""

OUTER = """
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription, LogInfo
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution, ThisLaunchFileDir


def generate_launch_description():
    return LaunchDescription([
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(PathJoinSubstitution([ThisLaunchFileDir(), "moveit_like.launch.py"])),
            launch_arguments={"use_sim_time": "true"}.items(),
        ),
        LogInfo(msg=["after the include: use_sim_time=", LaunchConfiguration("use_sim_time")]),
    ])
"""


def test_an_included_files_configurations_stay_set_after_it_as_in_jazzys_launch(prefix):
    """Jazzy's IncludeLaunchDescription (launch/actions/include_launch_description.py ``execute``) returns its
    arguments' SetLaunchConfiguration actions and the description, with no push or pop of the configurations: what
    the included file declares or is given stays set after it, and an action its event handler starts later reads it.
    ur_moveit_config's ur_moveit.launch.py starts move_group when ``wait_for_robot_description`` exits, with
    ``LaunchConfiguration("warehouse_sqlite_path")`` and ``use_sim_time`` from ur_sim_moveit.launch.py's include:
    gazelle scoped an include's configurations, so that stopped at "launch configuration 'warehouse_sqlite_path'
    does not exist" (issue 51)."""
    launch_dir = prefix / "share" / "demo_pkg" / "launch"
    write(launch_dir / "moveit_like.launch.py", MOVEIT_LIKE)
    write(launch_dir / "outer.launch.py", OUTER)
    out = ros2(["launch", "demo_pkg", "outer.launch.py"], prefix)
    said = out.stdout + out.stderr
    assert out.returncode == 0, said
    assert "after the include: use_sim_time=true" in said, said
    assert "after the wait: warehouse=/tmp/w.sqlite use_sim_time=true" in said, said


def test_a_launch_file_that_raises_shows_the_users_traceback(prefix):
    write(
        prefix / "share" / "demo_pkg" / "launch" / "bad.launch.py",
        """
        from launch import LaunchDescription


        def generate_launch_description():
            robots = {"burger": 1}
            return LaunchDescription([robots["waffle"]])
        """,
    )
    out = ros2(["launch", "demo_pkg", "bad.launch.py"], prefix)
    assert out.returncode == 1
    assert 'bad.launch.py", line 7, in generate_launch_description' in out.stderr
    assert "KeyError: 'waffle'" in out.stderr
    assert "gazelle" not in out.stderr.split("Traceback", 1)[-1]  # only the user's frames


def test_an_unsupported_launch_api_names_itself_and_the_line(prefix):
    write(
        prefix / "share" / "demo_pkg" / "launch" / "each.launch.py",
        """
        from launch import LaunchDescription
        from launch.actions import ForEach


        def generate_launch_description():
            return LaunchDescription([ForEach([1], function=print)])
        """,
    )
    out = ros2(["launch", "demo_pkg", "each.launch.py"], prefix)
    assert out.returncode == 1
    assert "launch.actions.ForEach is not supported by gazelle's launch yet" in out.stderr
    assert 'each.launch.py", line 7' in out.stderr


def test_ros2_run_finds_lib_and_colcon_bin_executables_and_pkg_lists_them(tmp_path, prefix):
    out = ros2(["run", "demo_pkg", "echo_args", "a", "b"], prefix)
    assert out.returncode == 0 and 'ARGS ["a", "b"]' in out.stdout
    # an ament_python package built by colcon without setup.cfg: its scripts land in <prefix>/bin
    ws = tmp_path / "ws_install" / "blogpkg"
    (ws / "share" / "ament_index" / "resource_index" / "packages").mkdir(parents=True)
    (ws / "share" / "ament_index" / "resource_index" / "packages" / "blogpkg").write_text("")
    (ws / "bin").mkdir()
    (ws / "bin" / "node").write_text(ECHO_ARGS.format(python=sys.executable))
    (ws / "bin" / "node").chmod(0o755)
    env_prefix = f"{ws}{os.pathsep}{prefix}"
    out = ros2(["run", "blogpkg", "node", "x"], Path(env_prefix))
    assert out.returncode == 0 and 'ARGS ["x"]' in out.stdout
    listed = ros2(["pkg", "executables", "demo_pkg"], prefix)
    assert listed.stdout.strip() == "demo_pkg echo_args"
    assert "demo_pkg" in ros2(["pkg", "list"], prefix).stdout.split()


def test_ctrl_c_stops_the_whole_tree_within_5_s(tmp_path, prefix):
    write(
        prefix / "share" / "demo_pkg" / "launch" / "sleepers.launch.py",
        """
        from launch import LaunchDescription
        from launch.actions import ExecuteProcess


        def generate_launch_description():
            stubborn = "import signal, time; signal.signal(signal.SIGINT, signal.SIG_IGN); print('up', flush=True); time.sleep(60)"
            return LaunchDescription([
                ExecuteProcess(cmd=["python3", "-c", "import time; print('up', flush=True); time.sleep(60)"], output="screen"),
                ExecuteProcess(cmd=["python3", "-c", stubborn], name="stubborn", output="screen"),
            ])
        """,
    )
    env = dict(os.environ, AMENT_PREFIX_PATH=f"{prefix}{os.pathsep}{sys.prefix}")
    proc = subprocess.Popen(
        [*ROS2, "launch", "demo_pkg", "sleepers.launch.py"],
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        env=env,
    )
    lines: list[str] = []
    assert proc.stdout is not None
    deadline = time.monotonic() + 30
    while sum("] up" in ln for ln in lines) < 2 and time.monotonic() < deadline:
        lines.append(proc.stdout.readline())
    pids = [int(ln.split("pid [")[1].split("]")[0]) for ln in lines if "process started with pid" in ln]
    assert len(pids) == 2, "".join(lines)
    t0 = time.monotonic()
    proc.send_signal(signal.SIGINT)
    rest, _ = proc.communicate(timeout=10)
    elapsed = time.monotonic() - t0
    assert elapsed < 5.0, f"took {elapsed:.1f} s"
    assert "user interrupted with ctrl-c (SIGINT)" in rest
    for pid in pids:
        with pytest.raises(ProcessLookupError):
            os.kill(pid, 0)


def test_gazelle_launch_and_run_are_the_ros2_verbs(prefix):
    env = dict(os.environ, AMENT_PREFIX_PATH=f"{prefix}{os.pathsep}{sys.prefix}")
    gazelle = [sys.executable, "-m", "gazelle.cli"]
    out = subprocess.run([*gazelle, "run", "demo_pkg", "echo_args", "z"], capture_output=True, text=True, env=env)
    assert out.returncode == 0 and 'ARGS ["z"]' in out.stdout
    write(prefix / "share" / "demo_pkg" / "launch" / "one.launch.py", INCLUDED)
    out = subprocess.run(
        [*gazelle, "launch", "demo_pkg", "one.launch.py", "robot:=waffle"], capture_output=True, text=True, env=env
    )
    assert out.returncode == 0 and "included with robot=waffle" in out.stderr


def test_a_failing_required_process_is_reported_and_shuts_the_launch_down(prefix):
    (prefix / "share" / "demo_pkg" / "config").mkdir()
    (prefix / "share" / "demo_pkg" / "config" / "p.yaml").write_text("/**:\n  ros__parameters:\n    speed: 2.5\n")
    write(
        prefix / "share" / "demo_pkg" / "launch" / "required.launch.py",
        """
        import os
        from launch import LaunchDescription
        from launch.actions import ExecuteProcess, LogInfo, RegisterEventHandler, Shutdown
        from launch.event_handlers import OnProcessStart, OnShutdown
        from launch_ros.actions import Node
        from launch_ros.parameter_descriptions import ParameterFile
        from launch_ros.substitutions import FindPackageShare
        from launch.substitutions import PathJoinSubstitution


        def generate_launch_description():
            sleeper = ExecuteProcess(cmd=["python3", "-c", "import time; time.sleep(60)"], name="sleeper")
            params = ParameterFile(PathJoinSubstitution([FindPackageShare("demo_pkg"), "config", "p.yaml"]))
            return LaunchDescription([
                sleeper,
                RegisterEventHandler(OnProcessStart(target_action=sleeper, on_start=[LogInfo(msg="sleeper is up")])),
                RegisterEventHandler(OnShutdown(on_shutdown=[LogInfo(msg="shutting down now")])),
                Node(package="demo_pkg", executable="echo_args", name="reader", parameters=[params], output="screen"),
                ExecuteProcess(cmd=["python3", "-c", "import sys, time; time.sleep(0.5); sys.exit(3)"],
                               name="required", on_exit=Shutdown(reason="required process died")),
            ])
        """,
    )
    t0 = time.monotonic()
    out = ros2(["launch", "demo_pkg", "required.launch.py"], prefix)
    text = out.stdout + out.stderr
    assert time.monotonic() - t0 < 20, text  # the sleeper did not keep it alive for 60 s
    assert "[INFO] [launch.user]: sleeper is up" in text
    assert "[ERROR] [required-" in text and "process has died" in text and "exit code 3" in text
    assert "[INFO] [launch.user]: shutting down now" in text
    assert "PARAMS /**:|  ros__parameters:|    speed: 2.5|" in text  # the ParameterFile reached the node


def test_gazebo_ros_paths_for_launch_files_that_import_it(prefix):
    code = "from gazebo_ros import GazeboRosPaths; m, p, r = GazeboRosPaths.get_paths(); print(m); print(p)"
    env = dict(os.environ, AMENT_PREFIX_PATH=f"{prefix}{os.pathsep}{sys.prefix}", GAZEBO_MODEL_PATH="/mine")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    assert out.returncode == 0, out.stderr
    model, plugin = out.stdout.splitlines()
    assert model.split(os.pathsep)[0] == "/mine" and str(prefix / "share") in model.split(os.pathsep)
    assert str(prefix / "lib") in plugin.split(os.pathsep)


def test_respawn_restarts_a_process_and_xacro_runs_with_ros2_run(prefix, tmp_path):
    counter = tmp_path / "count.txt"
    write(
        prefix / "share" / "demo_pkg" / "launch" / "respawn.launch.py",
        f"""
        from launch import LaunchDescription
        from launch.actions import ExecuteProcess, RegisterEventHandler, Shutdown, TimerAction
        from launch.event_handlers import OnProcessExit

        COUNT = {str(counter)!r}
        CODE = "import os; p = COUNT; n = int(open(p).read()) + 1 if os.path.exists(p) else 1; open(p, 'w').write(str(n))"


        def generate_launch_description():
            flaky = ExecuteProcess(cmd=["python3", "-c", CODE.replace("COUNT", repr(COUNT))], name="flaky",
                                   respawn=True, respawn_delay=0.2)
            # enough once it has run three times (counted, not timed: a busy machine starts it slowly)
            enough = OnProcessExit(
                target_action=flaky,
                on_exit=lambda event, context: [Shutdown(reason="enough")] if int(open(COUNT).read()) >= 3 else [],
            )
            return LaunchDescription([
                flaky,
                RegisterEventHandler(enough),
                TimerAction(period=60.0, actions=[Shutdown(reason="too long")]),
            ])
        """,
    )
    out = ros2(["launch", "demo_pkg", "respawn.launch.py"], prefix)
    assert out.returncode == 0, out.stderr
    assert int(counter.read_text()) >= 3  # it ran, exited, and was started again, until the shutdown
    assert "[INFO] [flaky-2]: process started" in out.stderr
    xacro_file = tmp_path / "r.urdf.xacro"
    xacro_file.write_text(
        '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:property name="w" value="0.5"/>'
        '<link name="base"><visual><geometry><box size="${w} 1 1"/></geometry></visual></link></robot>'
    )
    expanded = ros2(["run", "xacro", "xacro", str(xacro_file)], prefix)
    assert expanded.returncode == 0, expanded.stderr
    assert '<box size="0.5 1 1"/>' in expanded.stdout


def test_launch_prefix_goes_before_the_executables_its_filter_matches(prefix):
    """ros2launch Jazzy's --launch-prefix and --launch-prefix-filter (launch/descriptions/executable.py: the
    'launch-prefix' configuration before every executable whose file name the filter matches); gazelle took
    the option and dropped it."""
    write(
        prefix / "share" / "demo_pkg" / "launch" / "two.launch.py",
        """
        from launch import LaunchDescription
        from launch.actions import ExecuteProcess
        from launch_ros.actions import Node


        def generate_launch_description():
            return LaunchDescription([
                Node(package="demo_pkg", executable="echo_args", name="node", output="screen"),
                ExecuteProcess(cmd=["python3", "-c", "import os; print('PLAIN ' + os.environ.get('GREETING', '-'))"],
                               output="screen"),
            ])
        """,
    )
    every = ros2(["launch", "demo_pkg", "two.launch.py", "--launch-prefix", "env GREETING=hello"], prefix)
    text = every.stdout + every.stderr
    assert every.returncode == 0 and "ENV hello" in text and "PLAIN hello" in text, text
    filtered = ros2(
        [
            "launch",
            "demo_pkg",
            "two.launch.py",
            "--launch-prefix",
            "env GREETING=hi",
            "--launch-prefix-filter",
            "echo_",
        ],
        prefix,
    )
    text = filtered.stdout + filtered.stderr
    assert filtered.returncode == 0 and "ENV hi" in text and "PLAIN -" in text, text
    alone = ros2(["launch", "demo_pkg", "two.launch.py", "--launch-prefix-filter", "echo_"], prefix)
    assert alone.returncode == 2 and "--launch-prefix must be specified" in alone.stderr, alone.stderr


STARTING_CHILD = """
import sys
from launch import LaunchDescription
from launch.actions import ExecuteProcess, TimerAction
from launch_ros.actions import Node


def generate_launch_description():
    slow = ExecuteProcess(cmd=[sys.executable, "-c", "print('never')"], name="starting",
                          additional_env={{"PYTHONPATH": "{site}"}}, output="screen")
    return LaunchDescription([slow, TimerAction(period=1.0, actions=[Node(package="no_such_pkg", executable="x")])])
"""


def test_a_child_interrupted_while_python_starts_is_one_line(tmp_path: Path) -> None:
    """Issue 55 item 9: when a launch aborts, a child still importing Python's site module gets the SIGINT there
    and Python prints `Fatal Python error: init_import_site` and a traceback of importlib frames; one line says it."""
    site = tmp_path / "site"
    site.mkdir()
    # sitecustomize is imported by site at start-up: this child is inside that import when the launch aborts
    (site / "sitecustomize.py").write_text("import time\ntime.sleep(30)\n")
    launch_file = write(tmp_path / "starting.launch.py", STARTING_CHILD.format(site=site))
    result = ros2(["launch", str(launch_file)])
    out = result.stdout + result.stderr
    assert "Package 'no_such_pkg' not found" in out, out
    lines = [line for line in out.splitlines() if line.startswith("[starting-1] ")]
    assert lines == ["[starting-1] interrupted while Python was starting (the launch was shutting down)"], out
    assert "Traceback" not in out and "init_import_site" not in out, out
