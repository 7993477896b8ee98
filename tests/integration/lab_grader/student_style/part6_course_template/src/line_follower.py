#!/usr/bin/env python3
# Exercise 4 in the course template's habits: a crop of the 1920x1080 image in pixels (a band of floor ahead), an
# HSV threshold for the pink line, its centroid's column against the image's middle, kp = -0.001 rad/s per pixel,
# 0.1 m/s forwards, the angular velocity limited to the Waffle's 1.82 rad/s, cv2.imshow of the filtered image.
import cv2
import rospy
from cv_bridge import CvBridge, CvBridgeError
from sensor_msgs.msg import Image
from tb3 import Tb3Move


class LineFollower():
    def __init__(self):
        node_name = "line_follower"
        rospy.init_node(node_name, anonymous=True)
        self.rate = rospy.Rate(5)
        self.cvbridge_interface = CvBridge()
        self.img_sub = rospy.Subscriber("/camera/rgb/image_raw", Image, self.camera_cb)
        self.robot_controller = Tb3Move()
        self.ctrl_c = False
        rospy.on_shutdown(self.shutdown_ops)

    def shutdown_ops(self):
        self.robot_controller.stop()
        cv2.destroyAllWindows()
        self.ctrl_c = True

    def camera_cb(self, img_data):
        try:
            cv_img = self.cvbridge_interface.imgmsg_to_cv2(img_data, desired_encoding="bgr8")
        except CvBridgeError as e:
            print(e)
            return
        height, width, _ = cv_img.shape
        cropped_img = cv_img[800:900, 0:width]
        hsv_img = cv2.cvtColor(cropped_img, cv2.COLOR_BGR2HSV)
        lower = (140, 100, 100)
        upper = (160, 255, 255)
        mask = cv2.inRange(hsv_img, lower, upper)
        res = cv2.bitwise_and(cropped_img, cropped_img, mask=mask)
        m = cv2.moments(mask)
        cy = m['m10'] / (m['m00'] + 1e-5)
        cz = m['m01'] / (m['m00'] + 1e-5)
        cv2.circle(res, (int(cy), int(cz)), 10, (255, 0, 0), 2)
        cv2.imshow("filtered image", res)
        cv2.waitKey(1)

        kp = -0.001
        reference_input = width / 2
        feedback_signal = cy
        error = feedback_signal - reference_input
        ang_vel = kp * error
        if ang_vel < -1.82:
            ang_vel = -1.82
        elif ang_vel > 1.82:
            ang_vel = 1.82
        print(f"Error = {error:.1f} pixels | Control Signal = {ang_vel:.2f} rad/s")
        self.robot_controller.set_move_cmd(linear=0.1, angular=ang_vel)
        self.robot_controller.publish()

    def main(self):
        while not self.ctrl_c:
            self.rate.sleep()


if __name__ == '__main__':
    node = LineFollower()
    try:
        node.main()
    except rospy.ROSInterruptException:
        pass
