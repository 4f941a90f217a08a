"""Issue 48: ``gazelle sweep --ray local`` starts a Ray of its own that only this machine can reach: while a
sweep runs, every socket its Ray listens on is on the loopback, and neither ``RAY_ADDRESS`` nor a stale
``ray_current_cluster`` (in Ray's temp folder, which Ray makes world-writable) sends the sweep elsewhere."""

from __future__ import annotations

import ipaddress
import os
import shutil
import signal
import subprocess
import tempfile
from pathlib import Path

import pytest
from _harness import GAZELLE, wait_for

HOLD = '''
import os, time


def hold(sim, params, seed):
    """Says it runs, then waits (at most 120 s) until the test has looked at the sweep's sockets."""
    open({running!r}, "w").close()
    end = time.monotonic() + 120
    while not os.path.exists({go!r}) and time.monotonic() < end:
        time.sleep(0.02)
    return {{"passed": os.path.exists({go!r})}}
'''


def _descendants(root: int) -> set[int]:
    """``root`` and every process under it (Ray's GCS and raylet are the sweep's children, its workers the
    raylet's)."""
    children: dict[int, list[int]] = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat") as f:
                    ppid = int(f.read().rpartition(")")[2].split()[1])
            except (OSError, ValueError, IndexError):
                continue
            children.setdefault(ppid, []).append(int(entry))
    found, todo = set(), [root]
    while todo:
        pid = todo.pop()
        found.add(pid)
        todo += children.get(pid, [])
    return found


def _address(hex_ip: str) -> ipaddress.IPv4Address | ipaddress.IPv6Address:
    """An address as /proc/net/tcp{,6} writes it: 32-bit words in host (little-endian) order."""
    raw = bytes.fromhex(hex_ip)
    words = b"".join(raw[i : i + 4][::-1] for i in range(0, len(raw), 4))
    return ipaddress.ip_address(words)


def _listening(pids: set[int]) -> list[tuple[str, int, str]]:
    """(address, port, process name) of every TCP socket in LISTEN that one of ``pids`` holds."""
    owner: dict[str, int] = {}
    for pid in pids:
        try:
            for fd in os.listdir(f"/proc/{pid}/fd"):
                link = os.readlink(f"/proc/{pid}/fd/{fd}")
                if link.startswith("socket:["):
                    owner[link[8:-1]] = pid
        except OSError:  # ended meanwhile
            continue
    found = []
    for table in ("/proc/net/tcp", "/proc/net/tcp6"):
        with open(table) as f:
            for line in f.readlines()[1:]:
                fields = line.split()
                local, state, inode = fields[1], fields[3], fields[9]
                if state == "0A" and inode in owner:  # TCP_LISTEN
                    ip, port = local.split(":")
                    try:
                        with open(f"/proc/{owner[inode]}/comm") as c:
                            name = c.read().strip()
                    except OSError:
                        name = "?"
                    found.append((str(_address(ip)), int(port, 16), name))
    return found


def _loopback(address: str) -> bool:
    ip = ipaddress.ip_address(address)
    mapped = getattr(ip, "ipv4_mapped", None)
    return ip.is_loopback or (mapped is not None and mapped.is_loopback)


@pytest.mark.slow
def test_a_local_ray_listens_on_the_loopback_only_and_joins_no_cluster_it_is_pointed_at(tmp_path: Path) -> None:
    """One sweep on ``--ray local`` with RAY_ADDRESS and Ray's recorded cluster both naming an address where
    nothing runs: it starts its own Ray instead (before: it tried to join that one and stopped), and while its
    run holds, every LISTEN socket of the sweep's processes (GCS, raylet, workers, agents) is on 127.0.0.1. One
    Ray start for both checks (7 s here; starting Ray is most of it and takes longer on a loaded machine)."""
    running, go = tmp_path / "running", tmp_path / "go"
    scenario = tmp_path / "hold.py"
    scenario.write_text(HOLD.format(running=str(running), go=str(go)))
    # Ray's temp folder with a recorded cluster nobody runs (short: Ray's unix sockets live under it)
    ray_tmp = Path(tempfile.mkdtemp(prefix="g-"))
    (ray_tmp / "ray").mkdir()
    (ray_tmp / "ray" / "ray_current_cluster").write_text("127.0.0.1:9")
    env = {**os.environ, "RAY_ADDRESS": "127.0.0.1:9", "RAY_TMPDIR": str(ray_tmp)}
    sweep = subprocess.Popen(
        [*GAZELLE, "sweep", f"{scenario}::hold", "--ray", "local", "-j", "1", "--out", str(tmp_path / "out")],
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        env=env,
        start_new_session=True,  # Ray's processes in the sweep's group: stopped with it if the test fails
    )
    try:
        wait_for(lambda: running.exists() or sweep.poll() is not None, 180, "the sweep's run to start")
        assert sweep.poll() is None, sweep.communicate()[0][-3000:]
        listening = _listening(_descendants(sweep.pid))
        go.touch()
        names = {name for _ip, _port, name in listening}
        assert {"gcs_server", "raylet"} <= names, listening  # the sweep's own Ray, found
        exposed = [s for s in listening if not _loopback(s[0])]
        assert not exposed, f"listening beyond the loopback: {exposed}"
        out, _ = sweep.communicate(timeout=120)
        assert sweep.returncode == 0, out[-3000:]
        assert "1 passed" in out, out[-3000:]
    finally:
        go.touch()
        if sweep.poll() is None:
            os.killpg(sweep.pid, signal.SIGKILL)
            sweep.wait()
        shutil.rmtree(ray_tmp, ignore_errors=True)
