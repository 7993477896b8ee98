#!/usr/bin/env python3
"""The add_two_int service (beginner_tutorials/add_two_int): answers a + b.

A sum outside int64 cannot be put in the response, so it is refused with a ServiceException whose text
names the range (the caller sees "service cannot process request: ..."), and the server keeps serving.
"""
import rospy

from beginner_tutorials.addition import checked_sum
from beginner_tutorials.errors import SumOutOfRangeError
from beginner_tutorials.srv import add_two_int, add_two_intResponse


class AddTwoIntServer:
    def __init__(self):
        self.service = rospy.Service("add_two_int", add_two_int, self.handle_add_two_int)

    def handle_add_two_int(self, request):
        try:
            total = checked_sum(request.a, request.b)
        except SumOutOfRangeError as error:
            rospy.logwarn("Refusing [%s + %s]: %s", request.a, request.b, error)
            raise rospy.ServiceException(str(error)) from None
        rospy.loginfo("Returning [%s + %s = %s]", request.a, request.b, total)
        return add_two_intResponse(sum=total)


def main():
    rospy.init_node("add_two_int_server")
    AddTwoIntServer()
    rospy.loginfo("Ready to add two ints.")
    rospy.spin()


if __name__ == "__main__":
    main()
