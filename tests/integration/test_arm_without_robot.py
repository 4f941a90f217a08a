"""Issue 27: `gazelle arm` against a move_group that has no robot yet said `ValueError: not enough values
to unpack` with a traceback; it is one line naming what is missing, and the exit status says it failed."""

from __future__ import annotations

import subprocess

from _harness import GAZELLE, start


def test_gazelle_arm_against_a_move_group_without_a_robot_is_one_clear_line() -> None:
    move_group = start([*GAZELLE, "move_group"], "move_group")
    try:
        out = subprocess.run(
            [*GAZELLE, "arm", "panda_arm", "--named", "ready", "--timeout", "20"],
            capture_output=True,
            text=True,
            timeout=120,
        )
        text = out.stdout + out.stderr
        assert out.returncode != 0, text
        assert "Traceback" not in text and "not enough values" not in text, text
        assert "move_group has no robot yet" in text, text
    finally:
        assert move_group.interrupt() == 0, move_group.output


def test_move_group_with_a_malformed_srdf_exits_2_naming_the_file_and_line(tmp_path) -> None:
    """Issue 27: a malformed SRDF logged an error and move_group kept running, unable to plan."""
    srdf = tmp_path / "bad.srdf"
    srdf.write_text('<robot name="x"><group name="a">\n<chain base_link="a" tip_link="b"/>\n</grup></robot>\n')
    out = subprocess.run([*GAZELLE, "move_group", "--srdf", str(srdf)], capture_output=True, text=True, timeout=60)
    assert out.returncode == 2, out.stdout + out.stderr
    assert f"{srdf}:3:" in out.stderr and "Traceback" not in out.stderr, out.stderr


def test_a_second_move_group_on_the_domain_says_so() -> None:
    """Issue 27: a second move_group on the same domain started silently; both answered every request."""
    first = start([*GAZELLE, "move_group"], "move_group 1")
    second = start([*GAZELLE, "move_group"], "move_group 2")
    try:
        second.wait_line("another /move_group is running", 30)
    finally:
        for proc in (second, first):
            assert proc.interrupt() == 0, proc.output
