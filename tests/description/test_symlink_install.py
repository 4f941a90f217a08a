"""Issue 49: files that `colcon build --symlink-install` linked into an install prefix are read where the links
lead, in the workspace the prefix was built from, and nowhere else.

The workspace here is laid out by hand as colcon lays it out (colcon-core's verb/__init__.py markers:
``install/.colcon_install_layout`` and ``build/.built_by``; ament_cmake_symlink_install's one link per
installed file); tests/integration/test_symlink_install.py builds a real one with colcon.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from gazelle.description import Mesh, ResourceResolver, load_string

SECRET = "SECRET_CONTENT_49"


def _link(install: Path, target: Path, text: str = "solid m\nendsolid m\n") -> None:
    """``install`` a link to ``target`` (written if missing), as colcon's symlink install makes it."""
    target.parent.mkdir(parents=True, exist_ok=True)
    if not target.exists():
        target.write_text(text)
    install.parent.mkdir(parents=True, exist_ok=True)
    install.symlink_to(target)


@pytest.fixture
def workspace(tmp_path: Path) -> tuple[Path, dict[str, str]]:
    """``ws`` with one package ``pkg`` (source ``src/repo/pkg``, a sibling ``src/repo/common`` of shared
    meshes) installed with links, a model ``arena`` in its ``models``, and a secret outside ``ws`` that one
    installed mesh links to. Returns the workspace and the environment a sourced ``install/setup.bash`` gives."""
    ws = tmp_path / "ws"
    (ws / "install").mkdir(parents=True)
    (ws / "install" / ".colcon_install_layout").write_text("isolated\n")
    (ws / "build").mkdir()
    (ws / "build" / ".built_by").write_text("colcon\n")
    src, share = ws / "src" / "repo" / "pkg", ws / "install" / "pkg" / "share"
    index = share / "ament_index" / "resource_index" / "packages" / "pkg"
    index.parent.mkdir(parents=True)
    index.write_text("")
    _link(share / "pkg" / "package.xml", src / "package.xml", "<package><name>pkg</name></package>")
    model = (
        '<sdf version="1.6"><model name="arena"><static>true</static><link name="l"><visual name="v"><geometry>'
        "<mesh><uri>model://arena/meshes/wall.stl</uri></mesh></geometry></visual></link></model></sdf>"
    )
    _link(share / "pkg" / "models" / "arena" / "model.sdf", src / "models" / "arena" / "model.sdf", model)
    _link(share / "pkg" / "models" / "arena" / "meshes" / "wall.stl", src / "models" / "arena" / "meshes" / "wall.stl")
    _link(share / "pkg" / "meshes" / "shared.stl", ws / "src" / "repo" / "common" / "shared.stl")
    _link(share / "pkg" / "meshes" / "leak.stl", tmp_path / "outside" / "secret.stl", SECRET)
    env = {"AMENT_PREFIX_PATH": str(ws / "install" / "pkg"), "GZ_SIM_RESOURCE_PATH": str(share / "pkg" / "models")}
    return ws, env


WORLD = '<sdf version="1.6"><world name="w"><include><uri>model://arena</uri></include></world></sdf>'


def _urdf_mesh(uri: str, resolver: ResourceResolver) -> tuple[str | None, str]:
    """(the file a URDF string's mesh ``uri`` loads, every diagnostic's message)."""
    urdf = (
        f'<robot name="r"><link name="a"><visual><geometry><mesh filename="{uri}"/></geometry></visual></link></robot>'
    )
    result = load_string(urdf, resolver=resolver)
    mesh = result.model.links[0].visuals[0].geometry
    assert isinstance(mesh, Mesh)
    return mesh.path, " ".join(d.message for d in result.diagnostics)


def test_a_models_meshes_and_a_packages_shared_mesh_load_through_colcons_links(workspace) -> None:
    ws, env = workspace
    resolver = ResourceResolver(env=env)
    # TurtleBot3's turtlebot3_world: a model folder in a package's models, its meshes as model:// URIs
    result = load_string(WORLD, resolver=resolver)
    assert not result.diagnostics, [d.message for d in result.diagnostics]
    mesh = result.world.models[0].links[0].visuals[0].geometry
    assert isinstance(mesh, Mesh) and mesh.path is not None
    assert Path(mesh.path).resolve() == ws / "src" / "repo" / "pkg" / "models" / "arena" / "meshes" / "wall.stl"
    # a mesh the package installs from a sibling folder of its repository (outside the package's source)
    path, messages = _urdf_mesh("package://pkg/meshes/shared.stl", resolver)
    assert path is not None and Path(path).resolve() == ws / "src" / "repo" / "common" / "shared.stl", messages
    # the link inside the install prefix by file://, as a launch file's get_package_share_directory gives it
    linked = ws / "install" / "pkg" / "share" / "pkg" / "meshes" / "shared.stl"
    assert resolver.resolve_uri(f"file://{linked}") == linked
    assert resolver.is_inside_roots(linked)


def test_a_link_out_of_the_workspace_and_the_workspace_named_directly_stay_refused(workspace) -> None:
    ws, env = workspace
    resolver = ResourceResolver(env=env)
    for uri in (
        "package://pkg/meshes/leak.stl",  # colcon's link, to a file outside the workspace
        f"file://{ws}/install/pkg/share/pkg/meshes/leak.stl",
        f"file://{ws}/src/repo/common/shared.stl",  # the workspace, not through the install prefix
        f"{ws}/build/.built_by",
        "package://pkg/../../../../src/repo/common/shared.stl",  # climbing out of the package
        "model://arena/../../../../../../src/repo/common/shared.stl",
    ):
        path, messages = _urdf_mesh(uri, resolver)
        assert path is None, uri
        assert "outside the folders files may be read from" in messages, (uri, messages)
        assert SECRET not in messages
    assert not resolver.is_inside_roots(ws / "install" / "pkg" / "share" / "pkg" / "meshes" / "leak.stl")


@pytest.mark.parametrize(
    "change",
    ["no build base beside it", "a build base not colcon's", "an install marker that is not colcon's"],
)
def test_an_install_tree_colcon_did_not_build_in_a_workspace_keeps_the_plain_confinement(workspace, change) -> None:
    """``--install-base``/``--build-base`` elsewhere, or markers colcon did not write: the install tree's
    parent is not known to be the workspace, and its links are not followed."""
    ws, env = workspace
    if change == "no build base beside it":
        (ws / "build" / ".built_by").unlink()
    elif change == "a build base not colcon's":
        (ws / "build" / ".built_by").write_text("catkin_tools\n")
    else:
        (ws / "install" / ".colcon_install_layout").write_text("anything\n")
    resolver = ResourceResolver(env=env)
    path, messages = _urdf_mesh("package://pkg/meshes/shared.stl", resolver)
    assert path is None and "outside the folders files may be read from" in messages
    result = load_string(WORLD, resolver=resolver)
    assert [d.code.value for d in result.diagnostics] == ["MESH_NOT_FOUND"]
