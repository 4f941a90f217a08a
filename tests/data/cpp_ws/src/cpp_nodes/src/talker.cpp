// A talker on the node's clock: with use_sim_time it ticks and stamps in simulation time (/clock).
// It answers what it hears on "reply" so that the other side knows it is heard.
#include <chrono>
#include <memory>
#include <string>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

using namespace std::chrono_literals;

class Talker : public rclcpp::Node
{
public:
  Talker()
  : Node("talker")
  {
    publisher_ = create_publisher<std_msgs::msg::String>("chatter", 10);
    subscription_ = create_subscription<std_msgs::msg::String>(
      "reply", 10, [this](const std_msgs::msg::String & msg) {
        RCLCPP_INFO(get_logger(), "heard: '%s'", msg.data.c_str());
        heard_ = msg.data;
      });
    timer_ = create_timer(100ms, [this]() {
      std_msgs::msg::String msg;
      msg.data = "hello " + std::to_string(count_++) + " at " +
        std::to_string(now().nanoseconds()) + " heard " + heard_;
      publisher_->publish(msg);
    });
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr publisher_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr subscription_;
  rclcpp::TimerBase::SharedPtr timer_;
  std::string heard_ = "nothing";
  size_t count_ = 0;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Talker>());
  rclcpp::shutdown();
  return 0;
}
