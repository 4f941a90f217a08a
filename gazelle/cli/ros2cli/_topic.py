"""``ros2 topic list | echo | hz | info | type | pub``, with ros2cli Jazzy's arguments and output."""

from __future__ import annotations

import argparse
import copy
import sys
import time
from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING, Any

import yaml

from ._graph import (
    DEFAULT_SPIN_TIME,
    SETTLE_SEC,
    absolute,
    add_discovery_options,
    cli_node,
    discover,
    graph_view,
    is_hidden,
    matching_qos,
    offers,
    spin_once,
    wait_until,
)
from ._messages import InterfaceError, StampSetter, get_interface, parse_values, set_fields, to_csv, to_yaml

if TYPE_CHECKING:
    from rclpy.event_handler import QoSMessageLostInfo
    from rclpy.node import Node
    from rclpy.publisher import Publisher
    from rclpy.qos import QoSProfile
    from rclpy.topic_endpoint_info import TopicEndpointInfo

    from ._daemon_graph import DaemonGraph

_QOS_PRESETS = [
    "system_default",
    "sensor_data",
    "services_default",
    "parameters",
    "parameter_events",
    "action_status_default",
    "default",
    "best_available",
]
"""rclpy's ``QoSPresetProfiles`` short keys, which ros2cli's ``--qos-profile`` offers."""


def _topic_types(node: Node | DaemonGraph, hidden: bool = False) -> dict[str, list[str]]:
    """Topic name -> its type names, from the graph as discovered so far (hidden ones when asked)."""
    return {n: t for n, t in node.get_topic_names_and_types() if hidden or not is_hidden(n)}


def _resolve_type(node: Node, topic: str, given: str | None, wait: float = 5.0) -> str | None:
    """The topic's type: the one given, else the first the graph names within ``wait`` seconds (None)."""
    if given:
        return given
    types = wait_until(node, lambda: dict(node.get_topic_names_and_types()).get(topic), wait)
    return types[0] if types else None


def main(argv: list[str]) -> int:
    """``ros2 topic VERB ...``: ros2topic's verbs with Jazzy's arguments; exit status 1 with one line on
    stderr for a type or value that does not fit, 0 on Ctrl-C."""
    args = parser().parse_args(argv)
    try:
        if args.cmd in ("list", "find"):  # the graph alone: the daemon's when it runs
            with graph_view("ros2topic", args.no_daemon, args.spin_time) as graph:
                return (_list if args.cmd == "list" else _find)(graph, args)
        named = {"node_name": getattr(args, "node_name", None), "use_sim_time": getattr(args, "use_sim_time", False)}
        with cli_node("ros2topic", **named) as node:
            verbs = {"list": _list, "echo": _echo, "hz": _hz, "info": _info, "type": _type, "pub": _pub}
            verbs.update({"bw": _bw, "delay": _delay})
            return verbs[args.cmd](node, args)
    except InterfaceError as err:
        print(str(err), file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 0


def parser() -> argparse.ArgumentParser:
    """``ros2 topic``'s command line: every verb with its options."""
    p = argparse.ArgumentParser(prog="ros2 topic", description="Various topic related sub-commands")
    sub = p.add_subparsers(dest="cmd", required=True)
    _add_listing_verbs(sub)
    _add_echo(sub)
    _add_rate_verbs(sub)
    _add_pub(sub)
    return p


def _add_listing_verbs(sub: argparse._SubParsersAction) -> None:
    """``list`` and ``find``, with ros2cli's options."""
    ls = sub.add_parser("list", help="Output a list of available topics")
    ls.add_argument("-t", "--show-types", action="store_true")
    ls.add_argument("-c", "--count-topics", action="store_true")
    ls.add_argument("--include-hidden-topics", action="store_true")
    find = sub.add_parser("find", help="Output a list of available topics of a given type")
    find.add_argument("topic_type")
    find.add_argument("-c", "--count-topics", action="store_true")
    find.add_argument("--include-hidden-topics", action="store_true")
    add_discovery_options(ls, find)  # ros2cli's NodeStrategy options


def _add_echo(sub: argparse._SubParsersAction) -> None:
    """``echo``, with ros2cli's options (QoS chosen to match every publisher unless given)."""
    echo = sub.add_parser("echo", help="Output messages from a topic")
    echo.add_argument("topic_name")
    echo.add_argument("message_type", nargs="?")
    echo.add_argument("--once", action="store_true")
    echo.add_argument("--field", default=None)
    echo.add_argument("--no-arr", action="store_true")
    echo.add_argument("--no-str", action="store_true")
    echo.add_argument("--csv", action="store_true")
    echo.add_argument("--flow-style", action="store_true")
    echo.add_argument("--truncate-length", "-l", type=int, default=128)
    echo.add_argument(
        "--full-length", "-f", action="store_true", help="output arrays, bytes and strings whole (ros2cli's flag)"
    )
    echo.add_argument("--timeout", type=float, default=None)
    echo.add_argument("--no-lost-messages", action="store_true", help="don't report when a message is lost")
    echo.add_argument("--raw", action="store_true", help="echo the serialized bytes")
    echo.add_argument("--filter", dest="filter_expr", default=None, help="only messages `m` for which it is true")
    echo.add_argument("--include-message-info", "-i", action="store_true", help="show each message's info")
    echo.add_argument("-s", "--use-sim-time", action="store_true")
    echo.add_argument("--spin-time", type=float, default=DEFAULT_SPIN_TIME)
    _add_qos_arguments(echo, "subscribe", "sensor_data")


def _add_rate_verbs(sub: argparse._SubParsersAction) -> None:
    """``hz``, ``info``, ``type``, ``bw`` and ``delay``; ``--count`` (gazelle's) ends them after that many reports."""
    hz = sub.add_parser("hz", help="Print the average publishing rate to screen")
    hz.add_argument("topic_name")
    hz.add_argument("--window", "-w", type=int, default=10000)
    hz.add_argument("--filter", dest="filter_expr", default=None, help="only count messages `m` for which it is true")
    hz.add_argument("--wall-time", action="store_true", help="measure in wall time even with -s")
    hz.add_argument("-s", "--use-sim-time", action="store_true", help="measure in /clock's time")
    hz.add_argument("--spin-time", type=float, default=DEFAULT_SPIN_TIME)
    hz.add_argument("--count", type=int, default=None, help="(gazelle) stop after this many reports")
    info = sub.add_parser("info", help="Print information about a topic")
    info.add_argument("topic_name")
    info.add_argument("-v", "--verbose", action="store_true")
    typ = sub.add_parser("type", help="Print a topic's type")
    typ.add_argument("topic_name")
    bw = sub.add_parser("bw", help="Display bandwidth used by topic")
    bw.add_argument("topic_name")
    bw.add_argument("--window", "-w", type=int, default=100)
    bw.add_argument("--count", type=int, default=None, help="(gazelle) stop after this many reports")
    delay = sub.add_parser("delay", help="Display delay of topic from timestamp in header")
    delay.add_argument("topic_name")
    delay.add_argument("--window", "-w", type=int, default=10000)
    delay.add_argument("--count", type=int, default=None, help="(gazelle) stop after this many reports")
    delay.add_argument("--use-sim-time", action="store_true", help="(gazelle) compare with /clock's time")


def _add_pub(sub: argparse._SubParsersAction) -> None:
    """``pub``, with ros2cli Jazzy's options (ros2topic/verb/pub.py and the direct node's ``-s``/``--spin-time``)."""
    pub = sub.add_parser("pub", help="Publish a message to a topic")
    pub.add_argument("topic_name")
    pub.add_argument("message_type")
    source = pub.add_mutually_exclusive_group()
    source.add_argument("values", nargs="?", default="{}", help="the message's fields in YAML")
    source.add_argument("--stdin", action="store_true", help="read the YAML values from standard input")
    pub.add_argument("-r", "--rate", type=_positive_float, default=1.0, help="publishing rate in Hz (default: 1)")
    pub.add_argument("-p", "--print", type=int, default=1, help="only print every N-th published message")
    count = pub.add_mutually_exclusive_group()
    count.add_argument("-1", "--once", action="store_true", help="publish one message and exit")
    count.add_argument("-t", "--times", type=_nonnegative_int, default=0, help="publish this many times and exit")
    pub.add_argument(
        "-w",
        "--wait-matching-subscriptions",
        type=_nonnegative_int,
        default=None,
        help="wait for this many matching subscriptions (default: 1 with --once/--times, else 0)",
    )
    pub.add_argument("--max-wait-time-secs", type=_positive_float, default=None, help="give up waiting after this")
    pub.add_argument("--keep-alive", type=_positive_float, default=0.1, help="seconds to stay after the last message")
    pub.add_argument("-n", "--node-name", default=None, help="name of the publishing node")
    _add_qos_arguments(pub, "publish", "default")
    pub.add_argument("--spin-time", type=float, default=DEFAULT_SPIN_TIME)
    pub.add_argument("-s", "--use-sim-time", action="store_true", help="stamp `auto`/`now` with /clock's time")


def _add_qos_arguments(parser: argparse.ArgumentParser, direction: str, preset: str) -> None:
    """The ``--qos-*`` options of ``echo`` and ``pub`` (ros2topic/api ``add_qos_arguments``, jazzy): a preset
    (``--qos-profile``, echo's ``sensor_data``, pub's ``default``) and the overrides of its parts."""
    parser.add_argument(
        "--qos-profile",
        choices=_QOS_PRESETS,
        default=preset,
        help=f"QoS preset to {direction} with (default: {preset})",
    )
    parser.add_argument("--qos-depth", type=int, default=None, help="queue size (overrides the preset's)")
    # rclpy's policies' short_keys() (Jazzy), spelled out: the command line is parsed before rclpy is imported
    parser.add_argument("--qos-history", choices=["system_default", "keep_last", "keep_all", "unknown"], default=None)
    ends = ["unknown", "best_available"]
    parser.add_argument("--qos-reliability", choices=["system_default", "reliable", "best_effort", *ends])
    parser.add_argument("--qos-durability", choices=["system_default", "transient_local", "volatile", *ends])
    parser.add_argument("--qos-liveliness", choices=["system_default", "automatic", "manual_by_topic", *ends])
    parser.add_argument("--qos-liveliness-lease-duration-seconds", type=float, default=None)


def _positive_float(text: str) -> float:
    """argparse type of ros2cli's ``positive_float``."""
    value = float(text)
    if value <= 0:
        raise argparse.ArgumentTypeError(f"{text} is not a positive float")
    return value


def _nonnegative_int(text: str) -> int:
    """argparse type of ros2cli's ``nonnegative_int``."""
    value = int(text)
    if value < 0:
        raise argparse.ArgumentTypeError(f"{text} is not a non-negative integer")
    return value


def _list(node: Node | DaemonGraph, args: argparse.Namespace) -> int:
    """``list``: the names in the graph (the daemon's, or discovered for ``--spin-time``), sorted, with
    ``[types]`` for ``-t``."""
    topics = _topic_types(node, args.include_hidden_topics)
    if args.count_topics:
        print(len(topics))
        return 0
    for name in sorted(topics):
        print(f"{name} [{', '.join(topics[name])}]" if args.show_types else name)
    return 0


def _echo(node: Node, args: argparse.Namespace) -> int:
    """As ros2cli Jazzy's ``EchoVerb`` (ros2topic/verb/echo.py): a QoS that matches every publisher unless
    ``--qos-*`` says otherwise; each message (or its ``--field``) that passes ``--filter`` printed as YAML,
    CSV or its serialized bytes (``--raw``), with its message info first for ``-i``; "A message was
    lost!!!" when DDS reports one, unless ``--no-lost-messages``."""
    from rclpy.event_handler import SubscriptionEventCallbacks

    topic = absolute(args.topic_name)
    type_name = _resolve_type(node, topic, args.message_type)
    if type_name is None:
        print(f"Could not determine the type for the passed topic {topic}", file=sys.stderr)
        return 1
    cls = get_interface(type_name)
    keep = _filter(args.filter_expr)
    qos = _echo_qos(node, topic, args)
    got: list[tuple[object, Mapping[str, object]]] = []
    lost = None if args.no_lost_messages else SubscriptionEventCallbacks(message_lost=_said_lost)
    # rclpy calls a two-argument callback with the message info (Subscription.CallbackType.WithMessageInfo),
    # which create_subscription's hint (one argument) does not say
    with_info: Callable[..., None] = lambda msg, info: got.append((msg, info))
    node.create_subscription(cls, topic, with_info, qos, event_callbacks=lost, raw=args.raw)
    deadline = time.monotonic() + args.timeout if args.timeout else None
    while True:
        spin_once(node, timeout_sec=0.1)
        while got:
            msg, info = got.pop(0)
            if args.field and not args.raw:
                for part in args.field.split("."):
                    msg = getattr(msg, part)
            if keep is not None and not keep(msg):
                continue
            _print_echoed(msg, info, args)
            if args.once:
                return 0
        if deadline is not None and time.monotonic() > deadline:
            print(f"Timeout after {args.timeout} seconds", file=sys.stderr) if args.once else None
            return 0 if not args.once else 1


def _echo_qos(node: Node, topic: str, args: argparse.Namespace) -> QoSProfile:
    """The subscription's QoS as ros2topic's echo chooses it (verb/echo.py ``choose_qos``, jazzy): with any
    ``--qos-*`` override, the preset with the overrides; else the preset made reliable only when every
    publisher is, and transient local only when every publisher is (each said when only some are, as
    upstream: a transient local reader would not match a volatile writer)."""
    from rclpy.qos import DurabilityPolicy, QoSPresetProfiles, ReliabilityPolicy

    wait_until(node, lambda: node.get_publishers_info_by_topic(topic), 5.0)
    # every publisher's QoS, to match them all
    discover(node, 0.0, SETTLE_SEC, watch=lambda: len(node.get_publishers_info_by_topic(topic)))
    qos = copy.copy(QoSPresetProfiles.get_from_short_key(args.qos_profile))
    overrides = (
        args.qos_reliability,
        args.qos_durability,
        args.qos_depth,
        args.qos_history,
        args.qos_liveliness,
        args.qos_liveliness_lease_duration_seconds,
    )
    if any(v is not None for v in overrides):
        return _configured(qos, args)
    count, reliable, latched = offers(node, topic)
    if not count:
        return qos
    if reliable == count:
        qos.reliability = ReliabilityPolicy.RELIABLE
    else:
        if reliable:
            print(
                "Some, but not all, publishers are offering QoSReliabilityPolicy.RELIABLE. Falling back to "
                "QoSReliabilityPolicy.BEST_EFFORT as it will connect to all publishers"
            )
        qos.reliability = ReliabilityPolicy.BEST_EFFORT
    if latched == count:
        qos.durability = DurabilityPolicy.TRANSIENT_LOCAL
    else:
        if latched:
            print(
                "Some, but not all, publishers are offering QoSDurabilityPolicy.TRANSIENT_LOCAL. Falling back to "
                "QoSDurabilityPolicy.VOLATILE as it will connect to all publishers"
            )
        qos.durability = DurabilityPolicy.VOLATILE
    return qos


def _print_echoed(msg: object, info: Mapping[str, object], args: argparse.Namespace) -> None:
    """One echoed message as ros2cli prints it (``_subscriber_callback``)."""
    is_message = hasattr(msg, "get_fields_and_field_types")
    if not is_message and args.raw:
        if args.include_message_info:
            print(f"---Got new message, message info:---\n{info}\n---Message data:---")
        print(msg, end="\n---\n", flush=True)
    elif args.csv:
        text = to_csv(msg) if is_message else str(msg)
        print(f"{','.join(str(v) for v in info.values())},{text}" if args.include_message_info else text, flush=True)
    else:
        if args.include_message_info:
            print(yaml.safe_dump(dict(info)), end="---\n")
        if is_message:
            truncate = None if args.full_length else args.truncate_length
            print(to_yaml(msg, truncate=truncate, no_arr=args.no_arr, no_str=args.no_str) + "---", flush=True)
        else:
            print(f"{msg}\n---", flush=True)


def _said_lost(status: QoSMessageLostInfo) -> None:
    """ros2cli's ``_message_lost_event_callback``."""
    print(
        f"A message was lost!!!\n\ttotal count change:{status.total_count_change}\n\ttotal count: {status.total_count}",
        end="---\n",
        flush=True,
    )


def _hz(node: Node, args: argparse.Namespace) -> int:
    """As ros2cli Jazzy's ``ROSTopicHz`` (ros2topic/verb/hz.py): each message is timed by the node's clock
    when it arrives (ROS time, /clock's with ``-s``, the system's with ``--wall-time``); a report is due
    once the latest message came a second of that clock after the last report, so with ``-s`` it reports
    per second of simulated time and measures the rate in it, whatever the machine's load. A clock at
    zero (no /clock yet) is skipped, and a clock that went back starts the count again."""
    from rclpy.clock import Clock
    from rclpy.clock_type import ClockType

    clock = Clock(clock_type=ClockType.SYSTEM_TIME) if args.wall_time else node.get_clock()
    keep = _filter(args.filter_expr)
    state = {"t0": -1, "tn": 0, "printed": 0}
    intervals: list[int] = []

    def on_message(msg: object) -> None:
        """Note a message's arrival on the node's clock (sim time when the graph has /clock, as ros2 topic hz with
        use_sim_time): the interval since the last one joins the window. A clock that went back (a reset) starts
        the counts again, as ros2cli's does."""
        if keep is not None and not keep(msg):
            return
        now = clock.now().nanoseconds
        if now == 0:  # no /clock yet (or it was reset)
            if intervals:
                print("time has reset, resetting counters", flush=True)
                intervals.clear()
            return
        if state["t0"] < 0 or state["t0"] > now:
            state["t0"] = state["tn"] = now
            intervals.clear()
        else:
            intervals.append(now - state["tn"])
            state["tn"] = now
        if len(intervals) > args.window:
            intervals.pop(0)

    def report() -> bool:
        """Print the rate over the window once a second of the clock has passed since the last report (ros2cli's
        format: average rate, then min, max, std dev and window); False when there is nothing new to say."""
        if not intervals:
            return False
        if state["printed"] == 0:
            state["printed"] = state["tn"]
            return False
        if state["tn"] < state["printed"] + 1_000_000_000:
            return False
        mean, lo, hi, std = _stats([float(v) for v in intervals])
        state["printed"] = state["tn"]
        print(f"average rate: {1e9 / mean if mean > 0 else 0.0:.3f}")
        print(
            f"\tmin: {lo * 1e-9:.3f}s max: {hi * 1e-9:.3f}s std dev: {std * 1e-9:.5f}s window: {len(intervals)}",
            flush=True,
        )
        return True

    if _subscribed(node, args, on_message) is None:
        return 1
    reports = 0
    while args.count is None or reports < args.count:
        spin_once(node, timeout_sec=0.05)
        reports += 1 if report() else 0
    return 0


def _filter(expr: str | None) -> Callable[[object], bool] | None:
    """ros2cli's ``--filter EXPR``: a function of the message ``m``, evaluated as Python as upstream does
    (``eval(expr)`` with ``m`` in scope: the expression is the user's own, typed on their command line)."""
    if expr is None:
        return None
    try:
        code = compile(expr, "<--filter>", "eval")
    except SyntaxError as err:
        raise InterfaceError(f"--filter '{expr}' is not a Python expression: {err.msg}") from None

    def keep(m: object) -> bool:
        """Whether a message passes the user's ``--filter`` expression (``m`` is the message), as ros2cli evaluates
        it; an expression that fails on a message ends the verb with its error, once, not a traceback per
        message."""
        try:
            return bool(eval(code, {}, {"m": m}))
        except Exception as err:  # the expression's own failure, said once: the verb ends
            raise InterfaceError(f"--filter '{expr}' failed on a message: {type(err).__name__}: {err}") from None

    return keep


def _stats(values: list[float]) -> tuple[float, float, float, float]:
    """(mean, min, max, standard deviation)."""
    mean = sum(values) / len(values)
    return mean, min(values), max(values), (sum((v - mean) ** 2 for v in values) / len(values)) ** 0.5


def _subscribed(node: Node, args: argparse.Namespace, callback: Callable[..., None], raw: bool = False) -> str | None:
    """Subscribe ``callback`` to the topic (its type discovered); the topic's name, None when unknown."""
    topic = absolute(args.topic_name)
    type_name = _resolve_type(node, topic, None)
    if type_name is None:
        print(f"WARNING: topic [{topic}] does not appear to be published yet", file=sys.stderr)
        return None
    node.create_subscription(get_interface(type_name), topic, callback, matching_qos(node, topic), raw=raw)
    return topic


def _every_second(node: Node, count: int | None, report: Callable[[], bool]) -> None:
    """Spin, calling ``report()`` once a second (``count`` times, or until Ctrl-C); it returns whether it printed."""
    reports, last = 0, time.monotonic()
    while count is None or reports < count:
        spin_once(node, timeout_sec=0.05)
        if time.monotonic() - last >= 1.0:
            last = time.monotonic()
            reports += 1 if report() else 0


def _bytes(n: float) -> str:
    """A byte count as ros2topic bw prints it (B, KB, MB by thousands)."""
    for unit in ("B", "KB", "MB"):
        if n < 1000 or unit == "MB":
            return f"{n:.2f} {unit}"
        n /= 1000
    return f"{n:.2f} MB"


def _bw(node: Node, args: argparse.Namespace) -> int:
    """``bw``: the serialized sizes of the messages (a raw subscription: nothing is deserialized), their
    rate over the window and their mean/min/max, once a second of wall time, as ros2topic's ROSTopicBandwidth."""
    sizes: list[tuple[float, int]] = []
    if _subscribed(node, args, lambda data: sizes.append((time.monotonic(), len(data))), raw=True) is None:
        return 1
    print(f"Subscribed to [{args.topic_name}]", flush=True)

    def report() -> bool:
        """Print the bandwidth over the last ``--window`` messages (bytes over the time they span) and their sizes,
        in ros2cli's format."""
        window = sizes[-args.window :]
        if len(window) < 2:
            return False
        span = window[-1][0] - window[0][0]
        mean, lo, hi, _ = _stats([float(n) for _, n in window])
        rate = sum(n for _, n in window) / span if span > 0 else 0.0
        print(f"{_bytes(rate)}/s from {len(window)} messages")
        print(f"\tMessage size mean: {_bytes(mean)} min: {_bytes(lo)} max: {_bytes(hi)}", flush=True)
        return True

    _every_second(node, args.count, report)
    return 0


def _delay(node: Node, args: argparse.Namespace) -> int:
    """``delay``: now minus each message's ``header.stamp`` (messages without a header are counted and said),
    once a second; ``--use-sim-time`` compares with /clock's time, which a simulation's stamps are in."""
    if args.use_sim_time:
        from rclpy.parameter import Parameter

        node.set_parameters([Parameter("use_sim_time", Parameter.Type.BOOL, True)])
    clock = node.get_clock()
    delays: list[float] = []

    def on_message(msg: object) -> None:
        """A message's delay: the clock now minus its header stamp (a message without a header is not counted)."""
        header = getattr(msg, "header", None)
        if header is None:
            return
        stamp = header.stamp.sec + header.stamp.nanosec * 1e-9
        delays.append(clock.now().nanoseconds * 1e-9 - stamp)

    if _subscribed(node, args, on_message) is None:
        return 1

    def report() -> bool:
        """Print the mean, min, max and std dev of the delays in the window, in ros2cli's format (or why there is
        nothing to report)."""
        window = delays[-args.window :]
        if not window:
            print("msg does not have header" if not delays else "no new messages")
            return False
        mean, lo, hi, std = _stats(window)
        print(f"average delay: {mean:.3f}")
        print(f"\tmin: {lo:.3f}s max: {hi:.3f}s std dev: {std:.5f}s window: {len(window)}", flush=True)
        return True

    _every_second(node, args.count, report)
    return 0


def _find(node: Node | DaemonGraph, args: argparse.Namespace) -> int:
    """``find TYPE``: the topics of that type in the graph, sorted."""
    found = sorted(n for n, types in _topic_types(node, args.include_hidden_topics).items() if args.topic_type in types)
    if args.count_topics:
        print(len(found))
        return 0
    for name in found:
        print(name)
    return 0


def _info(node: Node, args: argparse.Namespace) -> int:
    """``info [-v]``: the type, publisher and subscription counts, and with ``-v`` each endpoint's node and
    QoS, after the graph has settled (a new topic's endpoints arrive in several discovery messages)."""
    topic = absolute(args.topic_name)
    types = wait_until(node, lambda: dict(node.get_topic_names_and_types()).get(topic))
    discover(node, 0.0, SETTLE_SEC, watch=lambda: (node.count_publishers(topic), node.count_subscribers(topic)))
    if not types:
        print(f"Unknown topic '{topic}'", file=sys.stderr)
        return 1
    pubs, subs = node.get_publishers_info_by_topic(topic), node.get_subscriptions_info_by_topic(topic)
    print(f"Type: {', '.join(types)}\n")
    print(f"Publisher count: {len(pubs)}\n" if not args.verbose else f"Publisher count: {len(pubs)}\n")
    for i in pubs if args.verbose else []:
        _endpoint(i, "PUBLISHER")
    print(f"Subscription count: {len(subs)}" + ("\n" if args.verbose else ""))
    for i in subs if args.verbose else []:
        _endpoint(i, "SUBSCRIPTION")
    return 0


def _endpoint(info: TopicEndpointInfo, kind: str) -> None:
    """One endpoint block of ``info -v``, in ros2topic's layout."""
    q = info.qos_profile
    print(f"Node name: {info.node_name}")
    print(f"Node namespace: {info.node_namespace}")
    print(f"Topic type: {info.topic_type}")
    print(f"Endpoint type: {kind}")
    print("QoS profile:")
    print(f"  Reliability: {q.reliability.name}")
    print(f"  History (Depth): {q.history.name} ({q.depth})")
    print(f"  Durability: {q.durability.name}\n")


def _type(node: Node, args: argparse.Namespace) -> int:
    """``type``: the topic's type names, one a line; "Unknown topic" with status 1."""
    topic = absolute(args.topic_name)
    types = wait_until(node, lambda: dict(node.get_topic_names_and_types()).get(topic))
    if not types:
        print(f"Unknown topic '{topic}'", file=sys.stderr)
        return 1
    for t in types:
        print(t)
    return 0


def _pub(node: Node, args: argparse.Namespace) -> int:
    """Publish as ros2cli Jazzy's ``publisher()`` (ros2topic/verb/pub.py): wait for the matching
    subscriptions asked for (1 with ``--once``/``--times``, however long it takes unless
    ``--max-wait-time-secs``), publish the first message at once and the others every ``1 / rate`` seconds,
    each with its ``header: auto``/``now`` stamps set to the node's clock (wall time, or /clock's with
    ``-s``), then stay ``--keep-alive`` seconds so that the last message reaches the wire."""
    from rclpy.qos import QoSPresetProfiles

    cls = get_interface(args.message_type)
    values = parse_values(sys.stdin.read() if args.stdin else args.values)
    if not isinstance(values, dict):
        print("The passed value needs to be a dictionary in YAML format", file=sys.stderr)
        return 1
    stamps: list[StampSetter] = []
    msg = set_fields(cls(), values, stamps=stamps)
    times = 1 if args.once else args.times
    wait_for = args.wait_matching_subscriptions if args.wait_matching_subscriptions is not None else int(times != 0)
    if wait_for == 0 and args.max_wait_time_secs is not None:
        print(
            "--max-wait-time-secs option is only effective with --wait-matching-subscriptions, --once or --times",
            file=sys.stderr,
        )
        return 1
    qos = _configured(copy.copy(QoSPresetProfiles.get_from_short_key(args.qos_profile)), args)
    pub = node.create_publisher(cls, args.topic_name, qos)
    if not _wait_for_subscriptions(node, pub, wait_for, args.max_wait_time_secs):
        return 1
    print("publisher: beginning loop", flush=True)
    count = 0
    period = 1.0 / args.rate
    next_at = time.monotonic()
    while times == 0 or count < times:
        now = node.get_clock().now().to_msg()
        for set_stamp in stamps:
            set_stamp(now)
        pub.publish(msg)
        count += 1
        if args.print and count % args.print == 0:
            print(
                f"publishing #{count}: {cls.__module__.split('.')[0]}.msg.{cls.__name__}({_short(msg)})\n", flush=True
            )
        if times and count >= times:
            break
        next_at += period  # a timer's pace, not a sleep after each publish
        while time.monotonic() < next_at:
            spin_once(node, timeout_sec=max(0.0, next_at - time.monotonic()))
    end = time.monotonic() + args.keep_alive  # the last message reaches the wire before the node goes
    while time.monotonic() < end:
        spin_once(node, timeout_sec=max(0.0, end - time.monotonic()))
    return 0


def _configured(qos: QoSProfile, args: argparse.Namespace) -> QoSProfile:
    """``qos`` with the ``--qos-*`` overrides, as ros2topic's ``profile_configure_short_keys`` (jazzy): a
    depth of 0 or less keeps the preset's, and a transient local profile of depth 0 gets depth 1."""
    from rclpy.duration import Duration
    from rclpy.qos import DurabilityPolicy, HistoryPolicy, LivelinessPolicy, ReliabilityPolicy

    if args.qos_history:
        qos.history = HistoryPolicy.get_from_short_key(args.qos_history)
    if args.qos_durability:
        qos.durability = DurabilityPolicy.get_from_short_key(args.qos_durability)
    if args.qos_reliability:
        qos.reliability = ReliabilityPolicy.get_from_short_key(args.qos_reliability)
    if args.qos_liveliness:
        qos.liveliness = LivelinessPolicy.get_from_short_key(args.qos_liveliness)
    lease = args.qos_liveliness_lease_duration_seconds
    if lease and lease >= 0:
        qos.liveliness_lease_duration = Duration(seconds=lease)
    if args.qos_depth and args.qos_depth >= 0:
        qos.depth = args.qos_depth
    elif qos.durability == DurabilityPolicy.TRANSIENT_LOCAL and qos.depth == 0:
        qos.depth = 1
    return qos


def _wait_for_subscriptions(node: Node, pub: Publisher, wanted: int, max_wait: float | None) -> bool:
    """Spin until ``pub`` matches ``wanted`` subscriptions, saying so once a second as ros2cli does; False
    (with ros2cli's message) when ``max_wait`` seconds pass first."""
    start = last_said = time.monotonic()
    said = False
    while pub.get_subscription_count() < wanted:
        now = time.monotonic()
        if not said or now - last_said >= 1.0:
            print(f"Waiting for at least {wanted} matching subscription(s)...", flush=True)
            said, last_said = True, now
        if max_wait is not None and now - start >= max_wait:
            print(
                f"Timed out waiting for subscribers: Expected {wanted} subcribers but only got "
                f"{pub.get_subscription_count()} subscribers",
                file=sys.stderr,
            )
            return False
        spin_once(node, timeout_sec=0.1)
    return True


def _short(msg: Any) -> str:
    """The fields of a message as ``name=repr`` pairs, as rclpy's message repr writes them."""
    return ", ".join(f"{k}={getattr(msg, k)!r}" for k in msg.get_fields_and_field_types())
