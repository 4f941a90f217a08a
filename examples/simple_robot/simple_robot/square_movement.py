#!/usr/bin/env python3
"""The seed's square_movement node: a plain rclpy program (it never imports gazelle).

A 10 Hz timer drives forward 5 s at 0.2 m/s, turns 3.14 s at 0.5 rad/s, and repeats,
timing itself with the node's own clock (so ``use_sim_time:=true`` makes it follow /clock).

Extra over the seed: the ``max_sides`` parameter (default 0 = run forever, as the seed)
stops the node after that many forward+turn sides, which the demo uses for one square.
"""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class SquareMovement(Node):
    def __init__(self):
        super().__init__('square_movement')
        self.publisher = self.create_publisher(Twist, '/cmd_vel', 10)
        self.timer = self.create_timer(0.1, self.timer_callback)
        self.max_sides = self.declare_parameter('max_sides', 0).value
        self.sides_done = 0
        self.state = 'forward'
        self.state_start_time = self.get_clock().now()
        self.get_logger().info('Square movement started')

    def timer_callback(self):
        current_time = self.get_clock().now()
        elapsed_time = (current_time - self.state_start_time).nanoseconds / 1e9

        msg = Twist()

        if self.state == 'forward':
            msg.linear.x = 0.2  # Move forward at 0.2 m/s
            msg.angular.z = 0.0
            if elapsed_time >= 5.0:  # After 5 seconds
                self.state = 'turn'
                self.state_start_time = current_time
                self.get_logger().info('Turning')
        elif self.state == 'turn':
            msg.linear.x = 0.0
            msg.angular.z = 0.5  # Turn at 0.5 rad/s
            if elapsed_time >= 3.14:  # After ~90 degrees
                self.state = 'forward'
                self.state_start_time = current_time
                self.sides_done += 1
                self.get_logger().info(f'Side {self.sides_done} done, moving forward')
        elif self.state == 'done':
            msg = Twist()

        if self.max_sides and self.sides_done >= self.max_sides:
            self.state = 'done'
            msg = Twist()
        self.publisher.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    node = SquareMovement()
    try:
        while rclpy.ok() and node.state != 'done':
            rclpy.spin_once(node)
        # say stop a few times so the robot surely gets it
        for _ in range(3):
            node.publisher.publish(Twist())
    except KeyboardInterrupt:
        pass
    node.destroy_node()
    if rclpy.ok():
        rclpy.shutdown()


if __name__ == '__main__':
    main()
