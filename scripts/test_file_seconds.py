#!/usr/bin/env python3
"""Write tests/file_seconds.json: seconds each test file took, summed from a pytest JUnit XML report.

``./test.sh`` runs the parallel phase on two workers, each taking whole files (``--dist loadfile``) in
the order tests/conftest.py gives them: the longest files first (longest-processing-time-first), so that
no long file starts last while the other worker idles. The weights only order the files; stale ones
cost speed, never correctness. Refresh them after adding slow tests:

    .venv/bin/python -m pytest --phase parallel -n 2 --dist loadfile --junitxml /tmp/suite.xml
    .venv/bin/python scripts/test_file_seconds.py /tmp/suite.xml
"""

from __future__ import annotations

import json
import sys
import xml.etree.ElementTree as ET
from collections import defaultdict
from pathlib import Path

OUT = Path(__file__).resolve().parents[1] / "tests" / "file_seconds.json"


def main(argv: list[str]) -> int:
    if len(argv) != 1:
        print(__doc__)
        return 2
    seconds: dict[str, float] = defaultdict(float)
    for case in ET.parse(argv[0]).getroot().iter("testcase"):
        name = case.get("classname", "")
        # "tests.ros.test_chessbot" (or "tests.ros.test_chessbot.TestX"): the file is the module part
        parts = name.split(".")
        while parts and not parts[-1].startswith("test_"):
            parts.pop()
        if parts:
            seconds["/".join(parts) + ".py"] += float(case.get("time", "0") or 0)
    ordered = dict(sorted(((k, round(v, 1)) for k, v in seconds.items()), key=lambda kv: -kv[1]))
    OUT.write_text(json.dumps(ordered, indent=1) + "\n")
    print(f"{OUT}: {len(ordered)} files, {sum(ordered.values()):.0f} s in all")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
