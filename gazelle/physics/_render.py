"""Offscreen rendering of the world from a camera pose: colour and metric depth, headless.

A :class:`OffscreenRenderer` owns an OpenGL context (EGL, which Mesa provides on a CPU and a GPU
driver accelerates, else OSMesa; ``MUJOCO_GL=egl|osmesa`` picks one) and MuJoCo's render context for
the world's current model, rebuilt after a recompile. It draws the visual geoms of entities whose
visuals are in the model and the collision geoms of the others (see the builder's geom groups),
lit by the world's lights, without shadows (measured: they cost 37 of 47 ms per 640 x 480 image
on Mesa's CPU rasteriser; see ``_ensure``).

The camera follows Gazebo's convention: it looks along the pose's +x with +z up, and the image has
``width`` x ``height`` pixels with horizontal field of view ``hfov``. Rendering must happen on one
thread (the simulation thread): the GL context is made current there.
"""

from __future__ import annotations

import math
import os

import mujoco
import numpy as np

from .._errors import SimError
from ..description import Pose, rotation_matrix
from ._builder import SHOWN_COLLISION_GROUP, VISUAL_GROUP


class RenderError(SimError, RuntimeError):
    """No OpenGL context could be made (no EGL or OSMesa library): the message says which were tried."""


def _gl_context(width: int, height: int):
    """An offscreen GL context from the first backend that works."""
    wanted = os.environ.get("MUJOCO_GL", "").strip().lower()
    order = [wanted] if wanted in ("egl", "osmesa") else ["egl", "osmesa"]
    errors = []
    for name in order:
        try:
            if name == "egl":
                from mujoco.egl import GLContext
            else:
                from mujoco.osmesa import GLContext
            return GLContext(width, height)
        except Exception as err:  # a missing library raises ImportError, OSError or a GL error
            errors.append(f"{name}: {type(err).__name__}: {err}")
    raise RenderError(
        "cannot render offscreen: " + "; ".join(errors) + " (install Mesa's libegl1 or libosmesa6: scripts/setup.sh)"
    )


class OffscreenRenderer:
    """Renders colour (uint8 H x W x 3) and depth (float32 metres, H x W) images of a world."""

    def __init__(self, world, width: int, height: int) -> None:
        """A renderer of ``width`` x ``height`` images of ``world`` (visual geoms, and the collision shapes of
        entities without visuals); the GL context is made at the first render, on the thread that renders."""
        if width < 1 or height < 1:
            raise ValueError(f"image size must be positive, got {width}x{height}")
        self.world = world
        self.width, self.height = width, height
        self._gl = None
        self._ctx: mujoco.MjrContext | None = None
        self._scene: mujoco.MjvScene | None = None
        self._generation = -1
        self._option = mujoco.MjvOption()
        self._option.geomgroup[:] = 0
        self._option.geomgroup[VISUAL_GROUP] = 1
        self._option.geomgroup[SHOWN_COLLISION_GROUP] = 1
        self._camera = mujoco.MjvCamera()
        self._viewport = mujoco.MjrRect(0, 0, width, height)
        self._rgb = np.empty((height, width, 3), dtype=np.uint8)
        self._depth = np.empty((height, width), dtype=np.float32)

    def _ensure(self) -> None:
        """A current GL context, and MuJoCo's scene and rendering context for the world's current model (made again
        after a recompile: a spawn or a delete), with shadows off."""
        if self._gl is None:
            self._gl = _gl_context(self.width, self.height)
        self._gl.make_current()
        if self._generation != self.world.generation:
            m = self.world.model
            glob = m.vis.global_
            glob.offwidth = max(int(glob.offwidth), self.width)
            glob.offheight = max(int(glob.offheight), self.height)
            self._scene = mujoco.MjvScene(m, maxgeom=max(1000, 2 * m.ngeom))
            # Shadow maps cost 37 of 47 ms of a 640x480 image on Mesa's CPU rasteriser (9.6 ms without):
            # camera images are drawn without shadows, so a 30 Hz camera keeps real time on a CPU
            self._scene.flags[mujoco.mjtRndFlag.mjRND_SHADOW] = 0
            if self._ctx is not None:
                self._ctx.free()
            self._ctx = mujoco.MjrContext(m, mujoco.mjtFontScale.mjFONTSCALE_100)
            mujoco.mjr_setBuffer(mujoco.mjtFramebuffer.mjFB_OFFSCREEN, self._ctx)
            self._generation = self.world.generation

    def render(
        self, X_WS: Pose, hfov: float, near: float, far: float, *, depth: bool = False
    ) -> tuple[np.ndarray, np.ndarray | None]:
        """Colour, and depth in metres when asked (``far`` where nothing is drawn), seen from ``X_WS``.

        The arrays are reused by the next call: copy what you keep.
        """
        self._ensure()
        w = self.world
        w.refresh_kinematics()
        scn, ctx = self._scene, self._ctx
        assert scn is not None and ctx is not None
        mujoco.mjv_updateScene(w.model, w.data, self._option, None, self._camera, mujoco.mjtCatBit.mjCAT_ALL, scn)
        R = rotation_matrix(X_WS.orientation)
        tan_v = math.tan(hfov / 2) * self.height / self.width
        for cam in (scn.camera[0], scn.camera[1]):
            cam.pos[:] = X_WS.position
            cam.forward[:] = R[:, 0]
            cam.up[:] = R[:, 2]
            cam.frustum_center = 0.0
            cam.frustum_width = 0.0
            cam.frustum_near = near
            cam.frustum_far = far
            cam.frustum_top = near * tan_v
            cam.frustum_bottom = -near * tan_v
            cam.orthographic = 0
        if w.model.vis.headlight.active and scn.nlight > 0:  # the headlight is lights[0]: it follows the camera
            scn.lights[0].pos[:] = X_WS.position
            scn.lights[0].dir[:] = R[:, 0]
            scn.lights[0].specular[:] = 0.0  # Gazebo has no headlight: no glare from one
        scn.enabletransform = 0
        mujoco.mjr_render(self._viewport, scn, ctx)
        mujoco.mjr_readPixels(self._rgb, self._depth, self._viewport, ctx)
        # where nothing was drawn (the depth buffer kept its clear value), the world's background colour
        # (MuJoCo clears to black; its skybox would be drawn at a finite depth, within some cameras' far
        # plane and beyond others')
        self._rgb[self._depth >= 1.0] = self.world.background
        rgb = np.flipud(self._rgb)  # OpenGL's rows go bottom-up
        if not depth:
            return rgb, None
        d = np.flipud(self._depth)
        metres = (near / (1.0 - d * (1.0 - near / far))).astype(np.float32)
        return rgb, metres

    def close(self) -> None:
        """Free the GL resources (call on the rendering thread)."""
        if self._ctx is not None:
            self._ctx.free()
            self._ctx = None
        if self._gl is not None:
            self._gl.free()
            self._gl = None
