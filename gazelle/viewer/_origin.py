"""Who may talk to the viewer: its own origin only, under a Host name it answers to.

A browser lets any web page open ``ws://127.0.0.1:8080``; without a check, a page the user
merely visits could spawn, delete and drive. Browsers always send ``Origin`` on a websocket
handshake, so the viewer accepts a websocket only when its ``Origin`` is the viewer's own
(``http://<the Host the browser asked for>``) or one the user allowed with
``--viewer-allow-origin``. A foreign ``Host`` header (DNS rebinding: a hostile name resolved to
127.0.0.1) is refused for every request, pages included, while the viewer is bound to loopback.
Bound to a wildcard (``--viewer-host 0.0.0.0``, a deliberate opening), any Host is accepted but
the Origin rule still holds. Clients that send no Origin (scripts, not browsers) are accepted.

viser does not expose its websockets server, so :func:`guarded` installs the check by wrapping
``websockets.asyncio.server.serve`` while a :class:`Viewer` creates its viser server.
"""

from __future__ import annotations

import contextlib
import http
import logging
import threading
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import Any
from urllib.parse import urlsplit

import websockets.asyncio.server as ws_server

_log = logging.getLogger("gazelle.viewer")

LOOPBACK_NAMES = ("127.0.0.1", "localhost", "[::1]", "::1")
WILDCARD_HOSTS = ("", "0.0.0.0", "::")


@dataclass(frozen=True)
class OriginPolicy:
    """The viewer's rule for Host and Origin headers."""

    bind_host: str
    """The interface the viewer binds to (``--viewer-host``)."""
    allow_origins: tuple[str, ...] = ()
    """Extra origins allowed to open a websocket (``--viewer-allow-origin``); ``*`` allows any."""

    def host_names(self) -> tuple[str, ...]:
        """The names the viewer answers to (without port); empty when bound to a wildcard (any)."""
        if self.bind_host in WILDCARD_HOSTS:
            return ()
        return tuple(dict.fromkeys((*LOOPBACK_NAMES, self.bind_host.lower())))

    def host_ok(self, host_header: str | None, port: int) -> bool:
        """Whether a request's ``Host`` header names this viewer."""
        names = self.host_names()
        if not names:
            return True
        if not host_header:
            return False
        parsed = urlsplit(f"//{host_header.strip().lower()}")
        try:
            hport = parsed.port
        except ValueError:
            return False
        name = parsed.hostname or ""
        if ":" in name:  # urlsplit strips the brackets of an IPv6 literal
            name = f"[{name}]"
        return (name in names or name.strip("[]") in names) and hport in (port, None if port == 80 else port)

    def origin_ok(self, origin: str | None, host_header: str | None) -> bool:
        """Whether a websocket handshake's ``Origin`` is the viewer's own (or allowed)."""
        if origin is None:
            return True  # not a browser: browsers always send Origin on a websocket handshake
        origin = origin.strip().rstrip("/").lower()
        if "*" in self.allow_origins or origin in (o.rstrip("/").lower() for o in self.allow_origins):
            return True
        if origin == "null" or not host_header:
            return False
        parsed = urlsplit(origin)
        return parsed.scheme in ("http", "https") and parsed.netloc == host_header.strip().lower()

    def check(self, connection: Any, request: Any) -> Any:
        """``process_request`` hook: None to go on, or a 403 response."""
        port = connection.local_address[1] if connection.local_address else 0
        host = request.headers.get("Host")
        if not self.host_ok(host, port):
            _log.warning(f"viewer: refused a request for foreign Host {host!r} (DNS rebinding guard)")
            return connection.respond(http.HTTPStatus.FORBIDDEN, "Forbidden: unknown Host\n")
        if request.headers.get("Upgrade", "").lower() == "websocket":
            origin = request.headers.get("Origin")
            if not self.origin_ok(origin, host):
                _log.warning(
                    f"viewer: refused a websocket from foreign origin {origin!r} (allow it with --viewer-allow-origin)"
                )
                return connection.respond(http.HTTPStatus.FORBIDDEN, "Forbidden: foreign Origin\n")
        return None


_LOCK = threading.Lock()
_pending: OriginPolicy | None = None
_original_serve = ws_server.serve


def _serve(*args: Any, process_request: Any = None, **kwargs: Any) -> Any:
    """viser's call of ``websockets.serve``, with the viewer's origin check put in front of viser's own request
    handling while the viewer being started has a policy (``_pending``): a refused handshake never reaches viser."""
    policy = _pending
    if policy is None:
        return _original_serve(*args, process_request=process_request, **kwargs)

    def guarded_request(connection: Any, request: Any) -> Any:
        refused = policy.check(connection, request)
        if refused is not None:
            return refused
        return process_request(connection, request) if process_request is not None else None

    return _original_serve(*args, process_request=guarded_request, **kwargs)


@contextlib.contextmanager
def guarded(policy: OriginPolicy) -> Iterator[None]:
    """Within this block, a websockets server started (by viser) checks every request with ``policy``."""
    global _pending
    with _LOCK:
        ws_server.serve = _serve
        _pending = policy
        try:
            yield
        finally:
            _pending = None
            ws_server.serve = _original_serve


def allowed_origins(values: Sequence[str]) -> tuple[str, ...]:
    """Normalise ``--viewer-allow-origin`` values (``http://host:port`` or ``*``)."""
    out = []
    for v in values:
        v = v.strip()
        if v != "*" and urlsplit(v).scheme not in ("http", "https"):
            raise ValueError(f"--viewer-allow-origin expects http(s)://HOST[:PORT] or '*', got {v!r}")
        out.append(v)
    return tuple(out)
