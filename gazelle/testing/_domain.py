"""A ROS_DOMAIN_ID no other process on this machine holds, whoever runs it.

Two test runs on one machine (two developers, or a developer and CI) that picked the same domain would
answer each other's service calls, and DDS domains are the machine's, not a user's: the reservation must be
seen by every user. A domain is taken by holding two things while it is in use, both dropped by the kernel
when the process ends, however it ends (a killed run never leaves a domain taken):

* a TCP socket bound to ``127.0.0.1:32768 + id``, ROS 2's own scheme (``domain_coordinator``, which
  launch_testing and ament's test runners use: its port base, so a ROS package's tests on this machine and
  gazelle's never share a domain either). Binding a port touches no file: nothing can be planted for it.
* an exclusive ``flock`` on ``$TMPDIR/gazelle-ros-domain-<id>.lock``, the scheme of earlier gazelle versions,
  so that their runs (another developer's checkout) and this one still see each other's domains. The file
  is opened without following a link, created only with ``O_EXCL``, and used only if it is a regular file: a
  planted link, a directory or a FIFO of that name makes the domain skipped, never a file created through the
  link (as root, the plugin once created a planted link's target) nor an error out of the reservation.

A port someone else holds, or a lock file that is taken or odd, means the next domain is tried.

The domains tried are 10-100, or the user's: ``--gazelle-domains`` of the pytest plugin, else the
environment variable :data:`DOMAINS_VAR` (``20-29``, ``20,22,25-27``, ``42``), for a team with a range of its own
(the rest of the machine's domains kept for its robots, or for launch_testing's coordinator).
"""

from __future__ import annotations

import contextlib
import fcntl
import os
import socket
import stat
import tempfile
from collections.abc import Iterator, Mapping, Sequence

FIRST, LAST = 10, 100
"""Domains handed out. Fast DDS maps a domain to UDP ports 7400 + 250 * id and up, and Linux's ephemeral
ports start at 32768: ids up to 101 stay below them (ROS 2's own guidance for Linux)."""
MAX_DOMAIN = 232
"""The largest domain id Fast DDS takes (its ports stay below 65536); ids above 101 reach Linux's ephemeral ports."""
DOMAINS_VAR = "GAZELLE_ROS_DOMAINS"
"""The environment variable with the domains tests may use (see :func:`parse_domains`)."""
PORT_BASE = 32768
"""Domain ``id`` is held by binding TCP port ``PORT_BASE + id`` on 127.0.0.1 (domain_coordinator's base)."""


class DomainReservation:
    """One reserved domain id; :meth:`release` (or the end of the process) frees it."""

    def __init__(self, domain_id: int, port: socket.socket, lock_fd: int) -> None:
        self.domain_id = domain_id
        self._port: socket.socket | None = port
        self._lock_fd: int | None = lock_fd

    def release(self) -> None:
        """Free the domain: close the bound socket and the lock file (which drops the flock)."""
        if self._port is not None:
            self._port.close()
            self._port = None
        if self._lock_fd is not None:
            os.close(self._lock_fd)
            self._lock_fd = None


def parse_domains(text: str, what: str = DOMAINS_VAR) -> tuple[int, ...]:
    """The domain ids of ``text``: comma-separated ids and ``first-last`` ranges (``20-29``, ``20,22,25-27``),
    each in 0..:data:`MAX_DOMAIN`, in order and each once.

    Raises:
        ValueError: one line naming ``what`` and the part that is not an id or a range.
    """
    out: list[int] = []
    for part in text.replace(" ", "").split(","):
        first, dash, last = part.partition("-")
        if not first.isdigit() or (dash and not last.isdigit()):
            raise ValueError(f"{what}: {part!r} is not a domain id or a range such as 20-29 (got {text!r})")
        lo, hi = int(first), int(last) if dash else int(first)
        if not 0 <= lo <= hi <= MAX_DOMAIN:
            raise ValueError(f"{what}: {part!r} is not within 0-{MAX_DOMAIN}, first to last (got {text!r})")
        out.extend(range(lo, hi + 1))
    return tuple(dict.fromkeys(out))


def domains_from_environment() -> tuple[int, ...]:
    """The domains of :data:`DOMAINS_VAR`, else FIRST..LAST."""
    text = os.environ.get(DOMAINS_VAR, "").strip()
    return parse_domains(text) if text else tuple(range(FIRST, LAST + 1))


def reserve_domain(preferred: int | None = None, domains: Sequence[int] | None = None) -> DomainReservation:
    """The first free domain of ``domains`` (default: :func:`domains_from_environment`, the user's range or
    10..100), starting at ``preferred`` if it is one of them (default: one picked from the process id, so
    concurrent runs rarely contend for the same one).

    Raises:
        RuntimeError: every one of them is held (the message names the range and how to give another).
        ValueError: :data:`DOMAINS_VAR` is not a list of ids and ranges.
    """
    pool = tuple(domains) if domains is not None else domains_from_environment()
    if not pool:
        raise ValueError("reserve_domain: no domains to choose from")
    span = len(pool)
    start = pool.index(preferred) if preferred in pool else os.getpid() % span
    for k in range(span):
        domain = pool[(start + k) % span]
        port = _bind_port(domain)
        if port is None:
            continue
        lock_fd = _lock_file(domain)
        if lock_fd is None:
            port.close()
            continue
        return DomainReservation(domain, port, lock_fd)
    shown = f"{pool[0]}..{pool[-1]}" if pool == tuple(range(pool[0], pool[-1] + 1)) else ",".join(map(str, pool))
    raise RuntimeError(
        f"no free ROS domain id in {shown}: each is held by a run or another process "
        f"(give more with --gazelle-domains or {DOMAINS_VAR})"
    )


def _bind_port(domain: int) -> socket.socket | None:
    """A TCP socket bound to 127.0.0.1:``PORT_BASE + domain`` (not listening: nothing can connect), or None
    when another process holds that port (domain_coordinator binds every interface, which conflicts too)."""
    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    try:
        sock.bind(("127.0.0.1", PORT_BASE + domain))
    except OSError:
        sock.close()
        return None
    return sock


def lock_path(domain: int) -> str:
    """The lock file of ``domain`` earlier gazelle versions reserve it with."""
    return os.path.join(tempfile.gettempdir(), f"gazelle-ros-domain-{domain}.lock")


def _lock_file(domain: int) -> int | None:
    """A descriptor holding the exclusive flock on :func:`lock_path`, or None when another process holds it or
    the name is anything but a regular file (a link is never followed, nothing is created through one)."""
    path = lock_path(domain)
    flags = os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC
    fd = None
    for create in (0, os.O_CREAT | os.O_EXCL, 0):  # open; else create (refuses any name there); else it just was
        try:
            fd = os.open(path, flags | create, 0o644)
            break
        except (FileNotFoundError, FileExistsError):
            continue
        except OSError:  # a link (ELOOP), no permission...: this domain is skipped
            return None
    if fd is None:
        return None
    try:
        if stat.S_ISREG(os.fstat(fd).st_mode):
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            return fd
    except OSError:
        pass
    os.close(fd)
    return None


@contextlib.contextmanager
def environ_applied(values: Mapping[str, str | None]) -> Iterator[None]:
    """``os.environ`` with ``values`` set (None: the variable removed) while the block runs, each key put back as it
    was (or removed)."""
    saved = {k: os.environ.get(k) for k in values}
    for k, v in values.items():
        if v is None:
            os.environ.pop(k, None)
        else:
            os.environ[k] = v
    try:
        yield
    finally:
        for k, v in saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v
