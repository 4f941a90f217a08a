"""Where test inputs are: the seed robot, a plain box model, and the shared real-robot fixtures
($GAZELLE_REAL_FIXTURES, else ../shared beside the repo)."""

from __future__ import annotations

import os
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
TEST_DATA = REPO / "tests" / "data"
"""The suite's own small inputs (URDF, SDF, SRDF, YAML) that no real fixture covers."""
SEED_XACRO = REPO / "examples" / "simple_robot" / "simple_robot" / "robot.urdf.xacro"
ARTIFACTS = REPO / "out" / "viewer"
"""Where the viewer tests keep what a person would look at (snapshots, videos) for a failing run."""
BOX = (
    '<?xml version="1.0"?><sdf version="1.9"><model name="box"><link name="link">'
    "<inertial><mass>1.0</mass><inertia><ixx>0.0067</ixx><iyy>0.0067</iyy><izz>0.0067</izz></inertia></inertial>"
    '<collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision></link></model></sdf>'
)
"""A free 1 kg, 0.2 m box (SDF)."""


def _real_fixtures() -> Path:
    env = os.environ.get("GAZELLE_REAL_FIXTURES")
    if env:
        return Path(env)
    for cand in (REPO.parent / "shared" / "fixtures" / "real", Path("/work/shared/fixtures/real")):
        if cand.is_dir():
            return cand
    return REPO.parent / "shared" / "fixtures" / "real"


REAL = _real_fixtures()
