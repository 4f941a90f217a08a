"""The payloads of the hardening trial of issue 25 (any ROS peer could read any file), each sent at the
layer that refuses it, in-process; the ROS-level ones are in tests/integration/test_hardening_ros.py."""

from __future__ import annotations

import os
import resource
import signal
import subprocess
import sys
import time
from pathlib import Path
from typing import Any, cast

import numpy as np
import pytest
from _paths import REAL, REPO
from _sim import new_simulation

from gazelle.description import (
    ModelLoadError,
    ResourceResolver,
    UntrustedInputError,
    load,
    load_string,
    read_regular_file,
    safe_load_bounded,
)
from gazelle.systems.ros2_control import (
    ControlError,
    ControllerManager,
    ParamsError,
    load_params,
    parse_params,
    valid_controller_name,
)

DIFFBOT_URDF = REAL / "ros2_control_diffbot" / "_xacro_expanded" / "diffbot.urdf"

# 693 bytes of YAML anchors that expand to millions of parameters (the trial's payload, same shape)
ANCHOR_BOMB = "\n".join(
    ["a: &a [" + ",".join(["x"] * 10) + "]"]
    + [f"{chr(98 + i)}: &{chr(98 + i)} [" + ",".join([f"*{chr(97 + i)}"] * 10) + "]" for i in range(7)]
    + ["controller_manager:", "  ros__parameters:", "    p: *h"]
)


def _manager(entity) -> ControllerManager:
    (cm,) = [s for s in entity.systems if isinstance(s, ControllerManager)]
    return cm


@pytest.fixture
def diffbot():
    sim = new_simulation()
    model = load(DIFFBOT_URDF).model
    entity = sim.spawn(model, name="diffbot")
    yield sim, _manager(entity)
    sim.stop()


# --------------------------------------------------------------------------- 1. params_file
def test_a_params_file_named_by_a_peer_is_read_only_from_the_resource_roots(diffbot, tmp_path: Path) -> None:
    _sim, cm = diffbot
    secret = tmp_path / "shadow"
    secret.write_text("root:*:19000:0:99999:7:::\n")
    for raw in (str(secret), "/etc/passwd", "../../../../etc/passwd"):
        with pytest.raises(ControlError) as info:
            cm.read_params_file(raw, "c.params_file: ")
        assert "not in a package or model folder gazelle may read" in str(info.value)
        assert "root:" not in str(info.value)


def test_a_fifo_a_device_and_an_anchor_bomb_are_refused_at_once(tmp_path: Path) -> None:
    fifo = tmp_path / "fifo.yaml"
    os.mkfifo(fifo)
    start = time.monotonic()
    for path, why in ((fifo, "not a regular file"), (Path("/dev/zero"), "not a regular file")):
        with pytest.raises(ParamsError) as info:
            load_params(path)
        assert why in str(info.value)
    bomb = tmp_path / "bomb.yaml"
    bomb.write_text(ANCHOR_BOMB)
    assert bomb.stat().st_size < 1000
    with pytest.raises(ParamsError) as info:
        load_params(bomb)
    assert "expands to more than" in str(info.value) and str(bomb) in str(info.value)
    assert time.monotonic() - start < 2.0


def test_a_refused_params_file_never_echoes_its_content(tmp_path: Path) -> None:
    f = tmp_path / "looks_like_shadow.yaml"
    f.write_text("root:*:19000:0:99999:7:::\n")
    with pytest.raises(ParamsError) as info:
        load_params(f)
    assert "root" not in str(info.value).replace(str(tmp_path), "")
    f.write_text("secret_key_material: [unclosed\n")
    with pytest.raises(ParamsError) as info:
        load_params(f)
    assert "secret_key_material" not in str(info.value) and ":2:" in str(info.value) or ":1:" in str(info.value)


def test_the_user_in_process_still_sets_a_params_file_anywhere(diffbot) -> None:
    _sim, cm = diffbot
    yaml = REAL / "ros2_control_diffbot" / "ros2_control_demo_example_2" / "config" / "diffbot_controllers.yaml"
    cm.set_parameter("diffbot_base_controller.params_file", str(yaml))
    cm.set_parameter("diffbot_base_controller.type", "diff_drive_controller/DiffDriveController")
    cm.load_controller("diffbot_base_controller")
    assert cm.controller_params("diffbot_base_controller")["wheel_separation"] == pytest.approx(0.10)


def test_a_peer_set_params_file_must_be_read_before_it_reaches_the_simulation(diffbot) -> None:
    _sim, cm = diffbot
    with pytest.raises(ControlError, match="was not read"):
        cm.set_parameter("c.params_file", "/etc/passwd", files={})


# --------------------------------------------------------------------------- 2. confinement
def test_parameters_in_a_string_description_resolve_against_no_folder(tmp_path: Path, monkeypatch, make_sim) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "c.yaml").write_text("controller_manager:\n  ros__parameters:\n    update_rate: 50\n")
    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", str(tmp_path))  # even a working directory that is a root
    text = DIFFBOT_URDF.read_text().replace(
        "</robot>",
        '<gazebo><plugin filename="libgazebo_ros2_control.so" name="gazebo_ros2_control">'
        "<parameters>c.yaml</parameters></plugin></gazebo></robot>",
    )
    sim = make_sim()
    try:
        model = load_string(text, source="<spawn_entity:diffbot>").model
        with pytest.raises(Exception) as info:
            sim.spawn(model, name="d")
        assert "c.yaml" in str(info.value) and "not in a package or model folder" in str(info.value)
        assert "d" not in sim.world.entities
    finally:
        sim.stop()


def test_a_package_folder_linking_to_etc_is_no_package_but_a_linked_package_is(tmp_path: Path) -> None:
    root = tmp_path / "res"
    root.mkdir()
    (root / "etcmodel").symlink_to("/etc")
    source = tmp_path / "src" / "my_robot"
    (source / "meshes").mkdir(parents=True)
    (source / "package.xml").write_text("<package><name>my_robot</name></package>")
    (source / "meshes" / "m.stl").write_text("solid x\nendsolid x\n")
    (root / "my_robot").symlink_to(source)  # an ament prefix's share/PKG -> /src/PKG
    resolver = ResourceResolver(extra_paths=[root], env={})
    assert resolver.find_package("etcmodel") is None
    assert resolver.resolve_uri("model://etcmodel/passwd") is None
    assert resolver.refused("model://etcmodel/passwd")
    assert "outside the folders files may be read from" in resolver.unresolved_reason("model://etcmodel/passwd")
    assert resolver.resolve_uri("package://my_robot/meshes/m.stl") == (source / "meshes" / "m.stl").resolve()
    assert resolver.allowed(source / "meshes" / "m.stl")
    urdf = (
        '<robot name="r"><link name="a"><collision><geometry><mesh filename="model://etcmodel/passwd"/>'
        "</geometry></collision></link></robot>"
    )
    result = load_string(urdf, resolver=resolver)
    collisions = result.model.links[0].collisions
    assert collisions == () or getattr(collisions[0].geometry, "path", None) is None
    assert "root:" not in " ".join(d.message for d in result.diagnostics)


# --------------------------------------------------------------------------- 3. name filters
def test_regex_bombs_in_a_name_filter_are_refused_without_holding_this_process() -> None:
    from gazelle.ros._entity_queries import _matching, _Refused

    names = [f"box_{i}" for i in range(50)] + ["aaaa"]
    assert _matching("^box_1[0-9]$", names) == [f"box_{i}" for i in range(10, 20)]
    rss0 = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    for pattern in ("a{4294967294}", "(?:(?:a{100}){100}){100}", "(a+)+$", "(?:a{1000}){1000}{1000}"):
        start = time.monotonic()
        try:
            _matching(pattern, ["a" * 5000 + "b"])
        except _Refused as err:
            assert "filters.filter" in str(err)
        assert time.monotonic() - start < 15.0, pattern
    assert resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - rss0 < 100_000  # KiB: nothing grew here
    with pytest.raises(_Refused, match="not a valid regular expression"):
        _matching("(", names)
    with pytest.raises(_Refused, match="characters"):
        from gazelle.ros._entity_queries import _check_filter

        _check_filter("a" * 5000)


# --------------------------------------------------------------------------- 4. wide trees
def _wide(n: int, fixed: bool = True) -> str:
    links = "".join(
        f'<link name="c{i}"><inertial><mass value="0.01"/><inertia ixx="1e-5" iyy="1e-5" izz="1e-5" ixy="0" ixz="0"'
        f' iyz="0"/></inertial><collision><geometry><box size="0.01 0.01 0.01"/></geometry></collision></link>'
        for i in range(n)
    )
    kind = "fixed" if fixed else "revolute"
    limit = "" if fixed else '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/>'
    joints = "".join(
        f'<joint name="j{i}" type="{kind}"><parent link="root"/><child link="c{i}"/>'
        f'<origin xyz="{i * 0.02} 0 0"/>{limit}</joint>'
        for i in range(n)
    )
    root = (
        '<link name="root"><inertial><mass value="1"/><inertia ixx="1e-2" iyy="1e-2" izz="1e-2" ixy="0" ixz="0"'
        ' iyz="0"/></inertial><collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>'
    )
    return f'<robot name="wide">{root}{links}{joints}</robot>'


def test_a_wide_fixed_tree_spawns_and_deletes_in_moments_and_a_wider_one_is_refused(make_sim) -> None:
    sim = make_sim()
    try:
        before = sim.world.entities.keys() - set()
        from gazelle.description import Pose

        start = time.monotonic()
        sim.spawn(load_string(_wide(999)).model, name="w", pose=Pose((0.0, 0.0, 1.0)))
        spawned = time.monotonic() - start
        start = time.monotonic()
        sim.delete("w")
        deleted = time.monotonic() - start
        assert spawned < 20.0 and deleted < 5.0, (spawned, deleted)
        with pytest.raises(Exception, match="1001 links, more than the 1000 a model may have"):
            sim.spawn(load_string(_wide(1000)).model, name="w2", pose=Pose((0.0, 0.0, 1.0)))
        assert set(sim.world.entities) == set(before)
        sim.step(10)  # still usable
    finally:
        sim.stop()


def test_many_moving_links_use_collision_bits_not_quadratic_excludes_and_never_self_collide(make_sim) -> None:
    from gazelle.description import Pose

    sim = make_sim()
    try:
        sim.spawn(load_string(_wide(120, fixed=False)).model, name="w", pose=Pose((0.0, 0.0, 0.5)))
        m = sim.world.model
        assert m.nexclude < 600
        sim.step(200)
        d = sim.world.data
        bodies = {b: m.body(b).name for b in range(m.nbody)}
        own = [
            (bodies[m.geom_bodyid[c.geom1]], bodies[m.geom_bodyid[c.geom2]])
            for c in d.contact[: d.ncon]
            if bodies[m.geom_bodyid[c.geom1]].startswith("w::") and bodies[m.geom_bodyid[c.geom2]].startswith("w::")
        ]
        assert own == []
        start = time.monotonic()
        sim.delete("w")
        assert time.monotonic() - start < 5.0
    finally:
        sim.stop()


# --------------------------------------------------------------------------- 7. signals
@pytest.mark.slow
def test_sigterm_ends_the_server_while_c_code_holds_the_interpreter(tmp_path: Path) -> None:
    script = tmp_path / "hold.py"
    script.write_text(
        "import re, signal, sys, threading\n"
        "from gazelle.sim import start_signal_watchdog\n"
        "stop = threading.Event()\n"
        "signal.signal(signal.SIGTERM, lambda *a: stop.set())\n"
        "start_signal_watchdog(3.0)\n"
        "print('holding', flush=True)\n"
        "re.match(r'(a+)+$', 'a' * 60 + 'b')  # C code that never lets go of the GIL\n"
    )
    proc = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert proc.stdout is not None
    assert proc.stdout.readline().strip() == "holding"
    time.sleep(0.3)  # let it enter the match
    start = time.monotonic()
    proc.send_signal(signal.SIGTERM)
    try:
        proc.wait(10)
    except subprocess.TimeoutExpired:
        proc.kill()
        pytest.fail("the process outlived SIGTERM by 10 s")
    assert time.monotonic() - start < 6.0
    assert proc.stderr is not None and "shutdown did not finish" in proc.stderr.read()


def test_a_bounded_helper_dies_with_its_parent(tmp_path: Path) -> None:
    script = tmp_path / "parent.py"
    script.write_text(
        "import os, sys, time\n"
        "from gazelle.description import BoundedWorker\n"
        "w = BoundedWorker(lambda r: print(os.getpid(), flush=True) or sum(range(10**12)))\n"
        "import threading\n"
        "threading.Thread(target=lambda: w.call({}, what='x', timeout_sec=600), daemon=True).start()\n"
        "time.sleep(600)\n"
    )
    proc = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, text=True)
    assert proc.stdout is not None
    helper = int(proc.stdout.readline())
    proc.kill()
    proc.wait(10)
    deadline = time.monotonic() + 10
    while time.monotonic() < deadline:
        try:
            os.kill(helper, 0)
        except ProcessLookupError:
            break
        with open(f"/proc/{helper}/stat") as f:
            if f.read().split(")")[1].split()[0] == "Z":
                break
        time.sleep(0.05)
    else:
        os.kill(helper, signal.SIGKILL)
        pytest.fail("the helper outlived its parent")


# --------------------------------------------------------------------------- 8. controller names
@pytest.mark.parametrize("name", ["", "../evil", "a" * 200_000, "ok\n[ERROR] fake log line", "9lives", "a b"])
def test_controller_names_follow_ros_node_name_rules(diffbot, name: str) -> None:
    _sim, cm = diffbot
    why = valid_controller_name(name)
    assert why is not None
    with pytest.raises(ControlError) as info:
        cm.load_controller(name)
    text = str(info.value)
    assert len(text) < 300 and "\n" not in text
    with pytest.raises(ControlError):
        cm.switch_controller([name], [])
    assert valid_controller_name("joint_state_broadcaster") is None


# --------------------------------------------------------------------------- 9. size bombs
def test_yaml_aliases_cannot_expand_a_message_or_recurse() -> None:
    from gazelle.cli.ros2cli._messages import InterfaceError, parse_values

    start = time.monotonic()
    with pytest.raises(InterfaceError, match="expands to more than"):
        parse_values(ANCHOR_BOMB)
    with pytest.raises(InterfaceError, match="refers to itself"):
        parse_values("a: &a [1, *a]")
    assert parse_values("{linear: {x: 0.2}, a: &x [1, 2], b: *x}") == {"linear": {"x": 0.2}, "a": [1, 2], "b": [1, 2]}
    assert time.monotonic() - start < 2.0
    with pytest.raises(UntrustedInputError):
        safe_load_bounded("[" * 100 + "]" * 100, max_nodes=50)


def test_read_regular_file_bounds_size(tmp_path: Path) -> None:
    big = tmp_path / "big"
    big.write_bytes(b"x" * 2000)
    with pytest.raises(UntrustedInputError, match="2000 bytes"):
        read_regular_file(big, 1000)
    assert read_regular_file(big, 2000) == "x" * 2000


def _sensor_robot(sensor: str) -> str:
    return (
        '<robot name="s"><link name="base"><inertial><mass value="1"/><inertia ixx="1e-2" iyy="1e-2" izz="1e-2"'
        ' ixy="0" ixz="0" iyz="0"/></inertial><collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>'
        f'</link><gazebo reference="base">{sensor}</gazebo></robot>'
    )


LIDAR = (
    '<sensor type="ray" name="lidar"><update_rate>{rate}</update_rate><ray><scan><horizontal><samples>{h}</samples>'
    "<min_angle>-3</min_angle><max_angle>3</max_angle></horizontal><vertical><samples>{v}</samples><min_angle>-0.3"
    "</min_angle><max_angle>0.3</max_angle></vertical></scan><range><min>0.1</min><max>10</max></range></ray>"
    '<plugin name="l" filename="libgazebo_ros_ray_sensor.so"><output_type>sensor_msgs/LaserScan</output_type>'
    "</plugin></sensor>"
)
CAMERA = (
    '<sensor type="camera" name="cam"><update_rate>1</update_rate><camera><horizontal_fov>1</horizontal_fov>'
    "<image><width>{w}</width><height>{w}</height></image></camera>"
    '<plugin name="c" filename="libgazebo_ros_camera.so"/></sensor>'
)


@pytest.mark.parametrize(
    "sensor,why",
    [
        (LIDAR.format(rate=5, h=2000, v=1000), "rays is more than"),
        (CAMERA.format(w=8192), "larger than"),
        (LIDAR.format(rate=-5, h=10, v=1), "update_rate"),
        (LIDAR.format(rate="nan", h=10, v=1), "update_rate"),
    ],
)
def test_an_over_limit_sensor_refuses_the_spawn_with_the_reason(sensor: str, why: str, make_sim) -> None:
    from gazelle.description import Pose

    sim = make_sim()
    try:
        before = sim.world.data.qpos.copy()
        with pytest.raises(Exception, match=why):
            sim.spawn(load_string(_sensor_robot(sensor)).model, name="s", pose=Pose((0.0, 0.0, 0.1)))
        assert "s" not in sim.world.entities
        assert np.array_equal(before, sim.world.data.qpos)
    finally:
        sim.stop()


def test_a_sensor_faster_than_the_physics_runs_every_step_with_a_warning(caplog, make_sim) -> None:
    from gazelle.description import Pose

    sim = make_sim()
    try:
        entity = sim.spawn(
            load_string(_sensor_robot(LIDAR.format(rate="1e9", h=10, v=1))).model, name="s", pose=Pose((0, 0, 0.1))
        )
        (lidar,) = [s for s in entity.systems if getattr(s, "kind", "") == "lidar"]
        assert lidar.rate_hz == pytest.approx(1.0 / sim.world.timestep)
        assert "faster than the physics step" in caplog.text
    finally:
        sim.stop()


def test_a_zstd_bomb_bag_is_refused_before_it_is_decompressed(tmp_path: Path) -> None:
    import zstandard
    from mcap.records import Chunk

    from gazelle.cli.ros2cli._bag import BagError, _check_chunks

    # a valid MCAP whose one chunk says 1 KB but holds 64 MB of zeros
    payload = zstandard.compress(b"\0" * (64 << 20))
    from mcap.writer import Writer

    path = tmp_path / "bomb.mcap"
    with open(path, "wb") as f:
        w = Writer(f)
        w.start()
        w.finish()
    data = bytearray(path.read_bytes())
    chunk = Chunk(
        compression="zstd",
        data=payload,
        message_start_time=0,
        message_end_time=0,
        uncompressed_crc=0,
        uncompressed_size=1024,
    )
    from mcap.data_stream import RecordBuilder

    builder = RecordBuilder()
    chunk.write(builder)
    bomb = bytes(data[:8]) + builder.end() + bytes(data[8:])
    path.write_bytes(bomb)
    rss0 = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    with pytest.raises(BagError, match="declares 1024 bytes decompressed but holds more"):
        _check_chunks(path)
    assert resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - rss0 < 32_000  # KiB


# --------------------------------------------------------------------------- 10. the convex cache
def test_a_forged_convex_cache_entry_is_not_trusted(tmp_path: Path, monkeypatch, caplog) -> None:
    import trimesh

    from gazelle.physics import _convex

    monkeypatch.setenv("GAZELLE_CACHE_DIR", str(tmp_path / "cache"))
    mesh = tmp_path / "u.stl"
    boxes = [
        trimesh.creation.box((0.1, 0.3, 0.1), trimesh.transformations.translation_matrix((-0.1, 0, 0))),
        trimesh.creation.box((0.1, 0.3, 0.1), trimesh.transformations.translation_matrix((0.1, 0, 0))),
        trimesh.creation.box((0.3, 0.1, 0.1), trimesh.transformations.translation_matrix((0, -0.1, 0))),
    ]
    u = trimesh.util.concatenate(boxes)
    u.export(mesh)
    # CoACD itself is not what is tested here (and took ~15 s a run): the decomposition is the U's own
    # three boxes, computed in the same bounded helper
    pieces = [np.asarray(b.vertices, dtype=float).tolist() for b in boxes]
    monkeypatch.setattr(_convex, "_decompose", lambda _v, _f: pieces)
    parts = _convex.collision_parts(str(mesh), (1.0, 1.0, 1.0))
    assert parts is not None and parts.source == "computed"
    folder = _convex.cache_dir()
    assert folder.stat().st_mode & 0o777 == 0o700
    (entry,) = folder.glob("*.npz")
    key = entry.stem
    slab = np.array([[x, y, z] for x in (-10, 10) for y in (-10, 10) for z in (-0.1, 0.1)], dtype=float)
    for forged in (
        {"key": np.asarray(key), "p0": slab},  # a 20 x 20 m slab for a 30 cm U
        {"key": np.asarray("0" * 64), "p0": slab[:4] * 0.001},  # another mesh's entry
        {"key": np.asarray(key), **{f"p{i}": slab * 0.001 for i in range(100)}},  # too many parts
    ):
        np.savez(entry, **cast(dict[str, Any], forged))
        _convex._memory.clear()
        _convex._keys.clear()
        caplog.clear()
        again = _convex.collision_parts(str(mesh), (1.0, 1.0, 1.0))
        assert again is not None and again.source == "computed"
        assert "is computed again" in caplog.text
        assert all(np.abs(p).max() < 0.5 for p in again.pieces)
    entry.write_bytes(b"x" * (_convex.MAX_ENTRY_BYTES + 1))
    _convex._memory.clear()
    _convex._keys.clear()
    parts = _convex.collision_parts(str(mesh), (1.0, 1.0, 1.0))
    assert parts is not None and parts.source == "computed"
    folder.chmod(0o777)
    _convex._memory.clear()
    _convex._keys.clear()
    caplog.clear()
    parts = _convex.collision_parts(str(mesh), (1.0, 1.0, 1.0))
    assert parts is not None and parts.source == "computed"
    assert "others may write" in caplog.text


# --------------------------------------------------------------------------- 11. ros2 launch ..
def test_ros2_launch_of_a_folder_or_a_bad_package_name_is_one_line() -> None:
    for args in ([".."], ["..", "x.launch.py"], ["no/such", "x.launch.py"]):
        out = subprocess.run(
            [str(Path(sys.executable).parent / "ros2"), "launch", *args],
            capture_output=True,
            text=True,
            timeout=60,
            cwd=REPO,
        )
        assert out.returncode != 0
        assert "Traceback" not in out.stderr, out.stderr
        assert len(out.stderr.strip().splitlines()) <= 3, out.stderr


def test_the_yaml_parameter_layout_still_parses() -> None:
    pf = parse_params("a:\n  ros__parameters:\n    x: 1\n    y: &v [1, 2]\n    z: *v\n", "f.yaml")
    assert pf.for_node("a") == {"x": 1, "y": [1, 2], "z": [1, 2]}
    with pytest.raises(ModelLoadError):
        load_string("<robot name='x'><link name='a'/><link name='a'/></robot>")
