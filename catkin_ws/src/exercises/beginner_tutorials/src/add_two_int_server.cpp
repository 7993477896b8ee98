// add_two_int_server_cpp: the C++ twin of nodes/add_two_int_server.py (node add_two_int_server_cpp,
// service add_two_int), interchangeable with it because both use beginner_tutorials/add_two_int.
//
// A sum outside int64 is refused rather than wrapped around: the callback throws, and roscpp sends the
// exception's text to the caller as the service error, with the same text as the Python server.
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <ros/ros.h>

#include "beginner_tutorials/add_two_int.h"

namespace
{
std::int64_t checkedSum(std::int64_t a, std::int64_t b)
{
  std::int64_t total = 0;
  if (__builtin_add_overflow(a, b, &total))
  {
    std::ostringstream reason;
    reason << a << " + " << b << " is outside the int64 range " << std::numeric_limits<std::int64_t>::min()
           << ".." << std::numeric_limits<std::int64_t>::max() << "; the sum cannot be returned";
    throw std::overflow_error(reason.str());
  }
  return total;
}

bool handleAddTwoInt(beginner_tutorials::add_two_int::Request& request,
                     beginner_tutorials::add_two_int::Response& response)
{
  response.sum = checkedSum(request.a, request.b);
  ROS_INFO_STREAM("Returning [" << request.a << " + " << request.b << " = " << response.sum << "]");
  return true;
}
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "add_two_int_server_cpp");
  ros::NodeHandle node;
  ros::ServiceServer service = node.advertiseService("add_two_int", handleAddTwoInt);
  ROS_INFO("Ready to add two ints.");
  ros::spin();
  return 0;
}
