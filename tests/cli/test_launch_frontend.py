"""gazelle's launch XML and YAML front end (launch.frontend, issue 49), against Jazzy's launch_xml / launch_yaml
semantics: the substitution language of launch's grammar.lark, each tag as launch's and launch_ros's ``parse``
classmethods read it, and errors as one line naming the file and line. The tags run through the real
``ros2 launch`` on a package of our own (tests/cli/test_launch.py's ``echo_args`` prints its command line,
parameters file and environment)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from launch.frontend import InvalidFrontendLaunchFileError, load_frontend_launch_description, parse_substitution
from launch.launch_context import LaunchContext
from launch.utilities import perform_substitutions

from .test_launch import ECHO_ARGS, ros2, write


@pytest.fixture
def prefix(tmp_path: Path) -> Path:
    """An install prefix with package demo_pkg (share/demo_pkg/launch, lib/demo_pkg/echo_args)."""
    root = tmp_path / "install"
    index = root / "share" / "ament_index" / "resource_index" / "packages"
    index.mkdir(parents=True)
    (index / "demo_pkg").write_text("")
    (root / "share" / "demo_pkg" / "launch").mkdir(parents=True)
    (root / "lib" / "demo_pkg").mkdir(parents=True)
    exe = root / "lib" / "demo_pkg" / "echo_args"
    exe.write_text(ECHO_ARGS.format(python=sys.executable))
    exe.chmod(0o755)
    return root


def _context(tmp_path: Path) -> LaunchContext:
    ctx = LaunchContext()
    ctx.launch_configurations.update({"x": "ex", "pkg": "demo_pkg", "on": "true"})
    ctx.environment.update({"GZL_SET": "set value"})
    ctx.environment.pop("GZL_UNSET", None)
    ctx.extend_locals(
        {"current_launch_file_path": str(tmp_path / "f.launch.xml"), "current_launch_file_directory": str(tmp_path)}
    )
    return ctx


@pytest.mark.parametrize(
    "text, expected",
    [
        ("plain text", "plain text"),
        ("", ""),
        ("$(var x)", "ex"),
        ("a $(var x) b", "a ex b"),
        ("$(var nope 'a default')", "a default"),
        ("$(var nope fallback)", "fallback"),
        ("$(env GZL_SET)", "set value"),
        ("[$(env GZL_UNSET 'd e f')]", "[d e f]"),
        ("[$(optenv GZL_UNSET)]", "[]"),
        ("$(optenv GZL_UNSET other)", "other"),
        ("$(optenv GZL_SET)", "set value"),
        ("$(command 'echo $(var x) there')", "ex there\n"),
        ("$(eval '2 * 3')", "6"),
        ("$(eval 'floor(2.7)')", "2"),
        ("$(eval 'os.sep' 'os')", "/"),
        ("$(eval \"'$(var x)' + '!'\")", "ex!"),
        ("$(not $(var on))", "false"),
        ("$(and true 0)", "false"),
        ("$(or false 1)", "true"),
        ("$(equals $(var x) ex)", "true"),
        ("$(not-equals 1.0 1)", "false"),
        ("$(if $(var on) yes no)", "yes"),
        ("\\$(var x)", "$(var x)"),
        ("a\\$b", "a$b"),
        ("cost $5", "cost $5"),
        ("$(var 'x')", "ex"),
        ('$(var "x")', "ex"),
    ],
)
def test_each_substitution_and_quoting_performs_as_in_launch(tmp_path, text, expected):
    assert perform_substitutions(_context(tmp_path), parse_substitution(text)) == expected


def test_path_substitutions_and_nesting(tmp_path, prefix, monkeypatch):
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(prefix))
    ctx = _context(tmp_path)

    def run(text: str) -> str:
        return perform_substitutions(ctx, parse_substitution(text))

    assert run("$(find-pkg-share demo_pkg)") == str(prefix / "share" / "demo_pkg")
    assert run("$(find-pkg-share $(var pkg))/launch") == str(prefix / "share" / "demo_pkg" / "launch")
    assert run("$(find-pkg-prefix demo_pkg)") == str(prefix)
    assert run("$(exec-in-pkg echo_args demo_pkg)") == str(prefix / "lib" / "demo_pkg" / "echo_args")
    assert run("$(find-exec sh)").endswith("/sh")
    assert run("$(dirname)/x") == f"{tmp_path}/x"
    assert run("$(filename)") == str(tmp_path / "f.launch.xml")
    anon = run("$(anon talker)")
    assert anon.startswith("talker_") and run("$(anon talker)") == anon


@pytest.mark.parametrize(
    "text, expected",
    [
        ("$(var x", "expected ')' or one space and an argument in $(var ...) at column 8"),
        ("$(var  x)", "expected an argument at column 7"),
        ("$()", "expected a substitution name after '$(' at column 3"),
        ("$(nosuch a)", "Unknown substitution: $(nosuch ...)"),
        ("$(var)", "$(var) takes 1 to 2 argument(s), got 0"),
        ("$(dirname x)", "$(dirname) takes 0 argument(s), got 1"),
        ("$(find-pkg-share a b)", "$(find-pkg-share) takes 1 argument (the package), got 2"),
        ("$(var 'x)", "no closing '"),
    ],
)
def test_substitution_syntax_errors_say_what_and_where(text, expected):
    with pytest.raises(ValueError) as err:
        parse_substitution(text)
    assert expected in str(err.value)


@pytest.mark.parametrize(
    "body, line, expected",
    [
        ('<log message="$(var x"/>', 3, "expected ')'"),
        ('<node pkg="a" exec="b" bogus="1"/>', 3, "Unexpected attribute(s) in <node>: bogus"),
        ("<group>\n<nope/>\n</group>", 4, "Unrecognized tag <nope>"),
        (
            '<node pkg="a" exec="b">\n<remap from="x" to="y"/>\n<extra/>\n</node>',
            5,
            "Unexpected nested tag <extra> in <node>",
        ),
        ('<node pkg="a" exec="b"><param name="p"/></node>', 3, "needs a value attribute or nested params"),
        ('<node pkg="a"/>', 3, "<node> needs the attribute 'exec'"),
        ('<log if="a" unless="b" message="m"/>', 3, "if and unless conditions can't be used simultaneously"),
        ('<include file="x.launch.py"><arg name="a"/></include>', 3, "<arg> needs the attribute 'value'"),
        ('<group ns="robot"/>', 3, "Unexpected attribute(s) in <group>: ns"),
        ('<node pkg="a" exec="b" respawn_delay="-1"/>', 3, "respawn_delay must not be negative"),
        ('<executable cmd="x" on_exit="restart"/>', 3, "on_exit must be 'shutdown'"),
        ('<node pkg="a" exec="b"><param name="p" value="1" type="complex"/></node>', 3, "invalid type identifier"),
        ("<log message='a'>", 4, "not well-formed XML"),
    ],
)
def test_an_xml_error_is_one_line_naming_file_and_line(tmp_path, body, line, expected):
    path = tmp_path / "bad.launch.xml"
    path.write_text(f'<?xml version="1.0"?>\n<launch>\n{body}\n</launch>\n')
    with pytest.raises(InvalidFrontendLaunchFileError) as err:
        load_frontend_launch_description(str(path))
    message = str(err.value)
    assert message.startswith(f"{path}:{line}: "), message
    assert expected in message and "\n" not in message


@pytest.mark.parametrize(
    "body, line, expected",
    [
        ("- log: {message: hi, colour: red}", 3, "Unexpected key(s) in `log`: colour"),
        ("- nope: {a: 1}", 3, "Unrecognized tag <nope>"),
        ("- arg: {name: x, default: true}", 3, "Attribute 'default' of `arg` must be str, got bool"),
        ("- log: {message: hi}\n- node:\n    pkg: a", 4, "`node` needs the attribute 'exec'"),
        ("- log: [unclosed", 4, "not valid YAML"),  # the line where YAML finds the list unclosed
    ],
)
def test_a_yaml_error_is_one_line_naming_file_and_line(tmp_path, body, line, expected):
    path = tmp_path / "bad.launch.yaml"
    path.write_text(f"# a yaml launch file\nlaunch:\n{body}\n")
    with pytest.raises(InvalidFrontendLaunchFileError) as err:
        load_frontend_launch_description(str(path))
    message = str(err.value).replace("<node>", "`node`")
    assert message.startswith(f"{path}:{line}: "), message
    assert expected in message


INCLUDED_XML = """\
<launch>
  <arg name="robot" default="burger" description="Which robot"/>
  <log message="included xml with robot=$(var robot) from $(dirname)"/>
</launch>
"""

INCLUDED_PY = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo
from launch.substitutions import LaunchConfiguration


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument("colour", default_value="red", description="A colour"),
        LogInfo(msg=["included py with colour=", LaunchConfiguration("colour")]),
    ])
"""

MAIN_XML = """\
<launch>
  <arg name="use_sim_time" default="false" description="Use simulation (Gazebo) clock if true">
    <choice value="true"/>
    <choice value="false"/>
  </arg>
  <arg name="namespace" default="r1" description="Robot namespace"/>
  <let name="params" value="$(find-pkg-share demo_pkg)/launch/params.yaml"/>
  <set_env name="GREETING" value="hello"/>
  <append_env name="GREETING" value="world" separator=" "/>
  <set_env name="DROPPED" value="x"/>
  <unset_env name="DROPPED"/>
  <include file="$(dirname)/included.launch.xml">
    <arg name="robot" value="waffle"/>
  </include>
  <include file="$(find-pkg-share demo_pkg)/launch/included.launch.py">
    <arg name="colour" value="blue"/>
  </include>
  <log if="$(var use_sim_time)" message="sim time on"/>
  <log unless="$(var use_sim_time)" message="sim time off"/>
  <log message="dropped=[$(optenv DROPPED)]"/>
  <group>
    <push-ros-namespace namespace="$(var namespace)"/>
    <set_parameter name="use_sim_time" value="$(var use_sim_time)"/>
    <set_remap from="/cmd_vel" to="cmd_vel_nav"/>
    <let name="inner" value="scoped"/>
    <node pkg="demo_pkg" exec="echo_args" name="talker" output="screen" args="--flag $(var namespace)/x 'two words'">
      <param name="robot_description" value="$(command 'echo &lt;robot name=$(var namespace)/&gt;')"/>
      <param name="rate" value="10.5"/>
      <param name="frame" value="'007'"/>
      <param name="count" value="3" type="str"/>
      <param name="ids" value="1,2,3" value-sep=","/>
      <param name="gains">
        <param name="p" value="1.5"/>
        <param name="inner"><param name="i" value="0.1"/></param>
      </param>
      <param from="$(var params)"/>
      <remap from="/odom" to="odom_raw"/>
      <env name="NODE_ONLY" value="yes"/>
    </node>
  </group>
  <log message="inner after the group: [$(var inner '')]"/>
  <push_ros_namespace namespace="outer"/>
  <node pkg="demo_pkg" exec="echo_args" name="outside" namespace="/abs" ros_args="--log-level warn"/>
  <node pkg="demo_pkg" exec="echo_args" name="never" if="false" args="$(var undefined_never_performed)"/>
  <executable cmd="$(find-exec sh) -c 'echo exec ran with $A'" name="first" output="screen">
    <env name="A" value="$(var namespace)"/>
  </executable>
  <timer period="0.3"><log message="timer fired"/></timer>
</launch>
"""


def _xml_package(prefix: Path) -> Path:
    launch_dir = prefix / "share" / "demo_pkg" / "launch"
    write(launch_dir / "included.launch.xml", INCLUDED_XML)
    write(launch_dir / "included.launch.py", INCLUDED_PY)
    write(launch_dir / "params.yaml", "/**:\n  ros__parameters:\n    from_file: 42\n")
    write(launch_dir / "main.launch.xml", MAIN_XML)
    return launch_dir


def _lines_of(text: str, marker: str) -> list[str]:
    return [ln for ln in text.splitlines() if marker in ln]


def test_an_xml_launch_file_runs_every_tag_as_jazzy(prefix):
    launch_dir = _xml_package(prefix)
    out = ros2(["launch", "demo_pkg", "main.launch.xml", "use_sim_time:=true"], prefix)
    text = out.stdout + out.stderr
    assert out.returncode == 0, text
    for line in (
        f"[INFO] [launch.user]: included xml with robot=waffle from {launch_dir}",
        "[INFO] [launch.user]: included py with colour=blue",
        "[INFO] [launch.user]: sim time on",
        "[INFO] [launch.user]: dropped=[]",
        "[INFO] [launch.user]: inner after the group: []",
        "[first-",
        "exec ran with r1",
        "[INFO] [launch.user]: timer fired",
    ):
        assert line in text, f"missing {line!r} in:\n{text}"
    assert "sim time off" not in text and "__node:=never" not in text
    talker = _lines_of(text, "__node:=talker")
    args = json.loads(talker[0].split("ARGS ", 1)[1])
    assert args[:4] == ["--flag", "r1/x", "two words", "--ros-args"]
    ros = " ".join(args[4:])
    assert "-r __ns:=/r1" in ros and "-r /cmd_vel:=cmd_vel_nav" in ros and "-r /odom:=odom_raw" in ros
    proc = talker[0].split("]", 1)[0] + "]"
    params = " ".join(ln for ln in text.splitlines() if ln.startswith(proc) and "PARAMS" in ln)
    for expected in (
        "use_sim_time: true",
        "rate: 10.5",
        "frame: '007'",
        "count: '3'",
        "ids: - 1 - 2 - 3",
        "gains: inner: i: 0.1 p: 1.5",
        "robot_description: <robot name=r1/>",
        "from_file: 42",
    ):
        assert expected in " ".join(params.replace("|", " ").split()), (expected, params)
    assert f"{proc} ENV hello world" in text
    outside = " ".join(json.loads(_lines_of(text, "__node:=outside")[0].split("ARGS ", 1)[1]))
    assert "-r __ns:=/abs" in outside and "--log-level warn" in outside


def test_show_args_and_arguments_of_an_xml_file(prefix):
    _xml_package(prefix)
    out = ros2(["launch", "demo_pkg", "main.launch.xml", "--show-args"], prefix)
    assert out.returncode == 0, out.stderr
    for expected in (
        "'use_sim_time':",
        "Use simulation (Gazebo) clock if true",
        "Valid choices are: ['true', 'false']",
        "(default: 'false')",
        "'robot':",
        "'colour':",
    ):
        assert expected in out.stdout, out.stdout
    bad = ros2(["launch", "demo_pkg", "main.launch.xml", "use_sim_time:=maybe"], prefix)
    assert bad.returncode != 0 and "Traceback" not in bad.stderr
    assert "provided value 'maybe' is not valid" in bad.stdout + bad.stderr


def test_a_python_launch_file_includes_an_xml_and_a_yaml_one(prefix):
    launch_dir = _xml_package(prefix)
    write(
        launch_dir / "included.launch.yaml",
        """\
        launch:
        - arg: {name: size, default: "2"}
        - log: {message: "included yaml with size=$(var size)"}
        """,
    )
    write(
        launch_dir / "main.launch.py",
        """
        from launch import LaunchDescription
        from launch.actions import IncludeLaunchDescription
        from launch.launch_description_sources import AnyLaunchDescriptionSource
        from launch_xml.launch_description_sources import XMLLaunchDescriptionSource
        from launch_yaml.launch_description_sources import YAMLLaunchDescriptionSource
        from launch.substitutions import PathJoinSubstitution, ThisLaunchFileDir


        def generate_launch_description():
            return LaunchDescription([
                IncludeLaunchDescription(XMLLaunchDescriptionSource(
                    PathJoinSubstitution([ThisLaunchFileDir(), "included.launch.xml"])),
                    launch_arguments={"robot": "py"}.items()),
                IncludeLaunchDescription(YAMLLaunchDescriptionSource(
                    PathJoinSubstitution([ThisLaunchFileDir(), "included.launch.yaml"])),
                    launch_arguments={"size": "3"}.items()),
                IncludeLaunchDescription(AnyLaunchDescriptionSource(
                    PathJoinSubstitution([ThisLaunchFileDir(), "included.launch.xml"]))),
            ])
        """,
    )
    out = ros2(["launch", "demo_pkg", "main.launch.py"], prefix)
    text = out.stdout + out.stderr
    assert out.returncode == 0, text
    assert f"included xml with robot=py from {launch_dir}" in text
    assert "included yaml with size=3" in text
    assert "included xml with robot=py" in text.split("included yaml", 1)[1]  # the include's value stays set


MAIN_YAML = """\
launch:
- arg:
    name: namespace
    default: r2
    description: Robot namespace
- let: {name: greeting, value: "hi $(var namespace)"}
- set_env: {name: GREETING, value: "$(var greeting)"}
- include:
    file: "$(dirname)/included.launch.xml"
    arg:
    - {name: robot, value: yaml}
- group:
    scoped: true
    children:
    - push_ros_namespace: {namespace: "$(var namespace)"}
    - node:
        pkg: demo_pkg
        exec: echo_args
        name: talker
        output: screen
        args: "--flag"
        param:
        - {name: rate, value: 2.5}
        - {name: names, value: [a, b]}
        - name: gains
          param:
          - {name: p, value: 3}
        - {from: "$(find-pkg-share demo_pkg)/launch/params.yaml"}
        remap:
        - {from: /odom, to: odom_raw}
- log: {if: "$(equals $(var namespace) r2)", message: "namespace is r2"}
- executable: {cmd: "$(find-exec sh) -c 'echo yaml exec'", output: screen}
"""


def test_a_yaml_launch_file_runs_as_jazzys_launch_yaml(prefix):
    launch_dir = _xml_package(prefix)
    write(launch_dir / "main.launch.yaml", MAIN_YAML)
    out = ros2(["launch", "demo_pkg", "main.launch.yaml"], prefix)
    text = out.stdout + out.stderr
    assert out.returncode == 0, text
    assert "included xml with robot=yaml" in text and "namespace is r2" in text and "yaml exec" in text
    talker = _lines_of(text, "__node:=talker")
    args = json.loads(talker[0].split("ARGS ", 1)[1])
    assert args[0] == "--flag" and "-r __ns:=/r2" in " ".join(args) and "-r /odom:=odom_raw" in " ".join(args)
    proc = talker[0].split("]", 1)[0] + "]"
    params = " ".join(ln for ln in text.splitlines() if ln.startswith(proc) and "PARAMS" in ln).replace("|", " ")
    for expected in ("rate: 2.5", "names: - a - b", "gains: p: 3", "from_file: 42"):
        assert expected in " ".join(params.split()), (expected, params)
    assert f"{proc} ENV hi r2" in text
    shown = ros2(["launch", "demo_pkg", "main.launch.yaml", "--show-args"], prefix)
    assert "'namespace':" in shown.stdout and "'robot':" in shown.stdout


def test_a_bad_xml_file_through_ros2_launch_is_one_line_without_a_traceback(prefix):
    launch_dir = prefix / "share" / "demo_pkg" / "launch"
    write(
        launch_dir / "bad.launch.xml",
        '<launch>\n  <arg name="x"/>\n  <node pkg="demo_pkg" exec="echo_args" colour="red"/>\n</launch>\n',
    )
    out = ros2(["launch", "demo_pkg", "bad.launch.xml"], prefix)
    assert out.returncode != 0 and "Traceback" not in out.stderr
    errors = [ln for ln in (out.stdout + out.stderr).splitlines() if "[ERROR]" in ln]
    assert errors == [f"[ERROR] [launch]: {launch_dir / 'bad.launch.xml'}:3: Unexpected attribute(s) in <node>: colour"]
    write(launch_dir / "late.launch.xml", '<launch>\n  <log message="$(var never_set)"/>\n</launch>\n')
    late = ros2(["launch", "demo_pkg", "late.launch.xml"], prefix)
    text = late.stdout + late.stderr
    assert late.returncode != 0 and "Traceback" not in text
    assert "launch configuration 'never_set' does not exist" in text
    assert f"in LogInfo made at {launch_dir / 'late.launch.xml'}:2" in text


def test_a_process_that_never_imports_launch_ros_reads_its_tags(tmp_path):
    """launch knows no launch_ros (issue 53: the reader imported it, a circle of ten files): launch_ros's tags and
    substitutions reach the reader through the ``launch.frontend.launch_extension`` entry point, as in Jazzy."""
    path = tmp_path / "n.launch.xml"
    path.write_text(
        '<launch>\n  <let name="p" value="$(find-pkg-prefix demo)"/>\n  <node pkg="demo" exec="e"/>\n</launch>\n'
    )
    code = (
        "import sys\n"
        "from launch.frontend import load_frontend_launch_description\n"
        "assert 'launch_ros' not in sys.modules\n"
        "print([type(e).__name__ for e in load_frontend_launch_description(sys.argv[1]).entities])\n"
    )
    out = subprocess.run([sys.executable, "-c", code, str(path)], capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "['SetLaunchConfiguration', 'Node']"


def test_an_extension_that_fails_to_load_is_one_warning_line(monkeypatch, capsys):
    import importlib.metadata

    from launch.frontend import expose

    declared = list(importlib.metadata.entry_points(group=expose.EXTENSION_GROUP))
    assert [(e.name, e.value) for e in declared] == [("launch_ros", "launch_ros")]
    broken = importlib.metadata.EntryPoint("broken", "no_such_launch_extension", expose.EXTENSION_GROUP)
    monkeypatch.setattr(importlib.metadata, "entry_points", lambda group: [broken, *declared])
    monkeypatch.setattr(expose, "_extensions_loaded", False)
    expose.load_launch_extensions()
    assert capsys.readouterr().err.splitlines() == [
        "[WARNING] [launch]: Failed to load the launch extension: broken: No module named 'no_such_launch_extension'"
    ]
    assert "node" in expose.action_parse_methods and "find-pkg-share" in expose.substitution_parse_methods
