"""Anisotropic friction (ODE's ``<mu>`` along ``<fdir1>``, ``<mu2>`` across it) on MuJoCo, for shapes touching a plane.

Gazebo Classic's ODE (``ODEPhysics::Collide``) gives a contact the friction ``mu = min(mu1, mu1')`` along the
first friction direction and ``mu2 = min(mu2, mu2')`` along ``normal × fdir1``, where ``fdir1`` is the surface's
``<fdir1>`` turned from the collision's frame into the world; ``mu2`` 0 leaves no friction row at all in that
direction (``dxJointContact::getInfo1``). Skid-steer robots give their wheels ``mu2`` 0 (or a small one) across the
wheel, so the wheels slide sideways as the robot turns instead of scrubbing.

MuJoCo's geoms have one sliding friction for both tangent directions. Anisotropic friction exists only in an
explicit ``<pair>`` (``friction`` = tangent1, tangent2, spin, roll1, roll2), in the contact's own frame, whose first
tangent is chosen by the collision function: a capsule on a plane puts it along the capsule's axis
(``mjc_PlaneCapsule``, ``engine_collision_primitive.c``); a cylinder, sphere, box or mesh on a plane leaves it to
``mju_makeFrame``, a fixed world direction (world y on level ground), so a pair of those would be anisotropic
along the world's axes, not the wheel's. Hence, for a moving collision with anisotropic friction whose contact with
a plane a capsule reproduces (:func:`add_contact_proxy`):

* a cylinder (a wheel) gets a hidden capsule of its radius and half length along its axis (it touches a plane at
  the two rim points the cylinder does; a drive's point-like wheel contact shrinks it to a point, see
  ``PhysicsWorld.make_wheel_contacts_pointlike``); a sphere, a capsule of its radius and no length along ``fdir1``;
  a capsule collision is its own proxy;
* the proxy collides with nothing dynamically (``contype`` = ``conaffinity`` = 0), only through the pairs
  :func:`sync_contact_pairs` makes with every plane of the world the collision's bitmask lets it touch, with the
  friction ``min(mu, plane's)`` along ``fdir1`` and ``min(mu2, plane's)`` across (along the axis or across it,
  whichever of the two ``fdir1`` is nearer), and the rest of the contact (condim, solref, solimp, torsional friction,
  margin) from the original geom and the plane as MuJoCo's own rule (``mj_contactParam``) would combine them;
* a second pair, of the original geom and the plane with a margin no contact reaches, replaces their dynamic
  contact (MuJoCo skips a dynamic pair that a ``<pair>`` names, ``mj_collision``), so the wheel touches the ground
  once, through its proxy, and everything else through its own shape with the isotropic ``min(mu, mu2)``.

What stays isotropic (``min(mu, mu2)``, see docs/contact_parameters.md): contacts with anything but a plane, other
shapes (box, mesh, ellipsoid, cone), and ``mu ≠ mu2`` without ``<fdir1>`` (ODE then takes a direction of its own).
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass
from typing import Any

import mujoco
import numpy as np

from ..description import Capsule, Collision, Cylinder, Sphere, Surface, Vec3

_log = logging.getLogger("gazelle.physics")

PROXY_SUFFIX = "#contact"
"""Name suffix of a proxy geom (its collision's geom name + this): contacts of it are the collision's."""
PROXY_GROUP = 4
"""MuJoCo geom group of the proxies: neither rays nor cameras see it (they look at groups 1 to 3)."""
POINT_HALF_LENGTH = 1e-6
"""Half length (m) of a point-like proxy: MuJoCo's capsule needs a positive one."""
PAIR_PREFIX = "gazelle#friction/"
"""Name prefix of the pairs :func:`sync_contact_pairs` makes (and remakes at every compile)."""
NO_CONTACT_MARGIN = -1e9
"""Margin (m) of the pair that replaces an original geom's dynamic contact with a plane: no contact is that deep."""
MIN_FRICTION_RATIO = 0.01
"""The smaller of a pair's two sliding coefficients is at least this fraction of the larger. MuJoCo's elliptic cone
regularizes the second tangent by (mu1 / mu2)² (``mj_makeImpedance``): a wheel's mu2 = 0 across (MuJoCo's floor,
1e-5, against 1 along) made its contact force grow without bound (5 kN in 4 steps), 1e-4 still did on a turn;
1e-2 is stable and leaves 1 % of the sideways grip (the skid-steer test turns 99.8 % of its odometry's claim)."""
MAX_FRICTION_PAIRS = 4096
"""The most pairs :func:`sync_contact_pairs` makes (MuJoCo tests every pair at every step; a robot's wheels on one
ground make 2 each). Past it, the remaining collisions keep their isotropic contact with a plane, and a warning
says how many (a world of thousands of planes, or of thousands of anisotropic wheels, still steps)."""
SDF_DEFAULT_MU = 1.0
"""SDFormat's ``<mu>`` and ``<mu2>`` when left out (``sdf/1.x/friction.sdf``)."""


@dataclass(frozen=True)
class ContactProxy:
    """A collision whose contacts with planes have ODE's anisotropic friction, through a capsule (see the module)."""

    proxy: str
    """The capsule geom that touches the planes (the collision's own geom when it is a capsule)."""
    original: str
    """The collision's geom: the pairs take its contact parameters, and its own contact with a plane is replaced."""
    entity_prefix: str
    """``<entity>::``: a plane of the same entity is left to the model's own collision rules."""
    mu_axis: float
    """Friction along the capsule's axis (``mu`` or ``mu2``, whichever ``fdir1`` is nearer to the axis)."""
    mu_across: float
    """Friction across the capsule's axis, in the plane."""


def anisotropic_friction(surface: Surface) -> tuple[float, float, Vec3] | None:
    """``(mu, mu2, unit fdir1)`` when ODE makes the surface's friction anisotropic: a non-zero ``<fdir1>`` and
    ``mu ≠ mu2`` (each SDFormat's 1 when left out, ODE's negative clamped to 0); None otherwise (``fdir1`` 0 0 0
    is no direction, as in Gazebo; ``mu`` 0 is no friction in either direction in ODE, which the isotropic
    ``min(mu, mu2)`` already gives)."""
    if surface.fdir1 is None:
        return None
    norm = math.sqrt(sum(c * c for c in surface.fdir1))
    if norm == 0.0 or not math.isfinite(norm):
        return None
    mu = max(0.0, SDF_DEFAULT_MU if surface.mu is None else surface.mu)
    mu2 = max(0.0, SDF_DEFAULT_MU if surface.mu2 is None else surface.mu2)
    if mu == mu2 or mu == 0.0:  # ODE with mu 0 makes no friction row at all (getInfo1): min(mu, mu2) = 0 says so
        return None
    x, y, z = surface.fdir1
    return mu, mu2, (x / norm, y / norm, z / norm)


def add_contact_proxy(body: mujoco.MjsBody, col: Collision, geom: str, entity_prefix: str) -> ContactProxy | None:
    """The proxy of the collision ``col`` (its geom is named ``geom``, in ``body``) when its friction is anisotropic
    and its shape is a cylinder, sphere or capsule (the capsule made and added to ``body``); None otherwise."""
    aniso = anisotropic_friction(col.surface)
    if aniso is None:
        return None
    mu, mu2, fdir1 = aniso
    g = col.geometry
    axis = (0.0, 0.0, 1.0)  # the capsule's axis in the collision frame: a cylinder's or capsule's own
    if isinstance(g, Capsule):
        return _proxy(geom, geom, entity_prefix, fdir1, axis, mu, mu2)
    if isinstance(g, Cylinder):
        size, quat = [g.radius, g.length / 2.0, 0.0], list(col.pose.orientation)
    elif isinstance(g, Sphere):
        axis = fdir1
        q_GA = np.zeros(4)
        mujoco.mju_quatZ2Vec(q_GA, np.asarray(fdir1, dtype=float))
        q_LA = np.zeros(4)
        mujoco.mju_mulQuat(q_LA, np.asarray(col.pose.orientation, dtype=float), q_GA)
        size, quat = [g.radius, POINT_HALF_LENGTH, 0.0], q_LA.tolist()
    else:
        return None
    name = geom + PROXY_SUFFIX
    body.add_geom(
        name=name,
        type=mujoco.mjtGeom.mjGEOM_CAPSULE,
        size=size,
        pos=list(col.pose.position),
        quat=quat,
        contype=0,
        conaffinity=0,
        density=0.0,
        group=PROXY_GROUP,
        rgba=[0.0, 0.0, 0.0, 0.0],
    )
    return _proxy(name, geom, entity_prefix, fdir1, axis, mu, mu2)


def _proxy(proxy: str, original: str, prefix: str, fdir1: Vec3, axis: Vec3, mu: float, mu2: float) -> ContactProxy:
    """``mu`` goes along the capsule's axis when ``fdir1`` is nearer to it than to the plane across it (ODE's first
    direction on a wheel is ``fdir1`` projected on the ground: along the axle when ``fdir1`` is, along the rolling
    direction when ``fdir1`` is across the axle)."""
    along = abs(sum(a * b for a, b in zip(fdir1, axis, strict=True))) >= math.sqrt(0.5)
    return ContactProxy(proxy, original, prefix, mu if along else mu2, mu2 if along else mu)


def sync_contact_pairs(spec: mujoco.MjSpec, proxies: dict[str, ContactProxy]) -> None:
    """Remake the pairs of every proxy in ``spec`` with every plane (see the module docstring), before a compile.

    ``proxies`` (proxy geom name -> proxy) loses the entries whose geoms are gone from the spec (a deleted or
    discarded entity); the pairs are remade from scratch, so an entity or a plane that came or went is accounted
    for."""
    for pair in list(spec.pairs):
        if pair.name.startswith(PAIR_PREFIX):
            spec.delete(pair)
    if not proxies:
        return
    geoms = {g.name: g for g in spec.geoms}
    for gone in [name for name, p in proxies.items() if name not in geoms or p.original not in geoms]:
        del proxies[gone]
    planes = [g for g in geoms.values() if g.type == mujoco.mjtGeom.mjGEOM_PLANE]
    made = left_out = 0
    for p in proxies.values():
        original = geoms[p.original]
        touched = [g for g in planes if not g.name.startswith(p.entity_prefix) and _may_touch(original, g)]
        per_plane = 1 if p.proxy == p.original else 2
        if made + per_plane * len(touched) > MAX_FRICTION_PAIRS:
            left_out += 1
            continue
        made += per_plane * len(touched)
        for plane in touched:
            spec.add_pair(
                name=f"{PAIR_PREFIX}{p.proxy}|{plane.name}",
                geomname1=p.proxy,
                geomname2=plane.name,
                **_pair_parameters(p, original, plane),
            )
            if per_plane == 2:
                spec.add_pair(
                    name=f"{PAIR_PREFIX}{p.original}|{plane.name}",
                    geomname1=p.original,
                    geomname2=plane.name,
                    margin=NO_CONTACT_MARGIN,
                )
    if left_out:
        _log.warning(
            f"{left_out} collision(s) with anisotropic friction keep isotropic contacts with the planes: the world "
            f"has more than {MAX_FRICTION_PAIRS} such contact pairs (see docs/contact_parameters.md)"
        )


def _may_touch(a: mujoco.MjsGeom, b: mujoco.MjsGeom) -> bool:
    """MuJoCo's dynamic filter, which a pair bypasses: ``(contype_a & conaffinity_b) | (contype_b & conaffinity_a)``
    (gazelle puts Gazebo's collide_bitmask in both)."""
    return bool((int(a.contype) & int(b.conaffinity)) | (int(b.contype) & int(a.conaffinity)))


def _pair_parameters(p: ContactProxy, g1: mujoco.MjsGeom, g2: mujoco.MjsGeom) -> dict[str, Any]:
    """A pair's fields as MuJoCo's ``mj_contactParam`` combines two geoms' (the higher priority's, else condim
    the larger, solref and solimp mixed by solmix, torsional and rolling friction the larger), with the sliding
    friction ODE's min per direction: ``min(mu_axis, plane's)``, ``min(mu_across, plane's)``."""
    mu_plane = float(g2.friction[0])
    sliding = [min(p.mu_axis, mu_plane), min(p.mu_across, mu_plane)]
    floor = MIN_FRICTION_RATIO * max(sliding)
    sliding = [max(mu, floor) for mu in sliding]
    if g1.priority != g2.priority:
        hi = g1 if g1.priority > g2.priority else g2
        condim, solref, solimp = int(hi.condim), list(hi.solref), list(hi.solimp)
        spin, roll = float(hi.friction[1]), float(hi.friction[2])
    else:
        condim = max(int(g1.condim), int(g2.condim))
        s1, s2 = float(g1.solmix), float(g2.solmix)
        mix = s1 / (s1 + s2) if s1 > 0 and s2 > 0 else (0.5 if s1 <= 0 and s2 <= 0 else float(s1 > 0))
        r1, r2 = np.asarray(g1.solref, dtype=float), np.asarray(g2.solref, dtype=float)
        solref = (mix * r1 + (1 - mix) * r2 if r1[0] > 0 and r2[0] > 0 else np.minimum(r1, r2)).tolist()
        solimp = (mix * np.asarray(g1.solimp, dtype=float) + (1 - mix) * np.asarray(g2.solimp, dtype=float)).tolist()
        spin, roll = (max(float(g1.friction[i]), float(g2.friction[i])) for i in (1, 2))
    return {
        "condim": condim,
        "friction": [*sliding, spin, roll, roll],
        "solref": solref,
        "solimp": solimp,
        "margin": max(float(g1.margin), float(g2.margin)),
        "gap": max(float(g1.gap), float(g2.gap)),
    }
