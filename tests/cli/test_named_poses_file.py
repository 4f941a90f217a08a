"""``gazelle sim --named-poses FILE``: the world ``<frame>``s of another SDF file join the world's named poses
(GetNamedPoses; issue 52), and a file that is no such list is refused at start with one line naming it."""

from __future__ import annotations

from pathlib import Path

import pytest

from gazelle.cli._sim import with_named_poses
from gazelle.description import load_string


def world_with(frames: str) -> str:
    return f'<sdf version="1.9"><world name="w">{frames}</world></sdf>'


WORLD = load_string(world_with('<frame name="dock"><pose>1 0 0 0 0 0</pose></frame>'), source="/tmp/w.sdf").world


def test_the_files_frames_come_after_the_worlds(tmp_path: Path) -> None:
    extra = tmp_path / "places.sdf"
    extra.write_text(world_with('<frame name="bay"><pose>5 5 0 0 0 0</pose><gazelle:tag>parking</gazelle:tag></frame>'))
    out = with_named_poses(WORLD, (extra,))
    assert [p.name for p in out.named_poses] == ["dock", "bay"] and out.named_poses[1].tags == ("parking",)
    assert with_named_poses(WORLD, ()) == WORLD


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (world_with('<frame name="dock"/>'), "named pose 'dock' is already defined at /tmp/w.sdf:1"),
        (world_with('<model name="m"><link name="l"/></model>'), "holds models"),
        ('<sdf version="1.9"><model name="m"><link name="l"/></model></sdf>', "not an SDF world"),
    ],
)
def test_a_file_that_is_no_list_of_frames_is_refused_naming_it(tmp_path: Path, text: str, message: str) -> None:
    extra = tmp_path / "places.sdf"
    extra.write_text(text)
    with pytest.raises(ValueError, match="--named-poses") as err:
        with_named_poses(WORLD, (extra,))
    assert message in str(err.value) and str(extra) in str(err.value)
