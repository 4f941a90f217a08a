"""``ros2 bag record | play | info``: rosbag2's MCAP storage, written and read with the ``mcap`` library.

A bag is a folder with ``metadata.yaml`` (rosbag2's version 9 layout) and ``<folder>_0.mcap``: profile
``ros2``, one schema per type (``ros2msg``: the definition with its dependencies, see
:mod:`._definitions`), one channel per topic (``cdr``, with the publishers' ``offered_qos_profiles``),
and the messages as the CDR bytes received (raw subscriptions: nothing is deserialised while
recording). rosbag2 itself, ``rosbags`` and Foxglove read it.

Decisions where rosbag2 leaves a choice:

* ``record`` subscribes with a QoS compatible with every publisher (reliable and transient local each only
  if all publishers offer it, as rosbag2), once a topic has a publisher (rosbag2's default;
  ``--include-unpublished-topics`` for the others), and logs each message at the time its reader received
  it, published at the time its writer sent it (``--use-sim-time``: logged at /clock's time), as rosbag2
  does; on Ctrl-C it writes what its readers still hold before it stops;
* ``--qos-profile-overrides-path`` (record and play) takes rosbag2's YAML, ``TOPIC: {history, depth,
  reliability, durability, deadline: {sec, nsec}, lifespan, liveliness, liveliness_lease_duration,
  avoid_ros_namespace_conventions}``, read as ros2bag's ``convert_yaml_to_qos_profile`` does: the profile
  replaces the adapted one for that topic;
* ``play`` waits, before the first message, until the subscribers already in the graph have matched its
  publishers (at most ``--wait`` seconds, 2 by default), so a listener started first misses nothing,
  and at the end until reliable subscribers acknowledged everything (at most 2 s).
"""

from __future__ import annotations

import argparse
import datetime
import re
import signal
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any, BinaryIO

import yaml

from ._bag_files import BagError, brief, qos_overrides, read_metadata
from ._graph import absolute, cli_node, is_hidden, matching_qos, offers, spin_once
from ._messages import InterfaceError, get_interface

if TYPE_CHECKING:
    from builtin_interfaces.msg import Time
    from mcap.reader import McapReader
    from mcap.records import Chunk
    from mcap.summary import Summary
    from rclpy.duration import Duration
    from rclpy.node import Node
    from rclpy.publisher import Publisher
    from rclpy.qos import QoSProfile
    from rclpy.subscription import Subscription
    from rclpy.topic_endpoint_info import TopicEndpointInfo

ROSBAG2_VERSION = 9
"""metadata.yaml's layout version (rosbag2 Jazzy's)."""
RECORD_DEPTH = 1000
"""The recorder's subscription queue: a burst waits here rather than being dropped."""
DISCOVERY_PERIOD_SEC = 0.1
"""How often ``record`` looks for new topics (rosbag2's default topic polling interval)."""


def _mixed_offers(node: Node, topic: str) -> list[str]:
    """rosbag2's warnings when only some of a topic's publishers offer reliable or transient local
    (rosbag2_transport qos.cpp, ``adapt_request_to_offers``): the recorder then asks for best effort or
    volatile, to match them all."""
    count, reliable, latched = offers(node, topic)
    out = []
    if 0 < reliable < count:
        out.append(
            f'Some, but not all, publishers on topic "{topic}" are offering RMW_QOS_POLICY_RELIABILITY_RELIABLE. '
            "Falling back to RMW_QOS_POLICY_RELIABILITY_BEST_EFFORT as it will connect to all publishers. "
            "Some messages from Reliable publishers could be dropped."
        )
    if 0 < latched < count:
        out.append(
            f'Some, but not all, publishers on topic "{topic}" are offering RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL. '
            "Falling back to RMW_QOS_POLICY_DURABILITY_VOLATILE as it will connect to all publishers. "
            "Previously-published latched messages will not be retrieved."
        )
    return out


OVERRIDES_HELP = "Path to a yaml file defining overrides of the QoS profile for specific topics."


def main(argv: list[str]) -> int:
    """``ros2 bag record|play|info``: rosbag2's verbs with Jazzy's arguments; a bag that is not there or
    not readable is one line on stderr and status 1 (:class:`BagError`)."""
    p = argparse.ArgumentParser(prog="ros2 bag", description="Various rosbag related sub-commands")
    sub = p.add_subparsers(dest="cmd", required=True)
    rec = sub.add_parser("record", help="Record ROS data to a bag")
    rec.add_argument("topics", nargs="*", help="topics to record")
    rec.add_argument("-a", "--all", action="store_true", help="record all topics")
    rec.add_argument("-e", "--regex", default="", help="record the topics matching this regular expression")
    rec.add_argument("-x", "--exclude", default="", help="leave out the topics matching this regular expression")
    rec.add_argument("-o", "--output", default=None, help="the bag folder (default rosbag2_<date>-<time>)")
    rec.add_argument("-s", "--storage", default="mcap", help="storage identifier (mcap)")
    rec.add_argument("-d", "--max-bag-duration", type=float, default=0.0, help="(not split: one file)")
    rec.add_argument(
        "--max-duration", type=float, default=0.0, help="stop after this many seconds from the first message"
    )
    rec.add_argument("--include-hidden-topics", action="store_true")
    rec.add_argument("--include-unpublished-topics", action="store_true", help="also topics nobody publishes yet")
    rec.add_argument("--use-sim-time", action="store_true", help="stamp messages with /clock's time")
    rec.add_argument("--qos-profile-overrides-path", type=Path, help=OVERRIDES_HELP)
    play = sub.add_parser("play", help="Play back ROS data from a bag")
    play.add_argument("bag_path")
    play.add_argument("-r", "--rate", type=float, default=1.0)
    play.add_argument("-l", "--loop", action="store_true")
    play.add_argument("--topics", nargs="+", default=None)
    play.add_argument("--clock", nargs="?", type=float, const=40.0, default=None, help="publish /clock at HZ (40)")
    play.add_argument("--start-offset", type=float, default=0.0)
    play.add_argument("--delay", type=float, default=0.0, help="seconds to wait before playing")
    play.add_argument(
        "--wait",
        type=float,
        default=3.5,
        help="(gazelle) at most this long for the subscribers already running to be found and matched (0: none)",
    )
    play.add_argument("-s", "--storage", default="mcap")
    play.add_argument("--qos-profile-overrides-path", type=Path, help=OVERRIDES_HELP)
    info = sub.add_parser("info", help="Print information about a bag to the screen")
    info.add_argument("bag_path")
    info.add_argument("-s", "--storage", default="mcap")
    args = p.parse_args(argv)
    try:
        if getattr(args, "storage", "mcap") != "mcap":
            raise BagError(f"storage '{args.storage}' is not available: gazelle's rosbag2 writes and reads mcap")
        if args.cmd == "info":
            return _info(Path(args.bag_path))
        if args.cmd == "record":
            return _record(args)
        return _play(args)
    except (BagError, InterfaceError) as err:
        print(f"[ERROR] [ros2bag]: {err}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 0


# --------------------------------------------------------------------------- metadata
def _qos_dicts(infos: list[TopicEndpointInfo]) -> list[dict[str, Any]]:
    """The offered QoS of publishers as rosbag2 Jazzy writes them (names lower case)."""
    out = []
    for info in infos:
        q = info.qos_profile

        def dur(d: Duration) -> dict[str, int]:
            ns = int(d.nanoseconds)
            return {"sec": ns // 1_000_000_000, "nsec": ns % 1_000_000_000}

        out.append(
            {
                "history": q.history.name.lower(),
                "depth": int(q.depth),
                "reliability": q.reliability.name.lower(),
                "durability": q.durability.name.lower(),
                "deadline": dur(q.deadline),
                "lifespan": dur(q.lifespan),
                "liveliness": q.liveliness.name.lower(),
                "liveliness_lease_duration": dur(q.liveliness_lease_duration),
                "avoid_ros_namespace_conventions": bool(q.avoid_ros_namespace_conventions),
            }
        )
    return out


def _mcap_files(bag: Path, meta: dict[str, Any]) -> list[Path]:
    """The bag's MCAP files as metadata.yaml lists them, inside the bag folder whatever path they name
    (a metadata.yaml can not point play at a file elsewhere)."""
    files = [bag / Path(p).name for p in meta["relative_file_paths"]]
    missing = [str(f) for f in files if not f.is_file()]
    if missing:
        raise BagError(f"the bag's file(s) {', '.join(missing)} are missing")
    return files


def _summary(path: Path) -> Summary:
    """The MCAP file's summary (schemas, channels, statistics); a corrupt file is a :class:`BagError`."""
    from mcap.reader import make_reader

    try:
        with open(path, "rb") as f:
            summary = make_reader(f).get_summary()
    except Exception as err:  # the mcap library raises several kinds on a damaged file
        raise BagError(f"could not read '{path}': not a valid MCAP file ({type(err).__name__}: {err})") from None
    if summary is None:
        raise BagError(f"could not read '{path}': the MCAP file has no summary (was the recording cut short?)")
    return summary


MAX_CHUNK_BYTES = 256 << 20
"""The largest decompressed MCAP chunk played (rosbag2 writes chunks of about 1 MB; 48.7 KB of zstd
declared as 1.6 GB was a decompression bomb)."""


def _check_chunks(path: Path, limit: int = MAX_CHUNK_BYTES) -> None:
    """Refuse a bag whose chunks decompress past ``limit`` or to another size than their headers declare.

    The mcap library decompresses a chunk in one call into a buffer of the size the chunk declares
    (zstd), or of whatever the data expands to (lz4). Here each chunk is decompressed first as a stream,
    counting, and stopped at ``min(declared, limit)`` + 1 bytes, so a lying or huge chunk costs at most
    1 MB of memory before it is refused.

    Raises:
        BagError: the file names a chunk over the limit or one that does not hold what it declares.
    """
    from mcap.records import Chunk
    from mcap.stream_reader import StreamReader

    try:
        with open(path, "rb") as f:
            for record in StreamReader(f, emit_chunks=True, record_size_limit=limit).records:
                if not isinstance(record, Chunk):
                    continue
                declared = record.uncompressed_size
                if declared > limit:
                    raise BagError(
                        f"could not read '{path}': a chunk declares {declared} bytes decompressed, more than the "
                        f"{limit} a chunk may have"
                    )
                got = _decompressed_size(record, declared + 1)
                if got != declared:
                    raise BagError(
                        f"could not read '{path}': a chunk declares {declared} bytes decompressed but holds "
                        + ("more" if got > declared else f"{got}")
                    )
    except BagError:
        raise
    except Exception as err:  # the mcap library raises several kinds on a damaged file
        raise BagError(f"could not read '{path}': not a valid MCAP file ({type(err).__name__}: {err})") from None


def _decompressed_size(chunk: Chunk, stop_at: int) -> int:
    """How many bytes ``chunk`` decompresses to, counting no further than ``stop_at``."""
    import io

    if chunk.compression == "":
        return len(chunk.data)
    if chunk.compression == "zstd":
        import zstandard

        stream: Any = zstandard.ZstdDecompressor().stream_reader(io.BytesIO(chunk.data))
    elif chunk.compression == "lz4":
        import lz4.frame

        stream = lz4.frame.open(io.BytesIO(chunk.data), "rb")
    else:
        raise BagError(f"chunk compression '{chunk.compression}' is not supported (zstd, lz4 or none)")
    total = 0
    with stream:
        while total < stop_at:
            piece = stream.read(min(1 << 20, stop_at - total))
            if not piece:
                break
            total += len(piece)
    return total


# --------------------------------------------------------------------------- info
def _stamp(ns: int) -> str:
    """A time as ``ros2 bag info`` prints it: local date and time with nanoseconds, then seconds since the
    epoch."""
    t = datetime.datetime.fromtimestamp(ns / 1e9)
    return (
        f"{t.strftime('%b %d %Y %H:%M:%S')}.{ns % 1_000_000_000:09d} ({ns // 1_000_000_000}.{ns % 1_000_000_000:09d})"
    )


def _size(n: float) -> str:
    """A byte count as ``ros2 bag info`` prints it (binary units, one decimal)."""
    for unit in ("B", "KiB", "MiB", "GiB"):
        if n < 1024 or unit == "GiB":
            return f"{n:.1f} {unit}" if unit != "B" else f"{int(n)} B"
        n /= 1024
    return f"{n:.1f} GiB"


def _info(bag: Path) -> int:
    """``info BAG``: rosbag2's layout of files, size, duration, start/end, counts and per-topic lines; every
    MCAP file is opened first, so a damaged one is reported instead of described from metadata.yaml."""
    meta = read_metadata(bag)
    files = _mcap_files(bag, meta)
    for f in files:
        _summary(f)  # a damaged file is reported, not described from metadata.yaml alone
    topics = meta["topics_with_message_count"]
    start = int(meta["starting_time"]["nanoseconds_since_epoch"])
    duration = int(meta["duration"]["nanoseconds"])
    label = 19
    print(f"{'Files:':{label}}{files[0].name}")
    for f in files[1:]:
        print(f"{'':{label}}{f.name}")
    print(f"{'Bag size:':{label}}{_size(sum(f.stat().st_size for f in files))}")
    print(f"{'Storage id:':{label}}{meta['storage_identifier']}")
    print(f"{'ROS Distro:':{label}}{meta.get('ros_distro', '')}")
    print(f"{'Duration:':{label}}{duration // 1_000_000_000}.{duration % 1_000_000_000:09d}s")
    print(f"{'Start:':{label}}{_stamp(start)}")
    print(f"{'End:':{label}}{_stamp(start + duration)}")
    print(f"{'Messages:':{label}}{meta['message_count']}")
    lines = [
        f"Topic: {t['topic_metadata']['name']} | Type: {t['topic_metadata']['type']} | Count: {t['message_count']} | "
        f"Serialization Format: {t['topic_metadata']['serialization_format']}"
        for t in topics
    ]
    print(f"{'Topic information:':{label}}{lines[0] if lines else ''}")
    for line in lines[1:]:
        print(f"{'':{label}}{line}")
    print(f"{'Service:':{label}}0")
    print(f"{'Service information:':{label}}")
    return 0


# --------------------------------------------------------------------------- record
class _Recorder:
    """One bag being written: a channel per topic (its ``ros2msg`` schema and its publishers' offered QoS
    as rosbag2 stores it), the CDR bytes of each message as received, metadata.yaml written at the end."""

    def __init__(self, node: Node, out: Path, use_sim_time: bool, overrides: dict[str, Any] | None = None) -> None:
        """An MCAP bag in ``out`` as rosbag2 writes one (``<name>_0.mcap`` with ZSTD chunks and the ros2 profile,
        and ``metadata.yaml`` at the end), stamping messages with the node's clock (sim time under
        ``use_sim_time``) or the wall clock."""
        from mcap.writer import CompressionType, Writer

        self.node = node
        self.overrides = overrides or {}
        """--qos-profile-overrides-path: topic -> the subscription's QoS, used as it is"""
        self.out = out
        self.path = out / f"{out.name}_0.mcap"
        self._file = open(self.path, "wb")
        self._writer = Writer(self._file, compression=CompressionType.ZSTD)
        self._writer.start(profile="ros2", library="gazelle rosbag2 (mcap)")
        self._schemas: dict[str, int] = {}
        self.topics: dict[str, dict[str, Any]] = {}
        """topic -> {type, channel, count, qos}"""
        self._subs: list[Subscription] = []
        self._clock = node.get_clock() if use_sim_time else None
        self.first = 2**63 - 1
        self.last = 0
        self.count = 0

    def add(self, topic: str, type_name: str) -> None:
        """Record ``topic``: its message definition as the schema (the full text with its dependencies, as rosbag2
        stores it), a channel with the publishers' offered QoS, and a raw subscription whose QoS matches the
        publishers' (rosbag2_transport's rule) unless the overrides file names one."""
        from gazelle.ros import InterfaceError as DefinitionError
        from gazelle.ros import message_definition

        cls = get_interface(type_name)
        schema = self._schemas.get(type_name)
        if schema is None:
            try:
                text = message_definition(type_name)
            except DefinitionError as err:
                raise InterfaceError(str(err)) from None
            schema = self._schemas[type_name] = self._writer.register_schema(
                name=type_name, encoding="ros2msg", data=text.encode()
            )
        qos = _qos_dicts(self.node.get_publishers_info_by_topic(topic))
        channel = self._writer.register_channel(
            topic=topic,
            message_encoding="cdr",
            schema_id=schema,
            metadata={"offered_qos_profiles": yaml.safe_dump(qos, sort_keys=False), "topic_type_hash": ""},
        )
        entry = {"type": type_name, "channel": channel, "count": 0, "qos": qos}
        self.topics[topic] = entry

        def on_message(data: bytes, info: dict[str, Any], entry: dict[str, Any] = entry) -> None:
            # as rosbag2_transport's recorder: logged when the reader received it (or at the node's sim time
            # with --use-sim-time), published when the writer sent it: the bag's order is the order of
            # arrival, not the order this Python loop came to each topic's queue
            sent = info.get("source_timestamp") or time.time_ns()
            if self._clock is not None:
                now = self._clock.now().nanoseconds
            else:
                now = info.get("received_timestamp") or time.time_ns()
            entry["count"] += 1
            self.count += 1
            self.first = min(self.first, now)
            self.last = max(self.last, now)
            self._writer.add_message(
                channel_id=entry["channel"], log_time=now, publish_time=sent, data=data, sequence=entry["count"]
            )

        if topic in self.overrides:  # rosbag2_transport recorder.cpp, subscription_qos_for_topic
            print(f"[INFO] [rosbag2_recorder]: Overriding subscription profile for {topic}", flush=True)
            qos = self.overrides[topic]
        else:
            for warning in _mixed_offers(self.node, topic):
                print(f"[WARN] [rosbag2_transport]: {warning}", flush=True)
            qos = matching_qos(self.node, topic)
            qos.depth = RECORD_DEPTH
        with_info: Callable[..., None] = on_message  # called with the message info, as rclpy does for two arguments
        self._subs.append(self.node.create_subscription(cls, topic, with_info, qos, raw=True))
        print(f"[INFO] [rosbag2_recorder]: Subscribed to topic '{topic}'", flush=True)

    def finish(self) -> None:
        """Close the MCAP file and write rosbag2's ``metadata.yaml`` (version, duration, start, counts per topic
        with their QoS), so ``ros2 bag info`` and rosbag2's reader open the bag."""
        self._writer.finish()
        self._file.close()
        count = self.count
        start = self.first if count else 0
        duration = self.last - self.first if count else 0
        meta = {
            "rosbag2_bagfile_information": {
                "version": ROSBAG2_VERSION,
                "storage_identifier": "mcap",
                "duration": {"nanoseconds": duration},
                "starting_time": {"nanoseconds_since_epoch": start},
                "message_count": count,
                "topics_with_message_count": [
                    {
                        "topic_metadata": {
                            "name": topic,
                            "type": e["type"],
                            "serialization_format": "cdr",
                            "offered_qos_profiles": e["qos"],
                            "type_description_hash": "",
                        },
                        "message_count": e["count"],
                    }
                    for topic, e in self.topics.items()
                ],
                "compression_format": "",
                "compression_mode": "",
                "relative_file_paths": [self.path.name],
                "files": [
                    {
                        "path": self.path.name,
                        "starting_time": {"nanoseconds_since_epoch": start},
                        "duration": {"nanoseconds": duration},
                        "message_count": count,
                    }
                ],
                "custom_data": {},
                "ros_distro": "jazzy",
            }
        }
        (self.out / "metadata.yaml").write_text(yaml.safe_dump(meta, sort_keys=False), encoding="utf-8")


def _record(args: argparse.Namespace) -> int:
    """``record``: the topics named, matched by ``-e`` or all of them (``-a``), minus ``-x``, including topics
    that appear later; stops on Ctrl-C/SIGTERM or ``--max-duration`` seconds after the first message, then
    writes metadata.yaml."""
    if not (args.all or args.topics or args.regex):
        raise BagError("no topics given: name topics, or use -a (all) or -e REGEX")
    try:
        include = re.compile(args.regex) if args.regex else None
        exclude = re.compile(args.exclude) if args.exclude else None
    except re.error as err:
        raise BagError(f"invalid regular expression: {err}") from None
    out = Path(args.output or datetime.datetime.now().strftime("rosbag2_%Y_%m_%d-%H_%M_%S"))
    if out.exists():
        raise BagError(f"Output folder '{out}' already exists.")
    wanted = {absolute(t) for t in args.topics}
    overrides = qos_overrides(args.qos_profile_overrides_path) if args.qos_profile_overrides_path else {}

    def chosen(topic: str) -> bool:
        if exclude is not None and exclude.search(topic):
            return False
        if topic in wanted:
            return True
        if include is not None and include.search(topic):
            return True
        return args.all and (args.include_hidden_topics or not is_hidden(topic))

    stop = {"now": False}

    def on_signal(_sig: int, _frame: Any) -> None:
        stop["now"] = True

    signal.signal(signal.SIGINT, on_signal)
    signal.signal(signal.SIGTERM, on_signal)
    with cli_node("ros2bag") as node:
        from rclpy.signals import uninstall_signal_handlers

        # a signal ends the loop below (on_signal) and leaves the context up, so that what the readers
        # hold is still written (_take_the_rest); rclpy's own handler shut the context down at once
        uninstall_signal_handlers()
        signal.signal(signal.SIGINT, on_signal)
        signal.signal(signal.SIGTERM, on_signal)
        if args.use_sim_time:
            from rclpy.parameter import Parameter

            node.set_parameters([Parameter("use_sim_time", Parameter.Type.BOOL, True)])
        out.mkdir(parents=True)
        rec = _Recorder(node, out, args.use_sim_time, overrides)
        print("[INFO] [rosbag2_recorder]: Listening for topics...", flush=True)
        started = time.monotonic()
        first: float | None = None
        """When the first message was recorded: --max-duration counts from there, so a busy machine's slow
        discovery does not eat the recording (it stops after that long without any message, too)."""
        next_scan = 0.0
        try:
            while not stop["now"]:
                now = time.monotonic()
                if first is None and any(e["count"] for e in rec.topics.values()):
                    first = now
                if args.max_duration and now - (started if first is None else first) >= args.max_duration:
                    break
                if now >= next_scan:
                    next_scan = now + DISCOVERY_PERIOD_SEC
                    for topic, types in node.get_topic_names_and_types():
                        # a topic nobody publishes yet waits for its first publisher, as rosbag2's
                        # (include_unpublished_topics false): its QoS is then the publishers' (a reliable
                        # one gets a reliable reader, which acknowledges what it got)
                        unpublished = not args.include_unpublished_topics and not node.count_publishers(topic)
                        if topic not in rec.topics and types and chosen(topic) and not unpublished:
                            try:
                                rec.add(topic, types[0])
                            except InterfaceError as err:
                                print(f"[WARN] [rosbag2_recorder]: topic '{topic}' not recorded: {err}", flush=True)
                                rec.topics[topic] = {"type": types[0], "channel": -1, "count": 0, "qos": []}
                spin_once(node, timeout_sec=0.01)
            _take_the_rest(node, rec)
        finally:
            rec.topics = {t: e for t, e in rec.topics.items() if e["channel"] >= 0}
            rec.finish()
        print(f"[INFO] [rosbag2_recorder]: Recording stopped: {rec.count} messages in '{out}'", flush=True)
    return 0


STOP_QUIET_SEC = 0.05
"""On Ctrl-C, ``record`` writes what its readers still hold until none came for this long..."""
STOP_MAX_SEC = 3.0
"""...or this long in all."""


def _take_the_rest(node: Node, rec: _Recorder) -> None:
    """Record what the readers received before the stop and the loop has not taken yet: a recorder that
    fell behind (a loaded machine) lost up to 1.8 s of sim time at the end of a test's bag, the test's last
    commands among it."""
    end = time.monotonic() + STOP_MAX_SEC
    quiet = time.monotonic() + STOP_QUIET_SEC
    while time.monotonic() < min(end, quiet):
        before = rec.count
        spin_once(node, timeout_sec=0.02)
        if rec.count != before:
            quiet = time.monotonic() + STOP_QUIET_SEC


# --------------------------------------------------------------------------- play
_SAME_OFFER_KEYS = ("reliability", "durability", "deadline", "liveliness", "liveliness_lease_duration")
"""What rosbag2 compares to call recorded offers the same (qos.cpp ``all_profiles_effectively_same``:
history, depth and lifespan excluded)."""


def _qos_profile(topic: str, offered: list[dict[str, Any]], overrides: dict[str, Any]) -> QoSProfile:
    """The QoS to publish a topic with, as rosbag2_transport player.cpp's ``publisher_qos_for_topic``
    chooses it: an override as it is; else the recorded publishers' reliability and durability when they
    all offered the same (``adapt_offer_to_recorded_offers``); else, said once, rosbag2's default offer
    (reliable, volatile). The depth is gazelle's 100, not rosbag2's 10: a played burst waits in it."""
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

    if topic in overrides:
        print(f"[INFO] [rosbag2_player]: Overriding QoS profile for topic {topic}", flush=True)
        return overrides[topic]
    qos = QoSProfile(depth=100)
    if not offered:
        return qos
    first = offered[0]
    if any(o.get(k) != first.get(k) for o in offered[1:] for k in _SAME_OFFER_KEYS):
        print(
            f"[WARN] [rosbag2_storage]: Not all original publishers on topic {topic} offered the same QoS "
            "profiles. Rosbag2 cannot yet choose an adapted profile to offer for this mixed case. Falling back "
            "to the rosbag2_storage default publisher offer.",
            flush=True,
        )
        return qos
    rel, dur = str(first.get("reliability", "reliable")), str(first.get("durability", "volatile"))
    qos.reliability = ReliabilityPolicy.BEST_EFFORT if rel in ("best_effort", "2") else ReliabilityPolicy.RELIABLE
    qos.durability = DurabilityPolicy.TRANSIENT_LOCAL if dur in ("transient_local", "1") else DurabilityPolicy.VOLATILE
    return qos


def _played(bag: Path, meta: dict[str, Any], wanted: list[str] | None) -> dict[str, tuple[Any, dict[str, Any]]]:
    """topic -> (message class, its recorded metadata) of each topic to play (``--topics``: those), before any
    node exists: its name a valid topic name and its type an installed message by the one checked resolver
    (rosidl's rules, the ament index's interface packages; nothing else is imported, see
    :func:`gazelle.ros.resolve_interface`).

    Raises:
        BagError: a bad name or type, one line naming metadata.yaml, the topic and the type.
    """
    from rclpy.exceptions import NameValidationException
    from rclpy.validate_full_topic_name import validate_full_topic_name

    recorded = {t["topic_metadata"]["name"]: t["topic_metadata"] for t in meta["topics_with_message_count"]}
    out = {}
    for topic, md in recorded.items():
        if wanted is not None and topic not in wanted:
            continue
        where = f"{bag / 'metadata.yaml'}: topic {brief(topic)}"
        try:
            validate_full_topic_name(topic)
        except NameValidationException as err:
            raise BagError(f"{where}: {str(err).splitlines()[0].rstrip(':')}") from None
        try:
            out[topic] = (get_interface(md["type"]), md)
        except InterfaceError as err:
            raise BagError(f"{where}: {err}") from None
    return out


def _play(args: argparse.Namespace) -> int:
    """``play BAG``: each topic published with its recorded type and QoS, messages in log-time order at
    ``-r`` times their recorded pace from ``--start-offset``, ``-l`` again and again, ``--clock`` publishing
    /clock from the bag's time."""
    from mcap.reader import make_reader
    from rclpy.duration import Duration

    overrides = qos_overrides(args.qos_profile_overrides_path) if args.qos_profile_overrides_path else {}
    bag = Path(args.bag_path)
    meta = read_metadata(bag)
    files = _mcap_files(bag, meta)
    for f in files:
        _summary(f)
        _check_chunks(f)
    if args.rate <= 0:
        raise BagError("--rate must be positive")
    played = _played(bag, meta, args.topics)
    with cli_node("ros2bag_player") as node:
        pubs: dict[str, Publisher] = {}
        for topic, (cls, md) in played.items():
            qos = _qos_profile(topic, md["offered_qos_profiles"], overrides)
            pubs[topic] = node.create_publisher(cls, topic, qos)
        clock_pub = None
        if args.clock is not None:
            from rosgraph_msgs.msg import Clock

            clock_pub = node.create_publisher(Clock, "/clock", 10)
        _wait_for_matches(node, pubs, args.wait)
        if args.delay > 0:
            time.sleep(args.delay)
        while True:
            for f in files:
                _play_file(node, f, pubs, clock_pub, args, make_reader)
            if not args.loop:
                break
        deadline = time.monotonic() + 2.0
        for pub in pubs.values():
            left = deadline - time.monotonic()
            if left > 0:
                pub.wait_for_all_acked(Duration(seconds=left))
    return 0


MATCH_SETTLE_SEC = 0.3
"""Once every reader in the graph is matched, how long play looks for more before it starts."""


def _wait_for_matches(node: Node, pubs: dict[str, Publisher], timeout: float) -> None:
    """Until the readers of the played topics are matched, at most ``timeout`` seconds: every subscriber the
    graph lists on a played topic matched by our publisher, and none more found for :data:`MATCH_SETTLE_SEC`.

    While the graph lists no subscriber at all, play waits the whole ``timeout``: a listener started before
    play is found only once its participant answers ours, which a node with Fast DDS's defaults may do at its
    next announcement, up to 3 s later (a fixed 0.5 s look lost the first 0.5-2.5 s of a bag, issue 50)."""
    start = time.monotonic()
    deadline = start + timeout
    seen, since = -1, start
    while time.monotonic() < deadline:
        spin_once(node, timeout_sec=0.05)
        in_graph = sum(node.count_subscribers(t) for t in pubs)
        pending = [t for t, p in pubs.items() if node.count_subscribers(t) > p.get_subscription_count()]
        if in_graph != seen:
            seen, since = in_graph, time.monotonic()
        if in_graph and not pending and time.monotonic() - since >= MATCH_SETTLE_SEC:
            return


def _play_file(
    node: Node,
    path: Path,
    pubs: dict[str, Publisher],
    clock_pub: Publisher | None,
    args: argparse.Namespace,
    make_reader: Callable[[BinaryIO], McapReader],
) -> None:
    """Publish one MCAP file's messages on their due wall times (and /clock, when asked, at its rate from
    the bag's time); a damaged chunk met midway is a :class:`BagError`."""
    from rosgraph_msgs.msg import Clock

    with open(path, "rb") as f:
        reader = make_reader(f)
        try:
            messages = reader.iter_messages(topics=list(pubs), log_time_order=True)
            first_time: int | None = None
            wall0 = time.monotonic()
            next_clock = 0.0
            for _schema, channel, message in messages:
                t = message.log_time
                if first_time is None:
                    first_time = t
                offset = (t - first_time) / 1e9
                if offset < args.start_offset:
                    continue
                due = wall0 + (offset - args.start_offset) / args.rate
                while True:
                    now = time.monotonic()
                    if clock_pub is not None and now >= next_clock:
                        sim_ns = t - int((due - now) * args.rate * 1e9)
                        clock_pub.publish(Clock(clock=_time_msg(sim_ns)))
                        next_clock = now + 1.0 / args.clock
                    if now >= due:
                        break
                    time.sleep(min(due - now, 0.01))
                pubs[channel.topic].publish(bytes(message.data))
        except BagError:
            raise
        except Exception as err:  # a damaged chunk in the middle of a file
            raise BagError(f"could not read '{path}': {type(err).__name__}: {err}") from None


def _time_msg(ns: int) -> Time:
    """builtin_interfaces/Time of nanoseconds since the epoch."""
    from builtin_interfaces.msg import Time

    return Time(sec=ns // 1_000_000_000, nanosec=ns % 1_000_000_000)
