"""Checkpoints: everything a run needs to go on bit-identically, in one file.

What is saved (:func:`save`):

* the world's description and the options of the :class:`~gazelle.sim.Simulation`, and every entity as
  it was added (model, name, placement, namespace, whether spawned), in the order they were added;
* MuJoCo's whole ``mjData`` (state, warm start, contacts and every derived quantity: the next step
  starts from exactly what the last one left);
* every system's state: its attributes (integrals, timers, odometry, trajectories in progress, noise
  streams as numpy generators), with what belongs to the world rather than to the system (the physics
  world, the bus and its endpoints, the entities, the joint and body handles) saved as a reference by
  name, found again in the rebuilt world;
* a system whose structure grows at run time (the controller manager loads controllers) says what to
  rebuild first with ``checkpoint_structure``/``restore_structure``.

Loading (:func:`restore`) rebuilds the world from the description and the entities, checks that the
rebuilt MuJoCo model has the saved one's sizes and names (another world, or another gazelle or MuJoCo
version, is a :class:`CheckpointError`), takes the saved model's parameters (gains changed at run time),
writes each system's state into the system the rebuilt world made (in place, so the callbacks the bus
holds stay valid), and copies the ``mjData`` in.

A checkpoint is a Python pickle: load only checkpoints you made (like a scenario file, it is code). It
is written owner-only.
"""

from __future__ import annotations

import dataclasses
import enum
import io
import os
import pickle
import platform
import stat
import threading
import types
from collections.abc import Callable
from pathlib import Path
from typing import Any, Protocol, TypeVar

import numpy as np

from .._errors import SimError
from .._files import atomic_write
from ..description import Model, Pose
from ..physics import Entity, PhysicsWorld
from ..systems import Bus, Endpoint, SystemManager

T = TypeVar("T")


class Simulation(Protocol):
    """What a checkpoint saves of a simulation and sets again (``_simulation.Simulation``): its world, systems and
    bus, the options it was made with, its counters, and the two calls that add an entity and run on its thread."""

    world: PhysicsWorld
    systems: SystemManager
    bus: Bus
    rtf: float
    seed: int | None
    visual_geoms: bool
    robot_state_publisher: bool
    iterations: int
    paused: bool

    def call(self, fn: Callable[[], T], timeout: float | None = 10.0) -> T: ...

    def add_entity_placed(
        self, model: Model, name: str, X_WM: Pose, namespace: str = "", *, spawned: bool = True
    ) -> Entity: ...


S = TypeVar("S", bound=Simulation)

MAGIC = "gazelle-checkpoint"
"""The first key of every checkpoint: a pickle of something else is refused with "not a gazelle checkpoint"
rather than half-read."""
_RLOCK = type(threading.RLock())
_LOCK_TYPES = (type(threading.Lock()), _RLOCK)


def _new(cls: type) -> Any:
    """An instance of ``cls`` without ``__init__``: its attributes come from the checkpoint."""
    return object.__new__(cls)


def _event(is_set: bool) -> threading.Event:
    """A threading.Event in the state it was saved in (events are saved as their flag: the threads waiting on one
    belong to the process that saved it)."""
    event = threading.Event()
    if is_set:
        event.set()
    return event


FORMAT = 1
"""The layout of the payload dict; raised when a key is added, removed or changes meaning, so an old
checkpoint is refused by name instead of failing with a KeyError mid-restore."""


class CheckpointError(SimError, RuntimeError):
    """A checkpoint cannot be made or used here: the message says why."""


def _versions() -> dict[str, str]:
    """The versions a checkpoint was written with (gazelle, MuJoCo, Python), compared when it is loaded: another
    MuJoCo may integrate differently, so its checkpoint is refused rather than silently diverging."""
    from importlib.metadata import PackageNotFoundError, version

    try:
        gazelle = version("gazelle")
    except PackageNotFoundError:  # a source tree without metadata
        gazelle = "source"
    return {"gazelle": gazelle, "mujoco": version("mujoco"), "python": platform.python_version()}


# ---------------------------------------------------------------------------- pickling with references
class _Pickler(pickle.Pickler):
    """Pickles a system's state; what belongs to the world is written as a reference (persistent id)."""

    def __init__(self, file: io.BytesIO, sim: Simulation) -> None:
        """A pickler that writes the world's own objects as references. Endpoints are named by (owner, topic,
        direction, type) and their index among equal ones, which the rebuilt world's bus reproduces in the same
        order."""
        super().__init__(file, protocol=pickle.HIGHEST_PROTOCOL)
        self.sim = sim
        self._entities = {id(e): e.name for e in sim.world.entities.values()}
        self._models = {id(e.model): e.name for e in sim.world.entities.values()}
        self._endpoints: dict[int, tuple[Any, ...]] = {}
        counts: dict[tuple[Any, ...], int] = {}
        for ep in sim.bus.endpoints():
            key = (ep.owner, ep.topic, ep.is_publisher, ep.msg_type.value)
            k = counts.get(key, 0)
            counts[key] = k + 1
            self._endpoints[id(ep)] = (*key, k)

    def reducer_override(self, obj: Any) -> Any:
        """Thread primitives (a goal's ``done`` event, a system's lock) are saved as what they hold: the
        checkpoint is taken between two steps, where no lock is held."""
        if isinstance(obj, threading.Event):
            return (_event, (obj.is_set(),))
        if isinstance(obj, _LOCK_TYPES):
            return (type(threading.RLock()) if isinstance(obj, _RLOCK) else threading.Lock, ())
        if isinstance(obj, threading.Condition):
            return (threading.Condition, ())
        skip = getattr(type(obj), "checkpoint_skip", None)
        if skip and hasattr(obj, "__dict__"):  # resources the live system keeps (a renderer's GL context)
            state = {k: v for k, v in vars(obj).items() if k not in skip}
            return (_new, (type(obj),), state)
        return NotImplemented

    def persistent_id(self, obj: Any) -> Any:
        """The reference a world object is saved as (None: pickle the object itself): the physics world, the bus,
        the simulation, an entity or its model by the entity's name, an endpoint by its key. A system that holds
        an entity or endpoint the world no longer has cannot be saved: a CheckpointError names it."""
        if obj is self.sim.world:
            return ("world",)
        if obj is self.sim.bus:
            return ("bus",)
        if obj is self.sim:
            return ("simulation",)
        if isinstance(obj, Entity):
            name = self._entities.get(id(obj))
            if name is None:
                raise CheckpointError(f"a system holds entity '{obj.name}', which is no longer in the world")
            return ("entity", name)
        if isinstance(obj, Endpoint):
            key = self._endpoints.get(id(obj))
            if key is None:
                raise CheckpointError(f"a system holds an endpoint of {obj.topic} that is no longer on the bus")
            return ("endpoint", *key)
        if id(obj) in self._models:
            return ("model", self._models[id(obj)])
        return None


class _Unpickler(pickle.Unpickler):
    def __init__(self, file: io.BytesIO, sim: Simulation) -> None:
        """An unpickler that resolves references against the rebuilt world ``sim``, whose endpoints are keyed as
        :class:`_Pickler` keyed the saved ones."""
        super().__init__(file)
        self.sim = sim
        self._endpoints: dict[tuple[Any, ...], Endpoint] = {}
        counts: dict[tuple[Any, ...], int] = {}
        for ep in sim.bus.endpoints():
            key = (ep.owner, ep.topic, ep.is_publisher, ep.msg_type.value)
            k = counts.get(key, 0)
            counts[key] = k + 1
            self._endpoints[(*key, k)] = ep

    def persistent_load(self, pid: Any) -> Any:
        """The rebuilt world's object for a saved reference; a reference the rebuilt world lacks (another world, a
        spawn that failed) is a CheckpointError naming it.

        The world, its bus, the simulation, its entities and models are not pickled: a checkpoint holds
        their names, and the loading process rebuilds them from the description files (MuJoCo's compiled
        model cannot be unpickled into another process's MuJoCo anyway). What systems hold of them
        (a controller's endpoint, a sensor's entity) is therefore saved as a reference and resolved here,
        so the restored system talks to the rebuilt bus, not to a copy of the old one."""
        kind = pid[0]
        if kind == "world":
            return self.sim.world
        if kind == "bus":
            return self.sim.bus
        if kind == "simulation":
            return self.sim
        if kind in ("entity", "model"):
            entity = self.sim.world.entities.get(pid[1])
            if entity is None:
                raise CheckpointError(f"the checkpoint refers to entity '{pid[1]}', which the rebuilt world lacks")
            return entity if kind == "entity" else entity.model
        if kind == "endpoint":
            ep = self._endpoints.get(tuple(pid[1:]))
            if ep is None:
                raise CheckpointError(
                    f"the checkpoint refers to a {pid[4]} endpoint on {pid[2]} the rebuilt world lacks"
                )
            return ep
        raise CheckpointError(f"unknown reference {kind!r} in the checkpoint")


def _dumps(obj: Any, sim: Simulation, what: str) -> bytes:
    """``obj`` pickled with the world's objects as references. A value that cannot be pickled (a GL context, a
    socket, a lambda) is a CheckpointError naming the attribute path that holds it (``Camera._renderer: ...``),
    found by :func:`_culprit`."""
    buf = io.BytesIO()
    try:
        _Pickler(buf, sim).dump(obj)
    except CheckpointError:
        raise
    except Exception as err:
        items = obj if isinstance(obj, list) else [obj]
        where = next((w for w in (_culprit(o, sim, type(o).__name__, 4) for o in items) if w), None)
        raise CheckpointError(f"cannot save the state of {what}: {where or ''}{err}") from None
    return buf.getvalue()


def _culprit(obj: Any, sim: Simulation, path: str, depth: int) -> str | None:
    """The attribute path (``Lidar._renderer: ``) of the first value under ``obj`` that cannot be saved.

    pickle's own error names the type it could not pickle (``cannot pickle 'EGLContext' object``), not
    where it sits: a plugin author needs the attribute, to list it in the system's ``checkpoint_skip``.
    The search tries each attribute in turn down to ``depth`` levels and returns the deepest path that
    still fails; its cost is paid only when a save has already failed."""
    try:
        _Pickler(io.BytesIO(), sim).dump(obj)
        return None
    except Exception:
        pass
    if depth == 0:
        return f"{path}: " if path else None
    if isinstance(obj, (list, tuple)):
        items: list[tuple[str, Any]] = [(f"{path}[{i}]", v) for i, v in enumerate(obj)]
    elif isinstance(obj, dict):
        items = [(f"{path}[{k!r}]", v) for k, v in obj.items()]
    elif hasattr(obj, "__dict__"):
        items = [(f"{path}.{k}", v) for k, v in vars(obj).items()]
    else:
        return f"{path}: " if path else None
    for sub, value in items:
        found = _culprit(value, sim, sub, depth - 1)
        if found is not None:
            return found
    return f"{path}: " if path else None


def _loads(data: bytes, sim: Simulation) -> Any:
    """The object graph of :func:`_dumps`' bytes, with references resolved in ``sim``'s rebuilt world."""
    return _Unpickler(io.BytesIO(data), sim).load()


# ---------------------------------------------------------------------------- writing state into live objects
_VALUES = (type(None), bool, int, float, complex, str, bytes, enum.Enum, np.generic, types.FunctionType, type)


def _is_value(obj: Any) -> bool:
    """Whether ``obj`` is taken as it was saved rather than merged into the live object: immutable values, functions
    and classes, and frozen dataclasses (bus payloads, configs)."""
    if isinstance(obj, _VALUES):
        return True
    if dataclasses.is_dataclass(obj) and getattr(type(obj), "__dataclass_params__").frozen:  # noqa: B009
        return True
    return False


def _slots(obj: Any) -> list[str]:
    """The ``__slots__`` attribute names of ``obj``'s class and its bases (their values are not in ``__dict__``)."""
    names: list[str] = []
    for cls in type(obj).__mro__:
        s = cls.__dict__.get("__slots__", ())
        names.extend([s] if isinstance(s, str) else s)
    return [n for n in names if n not in ("__dict__", "__weakref__")]


class _Merge:
    """Writes a restored object graph into the live one of the same shape, keeping the live objects
    (the bus's callbacks and the runtime's phase lists hold them) and taking the restored values."""

    def __init__(self) -> None:
        self.memo: dict[int, Any] = {}
        self._keep: list[Any] = []  # restored objects stay alive while the memo holds their ids

    def __call__(self, live: Any, new: Any) -> Any:
        """``new``'s values written into ``live``, returning the object that stays: the live one where both have the
        same type (its identity is what the bus's callbacks and the runtime's phase lists hold), ``new`` itself
        for a value. Arrays of the same shape are filled in place (a view of one sees the values); dicts and
        lists are merged item by item; an object's attributes (``__dict__`` and slots) one by one. A bound method
        is re-bound to the live owner."""
        if new is live:  # a reference to the world's own objects, resolved when loading
            return live
        if id(new) in self.memo:
            return self.memo[id(new)]
        if isinstance(new, types.MethodType):
            owner = self.memo.get(id(new.__self__))
            return getattr(owner, new.__func__.__name__) if owner is not None else new
        if _is_value(new) or type(live) is not type(new):
            return new
        self._keep.append(new)
        if isinstance(new, np.ndarray):
            if live.shape == new.shape and live.dtype == new.dtype and live.flags.writeable:
                live[...] = new  # in place: a view another object holds sees the values
                return live
            return new
        self.memo[id(new)] = live
        if isinstance(new, dict):
            for key in [k for k in live if k not in new]:
                del live[key]
            for key, value in new.items():
                live[key] = self(live[key], value) if key in live else value
            return live
        if isinstance(new, list):
            # item by item while the live list is no longer than the saved one (then the saved tail is
            # appended); a live list that grew past the saved one holds items the checkpoint never had,
            # so it takes the saved list whole
            live[:] = [self(a, b) for a, b in zip(live, new)] + new[len(live) :] if len(live) <= len(new) else new
            return live
        if isinstance(new, tuple):
            merged = tuple(self(a, b) for a, b in zip(live, new)) if len(live) == len(new) else new
            self.memo[id(new)] = merged
            return merged
        if hasattr(new, "__dict__") or _slots(new):
            state = dict(vars(new)) if hasattr(new, "__dict__") else {}
            for name in _slots(new):
                if hasattr(new, name):
                    state[name] = getattr(new, name)
            for name, value in state.items():
                current = getattr(live, name, None) if hasattr(live, name) else None
                object.__setattr__(live, name, self(current, value) if current is not None else value)
            return live
        return new


# ---------------------------------------------------------------------------- save / restore
def _type_name(obj: Any) -> str:
    return f"{type(obj).__module__}.{type(obj).__qualname__}"


def _systems_blob(sim: Simulation, entity: Entity) -> dict[str, Any]:
    """An entity's systems: their types, the structure each grows at run time (plain data, from the
    system's ``checkpoint_structure``), and their attributes (pickled with references to the world)."""
    structures = []
    for s in entity.systems:
        hook = getattr(s, "checkpoint_structure", None)
        structures.append(hook() if hook is not None else None)
    try:
        plain = pickle.dumps(structures, protocol=pickle.HIGHEST_PROTOCOL)
    except Exception as err:
        raise CheckpointError(f"cannot save the structure of '{entity.name}''s systems: {err}") from None
    return {
        "types": [_type_name(s) for s in entity.systems],
        "structures": plain,
        "state": _dumps(list(entity.systems), sim, f"'{entity.name}''s systems"),
    }


def save(sim: Simulation, path: str | os.PathLike[str], force: bool = False) -> Path:
    """Write ``sim``'s checkpoint to ``path`` (owner-only); call on the simulation thread or while it is
    not running.

    Owner-only because a checkpoint is a pickle: whoever can write one can run code in the process that
    loads it, so no other user may replace it. Written through :func:`gazelle._files.atomic_write` (a new
    file of a random name beside the target, renamed over it): a reader sees the old file or the new one,
    never half of one, and nothing planted beside the target is written through. A file at ``path`` that is
    not a checkpoint (a link included) is not replaced unless ``force``."""
    why = _refusal(Path(path), force)
    if why is not None:
        raise CheckpointError(why)
    world = sim.world
    entities = [
        {"name": e.name, "model": e.model, "X_WM": e.X_WM, "namespace": e.namespace, "spawned": e.spawned}
        for e in world.entities.values()
    ]
    payload = {
        "magic": MAGIC,
        "format": FORMAT,
        "versions": _versions(),
        "world": world.description,
        "options": {
            "rtf": sim.rtf,
            "robot_state_publisher": sim.robot_state_publisher,
            "visual_geoms": sim.visual_geoms,
            "seed": sim.seed,
        },
        "entities": entities,
        "systems": {e.name: _systems_blob(sim, e) for e in world.entities.values()},
        "runtime": {"iterations": sim.iterations, "paused": sim.paused, "world": world.checkpoint_extras()},
    }
    try:
        blob = pickle.dumps(payload, protocol=pickle.HIGHEST_PROTOCOL)
    except Exception as err:
        raise CheckpointError(f"cannot save the world's description: {err}") from None
    try:
        return atomic_write(path, blob, mode=0o600)
    except OSError as err:
        raise CheckpointError(f"{path}: {err.strerror or err}") from None


def _refusal(path: Path, force: bool) -> str | None:
    """Why a checkpoint must not replace what is at ``path`` (None: nothing is there, a checkpoint is, or
    ``force``). A checkpoint is recognised by its pickle's first key, ``MAGIC``, in its first bytes; nothing
    is unpickled to tell."""
    if force:
        return None
    try:
        info = path.lstat()
    except FileNotFoundError:
        return None
    except OSError as err:
        return f"{path}: {err.strerror or err}"
    head = b""
    if stat.S_ISREG(info.st_mode):
        try:
            fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC)
            with os.fdopen(fd, "rb") as f:
                head = f.read(64)
        except OSError:
            pass
    if MAGIC.encode() in head:
        return None
    kind = "a link" if stat.S_ISLNK(info.st_mode) else "not a checkpoint"
    return f"{path} exists and is {kind}: it is not overwritten (name another file, or pass force=True)"


def read(path: str | os.PathLike[str]) -> dict[str, Any]:
    """Read a checkpoint file and check that this gazelle can use it."""
    p = Path(path)
    try:
        raw = p.read_bytes()
    except OSError as err:
        raise CheckpointError(f"{p}: {err.strerror or err}") from None
    _check_header(raw, p)  # before anything in it runs: unpickling a foreign pickle would run its code
    try:
        payload = pickle.loads(raw)
    except Exception as err:
        raise CheckpointError(f"{p}: not a gazelle checkpoint ({type(err).__name__})") from None
    if not isinstance(payload, dict) or payload.get("magic") != MAGIC:
        raise CheckpointError(f"{p}: not a gazelle checkpoint")
    if payload.get("format") != FORMAT:
        raise CheckpointError(f"{p}: checkpoint format {payload.get('format')}, this gazelle reads {FORMAT}")
    saved, here = payload["versions"], _versions()
    different = [f"{k} {saved.get(k)} (here {v})" for k, v in here.items() if saved.get(k) != v]
    if different:
        raise CheckpointError(f"{p}: made by another version: {', '.join(different)}; use that version")
    return payload


_MEMO_OPS = frozenset({"PROTO", "FRAME", "MEMOIZE", "PUT", "BINPUT", "LONG_BINPUT"})
_STRING_OPS = frozenset({"SHORT_BINUNICODE", "BINUNICODE", "BINUNICODE8", "UNICODE"})
_INT_OPS = frozenset({"BININT1", "BININT2", "BININT", "INT", "LONG1"})


def _check_header(raw: bytes, p: Path) -> None:
    """The checkpoint's first two keys, ``magic`` and ``format`` (:func:`save` writes them first), read from the
    pickle's opcodes without running any: a file that is not a gazelle checkpoint (another pickle, whose
    loading would run what it names) or of another format is refused before anything in it is loaded. A file
    forged with this header still runs its code when loaded: a checkpoint is code, load only your own."""
    import pickletools

    ops: list[tuple[str, Any]] = []
    try:
        for op, arg, _pos in pickletools.genops(raw):
            if op.name not in _MEMO_OPS:
                ops.append((op.name, arg))
            if len(ops) == 6:
                break
    except Exception as err:  # not a pickle at all: an unknown opcode, a length past the end
        raise CheckpointError(f"{p}: not a gazelle checkpoint ({type(err).__name__})") from None
    names = [name for name, _ in ops]
    keys = [arg for _, arg in ops[2:5]]
    if names[:2] != ["EMPTY_DICT", "MARK"] or keys != ["magic", MAGIC, "format"] or set(names[2:5]) - _STRING_OPS:
        raise CheckpointError(f"{p}: not a gazelle checkpoint")
    kind, value = ops[5] if len(ops) == 6 else ("", None)
    if kind not in _INT_OPS or value != FORMAT:
        raise CheckpointError(f"{p}: checkpoint format {value}, this gazelle reads {FORMAT}")


def restore(payload: dict[str, Any], make: Callable[..., S], world: Any = None) -> S:
    """A new simulation (made by ``make``, the Simulation class) that goes on from the checkpoint. ``world``, when
    given, must be the checkpoint's world (a scenario's world): another one is a CheckpointError."""
    saved_world = payload["world"]
    if world is not None and pickle.dumps(world) != pickle.dumps(saved_world):
        raise CheckpointError(
            f"the checkpoint is of world '{saved_world.name}', not of the one given ('{getattr(world, 'name', '?')}')"
        )
    opts = payload["options"]
    sim = make(
        saved_world,
        rtf=opts["rtf"],
        robot_state_publisher=opts["robot_state_publisher"],
        visual_geoms=opts["visual_geoms"],
        seed=opts["seed"],
    )
    for e in payload["entities"]:
        if e["name"] not in sim.world.entities:  # the world's own models came with the constructor
            sim.add_entity_placed(e["model"], e["name"], e["X_WM"], e["namespace"], spawned=e["spawned"])
    names = [e["name"] for e in payload["entities"]]
    if list(sim.world.entities) != names or not sim.world.same_structure(payload["runtime"]["world"]):
        raise CheckpointError(
            "the world rebuilt from the checkpoint is not the one saved (its models' files or meshes changed since?)"
        )

    def apply() -> None:
        """On the simulation thread: each entity's systems must be those the checkpoint has, in the same order; what
        a system grows at run time is rebuilt first (a manager's controllers), then every saved attribute is
        merged into the live system; then the runtime's counters, whether it was paused, and the model's
        parameters as they were at the checkpoint (gains changed at run time, static bodies moved)."""
        merge = _Merge()
        for name, saved in payload["systems"].items():
            live = sim.world.entities[name].systems
            kinds = [_type_name(s) for s in live]
            if kinds != saved["types"]:
                raise CheckpointError(f"'{name}' has the systems {kinds} here, {saved['types']} in the checkpoint")
            # first what each system grows at run time (a manager's controllers), then every attribute
            for system, structure in zip(live, pickle.loads(saved["structures"])):
                if structure is not None:
                    system.restore_structure(structure)
            for system, restored in zip(live, _loads(saved["state"], sim)):
                merge(system, restored)
        runtime = payload["runtime"]
        sim.iterations = runtime["iterations"]
        sim.paused = runtime["paused"]
        sim.world.restore_checkpoint_extras(runtime["world"])
        sim.systems.refresh()

    sim.call(apply)
    return sim
