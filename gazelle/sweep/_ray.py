"""Ray for a sweep: a Ray of this machine kept to its loopback (``--ray local``), or a cluster joined (``auto``,
``ray://HOST:PORT``), each way it can fail said in one line of gazelle's own.

Why loopback takes more than an argument: Ray's servers (GCS, raylet, object manager, every worker's gRPC
server) listen on all interfaces unless the node's address is 127.0.0.1, and ``ray.init`` turns a
``_node_ip_address`` of 127.0.0.1 into the machine's network address (``services.resolve_ip_for_localhost``
asks ``get_node_ip_address``, which returns the loopback only where ``ray_constants.ENABLE_RAY_CLUSTER`` is
false: Ray's own setting for macOS and Windows, ``RAY_ENABLE_WINDOWS_OR_OSX_CLUSTER``; Ray 2.60). So for the
length of ``ray.init`` that setting is false here and in the environment the raylet and its workers inherit,
the address is checked to resolve to 127.0.0.1 before anything starts, and the started node's address is
checked again after: a Ray that would not keep to the loopback is refused, never run."""

from __future__ import annotations

import importlib
import os
import socket
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from ._spec import SweepError

LOOPBACK = "127.0.0.1"
_CLUSTER_VAR = "RAY_ENABLE_WINDOWS_OR_OSX_CLUSTER"
"""Ray's switch for the loopback-only node of macOS and Windows (ray/_private/ray_constants.py)."""
_ADDRESS_VAR = "RAY_ADDRESS"
"""The cluster ``ray.init`` joins when given no address or ``auto`` (ray/_private/worker.py)."""
_QUIET: dict[str, Any] = {"include_dashboard": False, "log_to_driver": False}


@contextmanager
def ray_session(address: str, jobs: int) -> Iterator[Any]:
    """The ``ray`` module, connected for a sweep: ``local`` starts a Ray of ``jobs`` CPUs on this machine's
    loopback, shut down at the end; ``auto`` joins the cluster in ``RAY_ADDRESS`` or the one ``ray start``
    recorded here; ``ray://HOST:PORT`` a Ray client server. A Ray session the caller already has is used as it is
    and left running (its addresses are the caller's choice)."""
    try:
        import ray
    except ImportError as err:
        raise SweepError(f"--ray needs the ray package: {err}") from None
    if ray.is_initialized():
        yield ray
        return
    if address == "local":
        _start_local(ray, jobs)
    else:
        _join(ray, address)
    try:
        yield ray
    finally:
        ray.shutdown()


def _start_local(ray: Any, jobs: int) -> None:
    """A new Ray node on 127.0.0.1 (never the cluster ``RAY_ADDRESS`` or a stale ``ray_current_cluster`` names:
    ``address="local"``, and ``RAY_ADDRESS`` out of the environment its processes inherit), its files under a
    folder only this user can enter, no dashboard."""
    constants: Any = importlib.import_module("ray._private.ray_constants")
    services = importlib.import_module("ray._private.services")
    temp = _private_folder("gazelle-ray") / "r"  # Ray makes its temp dir world-writable: one level down
    saved = constants.ENABLE_RAY_CLUSTER
    from ..testing import environ_applied

    with environ_applied({_CLUSTER_VAR: "0", _ADDRESS_VAR: None}):
        constants.ENABLE_RAY_CLUSTER = False
        try:
            resolved = services.resolve_ip_for_localhost(LOOPBACK)
            if resolved != LOOPBACK:
                raise SweepError(f"--ray local: this Ray would listen on {resolved}, not {LOOPBACK}: not started")
            context = ray.init(address="local", num_cpus=jobs, _node_ip_address=LOOPBACK, _temp_dir=str(temp), **_QUIET)
        except SweepError:
            raise
        except Exception as err:
            raise SweepError(f"--ray local: Ray did not start: {_first_line(err)}") from None
        finally:
            constants.ENABLE_RAY_CLUSTER = saved
    node = context.address_info.get("node_ip_address")
    if node != LOOPBACK:
        ray.shutdown()
        raise SweepError(f"--ray local: Ray's node came up on {node}, not {LOOPBACK}: stopped")


def _join(ray: Any, address: str) -> None:
    """Join a running cluster. ``auto`` with neither ``RAY_ADDRESS`` nor a cluster ``ray start`` recorded is
    refused here (Ray's own message names an ``--address`` flag gazelle does not have, and its fallback joins
    whatever raylet a process listing shows); a ``ray://`` address nothing answers is refused at once."""
    if address == "auto" and not _cluster_recorded():
        raise SweepError(
            "--ray auto: no Ray cluster to join (RAY_ADDRESS is not set and `ray start --head` has not run "
            "on this machine); start one, or use --ray local or --ray ray://HOST:PORT"
        )
    if address.startswith("ray://"):
        _probe(address)
    try:
        ray.init(address=address, ignore_reinit_error=True, **_QUIET)
    except Exception as err:
        raise SweepError(f"--ray {address}: cannot connect: {_first_line(err)}") from None


def _cluster_recorded() -> bool:
    """Whether ``ray.init(address="auto")`` has a cluster to go to other than a process listing's guess:
    ``RAY_ADDRESS``, or the address file ``ray start`` writes (ray/_common/utils.py get_ray_address_file)."""
    if os.environ.get(_ADDRESS_VAR):
        return True
    utils = importlib.import_module("ray._common.utils")
    return Path(utils.get_ray_address_file(None)).is_file()


def _probe(address: str, timeout: float = 5.0) -> None:
    """Refuse at once a Ray client address that nothing answers (Ray's own client waits 30 s)."""
    host, _, port = address.removeprefix("ray://").rpartition(":")
    try:
        with socket.create_connection((host.strip("[]") or LOOPBACK, int(port)), timeout=timeout):
            pass
    except ValueError:
        raise SweepError(f"--ray {address}: expected ray://HOST:PORT") from None
    except OSError as err:
        raise SweepError(f"--ray {address}: cannot connect: {err.strerror or err}") from None


def _first_line(err: BaseException) -> str:
    return f"{type(err).__name__}: {(str(err).splitlines() or [''])[0]}"


def _private_folder(prefix: str) -> Path:
    """``<tmp>/<prefix>-<uid>``, made owner-only; one that another user owns or can enter is refused."""
    folder = Path(tempfile.gettempdir()) / f"{prefix}-{os.getuid()}"
    folder.mkdir(mode=0o700, exist_ok=True)
    st = folder.lstat()
    if folder.is_symlink() or st.st_uid != os.getuid() or st.st_mode & 0o077:
        raise SweepError(f"--ray local: {folder} is not this user's own folder (owner-only): not started")
    return folder
