"""simulation_interfaces' EntityFilters, read once per request (:class:`EntityFilter`): the name pattern, the
categories, the tags (``FILTER_MODE_ANY`` / ``FILTER_MODE_ALL``) and the overlap bounds (``TYPE_BOX`` and
``TYPE_SPHERE`` in the world frame; ``TYPE_CONVEX_HULL`` is ``RESULT_FEATURE_UNSUPPORTED``), and an entity's
category (:func:`category_of`: what a client set with SetEntityInfo, else what its model implies)."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from simulation_interfaces.msg import Bounds, EntityCategory, EntityFilters, Result, TagsFilter

from ..description import JointType, excerpt
from ..physics import Entity
from ._si_results import _finite, _Refused

MAX_TAGS = 100
"""The most tags an entity may be given, or a filter may name."""
MAX_TAG_CHARS = 256
"""The longest tag accepted."""

CATEGORY_NAMES = {
    EntityCategory.CATEGORY_OBJECT: "object",
    EntityCategory.CATEGORY_ROBOT: "robot",
    EntityCategory.CATEGORY_HUMAN: "human",
    EntityCategory.CATEGORY_DYNAMIC_OBJECT: "dynamic object",
    EntityCategory.CATEGORY_STATIC_OBJECT: "static object",
}
"""Every EntityCategory code, by the name messages use."""


def category_of(entity: Entity) -> int:
    """The EntityCategory of an entity: the one a client set with SetEntityInfo; else ``CATEGORY_STATIC_OBJECT``
    for a static model (no free root), ``CATEGORY_ROBOT`` for a dynamic model with plugins or a movable joint,
    ``CATEGORY_DYNAMIC_OBJECT`` for another dynamic model."""
    if entity.category is not None:
        return entity.category
    if entity.static or entity.built.free_joint is None:
        return EntityCategory.CATEGORY_STATIC_OBJECT
    m = entity.model
    if m.plugins or any(j.type is not JointType.FIXED for j in m.joints):
        return EntityCategory.CATEGORY_ROBOT
    return EntityCategory.CATEGORY_DYNAMIC_OBJECT


def checked_tags(tags: Iterable[str], field_name: str) -> tuple[str, ...]:
    """A request's tags, once they are within :data:`MAX_TAGS` and :data:`MAX_TAG_CHARS` and hold no NUL
    (``RESULT_OPERATION_FAILED`` naming ``field_name`` otherwise)."""
    tags = list(tags)
    if len(tags) > MAX_TAGS:
        raise _Refused(Result.RESULT_OPERATION_FAILED, f"{field_name} has {len(tags)} tags; at most {MAX_TAGS}")
    for i, tag in enumerate(tags):
        if len(tag) > MAX_TAG_CHARS or "\x00" in tag:
            raise _Refused(
                Result.RESULT_OPERATION_FAILED,
                f"{field_name}[{i}] {excerpt(tag, 40)}: a tag has at most {MAX_TAG_CHARS} characters and no NUL",
            )
    return tuple(str(t) for t in tags)


Point = tuple[float, float, float]
"""A point in the world frame, as a request's ``geometry_msgs/Vector3`` gives it."""


def _overlap_shape(bounds: Bounds) -> tuple[tuple[Point, Point] | None, tuple[Point, float] | None]:
    """(box, sphere) of a request's ``filters.bounds``; both None when it is empty."""
    pts = [(p.x, p.y, p.z) for p in bounds.points]
    if bounds.type == Bounds.TYPE_EMPTY:
        if pts:
            raise _Refused(Result.RESULT_OPERATION_FAILED, "filters.bounds is TYPE_EMPTY but has points")
        return None, None
    if bounds.type == Bounds.TYPE_CONVEX_HULL:
        raise _Refused(
            Result.RESULT_FEATURE_UNSUPPORTED,
            "filters.bounds TYPE_CONVEX_HULL is not supported: use TYPE_BOX or TYPE_SPHERE",
        )
    if bounds.type not in (Bounds.TYPE_BOX, Bounds.TYPE_SPHERE):
        raise _Refused(Result.RESULT_FEATURE_UNSUPPORTED, f"filters.bounds.type {bounds.type} is unknown")
    if len(pts) != 2 or not _finite(*pts[0], *pts[1]):
        raise _Refused(
            Result.RESULT_OPERATION_FAILED,
            f"filters.bounds.points must be 2 finite points for TYPE_BOX and TYPE_SPHERE, got {len(pts)}",
        )
    if bounds.type == Bounds.TYPE_BOX:
        return (pts[0], pts[1]), None
    if pts[1][0] < 0:
        raise _Refused(Result.RESULT_OPERATION_FAILED, f"filters.bounds.points[1].x (the radius) is {pts[1][0]:g} < 0")
    return None, (pts[0], float(pts[1][0]))


@dataclass(frozen=True)
class EntityFilter:
    """One request's EntityFilters, checked (see the module docstring)."""

    pattern: str | None
    """The name filter (a regular expression matched by the bounded helper), None for all names."""
    categories: frozenset[int]
    """Any of these; empty for all."""
    tags: tuple[str, ...]
    """Empty for all."""
    all_tags: bool
    """``FILTER_MODE_ALL``: an entity needs every tag; else any one."""
    box: tuple[Point, Point] | None
    """Two opposite corners in the world frame, or None."""
    sphere: tuple[Point, float] | None
    """Centre in the world frame and radius, or None."""

    @classmethod
    def from_msg(cls, filters: EntityFilters) -> EntityFilter:
        """A request's ``filters``; raises :class:`_Refused` naming the field that is wrong."""
        mode = filters.tags.filter_mode
        if mode not in (TagsFilter.FILTER_MODE_ANY, TagsFilter.FILTER_MODE_ALL):
            raise _Refused(
                Result.RESULT_OPERATION_FAILED,
                f"filters.tags.filter_mode {mode} is unknown: FILTER_MODE_ANY (0) or FILTER_MODE_ALL (1)",
            )
        tags = checked_tags(filters.tags.tags, "filters.tags.tags")
        box, sphere = _overlap_shape(filters.bounds)
        pattern = str(filters.filter) or None
        cats = frozenset(c.category for c in filters.categories)
        return cls(pattern, cats, tags, mode == TagsFilter.FILTER_MODE_ALL, box, sphere)

    @property
    def overlap(self) -> bool:
        """Whether the bounds filter applies."""
        return self.box is not None or self.sphere is not None

    def keeps(self, entity: Entity) -> bool:
        """Whether the entity passes the category and tag filters (read on the sim thread)."""
        if self.categories and category_of(entity) not in self.categories:
            return False
        if not self.tags:
            return True
        have = set(entity.tags)
        return all(t in have for t in self.tags) if self.all_tags else any(t in have for t in self.tags)
