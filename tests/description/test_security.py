"""Descriptions that arrive as strings are data; xacro runs only on a user's own file, bounded.

The payloads are the ones an attacker used on `/spawn_entity` (issue 10): an escape from
xacro's evaluator that ran `id`, file and environment reads echoed back in errors, and
`${9**9**9}`, which froze the whole server.
"""

from __future__ import annotations

import os
import resource
import subprocess
import sys
import time
from pathlib import Path

import pytest

from gazelle.description import Box, ErrorCode, Mesh, ModelLoadError, load, load_string

RCE_EXPR = (
    "${python.vars(python.type(()).mro()[-1])['__getattribute__'](xacro.load_yaml, '__globals__')"
    "['os'].system('id > %s')}"
)


def _robot(body: str) -> str:
    return f'<robot name="x" xmlns:xacro="http://www.ros.org/wiki/xacro">{body}<link name="a"/></robot>'


def _refused(text: str, **kw) -> ModelLoadError:
    with pytest.raises(ModelLoadError) as info:
        load_string(text, **kw)
    return info.value


def test_the_remote_code_execution_payload_is_refused_and_runs_nothing(tmp_path: Path) -> None:
    marker = tmp_path / "pwned"
    text = _robot(f'<xacro:property name="p" value="{RCE_EXPR % marker}"/>')
    for fmt in ("auto", "urdf", "xacro"):
        err = _refused(text, format=fmt)
        assert err.first is not None and err.first.code is ErrorCode.XACRO_NOT_ALLOWED
        assert "expand it first" in str(err) and "gazelle spawn -file" in str(err)
    # the expression alone in an attribute, without any xacro element, is refused the same way
    err = _refused(f'<robot name="x"><link name="{RCE_EXPR % marker}"/></robot>')
    assert err.first is not None and err.first.code is ErrorCode.XACRO_NOT_ALLOWED
    assert not marker.exists()


@pytest.mark.parametrize(
    "body",
    [
        "<link name=\"${xacro.load_yaml('/etc/passwd')}\"/>",
        '<link name="$(env PATH)"/>',
        '<xacro:property name="p" value="${\'a\'*(10**9)}"/>',
    ],
)
def test_file_and_environment_reads_are_never_evaluated_or_echoed(body: str) -> None:
    start = time.monotonic()
    err = _refused(_robot(body))
    assert time.monotonic() - start < 1.0
    text = str(err)
    assert "root:" not in text and os.environ.get("PATH", "/usr/bin") not in text
    assert len(text) < 600


def test_the_power_bomb_in_a_string_is_answered_at_once() -> None:
    start = time.monotonic()
    err = _refused(_robot('<xacro:property name="p" value="${9**9**9}"/>'))
    assert time.monotonic() - start < 1.0
    assert err.first is not None and err.first.code is ErrorCode.XACRO_NOT_ALLOWED


def test_a_plain_urdf_that_only_declares_the_xacro_namespace_loads() -> None:
    # xacro's own output keeps xmlns:xacro on <robot>: that is no markup and must still spawn
    model = load_string(_robot("")).model
    assert model.name == "x"


@pytest.mark.slow
def test_the_power_bomb_in_a_local_file_ends_within_10_s_with_a_clear_error(tmp_path: Path) -> None:
    bomb = tmp_path / "bomb.urdf.xacro"
    bomb.write_text(_robot('<xacro:property name="p" value="${9**9**9}"/><link name="b${p}"/>'))
    start, cpu0 = time.monotonic(), resource.getrusage(resource.RUSAGE_CHILDREN)
    proc = subprocess.run(
        [sys.executable, "-m", "gazelle.cli", "check", str(bomb)], capture_output=True, text=True, timeout=60
    )
    elapsed, cpu1 = time.monotonic() - start, resource.getrusage(resource.RUSAGE_CHILDREN)
    assert proc.returncode == 1, proc.stderr
    # the work is bounded (5 s of the helper's CPU, the check's own start-up besides); the wall clock only
    # guards against a hang, since on a loaded machine (a CPU hog, two test workers) 10 s of CPU took 12.9 s
    cpu = (cpu1.ru_utime + cpu1.ru_stime) - (cpu0.ru_utime + cpu0.ru_stime)
    assert cpu < 10.0, cpu
    assert elapsed < 30.0, elapsed
    assert f"{bomb}: error: [XACRO_ERROR]" in proc.stderr and "took longer than" in proc.stderr
    assert "Traceback" not in proc.stderr


def test_a_memory_bomb_in_a_local_file_is_stopped_by_the_memory_limit(tmp_path: Path, monkeypatch) -> None:
    monkeypatch.setenv("GAZELLE_XACRO_MEMORY_MB", "200")
    bomb = tmp_path / "big.urdf.xacro"
    bomb.write_text(_robot('<xacro:property name="p" value="${\'a\'*(10**9)}"/><link name="b${p}"/>'))
    with pytest.raises(ModelLoadError) as info:
        load(bomb)
    assert "out of memory" in str(info.value) and "GAZELLE_XACRO_MEMORY_MB" in str(info.value), str(info.value)


def test_a_users_own_xacro_file_still_expands(tmp_path: Path) -> None:
    f = tmp_path / "ok.urdf.xacro"
    f.write_text(
        _robot(
            '<xacro:property name="w" value="0.5"/><link name="b"><visual><geometry><box size="${w} 1 1"/></geometry>'
            '</visual></link><joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>'
        )
    )
    model = load(f).model
    assert sorted(lk.name for lk in model.links) == ["a", "b"]
    box = model.link("b").visuals[0].geometry
    assert isinstance(box, Box) and box.size == (0.5, 1.0, 1.0)
    # ... unless the caller says the file came from a remote request (the viewer's spawn panel)
    with pytest.raises(ModelLoadError) as info:
        load(f, expand_xacro=False)
    assert info.value.first is not None and info.value.first.code is ErrorCode.XACRO_NOT_ALLOWED


def test_errors_echo_only_an_excerpt_of_a_long_value() -> None:
    huge = "9" * 5000 + "x"
    err = _refused(
        f'<robot name="r"><link name="a"><collision><geometry><box size="{huge}"/></geometry></collision></link></robot>'
    )
    text = err.summary()
    assert "characters" in text and len(text) < 600, text


def _box_model(name: str) -> str:
    return (
        f'<sdf version="1.9"><model name="{name}"><link name="l"><inertial><mass>1</mass></inertial>'
        '<collision name="c"><geometry><box><size>0.1 0.1 0.1</size></box></geometry></collision></link></model></sdf>'
    )


@pytest.fixture
def roots(tmp_path: Path):
    """A resource root with a good model, a model whose model.sdf links to a secret outside, and a secret."""
    from gazelle.description import ResourceResolver

    root = tmp_path / "models"
    (root / "good").mkdir(parents=True)
    (root / "good" / "model.sdf").write_text(_box_model("good"))
    outside = tmp_path / "private"
    outside.mkdir()
    secret = outside / "secret.sdf"
    secret.write_text(_box_model("SECRET_CONTENT"))
    (root / "evil").mkdir()
    (root / "evil" / "model.sdf").symlink_to(secret)
    (root / "linked_dir").symlink_to(outside)  # a whole folder linking out
    return ResourceResolver(extra_paths=[root], env={}), root, secret


def _world(include_uri: str) -> str:
    return f'<sdf version="1.9"><world name="w"><include><uri>{include_uri}</uri></include></world></sdf>'


def test_model_uris_do_not_follow_symlinks_out_of_the_resource_paths(roots) -> None:
    resolver, root, secret = roots
    ok = load_string(_world("model://good"), resolver=resolver).world
    assert [m.name for m in ok.models] == ["good"]
    for uri in ("model://evil", "model://linked_dir/secret.sdf", str(secret), f"file://{secret}"):
        with pytest.raises(ModelLoadError) as info:
            load_string(_world(uri), resolver=resolver)
        assert "SECRET_CONTENT" not in str(info.value)
        first = info.value.first
        assert first is not None and first.code is ErrorCode.URI_UNRESOLVED or "outside" in str(info.value), str(
            info.value
        )
    assert resolver.resolve_uri("model://evil/model.sdf") is None


def test_includes_in_a_users_world_file_are_confined_like_spawn_by_uri(roots, tmp_path: Path) -> None:
    resolver, root, secret = roots
    world = tmp_path / "mine" / "w.sdf"
    world.parent.mkdir()
    (world.parent / "local.sdf").write_text(_box_model("local"))
    world.write_text(
        '<sdf version="1.9"><world name="w"><include><uri>local.sdf</uri></include>'
        f"<include><uri>{secret}</uri></include></world></sdf>"
    )
    with pytest.raises(ModelLoadError) as info:
        load(world, resolver=resolver)
    assert "outside the folders files may be read from" in str(info.value) and "GAZELLE_RESOURCE_PATH" in str(
        info.value
    )
    # the folder of the user's own file may be read
    world.write_text('<sdf version="1.9"><world name="w"><include><uri>local.sdf</uri></include></world></sdf>')
    assert [m.name for m in load(world, resolver=resolver).world.models] == ["local"]


def test_a_spawn_string_reads_no_file_outside_the_resource_paths(roots) -> None:
    resolver, root, secret = roots
    urdf = (
        '<robot name="r"><link name="a"><visual><geometry><mesh filename="file:///etc/passwd"/></geometry></visual>'
        '<collision><geometry><mesh filename="/etc/passwd"/></geometry></collision></link></robot>'
    )
    result = load_string(urdf, resolver=resolver)
    link = result.model.links[0]
    mesh = link.visuals[0].geometry
    assert isinstance(mesh, Mesh) and mesh.path is None
    messages = " ".join(d.message for d in result.diagnostics)
    assert "outside the folders files may be read from" in messages and "root:" not in messages


def test_a_5000_digit_integer_in_yaml_is_refused_with_its_line() -> None:
    """Issue 48: PyYAML reads an integer with ``int()``, and past Python's int-string-conversion limit
    (``sys.get_int_max_str_digits()``, 4,300 digits) that raised a bare ValueError, not a YAMLError: a
    traceback from every reader of untrusted YAML (a QoS overrides file, a bag's metadata.yaml, ``ros2 topic
    pub``'s values). The bounded loader refuses an integer literal of over 1,000 characters, in any base,
    naming its line and not its digits."""
    from gazelle.description import UntrustedInputError, safe_load_bounded

    assert sys.get_int_max_str_digits() in (0, 4300)
    for text, line in (("a: 1\nb: " + "9" * 5000, 2), ("- 0x" + "f" * 2000, 1), ("x: !!int '" + "1" * 1001 + "'", 1)):
        with pytest.raises(UntrustedInputError) as err:
            safe_load_bounded(text, "q.yaml")
        assert str(err.value).startswith(f"q.yaml:{line}: an integer of ") and "999" not in str(err.value)
    assert safe_load_bounded("a: " + "9" * 1000) == {"a": int("9" * 1000)}
