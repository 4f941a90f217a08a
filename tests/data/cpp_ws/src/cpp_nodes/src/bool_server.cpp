// A service server: std_srvs/SetBool on "set_flag", answering with the node's time (simulation time
// under use_sim_time) and how many requests it has served.
#include <memory>
#include <string>

#include "rclcpp/rclcpp.hpp"
#include "std_srvs/srv/set_bool.hpp"

class BoolServer : public rclcpp::Node
{
public:
  BoolServer()
  : Node("bool_server")
  {
    service_ = create_service<std_srvs::srv::SetBool>(
      "set_flag",
      [this](const std::shared_ptr<std_srvs::srv::SetBool::Request> request,
      std::shared_ptr<std_srvs::srv::SetBool::Response> response) {
        ++served_;
        response->success = request->data;
        response->message = "request " + std::to_string(served_) + " at " +
          std::to_string(now().nanoseconds());
        RCLCPP_INFO(get_logger(), "set_flag(%s): %s", request->data ? "true" : "false",
          response->message.c_str());
      });
  }

private:
  rclcpp::Service<std_srvs::srv::SetBool>::SharedPtr service_;
  size_t served_ = 0;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<BoolServer>());
  rclcpp::shutdown();
  return 0;
}
