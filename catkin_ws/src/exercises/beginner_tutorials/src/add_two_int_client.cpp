// add_two_int_client_cpp A B: the C++ twin of nodes/add_two_int_client.py. Prints "A + B = SUM" from the
// add_two_int service (either server). Wrong arguments print the reason and the usage and exit with 1, as do
// a missing service (after 10 s) and a refused call.
#include <cstdint>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <ros/ros.h>

#include "beginner_tutorials/add_two_int.h"

namespace
{
const double kServiceWaitSeconds = 10.0;

// An optional sign and decimal digits, nothing else (no "4.0", "0x10", " 4"), within int64.
std::int64_t parseInt64(const std::string& text)
{
  const std::size_t digits_start = (!text.empty() && (text[0] == '+' || text[0] == '-')) ? 1 : 0;
  if (text.size() == digits_start || text.find_first_not_of("0123456789", digits_start) != std::string::npos)
  {
    throw std::invalid_argument("'" + text + "' is not an integer");
  }
  try
  {
    return std::stoll(text);
  }
  catch (const std::out_of_range&)
  {
    throw std::invalid_argument(text + " is outside the int64 range " +
                                std::to_string(std::numeric_limits<std::int64_t>::min()) + ".." +
                                std::to_string(std::numeric_limits<std::int64_t>::max()));
  }
}

void printUsage()
{
  std::cerr << "usage: add_two_int_client_cpp A B\n"
            << "  prints A + B, computed by the add_two_int service;\n"
            << "  A and B are integers from " << std::numeric_limits<std::int64_t>::min() << " to "
            << std::numeric_limits<std::int64_t>::max() << " (int64)" << std::endl;
}
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "add_two_int_client_cpp", ros::init_options::AnonymousName);
  std::vector<std::string> args;
  ros::removeROSArgs(argc, argv, args);
  beginner_tutorials::add_two_int service;
  try
  {
    if (args.size() != 3)
    {
      throw std::invalid_argument("expected 2 arguments, A and B; got " + std::to_string(args.size() - 1));
    }
    service.request.a = parseInt64(args[1]);
    service.request.b = parseInt64(args[2]);
  }
  catch (const std::invalid_argument& error)
  {
    std::cerr << "error: " << error.what() << std::endl;
    printUsage();
    return 1;
  }

  ros::NodeHandle node;
  ros::ServiceClient client = node.serviceClient<beginner_tutorials::add_two_int>("add_two_int");
  std::cout << "Requesting " << service.request.a << " + " << service.request.b << std::endl;
  if (!client.waitForExistence(ros::Duration(kServiceWaitSeconds)))
  {
    std::cerr << "error: service " << client.getService() << " is not available after " << kServiceWaitSeconds
              << " s (is add_two_int_server running?)" << std::endl;
    return 1;
  }
  if (!client.call(service))
  {
    std::cerr << "error: the call to " << client.getService()
              << " failed; roscpp logged the server's reason above" << std::endl;
    return 1;
  }
  std::cout << service.request.a << " + " << service.request.b << " = " << service.response.sum << std::endl;
  return 0;
}
