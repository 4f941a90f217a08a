// A component: a node class registered with rclcpp_components, loaded from its shared library by the
// executable rclcpp_components_register_node() generates (or by a component container). It publishes on
// "component_chatter", stamped with the node's clock.
#include <chrono>
#include <memory>
#include <string>

#include "rclcpp/rclcpp.hpp"
#include "rclcpp_components/register_node_macro.hpp"
#include "std_msgs/msg/string.hpp"

using namespace std::chrono_literals;

namespace cpp_nodes
{

class ComponentTalker : public rclcpp::Node
{
public:
  explicit ComponentTalker(const rclcpp::NodeOptions & options)
  : Node("component_talker", options)
  {
    publisher_ = create_publisher<std_msgs::msg::String>("component_chatter", 10);
    timer_ = create_timer(100ms, [this]() {
      std_msgs::msg::String msg;
      msg.data = "component " + std::to_string(count_++) + " at " + std::to_string(now().nanoseconds());
      publisher_->publish(msg);
    });
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr publisher_;
  rclcpp::TimerBase::SharedPtr timer_;
  size_t count_ = 0;
};

}  // namespace cpp_nodes

RCLCPP_COMPONENTS_REGISTER_NODE(cpp_nodes::ComponentTalker)
