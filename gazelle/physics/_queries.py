"""What the world answers without changing it (:class:`WorldQueries`, a part :class:`~gazelle.physics.PhysicsWorld`
owns, ``world.queries``, whose public methods the world hands on to it): poses and twists of bodies and frames,
ray casts against the collision geoms, an ideal IMU's reading, the wrench through a joint and the contacts of a
link. Each brings the kinematics up to date first; only MuJoCo's derived fields are computed, so no query changes
a trajectory. The part sees the world as a :class:`~._world_part.WorldView` (its compiled model and data, its entities),
so it imports nothing of the module that builds it."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import mujoco
import numpy as np

from ..description import Pose, rotation_matrix
from ._builder import SEP, scoped
from ._contact_pairs import PROXY_SUFFIX
from ._entities import WORLD_FRAMES, EntityState, ErrorKind, WorldError
from ._world_part import WorldPart, WorldView

ONE_DOF_JOINTS = (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))
"""MuJoCo's joint types with one degree of freedom (hinge, slide)."""

RAY_GEOM_GROUPS = np.array([0, 0, 1, 1, 0, 0], dtype=np.uint8)
"""Geom groups rays hit: the collision geoms (groups 2 and 3), as Gazebo's ``ray`` sensor sees collisions."""


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """a x b for 3-vectors (np.cross costs ~10 µs a call)."""
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])


@dataclass(frozen=True)
class ContactPoint:
    """One MuJoCo contact, seen from the side of ``collision1``: the force and torque that
    ``collision2`` exerts on ``collision1`` (world frame, at the contact point), the normal pointing
    from ``collision2`` into ``collision1``, and the penetration depth (positive when overlapping)."""

    collision1: str
    """The watched side's collision (the forces act on it), scoped ``model::link::collision``."""
    collision2: str
    """The other side's collision, scoped the same way (Gazebo's naming)."""
    position: tuple[float, float, float]
    """The contact point, world frame, metres."""
    normal: tuple[float, float, float]
    """Unit normal, world frame, pointing from ``collision2`` into ``collision1``."""
    force: tuple[float, float, float]
    """Force on ``collision1``, newtons, world frame."""
    torque: tuple[float, float, float]
    """Torque on ``collision1`` about the contact point, N·m, world frame."""
    depth: float
    """Penetration, metres (positive: overlapping)."""


def _vec3(v: Sequence[float] | np.ndarray) -> tuple[float, float, float]:
    """Three floats of a MuJoCo vector, as a typed 3-tuple."""
    return (float(v[0]), float(v[1]), float(v[2]))


def _gazebo_collision_name(geom_name: str) -> str:
    """``entity::link::collision#i`` (MuJoCo; its anisotropic-friction proxy ``...#i#contact``) ->
    ``entity::link::collision`` (Gazebo)."""
    geom_name = geom_name.removesuffix(PROXY_SUFFIX)
    return geom_name.rsplit("#", 1)[0] if "#" in geom_name else geom_name


class WorldQueries(WorldPart[WorldView]):
    """The read-only queries of a world (see the module docstring)."""

    def __init__(self, world: WorldView) -> None:
        super().__init__(world)
        self.kinematics_stale = False
        """Whether qpos/qvel changed since the body poses were computed (a block of steps, a set-state)."""
        self._offsets: dict[Pose, tuple[np.ndarray, np.ndarray, bool, bool]] = {}
        """Sensor offsets (in their body) -> (position, rotation matrix, at the origin, unrotated)."""
        self._imu_acc, self._imu_vel, self._imu_quat, self._imu_R, self._imu_wa = (
            np.empty(6),
            np.empty(6),
            np.empty(4),
            np.empty((3, 3)),
            np.empty((2, 3)),
        )
        """Scratch arrays of :meth:`imu_reading` (6, 6, 4, 3x3 and 2x3)."""

    def refresh_kinematics(self) -> None:
        """Bring body poses up to the current state (cheap when already current); for renderers."""
        self._refresh_kinematics()

    def _refresh_kinematics(self) -> None:
        """Bring body poses and velocities up to the current qpos/qvel (derived fields only:
        the next mj_step recomputes them anyway, so trajectories are unchanged)."""
        if self.kinematics_stale:
            mujoco.mj_kinematics(self.model, self.data)
            mujoco.mj_comPos(self.model, self.data)
            mujoco.mj_comVel(self.model, self.data)
            self.kinematics_stale = False

    def joint_wrench(self, body_id: int, point: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(force, torque) that the parent exerts on body ``body_id`` through the joint above it, in the
        world frame, the torque about ``point`` (world). From MuJoCo's ``cfrc_int`` (after
        ``mj_rnePostConstraint``: derived fields only, the trajectory is unchanged), so gravity and
        motion of the child's whole subtree are in it, as a force-torque sensor at the joint reads."""
        self._refresh_kinematics()
        m, d = self.model, self.data
        mujoco.mj_rnePostConstraint(m, d)
        bid = body_id
        torque_c, force = np.array(d.cfrc_int[bid, :3]), np.array(d.cfrc_int[bid, 3:])
        c = d.subtree_com[int(m.body_rootid[bid])]  # cfrc_int is about its tree's centre of mass
        return force, torque_c + np.cross(c - point, force)

    def collision_geoms(self, entity: str, link: str, collision: str | None = None) -> frozenset[int]:
        """MuJoCo ids of a link's collision geoms (every convex part of a decomposed mesh), or of its
        collision named ``collision`` (valid until the next recompile)."""
        prefix = scoped(entity, f"{link}{SEP}{collision}#") if collision else scoped(entity, f"{link}{SEP}")
        m = self.model
        out = set()
        for i in range(m.ngeom):
            name = mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_GEOM, i) or ""
            if name.startswith(prefix) and "#v" not in name[len(prefix) - 1 :]:
                out.add(i)
        return frozenset(out)

    def contacts_of(self, geoms: frozenset[int]) -> list[ContactPoint]:
        """The current contacts that involve any of ``geoms``, each seen from that geom's side."""
        m, d = self.model, self.data
        out: list[ContactPoint] = []
        if not d.ncon or not geoms:
            return out
        # the contacts that involve one of the geoms, found in numpy (a chess set at rest has ~130 contacts
        # and a robot with a bumper on every link asks once per link: a Python loop over every contact per
        # sensor took more of the simulation thread than mj_step did)
        mine_lut = np.zeros(m.ngeom, dtype=bool)
        mine_lut[list(geoms)] = True
        f6 = np.zeros(6)
        for i in np.flatnonzero(mine_lut[d.contact.geom].any(axis=1)).tolist():
            c = d.contact[i]
            g1, g2 = int(c.geom1), int(c.geom2)
            mujoco.mj_contactForce(m, d, i, f6)
            frame = np.asarray(c.frame, dtype=float).reshape(3, 3)  # rows: normal (geom1 -> geom2), tangents
            force_w = frame.T @ f6[:3]  # MuJoCo: the force geom1 exerts on geom2, in the contact frame
            torque_w = frame.T @ f6[3:]
            mine, other, sign = (g1, g2, -1.0) if g1 in geoms else (g2, g1, 1.0)
            normal = sign * frame[0]  # MuJoCo's normal points from geom1 to geom2: turned to point into mine
            out.append(
                ContactPoint(
                    _gazebo_collision_name(mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_GEOM, mine) or str(mine)),
                    _gazebo_collision_name(mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_GEOM, other) or str(other)),
                    _vec3(c.pos),
                    _vec3(normal),
                    _vec3(sign * force_w),
                    _vec3(sign * torque_w),
                    float(-c.dist),
                )
            )
        return out

    def body_id(self, entity: str, link: str | None = None) -> int:
        """MuJoCo id of an entity's root body, or of one of its links' bodies (valid until the next recompile)."""
        e = self.entities.get(entity)
        if e is None:
            raise WorldError(ErrorKind.NOT_FOUND, f"entity '{entity}' does not exist")
        body = e.built.root_body if link is None else e.built.bodies.get(link)
        if body is None:
            raise WorldError(ErrorKind.NOT_FOUND, f"entity '{entity}' has no link '{link}'")
        return mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_BODY, body)

    def body_pose(self, body_id: int) -> Pose:
        """World pose of a body by id (kinematics refreshed first if stale)."""
        self._refresh_kinematics()
        x, y, z = self.data.xpos[body_id].tolist()
        w, qx, qy, qz = self.data.xquat[body_id].tolist()
        return Pose((x, y, z), (w, qx, qy, qz))

    def body_poses(self, body_ids: Sequence[int] | np.ndarray) -> np.ndarray:
        """World poses of many bodies at once: an (n, 7) array of x, y, z, qw, qx, qy, qz (a copy)."""
        self._refresh_kinematics()
        ids = np.asarray(body_ids, dtype=int)
        return np.concatenate((self.data.xpos[ids], self.data.xquat[ids]), axis=1)

    def link_poses_along(
        self, entity: str, link: str, joints: Sequence[str], positions: Sequence[Sequence[float]]
    ) -> list[Pose]:
        """World poses of an entity's ``link`` were its ``joints`` (1-dof, description names) at each row
        of ``positions``, every other joint where it is now: forward kinematics on a scratch copy of the
        state (a planned path drawn before the arm moves); the simulation is untouched.

        Raises:
            WorldError: (NOT_FOUND) no such entity, link or movable joint; (INVALID_POSE) a row whose
                length is not the number of joints.
        """
        body = self.body_id(entity, link)
        e = self.entities[entity]
        addresses = []
        for joint in joints:
            mj = e.built.joints.get(joint)
            if not mj:
                raise WorldError(ErrorKind.NOT_FOUND, f"entity '{entity}' has no movable joint '{joint}'")
            jid = mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_JOINT, mj[0])
            if int(self.model.jnt_type[jid]) not in ONE_DOF_JOINTS:
                raise WorldError(ErrorKind.NOT_FOUND, f"joint '{joint}' of '{entity}' is not a 1-dof joint")
            addresses.append(int(self.model.jnt_qposadr[jid]))
        scratch = mujoco.MjData(self.model)
        scratch.qpos[:] = self.data.qpos
        poses = []
        for row in positions:
            if len(row) != len(addresses):
                raise WorldError(ErrorKind.INVALID_POSE, f"{len(row)} positions for {len(addresses)} joints")
            scratch.qpos[addresses] = row
            mujoco.mj_kinematics(self.model, scratch)
            x, y, z = scratch.xpos[body].tolist()
            w, qx, qy, qz = scratch.xquat[body].tolist()
            poses.append(Pose((x, y, z), (w, qx, qy, qz)))
        return poses

    def body_velocity(self, body_id: int) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
        """World-frame linear velocity of the body origin and angular velocity."""
        self._refresh_kinematics()
        vel = np.zeros(6)
        mujoco.mj_objectVelocity(self.model, self.data, mujoco.mjtObj.mjOBJ_BODY, body_id, vel, 0)
        ang = vel[:3]
        lin = vel[3:]
        return (float(lin[0]), float(lin[1]), float(lin[2])), (float(ang[0]), float(ang[1]), float(ang[2]))

    def cast_rays(
        self, origin: np.ndarray, directions: np.ndarray, exclude_body: int, max_range: float
    ) -> tuple[np.ndarray, np.ndarray]:
        """Cast rays from ``origin`` along the unit ``directions`` (N×3, world frame) against collision
        geoms (what Gazebo's ``ray`` sensor sees), ignoring the body ``exclude_body``, in one
        ``mj_multiRay`` call. Returns (distances, geom ids): distance -1 and id -1 where nothing is hit
        within ``max_range``."""
        self._refresh_kinematics()
        origin, directions = np.ascontiguousarray(origin, dtype=float), np.ascontiguousarray(directions, dtype=float)
        return self._multi_ray(origin, directions, exclude_body, max_range)

    def cast_rays_from(
        self, body_id: int, offset: Pose, directions: np.ndarray, max_range: float
    ) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`cast_rays` from a sensor at ``offset`` in body ``body_id``'s frame, with the unit
        ``directions`` (N×3) in the sensor's frame, ignoring that body (a lidar's own housing). The
        sensor's world pose is composed from MuJoCo's arrays (a lidar scans at its rate, often)."""
        self._refresh_kinematics()
        d = self.data
        p_BS, R_BS, at_origin, unrotated = self._offset(offset)
        R_WB = d.xmat[body_id].reshape(3, 3)
        origin = d.xpos[body_id] if at_origin else d.xpos[body_id] + R_WB @ p_BS
        R_WS = R_WB if unrotated else R_WB @ R_BS
        return self._multi_ray(np.ascontiguousarray(origin), directions @ R_WS.T, body_id, max_range)

    def _multi_ray(
        self, origin: np.ndarray, directions: np.ndarray, exclude_body: int, max_range: float
    ) -> tuple[np.ndarray, np.ndarray]:
        """One ``mj_multiRay`` call for every direction (world frame, unit vectors) from ``origin``: the
        distance to the first hit (-1 for none within ``max_range``) and the geom hit (-1 for none). Only the
        geom groups of :data:`RAY_GEOM_GROUPS` are seen (collision shapes, not visuals), static geoms
        included; ``exclude_body`` (the sensor's own body) is not, so a sensor does not see the link it is
        mounted in."""
        n = len(directions)
        dist = np.empty(n)
        geom = np.empty(n, dtype=np.int32)
        mujoco.mj_multiRay(
            self.model,
            self.data,
            origin,
            directions.reshape(-1),
            RAY_GEOM_GROUPS,
            True,
            exclude_body,
            geom,
            dist,
            None,
            n,
            max_range,
        )
        return dist, geom

    def _offset(self, offset: Pose) -> tuple[np.ndarray, np.ndarray, bool, bool]:
        """A sensor's pose in its body, cached as (position, rotation matrix, at the origin, unrotated)."""
        cached = self._offsets.get(offset)
        if cached is None:
            p = np.asarray(offset.position, dtype=float)
            R = rotation_matrix(offset.orientation)
            cached = self._offsets[offset] = (p, R, not p.any(), offset.orientation == (1.0, 0.0, 0.0, 0.0))
        return cached

    def imu_reading(self, body_id: int, offset: Pose) -> list[float]:
        """What an ideal IMU at ``offset`` (a pose in the body frame) reads now, as ten floats: its world
        orientation (w, x, y, z), then its angular velocity and its proper linear acceleration, both in its
        own frame. At rest the acceleration is +g upwards (0, 0, 9.81), as a real accelerometer reads:
        MuJoCo's body accelerations (``mj_rnePostConstraint``) start from the gravity as a base
        acceleration. Only derived fields are computed, so the trajectory is unchanged.

        Called at an IMU's rate, thousands of times a wall second when the world runs faster than real
        time: a sensor at the body's origin and unrotated in it (the usual case) costs three MuJoCo calls
        (after the kinematics are brought up to date) and one 2x3 by 3x3 product."""
        self._refresh_kinematics()
        m, d = self.model, self.data
        mujoco.mj_rnePostConstraint(m, d)
        acc, vel, wa = self._imu_acc, self._imu_vel, self._imu_wa
        mujoco.mj_objectAcceleration(m, d, mujoco.mjtObj.mjOBJ_XBODY, body_id, acc, 0)
        mujoco.mj_objectVelocity(m, d, mujoco.mjtObj.mjOBJ_XBODY, body_id, vel, 0)
        p_BS, R_BS, at_origin, unrotated = self._offset(offset)
        R_WB = d.xmat[body_id].reshape(3, 3)
        wa[0] = vel[:3]
        if at_origin:
            wa[1] = acc[3:]
        else:  # a sensor off the body origin also feels alpha x r and the centripetal w x (w x r)
            r = R_WB @ p_BS
            w = vel[:3]
            wa[1] = acc[3:] + _cross(acc[:3], r) + _cross(w, _cross(w, r))
        if unrotated:
            R_WS = R_WB
            q = d.xquat[body_id].tolist()
        else:
            R_WS, q4 = self._imu_R, self._imu_quat
            mujoco.mju_mulMatMat(R_WS, R_WB, R_BS)
            mujoco.mju_mat2Quat(q4, R_WS.reshape(-1))
            q = q4.tolist()
        # the rows of wa @ R_WS are (R_WS^T w)^T and (R_WS^T a)^T: both vectors in the sensor's frame
        return q + (wa @ R_WS).ravel().tolist()

    def frame_pose(self, frame: str) -> Pose:
        """World pose of a frame named in a request: a :data:`WORLD_FRAMES` name, an entity (its model
        frame), or ``entity::link``.

        Raises:
            WorldError: (NOT_FOUND) no such entity or link.
        """
        if frame in WORLD_FRAMES:
            return Pose()
        entity, _, link = frame.partition(SEP)
        return self.entity_state(entity, link or None).pose

    def entity_state(self, entity: str, link: str | None = None) -> EntityState:
        """World pose and twist of an entity's model frame (its root link), or of one of its links."""
        bid = self.body_id(entity, link)
        lin, ang = self.body_velocity(bid)
        return EntityState(self.body_pose(bid), lin, ang)
