"""MoveIt's allowed collision matrix (ACM) over gazelle's planning scene.

MoveIt's planning scene starts with every robot link that has collision geometry in the matrix, each pair
not allowed, and the SRDF's ``<disable_collisions>`` pairs allowed (planning_scene.cpp, ``initialize``;
collision_matrix.cpp). A client reads it with ``get_planning_scene`` and sends a whole new one back with
``apply_planning_scene``: MoveIt then *replaces* its matrix with the message's
(``setPlanningSceneDiffMsg``), so a pair the message allows is no longer checked and a pair it leaves out
or forbids is checked, the SRDF's pairs included. pymoveit2's ``allow_collisions(id, allow)`` works that
way: it reads the matrix, adds a row and a column for ``id`` and applies it.

Here the matrix is kept as the names it covers and the pairs it allows; :class:`RobotScene` applies it to
roboplan's collision pairs (links by name, a world object by its geometries) whenever the scene changes.
What gazelle allows on its own besides (an attached object with its link and ``touch_links``, world
objects with the links no plan moves and with each other) is not part of the matrix and stays allowed.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field


@dataclass
class CollisionMatrix:
    """The names the matrix covers, in order, the pairs among them whose collisions are allowed, and the
    default entries (a name's value for every pair the entries do not decide)."""

    names: list[str]
    allowed: set[frozenset[str]] = field(default_factory=set)
    defaults: dict[str, bool] = field(default_factory=dict)
    """``default_entry_names`` -> ``default_entry_values``: MoveIt's ``setDefaultEntry`` (ALWAYS or NEVER)."""
    named: frozenset[str] = field(init=False, repr=False, compare=False)
    """:attr:`names` as a set, made once (every pair's lookup asks it; the names never change)."""

    def __post_init__(self) -> None:
        self.named = frozenset(self.names)

    @classmethod
    def initial(cls, links: Sequence[str], disabled: Iterable[tuple[str, str]]) -> CollisionMatrix:
        """MoveIt's starting matrix: ``links`` (those with collision geometry), the SRDF pairs allowed."""
        known = set(links)
        return cls(list(links), {frozenset(p) for p in disabled if p[0] in known and p[1] in known})

    def message_names(self) -> list[str]:
        """``entry_names`` of the message MoveIt writes (collision_matrix.cpp ``getMessage``): the names
        with entries, then those with only a default entry."""
        return [*self.names, *(d for d in self.defaults if d not in self.named)]

    def rows(self) -> list[list[bool]]:
        """``entry_values`` for :meth:`message_names`: row i, column j says whether the two may collide,
        defaults included (a name with a default ALWAYS may collide with itself, as MoveIt writes it)."""
        names = self.message_names()
        return [[self.is_allowed(a, b) for b in names] for a in names]

    def is_allowed(self, a: str, b: str) -> bool:
        """MoveIt's ``getAllowedCollision``: the pair's entry, else the default entries (one name's
        default decides; with both, allowed only when both say ALWAYS), else not allowed."""
        if a != b and a in self.named and b in self.named:
            return frozenset((a, b)) in self.allowed
        da, db = self.defaults.get(a), self.defaults.get(b)
        if da is None and db is None:
            return False
        return bool(da if db is None else db if da is None else da and db)

    @classmethod
    def from_rows(
        cls,
        names: Sequence[str],
        rows: Sequence[Sequence[bool]],
        default_names: Sequence[str] = (),
        default_values: Sequence[bool] = (),
    ) -> CollisionMatrix:
        """The matrix of an ``AllowedCollisionMatrix`` message; a row count or length that does not match the
        names is a ValueError naming it (MoveIt's AllowedCollisionMatrix constructor refuses it too). A pair
        is read from the upper triangle, row i's cell j for j > i, as that constructor reads it
        (collision_matrix.cpp); the lower triangle is not read."""
        if len(rows) != len(names):
            raise ValueError(f"{len(names)} entry_names but {len(rows)} entry_values")
        if len(default_names) != len(default_values):
            raise ValueError(f"{len(default_names)} default_entry_names but {len(default_values)} default_entry_values")
        for i, row in enumerate(rows):
            if len(row) != len(names):
                raise ValueError(f"entry_values[{i}] has {len(row)} values for {len(names)} entry_names")
        allowed = {frozenset((a, b)) for i, a in enumerate(names) for j, b in enumerate(names) if i < j and rows[i][j]}
        defaults = {str(n): bool(v) for n, v in zip(default_names, default_values)}
        return cls(list(dict.fromkeys(names)), allowed, defaults)

    def pairs_with(self, name: str) -> list[tuple[str, bool]]:
        """Every other name of the matrix with whether its collisions with ``name`` are allowed."""
        names = self.message_names()
        if name not in names:
            return []
        return [(other, self.is_allowed(name, other)) for other in names if other != name]
