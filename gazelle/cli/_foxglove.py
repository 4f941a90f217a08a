"""A Foxglove WebSocket bridge for the ROS graph (``gazelle foxglove``, ``gazelle sim --foxglove``).

What the ROS ``foxglove_bridge`` node does, with the foxglove-sdk server:

* every topic on the graph (not hidden) is a Foxglove channel: its type's ``ros2msg`` definition as the
  schema (:func:`gazelle.ros.message_definition`), ``cdr`` as the encoding;
* a topic is subscribed in ROS (a raw subscription: the CDR bytes go out as they came) only while a
  Foxglove client subscribes to its channel, so nothing is taken for nobody;
* the topics are looked up again every second (new ones are advertised, gone ones withdrawn).

foxglove-sdk's server has no hook on the websocket handshake, so it listens on a private loopback port
and clients reach it through a small proxy that applies the viewer's rule (``gazelle.viewer``'s
:class:`~gazelle.viewer.OriginPolicy`): a foreign ``Host`` is refused while bound to loopback (DNS
rebinding), and a browser may connect only from the Foxglove app (``https://app.foxglove.dev``) or an
origin given with ``--allow-origin``. Clients that send no Origin (the desktop app, scripts) are
accepted. It binds 127.0.0.1 unless told otherwise.

The private port is not a way around the proxy: the server there speaks only TLS (``wss://``), with a
certificate made for this run in memory, which only the proxy trusts (it pins it). A web page that
finds the port (a port scan, DNS rebinding) cannot complete the handshake: a plain ``ws://`` gets no
websocket, and a browser refuses the unknown certificate. (A local program can skip the certificate
check; but a local program can join the ROS graph itself, which is what discovery limited to the
machine allows.) Frames from clients are bounded (:data:`MAX_CLIENT_FRAME`).
"""

from __future__ import annotations

import asyncio
import logging
import queue
import signal
import threading
import time
from typing import Any

import rclpy
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node

from ..ros import InterfaceError, message_class
from ..ros import message_definition as full_text
from ..viewer import OriginPolicy
from .ros2cli import matching_qos

_log = logging.getLogger("gazelle.foxglove")

DEFAULT_PORT = 8765
"""foxglove_bridge's port."""
FOXGLOVE_APP_ORIGINS = ("https://app.foxglove.dev",)
"""Browser origins allowed by default: the Foxglove web app."""
SUBPROTOCOLS = ("foxglove.sdk.v1",)
"""The Foxglove WebSocket protocol's name that foxglove-sdk's server speaks (it refuses the legacy
``foxglove.websocket.v1``)."""
REFRESH_SEC = 1.0
MAX_CLIENT_FRAME = 16 << 20
"""The largest frame a client may send (subscriptions, advertisements and published messages are small;
a 256 MB frame held 430 MB of the proxy's memory)."""


def _private_tls() -> tuple[bytes, bytes]:
    """A self-signed certificate and key for ``127.0.0.1``, made now and never written anywhere."""
    import datetime
    import ipaddress

    from cryptography import x509
    from cryptography.hazmat.primitives import hashes, serialization
    from cryptography.hazmat.primitives.asymmetric import ec
    from cryptography.x509.oid import NameOID

    key = ec.generate_private_key(ec.SECP256R1())
    name = x509.Name([x509.NameAttribute(NameOID.COMMON_NAME, "gazelle foxglove (this run only)")])
    now = datetime.datetime.now(datetime.UTC)
    cert = (
        x509.CertificateBuilder()
        .subject_name(name)
        .issuer_name(name)
        .public_key(key.public_key())
        .serial_number(x509.random_serial_number())
        .not_valid_before(now - datetime.timedelta(minutes=5))
        .not_valid_after(now + datetime.timedelta(days=365))
        .add_extension(x509.SubjectAlternativeName([x509.IPAddress(ipaddress.ip_address("127.0.0.1"))]), False)
        .sign(key, hashes.SHA256())
    )
    pem_key = key.private_bytes(
        serialization.Encoding.PEM, serialization.PrivateFormat.PKCS8, serialization.NoEncryption()
    )
    return cert.public_bytes(serialization.Encoding.PEM), pem_key


def _hidden(name: str) -> bool:
    return any(part.startswith("_") for part in name.split("/") if part)


class FoxgloveBridge:
    """Topics of the ROS graph as Foxglove channels, served behind the origin-checking proxy."""

    def __init__(self, host: str = "127.0.0.1", port: int = DEFAULT_PORT, allow_origins: tuple[str, ...] = ()):
        """A Foxglove WebSocket server on ``host:port`` for the ROS graph of this process's domain: foxglove-sdk's
        server runs on a private loopback port with a certificate made for this run, behind :class:`_Proxy`,
        which refuses foreign origins (the Foxglove app's and ``allow_origins`` are let in). Channels are the
        graph's topics; a topic is subscribed to in ROS only while a client subscribes to its channel."""
        import foxglove

        self.context = Context()
        rclpy.init(args=[], context=self.context)
        self.node = Node("foxglove_bridge", context=self.context)
        self._executor = SingleThreadedExecutor(context=self.context)
        self._executor.add_node(self.node)
        self._foxglove = foxglove
        self._channels: dict[str, Any] = {}
        """topic -> foxglove Channel"""
        self._types: dict[str, str] = {}
        self._subs: dict[str, Any] = {}
        self._subscribers: dict[str, set[int]] = {}
        """topic -> ids of the clients subscribed to its channel"""
        self._requests: queue.SimpleQueue[tuple[str, str, int]] = queue.SimpleQueue()
        """(subscribe | unsubscribe, topic, client id), done on the ROS thread."""
        self._warned: set[str] = set()
        cert, key = _private_tls()
        self._upstream = foxglove.start_server(
            name="gazelle",
            host="127.0.0.1",
            port=0,
            tls_cert=cert,
            tls_key=key,
            server_listener=_Listener(self),  # pyright: ignore[reportArgumentType] - a Protocol, by its methods
        )
        self.policy = OriginPolicy(host, tuple(dict.fromkeys((*FOXGLOVE_APP_ORIGINS, *allow_origins))))
        self._proxy = _Proxy(self.policy, host, port, self._upstream.port, cert)
        self.port = self._proxy.port

    # ------------------------------------------------------------------ channels
    def refresh(self) -> None:
        """Advertise the graph's topics as channels; withdraw the gone ones."""
        seen: set[str] = set()
        for topic, types in self.node.get_topic_names_and_types():
            if _hidden(topic) or not types:
                continue
            seen.add(topic)
            if topic in self._channels and self._types.get(topic) == types[0]:
                continue
            try:
                schema = full_text(types[0])
            except InterfaceError as err:
                if topic not in self._warned:
                    self._warned.add(topic)
                    _log.warning(f"topic {topic} is not bridged: {err}")
                continue
            self._close(topic)
            fg = self._foxglove
            self._channels[topic] = fg.Channel(
                topic,
                schema=fg.Schema(name=types[0], encoding="ros2msg", data=schema.encode()),
                message_encoding="cdr",
            )
            self._types[topic] = types[0]
        for topic in [t for t in self._channels if t not in seen]:
            self._close(topic)

    def _close(self, topic: str) -> None:
        """A topic left the graph: its channel, its ROS subscription and its clients go."""
        channel = self._channels.pop(topic, None)
        if channel is not None:
            channel.close()
        sub = self._subs.pop(topic, None)
        if sub is not None:
            self.node.destroy_subscription(sub)
        self._subscribers.pop(topic, None)

    # ------------------------------------------------------------------ subscriptions (ROS thread)
    def _apply(self, action: str, topic: str, client: int) -> None:
        """A client's subscribe or unsubscribe, on the ROS thread: the topic is subscribed to in ROS while at least
        one client wants it, and no longer."""
        clients = self._subscribers.setdefault(topic, set())
        if action == "subscribe":
            clients.add(client)
        else:
            clients.discard(client)
        if clients and topic not in self._subs and topic in self._channels:
            self._subs[topic] = self._subscribe(topic)
        elif not clients and topic in self._subs:
            self.node.destroy_subscription(self._subs.pop(topic))

    def _subscribe(self, topic: str) -> Any:
        """A raw subscription forwarding each message's CDR bytes to the topic's channel."""
        channel = self._channels[topic]

        def forward(data: bytes) -> None:
            channel.log(data, log_time=time.time_ns())

        cls = message_class(self._types[topic])
        return self.node.create_subscription(cls, topic, forward, matching_qos(self.node, topic), raw=True)

    def spin(self, stop: threading.Event) -> None:
        """Serve until ``stop`` is set."""
        next_refresh = 0.0
        while not stop.is_set() and self.context.ok():
            now = time.monotonic()
            if now >= next_refresh:
                next_refresh = now + REFRESH_SEC
                self.refresh()
            while True:
                try:
                    action, topic, client = self._requests.get_nowait()
                except queue.Empty:
                    break
                self._apply(action, topic, client)
            self._executor.spin_once(timeout_sec=0.05)

    def shutdown(self) -> None:
        """Stop the proxy and the server, destroy the node."""
        self._proxy.stop()
        self._upstream.stop()
        self._executor.shutdown(timeout_sec=1.0)
        self.node.destroy_node()
        if self.context.ok():
            rclpy.shutdown(context=self.context)


class _Listener:
    """foxglove-sdk's server listener: client (un)subscriptions, handed to the ROS thread."""

    def __init__(self, bridge: FoxgloveBridge):
        self.bridge = bridge

    def on_subscribe(self, client: Any, channel: Any) -> None:
        self.bridge._requests.put(("subscribe", channel.topic, client.id))

    def on_unsubscribe(self, client: Any, channel: Any) -> None:
        self.bridge._requests.put(("unsubscribe", channel.topic, client.id))


class _Proxy:
    """The public websocket endpoint: checks Host and Origin, then relays frames to foxglove-sdk's server."""

    def __init__(self, policy: OriginPolicy, host: str, port: int, upstream_port: int, upstream_cert: bytes):
        """The public side of the Foxglove server: a WebSocket server on ``host:port`` that checks each connection's
        Origin and Host (see :class:`OriginPolicy`) and relays an accepted one to the upstream server over TLS,
        trusting only the upstream's certificate of this run."""
        import ssl

        self.policy = policy
        self._upstream = f"wss://127.0.0.1:{upstream_port}"
        # trusts exactly the upstream's certificate of this run
        self._tls = ssl.create_default_context(ssl.Purpose.SERVER_AUTH, cadata=upstream_cert.decode())
        self._loop = asyncio.new_event_loop()
        self._ready = threading.Event()
        self._error: BaseException | None = None
        self._server: Any = None
        self.port = 0
        self._thread = threading.Thread(target=self._run, args=(host, port), name="foxglove-proxy", daemon=True)
        self._thread.start()
        self._ready.wait(10.0)
        if self._error is not None:
            raise self._error

    def _run(self, host: str, port: int) -> None:
        """The proxy's thread: start the server (an error, such as a port in use, is handed to the constructor) and
        serve until closed."""
        asyncio.set_event_loop(self._loop)
        try:
            self._loop.run_until_complete(self._start(host, port))
        except BaseException as err:  # reported to the constructor (a port in use)
            self._error = err
            self._ready.set()
            return
        self._ready.set()
        self._loop.run_forever()

    async def _start(self, host: str, port: int) -> None:
        """Listen on ``host:port`` for Foxglove's subprotocols, with the origin check on the opening request and a
        bound on a client's frame size."""
        from websockets.asyncio.server import serve

        self._server = await serve(
            self._relay,
            host,
            port,
            subprotocols=list(SUBPROTOCOLS),  # pyright: ignore[reportArgumentType] - foxglove's binding declares a list of its own type for the subprotocols
            process_request=self.policy.check,
            max_size=MAX_CLIENT_FRAME,
            compression=None,
        )
        self.port = self._server.sockets[0].getsockname()[1]

    async def _relay(self, client: Any) -> None:
        """Relay one accepted client to the upstream server, frames both ways, until either side closes."""
        from websockets.asyncio.client import connect
        from websockets.typing import Subprotocol

        chosen = Subprotocol(client.subprotocol or SUBPROTOCOLS[0])
        async with connect(
            self._upstream, subprotocols=[chosen], max_size=None, compression=None, ssl=self._tls
        ) as upstream:

            async def pump(src: Any, dst: Any) -> None:
                async for frame in src:
                    await dst.send(frame)

            tasks = [asyncio.ensure_future(pump(client, upstream)), asyncio.ensure_future(pump(upstream, client))]
            _done, pending = await asyncio.wait(tasks, return_when=asyncio.FIRST_COMPLETED)
            for task in pending:
                task.cancel()

    async def _close(self) -> None:
        """Close the listening socket and the relays, then stop the loop (a close left to a loop that had
        stopped printed "Task was destroyed but it is pending" at every shutdown)."""
        if self._server is not None:
            self._server.close()
            try:
                await asyncio.wait_for(self._server.wait_closed(), 1.0)
            except (TimeoutError, Exception):
                pass
        self._loop.stop()

    def stop(self) -> None:
        if self._loop.is_running():
            asyncio.run_coroutine_threadsafe(self._close(), self._loop)
        self._thread.join(timeout=2.0)


PARENT_PID_VARIABLE = "GAZELLE_FOXGLOVE_PARENT"
"""Set by ``gazelle sim --foxglove`` to its pid: the bridge then ends with the server, however it ends."""


def _exit_with_parent() -> None:
    """Under ``gazelle sim``: be sent SIGTERM when the server's process ends (``PR_SET_PDEATHSIG``), so a
    server stopped by its watchdog or killed leaves no bridge holding the port."""
    import os

    parent = os.environ.get(PARENT_PID_VARIABLE, "")
    if not parent.isdigit():
        return
    try:
        import ctypes

        ctypes.CDLL(None).prctl(1, signal.SIGTERM, 0, 0, 0)
    except (OSError, AttributeError):
        return
    if os.getppid() != int(parent):  # the server ended before the line above
        os._exit(0)


def run(host: str = "127.0.0.1", port: int = DEFAULT_PORT, allow_origins: tuple[str, ...] = ()) -> int:
    """``gazelle foxglove``: serve until Ctrl-C; returns the exit status."""
    logging.basicConfig(level=logging.INFO, format="[%(levelname)s] [%(name)s]: %(message)s")
    _exit_with_parent()
    try:
        bridge = FoxgloveBridge(host, port, allow_origins)
    except OSError as err:
        print(f"gazelle foxglove: cannot listen on {host}:{port}: {err.strerror or err}", flush=True)
        return 1
    stop = threading.Event()
    signal.signal(signal.SIGINT, lambda *_a: stop.set())
    signal.signal(signal.SIGTERM, lambda *_a: stop.set())
    print(f"gazelle: Foxglove bridge at ws://{host}:{bridge.port}", flush=True)
    try:
        bridge.spin(stop)
    finally:
        bridge.shutdown()
    return 0
