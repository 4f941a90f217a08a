"""What a sweep runs: a scenario function from a user's file, and the grid of parameters and seeds."""

from __future__ import annotations

import hashlib
import importlib.util
import itertools
import math
import sys
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, cast

from .._errors import SimError

ParamValue = float | int | str
Scenario = Callable[..., Mapping[str, Any]]
"""``scenario(sim, params, seed) -> metrics``: ``sim`` is a fresh in-process ``Simulation`` (no ROS),
``params`` the run's parameters, ``seed`` its seed (the simulation's noise is seeded with it too).
A metric ``passed`` (bool) says whether the run passed; other metrics are numbers."""


class SweepError(SimError, ValueError):
    """Bad input to a sweep (a scenario that cannot be found, a parameter that cannot be read): one line."""


def parse_value(text: str) -> ParamValue:
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def parse_param(spec: str) -> tuple[str, list[ParamValue]]:
    """``name=a,b,c`` (listed values) or ``name=start:stop:count`` (``count`` values evenly spaced, ends
    included): ``friction=0.4,0.8,1.2``, ``start_x=-1:1:5``."""
    name, sep, values = spec.partition("=")
    name = name.strip()
    if not sep or not name.isidentifier() or not values.strip():
        raise SweepError(f"--param {spec!r}: expected NAME=a,b,c or NAME=start:stop:count")
    if ":" in values and "," not in values:
        parts = values.split(":")
        if len(parts) != 3:
            raise SweepError(f"--param {spec!r}: a range is start:stop:count")
        try:
            start, stop, count = float(parts[0]), float(parts[1]), int(parts[2])
        except ValueError:
            raise SweepError(f"--param {spec!r}: start and stop are numbers, count an integer") from None
        if count < 1 or count > 100_000 or not (math.isfinite(start) and math.isfinite(stop)):
            raise SweepError(f"--param {spec!r}: count is 1..100000, start and stop finite")
        if count == 1:
            return name, [start]
        return name, [start + (stop - start) * i / (count - 1) for i in range(count)]
    return name, [parse_value(v.strip()) for v in values.split(",") if v.strip()]


def parse_seeds(spec: str) -> list[int]:
    """``0:100`` (0 to 99), ``7`` (one seed) or ``1,5,9``."""
    try:
        if ":" in spec:
            a, b = spec.split(":", 1)
            seeds = list(range(int(a), int(b)))
        else:
            seeds = [int(s) for s in spec.split(",") if s.strip()]
    except ValueError:
        raise SweepError(f"--seeds {spec!r}: expected START:STOP, N or a,b,c (integers)") from None
    if not seeds or len(seeds) > 1_000_000:
        raise SweepError(f"--seeds {spec!r}: gives {len(seeds)} seeds")
    return seeds


@dataclass(frozen=True)
class RunSpec:
    """One run of a sweep: its parameters and its seed."""

    params: tuple[tuple[str, ParamValue], ...]
    seed: int

    @property
    def key(self) -> str:
        """Stable across processes and machines: what --resume matches done runs by."""
        text = repr((self.params, self.seed))
        return hashlib.sha256(text.encode()).hexdigest()[:16]

    def as_dict(self) -> dict[str, ParamValue]:
        return dict(self.params)


def grid(params: Sequence[tuple[str, Sequence[ParamValue]]], seeds: Sequence[int]) -> list[RunSpec]:
    """Every combination of the parameters' values, for every seed (parameters vary slowest)."""
    names = [n for n, _ in params]
    if len(set(names)) != len(names):
        raise SweepError(f"a parameter is given twice: {', '.join(names)}")
    combos: Iterator[tuple[ParamValue, ...]] = itertools.product(*[list(v) for _, v in params])
    return [RunSpec(tuple(zip(names, combo)), seed) for combo in combos for seed in seeds]


def load_scenario(ref: str) -> tuple[Path, str, Scenario]:
    """``path/to/file.py::function`` -> (file, function name, the function)."""
    path_text, sep, name = ref.partition("::")
    if not sep or not name.isidentifier():
        raise SweepError(f"{ref!r}: expected FILE.py::FUNCTION")
    path = Path(path_text).resolve()
    if not path.is_file():
        raise SweepError(f"{path_text}: no such scenario file")
    return path, name, scenario_from_file(path, name)


_MODULES: dict[str, Any] = {}


def scenario_from_file(path: Path, name: str) -> Scenario:
    """The function ``name`` of the Python file ``path`` (imported once per process)."""
    key = str(path)
    module = _MODULES.get(key)
    if module is None:
        mod_name = "gazelle_scenario_" + hashlib.sha256(key.encode()).hexdigest()[:12]
        spec = importlib.util.spec_from_file_location(mod_name, path)
        if spec is None or spec.loader is None:
            raise SweepError(f"{path}: cannot be imported as Python")
        module = importlib.util.module_from_spec(spec)
        sys.modules[mod_name] = module
        try:
            spec.loader.exec_module(module)
        except Exception as err:
            sys.modules.pop(mod_name, None)
            raise SweepError(f"{path}: importing it failed: {type(err).__name__}: {err}") from err
        _MODULES[key] = module
    fn: Any = getattr(module, name, None)
    if not callable(fn):
        raise SweepError(f"{path}: has no function {name!r}")
    return cast(Scenario, fn)
