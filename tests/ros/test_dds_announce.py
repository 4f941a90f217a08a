"""gazelle's own processes announce their participants every 0.1 s unless the user gave Fast DDS a profile of
their own. The profile a gazelle test process gives its own writers is not the user's: a server a test started
inherited it and announced only every 3 s, and a ``ros2`` verb the test ran then missed the server (CI)."""

from __future__ import annotations

import os

import pytest

from gazelle.ros import _dds


def test_a_test_process_s_writer_profile_does_not_stop_the_announcements(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("RMW_IMPLEMENTATION", raising=False)
    monkeypatch.delenv("FASTDDS_DEFAULT_PROFILES_FILE", raising=False)
    monkeypatch.setenv("FASTRTPS_DEFAULT_PROFILES_FILE", "/x/fastdds_test_node.xml")
    monkeypatch.setenv("GAZELLE_TEST_WRITER_PROFILE", "/x/fastdds_test_node.xml")
    assert _dds.announce_often()
    assert os.environ["FASTRTPS_DEFAULT_PROFILES_FILE"] == str(_dds.ANNOUNCE_PROFILE)


def test_a_user_s_own_profile_is_kept(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("RMW_IMPLEMENTATION", raising=False)
    monkeypatch.setenv("FASTRTPS_DEFAULT_PROFILES_FILE", "/home/me/my_profile.xml")
    monkeypatch.setenv("GAZELLE_TEST_WRITER_PROFILE", "/x/fastdds_test_node.xml")
    assert not _dds.announce_often()
    assert os.environ["FASTRTPS_DEFAULT_PROFILES_FILE"] == "/home/me/my_profile.xml"
