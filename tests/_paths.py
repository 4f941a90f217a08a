"""Where the shared real-robot fixtures are: $GAZELLE_REAL_FIXTURES, else ../shared beside the repo."""

from __future__ import annotations

import os
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]


def _real_fixtures() -> Path:
    env = os.environ.get("GAZELLE_REAL_FIXTURES")
    if env:
        return Path(env)
    for cand in (REPO.parent / "shared" / "fixtures" / "real", Path("/work/shared/fixtures/real")):
        if cand.is_dir():
            return cand
    return REPO.parent / "shared" / "fixtures" / "real"


REAL = _real_fixtures()
