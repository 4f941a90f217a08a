#!/usr/bin/env python3
"""A plain rclpy node (it never imports gazelle): subscribes to sensor topics and prints one JSON line
per message received (topic, type, stamp, frame and a few fields), exiting after ``count`` of each.

Usage: sensor_listener.py COUNT TOPIC:TYPE [TOPIC:TYPE ...], TYPE one of LaserScan, Imu, PointCloud2,
Range, Image, CameraInfo,
ContactsState, NavSatFix, Vector3Stamped, WrenchStamped.
"""

import json
import sys

import rclpy
import rclpy.utilities
from gazebo_msgs.msg import ContactsState
from geometry_msgs.msg import Vector3Stamped, WrenchStamped
from rclpy.qos import qos_profile_sensor_data
from sensor_msgs.msg import CameraInfo, Image, Imu, LaserScan, NavSatFix, PointCloud2, Range

TYPES = {
    "LaserScan": LaserScan,
    "Imu": Imu,
    "PointCloud2": PointCloud2,
    "Range": Range,
    "Image": Image,
    "CameraInfo": CameraInfo,
    "ContactsState": ContactsState,
    "NavSatFix": NavSatFix,
    "Vector3Stamped": Vector3Stamped,
    "WrenchStamped": WrenchStamped,
}


def summary(msg) -> dict:
    if isinstance(msg, LaserScan):
        finite = [r for r in msg.ranges if r == r and abs(r) != float("inf")]
        return {
            "n": len(msg.ranges),
            "finite": len(finite),
            "min": min(finite) if finite else None,
            "angle_min": msg.angle_min,
            "angle_increment": msg.angle_increment,
        }
    if isinstance(msg, Imu):
        a, w = msg.linear_acceleration, msg.angular_velocity
        return {"accel": [a.x, a.y, a.z], "gyro": [w.x, w.y, w.z]}
    if isinstance(msg, Image):
        data = bytes(msg.data)
        return {
            "width": msg.width,
            "height": msg.height,
            "encoding": msg.encoding,
            "bytes": len(data),
            "mean": sum(data[::97]) / max(1, len(data[::97])),
        }
    if isinstance(msg, CameraInfo):
        return {"width": msg.width, "height": msg.height, "k": list(msg.k)}
    if isinstance(msg, ContactsState):
        return {"pairs": [[st.collision1_name, st.collision2_name] for st in msg.states]}
    if isinstance(msg, NavSatFix):
        return {"lat": msg.latitude, "lon": msg.longitude, "alt": msg.altitude, "status": msg.status.status}
    if isinstance(msg, Vector3Stamped):
        return {"v": [msg.vector.x, msg.vector.y, msg.vector.z]}
    if isinstance(msg, WrenchStamped):
        f = msg.wrench.force
        return {"force": [f.x, f.y, f.z]}
    if isinstance(msg, PointCloud2):
        return {"width": msg.width, "fields": [f.name for f in msg.fields]}
    return {"range": msg.range, "radiation": msg.radiation_type}


def main() -> None:
    count = int(sys.argv[1])
    rclpy.init()
    node = rclpy.create_node("sensor_listener")
    got = {}
    for spec in sys.argv[2:]:
        topic, kind = spec.rsplit(":", 1)
        got[topic] = 0

        def cb(msg, topic=topic, kind=kind):
            if got[topic] >= count:
                return
            got[topic] += 1
            line = {
                "topic": topic,
                "type": kind,
                "frame": msg.header.frame_id,
                "stamp": msg.header.stamp.sec + msg.header.stamp.nanosec * 1e-9,
                **summary(msg),
            }
            print(json.dumps(line), flush=True)

        # SensorDataQoS (best effort) matches the simulator's reliable writers, as RViz and SLAM do
        node.create_subscription(TYPES[kind], topic, cb, qos_profile_sensor_data)
    print(json.dumps({"ready": True}), flush=True)
    while rclpy.utilities.ok() and any(n < count for n in got.values()):
        rclpy.spin_once(node, timeout_sec=0.5)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
