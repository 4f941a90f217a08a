"""Cameras and depth cameras: colour and metric depth rendered offscreen (MuJoCo over EGL), with
camera_info from the field of view, and points for depth sensors.

What a ROS user gets, and where it comes from:

* **Frames.** Images, depth and points are stamped with the sensor's frame as the plugin names it
  (gazebo_ros: ``<frame_name>``, else the link; gz-sim: ``<gz_frame_id>``/``<frame_id>``, else
  ``model::link::sensor``), and the pixels follow ROS's optical convention (REP 103, camera_info):
  z forward, x right, y down (:data:`OPTICAL`). A URDF that adds its own ``*_optical_frame`` link and
  names it in ``<frame_name>`` gets that frame, as in Gazebo.
* **Units.** Depth is 32FC1 in metres (REP 118): ``+inf`` where nothing is within ``<clip><far>``,
  ``-inf`` nearer than ``<near>`` (gazebo_ros_camera: nearer than its ``<min_depth>``, 0.4 m by default).
  Points are an organised cloud (a point per pixel) in metres with the pixel's colour (``rgb``), laid out
  as each Gazebo lays them out: gazebo_ros_camera's in the optical frame, gz-sim's in the sensor's
  x-forward frame (:meth:`Camera.cloud`).
* **Intrinsics.** Square pixels from ``<horizontal_fov>`` and the image size. gz-sim's CameraInfo puts the
  principal point at the centre, (w / 2, h / 2) (:meth:`CameraSpec.k`, as gz-sensors derives it from the
  projection when no ``<lens><intrinsics>`` are given); gazebo_ros_camera's at ((w + 1) / 2, (h + 1) / 2)
  unless its ``<cx>``/``<cy>`` say otherwise (:func:`classic_info`). ``<distortion>`` is published in
  CameraInfo, not applied to the image (gazelle warns).
* **Noise.** ``<noise type="gaussian">`` as gz-sensors' image noise: mean and stddev are in units of
  the full channel range (0..1), so a stddev of 0.007 moves a channel by about 1.8 of 255.
* **Cost.** Rendering is the most expensive thing a sensor does: a camera renders only at its rate and
  only while a topic of it has a subscriber, and renders depth only when depth or points are wanted.

Topic names: gazebo_ros's ``<camera_name>/image_raw``, ``camera_info``, ``depth/image_raw``, ``points``
under the plugin node's namespace; gz-sim's ``<topic>`` with ``camera_info`` beside it, and an RGBD
camera's ``<topic>/image``, ``/depth_image``, ``/points`` (see :meth:`Camera._topics`).
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from ...description import (
    ConfigElement,
    Plugin,
    Sensor,
    parse_floats,
)
from ...physics import OffscreenRenderer, PhysicsWorld, RenderError
from .._base import SystemContext, UpdateInfo
from .._bus import Endpoint, MsgType, resolve_topic
from .._payloads import XYZ_RGB, XYZ_RGB_PADDED, CameraInfo, Image, PointCloud
from .._plugin_config import child_text, parse_float
from .._registration import add_plugin
from ._common import (
    SENSOR_DEPTH,
    Noise,
    SensorConfigError,
    SensorLimitError,
    SensorPluginConfig,
    _SensorSystem,
    gz_scoped_topic,
    parse_noise,
)

CAMERA_TYPES = frozenset({"camera", "depth", "depth_camera", "rgbd_camera", "rgbd"})
DEPTH_TYPES = frozenset({"depth", "depth_camera", "rgbd_camera", "rgbd"})
# a depth camera in gazebo_ros is a camera with a depth plugin; gz-sim spells it depth_camera or rgbd_camera
MAX_IMAGE_SIDE = 4096
"""The widest and tallest camera image (4K; 8192 x 8192 fills a 256 MB buffer a frame)."""


# --------------------------------------------------------------------------- cameras
@dataclass(frozen=True)
class CameraSpec:
    """A ``<camera>`` block: image size and format, field of view, clip planes, distortion, noise."""

    width: int = 320
    """``<image><width>``, pixels (SDF's default)."""
    height: int = 240
    """``<image><height>``, pixels."""
    format: str = "R8G8B8"
    """``<image><format>``: R8G8B8 (rgb8), B8G8R8 (bgr8) or L8 (mono8); others are published as rgb8."""
    horizontal_fov: float = 1.047
    """``<horizontal_fov>``, radians (60°); the vertical one follows from the aspect ratio."""
    near: float = 0.1
    """``<clip><near>``, metres: nearer is not drawn (depth ``-inf``)."""
    far: float = 100.0
    """``<clip><far>``, metres: farther is not drawn (depth ``+inf``)."""
    distortion: tuple[float, float, float, float, float] = (0.0, 0.0, 0.0, 0.0, 0.0)
    """k1, k2, p1, p2, k3 (ROS's plumb_bob order); published in CameraInfo, not applied to the image."""
    noise: Noise = Noise()
    """``<noise>``: Gaussian, in units of the full channel range (see the module docstring)."""

    def k(self) -> tuple[float, ...]:
        """The intrinsic matrix: square pixels, f = (width / 2) / tan(hfov / 2), principal point at the
        image centre (pixel centres at half-integers, as the renderer draws them)."""
        f = (self.width / 2.0) / math.tan(self.horizontal_fov / 2.0)
        return (f, 0.0, self.width / 2.0, 0.0, f, self.height / 2.0, 0.0, 0.0, 1.0)


# SDF <image><format> -> sensor_msgs/Image encoding (gz-sim 8 spells both the old and the new names)
_ENCODINGS = {
    "R8G8B8": "rgb8",
    "RGB_INT8": "rgb8",
    "B8G8R8": "bgr8",
    "BGR_INT8": "bgr8",
    "L8": "mono8",
    "L_INT8": "mono8",
}


def parse_camera(sensor: Sensor, log: logging.Logger) -> CameraSpec:
    """The ``<camera>`` block of a camera sensor.

    Raises:
        SensorConfigError: an image of zero size, a field of view outside (0, pi), or clip planes out of order.
    """
    cam = sensor.config.find("camera") if sensor.config is not None else None
    where = f"{sensor.location}: " if sensor.location else ""
    if cam is None:
        log.warning(f"{where}sensor '{sensor.name}' ({sensor.type}) has no <camera> block; using SDF's defaults")
        return CameraSpec()
    image, clip, dist = cam.find("image"), cam.find("clip"), cam.find("distortion")
    width = int(parse_float(image, "width", 320, log))
    height = int(parse_float(image, "height", 240, log))
    fmt = (child_text(image, "format") or "R8G8B8").strip()
    hfov = parse_float(cam, "horizontal_fov", 1.047, log)
    near, far = parse_float(clip, "near", 0.1, log), parse_float(clip, "far", 100.0, log)
    if width < 1 or height < 1:
        raise SensorConfigError(f"{where}sensor '{sensor.name}': a camera of {width}x{height} pixels cannot render")
    if width > MAX_IMAGE_SIDE or height > MAX_IMAGE_SIDE:
        raise SensorLimitError(
            f"{where}sensor '{sensor.name}': a camera of {width}x{height} pixels is larger than "
            f"{MAX_IMAGE_SIDE}x{MAX_IMAGE_SIDE}, the largest image gazelle renders"
        )
    if not 0.0 < hfov < math.pi:
        raise SensorConfigError(f"{where}sensor '{sensor.name}': <horizontal_fov> must be in (0, pi), got {hfov}")
    if not 0.0 < near < far:
        raise SensorConfigError(f"{where}sensor '{sensor.name}': <clip> needs 0 < near < far, got {near} .. {far}")
    if fmt not in _ENCODINGS:
        log.warning(f"{where}sensor '{sensor.name}': image format '{fmt}' is not rendered; publishing rgb8 (R8G8B8)")
        fmt = "R8G8B8"
    _warn_unrendered(cam, sensor, log)
    k1, k2, p1, p2, k3 = (parse_float(dist, t, 0.0, log) for t in ("k1", "k2", "p1", "p2", "k3"))
    coeffs = (k1, k2, p1, p2, k3)
    if dist is not None and any(coeffs):
        log.warning(
            f"{where}sensor '{sensor.name}': <distortion> is published in CameraInfo but not applied to the image"
        )
    return CameraSpec(
        width,
        height,
        fmt,
        hfov,
        near,
        far,
        coeffs,
        parse_noise(cam.find("noise"), log, f"sensor '{sensor.name}'"),
    )


_CAMERA_READ = frozenset({"image", "clip", "horizontal_fov", "distortion", "noise", "camera_info_topic"})
"""The ``<camera>`` children gazelle reads; ``optical_frame_id`` (deprecated in gz-sensors, which uses the
sensor's frame) and ``save`` (writes frames to disk) change nothing a subscriber gets."""
_CAMERA_QUIET = frozenset({"optical_frame_id", "save"})


def _warn_unrendered(cam: ConfigElement, sensor: Sensor, log: logging.Logger) -> None:
    """Name the ``<camera>`` elements that change what Gazebo publishes but are not simulated here:
    ``<lens>`` (gz-sensors renders with its intrinsics or projection; here the image and CameraInfo follow
    ``<horizontal_fov>``), ``<triggered>`` (gz publishes only when triggered; here at the rate), the masks,
    segmentation and bounding-box kinds, a ``<pose>`` of the camera in its sensor, ``<depth_camera>``'s own
    clip planes."""
    where = f"{sensor.location}: " if sensor.location else ""
    for child in cam.children:
        tag = child.tag
        if tag in _CAMERA_READ or tag in _CAMERA_QUIET or ":" in tag:
            continue
        if tag == "triggered" and child.text.strip().lower() not in ("1", "true"):
            continue
        log.warning(
            f"{f'{child.location}: ' if child.location else where}sensor '{sensor.name}': <{tag}> in <camera> "
            "is not simulated (the image and CameraInfo follow <horizontal_fov>, <image> and <clip>, at the "
            "sensor's rate)"
        )


@dataclass(frozen=True)
class ClassicInfo:
    """What gazebo_ros_camera publishes as CameraInfo (gazebo_plugins/src/gazebo_ros_camera.cpp, ros2 branch):
    its own intrinsics, from the plugin's parameters over the field of view, and its depth limits."""

    k: tuple[float, ...]
    r: tuple[float, ...]
    p: tuple[float, ...]
    min_depth: float = 0.4
    """``<min_depth>``, metres: depth at or nearer than it reads -inf (points too)."""
    max_depth: float = math.inf
    """``<max_depth>``, metres: depth at or beyond it reads +inf."""


def classic_info(cfg: ConfigElement, spec: CameraSpec, log: logging.Logger) -> ClassicInfo:
    """gazebo_ros_camera's CameraInfo: the principal point at ((w + 1) / 2, (h + 1) / 2) unless ``<cx>``/``<cy>``;
    ``<focal_length>`` (0: width / (2 tan(hfov / 2)), which it warns about when they differ); R from
    ``<rectification_matrix>``; P from ``<P_fx>``, ``<P_cx>``, ``<Tx>`` (-f · ``<hack_baseline>``), ``<P_fy>``,
    ``<P_cy>``, ``<Ty>``. The image itself is rendered from the field of view, as Classic's is."""
    w, h = spec.width, spec.height
    cx = parse_float(cfg, "cx", (w + 1.0) / 2.0, log)
    cy = parse_float(cfg, "cy", (h + 1.0) / 2.0, log)
    computed = w / (2.0 * math.tan(spec.horizontal_fov / 2.0))
    f = parse_float(cfg, "focal_length", 0.0, log)
    if f == 0:
        f = computed
    elif abs(f - computed) > 1e-6:
        el = cfg.find("focal_length")
        where = f"{el.location}: " if el is not None and el.location else ""
        log.warning(
            f"{where}The <focal_length> [{f:f}] you have provided is inconsistent with specified <image_width> "
            f"[{w}] and HFOV [{spec.horizontal_fov:f}]. Please double check to see that focal_length = width / "
            f"(2.0 * tan(HFOV/2.0)). The expected focal_length value is [{computed:f}], please update your camera "
            "model description accordingly."
        )
    baseline = parse_float(cfg, "hack_baseline", 0.0, log)
    r = (1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0)
    raw = child_text(cfg, "rectification_matrix")
    if raw:
        values = parse_floats(raw, 9)
        if values is not None:
            r = values
        else:
            el = cfg.find("rectification_matrix")
            where = f"{el.location}: " if el is not None and el.location else ""
            log.warning(f"{where}<rectification_matrix> needs 9 numbers, got {raw!r}; using the identity")

    def number(tag: str, default: float) -> float:
        return parse_float(cfg, tag, default, log)

    p = (
        number("P_fx", f), 0.0, number("P_cx", cx), number("Tx", -f * baseline),
        0.0, number("P_fy", f), number("P_cy", cy), number("Ty", 0.0),
        0.0, 0.0, 1.0, 0.0,
    )  # fmt: skip
    return ClassicInfo(
        (f, 0.0, cx, 0.0, f, cy, 0.0, 0.0, 1.0), r, p, number("min_depth", 0.4), number("max_depth", math.inf)
    )


@dataclass(frozen=True)
class CameraTopics:
    """Where a camera publishes (an empty name: not published)."""

    image: str
    info: str
    depth: str = ""
    depth_info: str = ""
    points: str = ""


OPTICAL = np.array([[0.0, -1.0, 0.0], [0.0, 0.0, -1.0], [1.0, 0.0, 0.0]])
"""Rotation from a link frame (x forward, z up) to the optical frame (z forward, x right, y down)."""


@dataclass(frozen=True)
class CameraPluginConfig(SensorPluginConfig):
    """The camera plugins' settings (``libgazebo_ros_camera.so``, its depth and openni_kinect variants): the common
    ones and ``<camera_name>``, which names the topics."""

    camera_name: str = ""
    """``<camera_name>`` (ROS 1: ``<cameraName>``), the first part of the topics; default the sensor's name."""

    @classmethod
    def settings(cls, plugin: Plugin, cfg: ConfigElement, ctx: SystemContext) -> dict[str, Any]:
        """The common settings and ``<camera_name>``."""
        name = child_text(cfg, "camera_name") or child_text(cfg, "cameraName") or ""
        return super().settings(plugin, cfg, ctx) | {"camera_name": name}

    def plugin_topic(self, ctx: SystemContext, sensor: Sensor | None) -> str:
        """gazebo_ros_camera's ``<camera_name>/image_raw`` in the plugin's namespace (remappable)."""
        name = self.camera_name or (sensor.name if sensor is not None else "camera")
        return resolve_topic(f"{name}/image_raw", self.namespace, dict(self.remappings))


class Camera(_SensorSystem):
    """A camera or depth camera: Image, CameraInfo, depth Image (32FC1) and PointCloud2 (see the module
    docstring). It renders only while someone subscribes."""

    sdf_types = CAMERA_TYPES
    classic_plugins: ClassVar[dict[str, frozenset[str] | None]] = {
        "gazebo_ros_camera": None,
        "gazebo_ros_depth_camera": DEPTH_TYPES,
        "gazebo_ros_openni_kinect": DEPTH_TYPES,
    }
    gz_system = "Sensors"
    output_kind = "image"
    plugin_config = CameraPluginConfig
    config: CameraPluginConfig

    kind = "camera"

    checkpoint_skip = ("_renderer",)
    """Its offscreen renderer (a GL context) is made again where a checkpoint is loaded."""

    def __init__(self, seed: int | None = None) -> None:
        super().__init__(seed)
        self.spec = CameraSpec()
        self.topics = CameraTopics("", "")
        self.depth = False
        self._eps: dict[str, Endpoint] = {}
        self._renderer: OffscreenRenderer | None = None
        self._failed = False
        self.classic: ClassicInfo | None = None
        """gazebo_ros_camera's own CameraInfo and depth limits (None: gz-sim's, from the rendered projection)."""

    def configure(self, ctx: SystemContext) -> None:
        """Parse the ``<camera>`` block and the plugin; declare the image, info, depth and points topics.

        Who configured the camera decides its topics and its CameraInfo: a gazebo_ros camera plugin
        (``<camera_name>/image_raw`` and ``camera_info`` in its node's namespace, its own projection and
        ``<hack_baseline>``; a depth camera adds ``depth/image_raw`` and ``points``), or gz-sim's sensor
        system (the sensor's ``<topic>`` with ``camera_info`` beside it, the projection from the rendered
        intrinsics). The image is rendered at the sensor's rate off the physics state of its step; what
        the plugin asks that is not simulated (``<triggered>``) is said, never silently dropped."""
        spec = self._parse_sensor(ctx, "camera", parse_camera)
        if spec is None or ctx.sensor is None:
            return
        self.spec = spec
        if not self._configure_common(ctx):
            return
        assert self.output is not None and self._pub is not None
        self.depth = ctx.sensor.type in DEPTH_TYPES
        if ctx.plugin is not None:
            self.classic = classic_info(ctx.plugin.config, spec, ctx.logger)
            trigger = ctx.plugin.config.find("triggered")
            if trigger is not None and trigger.text.strip().lower() in ("1", "true"):
                ctx.logger.warning(
                    f"{f'{trigger.location}: ' if trigger.location else ''}<triggered> camera: gazebo_ros_camera "
                    "publishes a frame per message on <camera_name>/image_trigger; here it is not simulated and "
                    "the camera publishes at its rate"
                )
        self.topics = self._topics(ctx)
        # _configure_common advertised the image topic (output.topic); the others go beside it
        self._eps = {"image": self._pub}
        for key, msg_type in (
            ("info", MsgType.CAMERA_INFO),
            ("depth", MsgType.IMAGE),
            ("depth_info", MsgType.CAMERA_INFO),
            ("points", MsgType.POINT_CLOUD2),
        ):
            topic = getattr(self.topics, key)
            if topic:
                self._eps[key] = ctx.bus.advertise(ctx.entity.name, topic, msg_type, depth=SENSOR_DEPTH)
        s = self.spec
        streams = " and ".join(f"[{t}]" for t in (self.topics.image, self.topics.depth, self.topics.points) if t)
        ctx.logger.info(
            f"{ctx.sensor.type} '{ctx.sensor.name}': {s.width}x{s.height} at {self.rate_hz:g} Hz on {streams} "
            f"in frame [{self.output.frame_id}]"
        )

    def _topics(self, ctx: SystemContext) -> CameraTopics:
        """Where each stream goes, by who configured the camera: a gazebo_ros plugin (its node's names), an
        RGBD camera of gz-sim (one ``<topic>`` prefix), a gz-sim depth camera (``<topic>`` is the depth
        image) or a plain camera (``<topic>`` is the image, ``camera_info`` beside it)."""
        assert self.output is not None and self.sensor is not None
        image = self.output.topic
        parent = image.rsplit("/", 1)[0]
        if ctx.plugin is not None:  # gazebo_ros: <camera_name>/image_raw etc. under the node's namespace
            return CameraTopics(
                image,
                f"{parent}/camera_info",
                f"{parent}/depth/image_raw" if self.depth else "",
                f"{parent}/depth/camera_info" if self.depth else "",
                f"{parent}/points" if self.depth else "",
            )
        if self.sensor.type in ("rgbd_camera", "rgbd"):  # gz: <topic>/image, /depth_image, /points, /camera_info
            base = resolve_topic(
                self.sensor.topic or gz_scoped_topic(ctx, self.link, self.sensor, ""), ctx.entity.namespace
            ).rstrip("/")
            return CameraTopics(
                f"{base}/image", f"{base}/camera_info", f"{base}/depth_image", f"{base}/camera_info", f"{base}/points"
            )
        cam = self.sensor.config.find("camera") if self.sensor.config is not None else None
        given = child_text(cam, "camera_info_topic")  # gz-sensors CameraSensor.cc: <camera_info_topic> names it
        info = resolve_topic(given, ctx.entity.namespace) if given else f"{parent}/camera_info"
        if self.depth:  # gz depth_camera: <topic> is the depth image
            return CameraTopics("", info, image, info, f"{image}/points")
        return CameraTopics(image, info)

    def _wanted(self) -> dict[str, bool]:
        return {k: ep.wanted for k, ep in self._eps.items()}

    def info(self, stamp: float) -> CameraInfo:
        """CameraInfo of this camera (K and P from ``horizontal_fov`` and the image size)."""
        s = self.spec
        assert self.output is not None
        if self.classic is not None:  # gazebo_ros_camera's own numbers (see classic_info)
            k, r, p = self.classic.k, self.classic.r, self.classic.p
        else:
            k = s.k()
            # a monocular camera: P is K with a zero fourth column (no baseline), R the identity (not rectified)
            r = (1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0)
            p = (k[0], 0.0, k[2], 0.0, 0.0, k[4], k[5], 0.0, 0.0, 0.0, 1.0, 0.0)
        return CameraInfo(stamp, self.output.frame_id, s.height, s.width, "plumb_bob", s.distortion, k, r, p)

    def render(self, world: PhysicsWorld, depth: bool) -> tuple[np.ndarray, np.ndarray | None] | None:
        """Colour (H x W x 3 uint8) and depth (metres, -inf nearer than near, +inf where nothing is
        within far) as this camera sees the world now; None when no GL context could be made."""
        if self._failed:
            return None
        s = self.spec
        try:
            if self._renderer is None:
                self._renderer = world.offscreen_renderer(s.width, s.height)
            rgb, d = self._renderer.render(self.sensor_pose(), s.horizontal_fov, s.near, s.far, depth=depth)
        except RenderError as err:
            self._failed = True
            logging.getLogger("gazelle.sensors").error(f"camera '{self.sensor.name if self.sensor else ''}': {err}")
            return None
        if d is not None:
            # the depth buffer reads `far` (to float precision) where nothing was drawn: REP 118's +inf
            d = d.copy()
            d[d >= s.far * (1 - 1e-4)] = np.inf
            if self.classic is not None:  # gazebo_ros_camera OnNewDepthFrame: its own valid range
                d[d <= self.classic.min_depth] = -np.inf
                d[d >= self.classic.max_depth] = np.inf
        return rgb.copy(), d

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """At the camera's rate, while anyone subscribes: render and publish stamped with this sim time."""
        if self._pub is None or info.paused or not self._gate.due(info.sim_time_sec, self.rate_hz):
            return
        want = self._wanted()
        if not any(want.values()):
            return
        t, s = info.sim_time_sec, self.spec
        assert self.output is not None
        frame = self.output.frame_id
        # render only what a subscriber will get: depth costs a second read of the GL buffer
        need_depth = self.depth and (want.get("depth", False) or want.get("points", False))
        need_image = want.get("image", False) and bool(self.topics.image)
        out = self.render(world, need_depth) if (need_image or need_depth) else None
        ci = self.info(t)
        for key in ("info", "depth_info"):
            if want.get(key):
                self._eps[key].publish(ci)
        if out is None:
            return
        rgb, d = out
        if need_image:
            img = rgb
            if s.noise.active:  # per pixel and channel, in units of the full range (gz-sensors' ImageGaussianNoise)
                noisy = rgb.astype(np.float32) + 255.0 * self._rng.normal(s.noise.mean, s.noise.stddev, rgb.shape)
                img = np.clip(noisy, 0, 255).astype(np.uint8)
            enc = _ENCODINGS[s.format]
            if enc == "bgr8":
                img = img[..., ::-1]
            elif enc == "mono8":  # luma with ITU-R BT.601 weights, as OpenCV's RGB2GRAY
                img = (img.astype(np.float32) @ np.array([0.299, 0.587, 0.114], np.float32)).astype(np.uint8)
            data = np.ascontiguousarray(img)
            channels = 1 if data.ndim == 2 else 3
            self._eps["image"].publish(Image(t, frame, s.height, s.width, enc, s.width * channels, data.tobytes()))
        if d is None:
            return
        if want.get("depth"):
            self._eps["depth"].publish(
                Image(t, frame, s.height, s.width, "32FC1", s.width * 4, d.astype("<f4").tobytes())
            )
        if want.get("points"):
            self._eps["points"].publish(self.cloud(t, frame, rgb, d))

    def cloud(self, t: float, frame: str, rgb: np.ndarray, d: np.ndarray) -> PointCloud:
        """The depth image as the organised cloud (one point per pixel, row by row) each Gazebo publishes:

        * gazebo_ros_camera (``OnNewDepthFrame``): in the optical frame, x = z·tan(right angle),
          y = z·tan(down angle), z the depth, the angles about the centre ((w - 1) / 2, (h - 1) / 2) through
          f = w / (2 tan(hfov / 2)); an invalid depth makes every coordinate ±inf; rgb at byte 16 of 32 holds the
          image's r, g, b bytes in that order (as Classic copies them).
        * gz-sensors (``PointCloudUtil::FillMsg``): in the sensor frame, x the depth, y = x·tan(left angle),
          z = x·tan(up angle); rgb at byte 12 of 16 holds b, g, r (little-endian packing)."""
        s = self.spec
        h, w = d.shape
        f = w / (2.0 * math.tan(s.horizontal_fov / 2.0))
        right = np.tan(np.arctan2(np.arange(w) - 0.5 * (w - 1), f))[None, :]
        down = np.tan(np.arctan2(np.arange(h) - 0.5 * (h - 1), f))[:, None]
        colour = rgb if rgb.ndim == 3 else np.repeat(rgb[..., None], 3, axis=2)
        with np.errstate(invalid="ignore"):  # inf x tan(0) is nan, as in Gazebo's own arithmetic
            if self.classic is not None:
                layout, xyz = XYZ_RGB_PADDED, np.stack([d * right, d * down, d], axis=-1)
                invalid = ~np.isfinite(d)
                xyz[invalid] = d[invalid][:, None]  # every coordinate of an invalid point is its ±inf
                bytes_rgb = colour
            else:
                layout, xyz = XYZ_RGB, np.stack([d, -d * right, -d * down], axis=-1)
                bytes_rgb = colour[..., ::-1]
        points = np.zeros((h, w, layout.point_step), np.uint8)
        points[..., :12] = xyz.astype("<f4").view(np.uint8).reshape(h, w, 12)
        offset = dict(layout.fields)["rgb"]
        points[..., offset : offset + 3] = bytes_rgb
        return PointCloud(t, frame, w, h, points.tobytes(), layout, bool(np.isfinite(d).all()))

    def shutdown(self) -> None:
        """Free the GL context (on the simulation thread, where it was made)."""
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None


add_plugin(Camera)
