#!/usr/bin/env python3
"""The seed's square_movement node: a plain rclpy program (it never imports gazelle).

A 10 Hz timer drives forward 5 s at 0.2 m/s, turns 3.14 s at 0.5 rad/s, and repeats,
timing itself with the node's own clock (so ``use_sim_time:=true`` makes it follow /clock).

Changes from the seed, each for a measured reason:
- the ``max_sides`` parameter (default 0 = run forever, as the seed) stops the node after
  that many forward+turn sides; the demo uses it for one square;
- the clock starts at the first tick once /cmd_vel has had a subscriber for 0.5 s (with
  use_sim_time the clock reads 0 until the first /clock message, and early commands are lost
  to discovery);
- a switching tick publishes the new state's command (the seed drove every side 0.1 s long).
"""

import time

import rclpy
from geometry_msgs.msg import Twist
from rclpy.duration import Duration
from rclpy.node import Node

TICK_TOLERANCE = 0.01  # seconds: timer ticks jitter by a few milliseconds
MATCH_SETTLE_SEC = 0.5  # wall seconds between seeing the simulator's subscription and the first command


class SquareMovement(Node):
    def __init__(self):
        super().__init__('square_movement')
        self.publisher = self.create_publisher(Twist, '/cmd_vel', 10)
        self.timer = self.create_timer(0.1, self.timer_callback)
        self.max_sides = self.declare_parameter('max_sides', 0).value
        self.sides_done = 0
        self.state = 'forward'
        # Started at the first tick, not here: with use_sim_time the clock reads 0 until
        # the first /clock message, and the seed's first side would then end at once.
        self.state_start_time = None
        self.last_tick = None
        self.subscriber_seen = None
        self.get_logger().info('Square movement started')

    def timer_callback(self):
        if self.state_start_time is None and self.publisher.get_subscription_count() == 0:
            # Commands published before DDS discovery matches them with the simulator are
            # lost, and the first side would come out short: wait for the subscriber.
            self.get_logger().info('Waiting for a /cmd_vel subscriber', throttle_duration_sec=2.0)
            self.subscriber_seen = None
            return
        if self.state_start_time is None:
            # ...and then a little longer: discovery ends on the two sides at different times, and
            # the simulator took our first commands 0.28 s after we saw its subscription on a busy
            # machine (a 0.946 m first side). Wall time, so that it holds with use_sim_time too.
            seen = self.subscriber_seen = self.subscriber_seen or time.monotonic()
            if time.monotonic() - seen < MATCH_SETTLE_SEC:
                return
        current_time = self.get_clock().now()
        if current_time.nanoseconds == 0:
            return  # use_sim_time and no /clock message yet
        if self.state_start_time is None:
            # Start on a tick that comes one period after the previous one: then this node's clock
            # is current. Right after start-up it may still be reading an old /clock message, and a
            # side timed from that stale start ends early (we measured 0.58 m instead of 1 m at 10x).
            last, self.last_tick = self.last_tick, current_time
            if last is None or not 0.05 <= (current_time - last).nanoseconds / 1e9 <= 0.2:
                return
            self.state_start_time = current_time
            self.get_logger().info(f'Starting at t={current_time.nanoseconds / 1e9:.3f}')
        elapsed_time = (current_time - self.state_start_time).nanoseconds / 1e9

        # Switch first, then publish the new state's command. The seed published the old
        # state's command on the switching tick, which drove every side a tick (0.1 s) too
        # long; and a tick that runs a millisecond early (elapsed 4.999 s) would add another.
        if self.state == 'forward' and elapsed_time >= 5.0 - TICK_TOLERANCE:  # after 5 seconds
            self.state = 'turn'
            self.state_start_time = current_time
            self.get_logger().info(f'Turning (forward for {elapsed_time:.3f} s from t={self.state_start_time.nanoseconds / 1e9:.3f})')
        elif self.state == 'turn' and elapsed_time >= 3.14 - TICK_TOLERANCE:  # after ~90 degrees
            self.sides_done += 1
            self.state = 'done' if self.max_sides and self.sides_done >= self.max_sides else 'forward'
            self.state_start_time = current_time
            self.get_logger().info(f'Side {self.sides_done} done')

        msg = Twist()
        if self.state == 'forward':
            msg.linear.x = 0.2  # Move forward at 0.2 m/s
        elif self.state == 'turn':
            msg.angular.z = 0.5  # Turn at 0.5 rad/s
        self.publisher.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    node = SquareMovement()
    try:
        while rclpy.ok() and node.state != 'done':
            rclpy.spin_once(node)
        # stop, and make sure the simulator has the message before this process goes away
        node.publisher.publish(Twist())
        node.publisher.wait_for_all_acked(Duration(seconds=5.0))
    except KeyboardInterrupt:
        pass
    node.destroy_node()
    if rclpy.ok():
        rclpy.shutdown()


if __name__ == '__main__':
    main()
