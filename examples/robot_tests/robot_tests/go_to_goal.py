#!/usr/bin/env python3
"""A plain rclpy node (it never imports gazelle): drive a differential robot to a goal with a
proportional controller on /odom, publishing /cmd_vel, and stop there.

Parameters: goal_x, goal_y (m, odom frame), tolerance (m, default 0.05), max_speed (m/s, default 0.2).
Run with use_sim_time:=true so its timer follows the simulation's /clock.
"""

import math

import rclpy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rclpy.node import Node


class GoToGoal(Node):
    def __init__(self):
        super().__init__("go_to_goal")
        self.goal = (self.declare_parameter("goal_x", 1.0).value, self.declare_parameter("goal_y", 0.0).value)
        self.tolerance = self.declare_parameter("tolerance", 0.05).value
        self.max_speed = self.declare_parameter("max_speed", 0.2).value
        self.pose = None
        self.cmd = self.create_publisher(Twist, "/cmd_vel", 10)
        self.create_subscription(Odometry, "/odom", self.on_odom, 10)
        self.create_timer(0.05, self.tick)  # 20 Hz of sim time

    def on_odom(self, msg):
        p, q = msg.pose.pose.position, msg.pose.pose.orientation
        yaw = math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))
        self.pose = (p.x, p.y, yaw)

    def tick(self):
        if self.pose is None:
            return
        x, y, yaw = self.pose
        dx, dy = self.goal[0] - x, self.goal[1] - y
        distance = math.hypot(dx, dy)
        cmd = Twist()
        if distance > self.tolerance:
            heading_error = math.atan2(math.sin(math.atan2(dy, dx) - yaw), math.cos(math.atan2(dy, dx) - yaw))
            cmd.angular.z = max(-1.0, min(1.0, 2.0 * heading_error))
            if abs(heading_error) < 0.5:  # turn towards the goal first, then drive
                cmd.linear.x = min(self.max_speed, 0.8 * distance)
        self.cmd.publish(cmd)


def main():
    rclpy.init()
    node = GoToGoal()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
