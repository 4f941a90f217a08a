// The seed blog's square_movement node (examples/simple_robot/simple_robot/square_movement.py) as a
// plain rclcpp program: a 10 Hz timer drives forward 5 s at 0.2 m/s, turns 3.14 s at 0.5 rad/s, and
// repeats, timing itself with the node's own clock (use_sim_time:=true makes it follow /clock).
// As the Python one: max_sides (0 = forever) stops it after that many sides; the clock starts once
// /cmd_vel has had a subscriber for 0.5 s and on a tick one period after the previous one; a switching
// tick publishes the new state's command.
#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "geometry_msgs/msg/twist.hpp"
#include "rclcpp/rclcpp.hpp"

using namespace std::chrono_literals;

constexpr double TICK_TOLERANCE = 0.01;  // seconds: timer ticks jitter by a few milliseconds
constexpr double MATCH_SETTLE_SEC = 0.5;  // wall seconds between seeing the subscription and the first command

class SquareMovement : public rclcpp::Node
{
public:
  SquareMovement()
  : Node("square_movement")
  {
    publisher_ = create_publisher<geometry_msgs::msg::Twist>("/cmd_vel", 10);
    timer_ = create_timer(100ms, [this]() {timer_callback();});
    max_sides_ = declare_parameter<int64_t>("max_sides", 0);
    RCLCPP_INFO(get_logger(), "Square movement started");
  }

  bool done() const {return state_ == "done";}

  void stop()
  {
    publisher_->publish(geometry_msgs::msg::Twist());
    publisher_->wait_for_all_acked(5s);
  }

private:
  void timer_callback()
  {
    if (!state_start_time_ && publisher_->get_subscription_count() == 0) {
      RCLCPP_INFO_THROTTLE(get_logger(), steady_, 2000, "Waiting for a /cmd_vel subscriber");
      subscriber_seen_.reset();
      return;
    }
    if (!state_start_time_) {
      if (!subscriber_seen_) {
        subscriber_seen_ = steady_.now();
      }
      if ((steady_.now() - *subscriber_seen_).seconds() < MATCH_SETTLE_SEC) {
        return;
      }
    }
    const rclcpp::Time current_time = now();
    if (current_time.nanoseconds() == 0) {
      return;  // use_sim_time and no /clock message yet
    }
    if (!state_start_time_) {
      const std::optional<rclcpp::Time> last = last_tick_;
      last_tick_ = current_time;
      if (!last) {
        return;
      }
      const double period = (current_time - *last).seconds();
      if (period < 0.05 || period > 0.2) {
        return;
      }
      state_start_time_ = current_time;
      RCLCPP_INFO(get_logger(), "Starting at t=%.3f", current_time.seconds());
    }
    const double elapsed_time = (current_time - *state_start_time_).seconds();

    if (state_ == "forward" && elapsed_time >= 5.0 - TICK_TOLERANCE) {
      state_ = "turn";
      state_start_time_ = current_time;
      RCLCPP_INFO(get_logger(), "Turning (forward for %.3f s from t=%.3f)", elapsed_time, current_time.seconds());
    } else if (state_ == "turn" && elapsed_time >= 3.14 - TICK_TOLERANCE) {
      ++sides_done_;
      state_ = (max_sides_ && sides_done_ >= max_sides_) ? "done" : "forward";
      state_start_time_ = current_time;
      RCLCPP_INFO(get_logger(), "Side %ld done", static_cast<long>(sides_done_));
    }

    geometry_msgs::msg::Twist msg;
    if (state_ == "forward") {
      msg.linear.x = 0.2;
    } else if (state_ == "turn") {
      msg.angular.z = 0.5;
    }
    publisher_->publish(msg);
  }

  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr publisher_;
  rclcpp::TimerBase::SharedPtr timer_;
  rclcpp::Clock steady_{RCL_STEADY_TIME};
  int64_t max_sides_ = 0;
  int64_t sides_done_ = 0;
  std::string state_ = "forward";
  std::optional<rclcpp::Time> state_start_time_;
  std::optional<rclcpp::Time> last_tick_;
  std::optional<rclcpp::Time> subscriber_seen_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<SquareMovement>();
  rclcpp::executors::SingleThreadedExecutor executor;
  executor.add_node(node);
  while (rclcpp::ok() && !node->done()) {
    executor.spin_once(100ms);
  }
  if (rclcpp::ok()) {
    node->stop();
  }
  rclcpp::shutdown();
  return 0;
}
