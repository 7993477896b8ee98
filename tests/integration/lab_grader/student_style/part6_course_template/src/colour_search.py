#!/usr/bin/env python3
# Exercise 3 in the course template's habits, extended to every pillar: a crop of the 1920x1080 image in pixels,
# one HSV threshold per pillar colour, turn clockwise fast until a blob is in view, then slowly until its centroid
# is within 100 px of the crop's middle, stop for 30 loops of a 5 Hz rospy.Rate (6 s), then turn on. The images
# are shown with cv2.imshow as the template does.
import cv2
import rospy
from cv_bridge import CvBridge, CvBridgeError
from sensor_msgs.msg import Image
from tb3 import Tb3Move

thresholds = {
    "red": ((0, 200, 100), (10, 255, 255)),
    "green": ((50, 200, 100), (70, 255, 255)),
    "turquoise": ((80, 200, 100), (100, 255, 255)),
    "blue": ((115, 224, 100), (130, 255, 255)),
}


class ColourSearch():

    def __init__(self):
        rospy.init_node("turn_and_face")
        self.camera_subscriber = rospy.Subscriber("/camera/rgb/image_raw", Image, self.camera_callback)
        self.cvbridge_interface = CvBridge()
        self.robot_controller = Tb3Move()
        self.turn_vel_fast = -0.5
        self.turn_vel_slow = -0.1
        self.robot_controller.set_move_cmd(0.0, self.turn_vel_fast)
        self.move_rate = ""
        self.stop_counter = 0
        self.ctrl_c = False
        rospy.on_shutdown(self.shutdown_ops)
        self.rate = rospy.Rate(5)
        self.m00 = 0
        self.m00_min = 10000
        self.cy = 0
        self.colour = ""

    def shutdown_ops(self):
        self.robot_controller.stop()
        cv2.destroyAllWindows()
        self.ctrl_c = True

    def camera_callback(self, img_data):
        try:
            cv_img = self.cvbridge_interface.imgmsg_to_cv2(img_data, desired_encoding="bgr8")
        except CvBridgeError as e:
            print(e)
            return
        height, width, _ = cv_img.shape
        crop_width = width - 800
        crop_height = 400
        crop_x = int((width / 2) - (crop_width / 2))
        crop_y = int((height / 2) - (crop_height / 2))
        crop_img = cv_img[crop_y:crop_y + crop_height, crop_x:crop_x + crop_width]
        hsv_img = cv2.cvtColor(crop_img, cv2.COLOR_BGR2HSV)
        biggest = 0
        for colour, (lower, upper) in thresholds.items():
            mask = cv2.inRange(hsv_img, lower, upper)
            m = cv2.moments(mask)
            if m['m00'] > biggest:
                biggest = m['m00']
                self.m00 = m['m00']
                self.cy = m['m10'] / (m['m00'] + 1e-5)
                self.colour = colour
        if biggest == 0:
            self.m00 = 0
        cv2.imshow('cropped image', crop_img)
        cv2.waitKey(1)

    def main(self):
        while not self.ctrl_c:
            if self.stop_counter > 0:
                self.stop_counter -= 1
            if self.m00 > self.m00_min:
                if self.cy >= 560 - 100 and self.cy <= 560 + 100:
                    if self.move_rate == 'slow':
                        self.move_rate = 'stop'
                        self.stop_counter = 30
                else:
                    self.move_rate = 'slow'
            else:
                self.move_rate = 'fast'

            if self.move_rate == 'fast':
                print("MOVING FAST: I can't see anything at the moment, scanning the area...")
                self.robot_controller.set_move_cmd(0.0, self.turn_vel_fast)
            elif self.move_rate == 'slow':
                print(f"MOVING SLOW: a {self.colour} blob is in view at y-position: {self.cy:.0f} pixels.")
                self.robot_controller.set_move_cmd(0.0, self.turn_vel_slow)
            elif self.move_rate == 'stop' and self.stop_counter > 0:
                print(f"STOPPED: the {self.colour} pillar is dead ahead. Counting down: {self.stop_counter}")
                self.robot_controller.set_move_cmd(0.0, 0.0)
            else:
                self.robot_controller.set_move_cmd(0.0, self.turn_vel_slow)
            self.robot_controller.publish()
            self.rate.sleep()


if __name__ == '__main__':
    node = ColourSearch()
    try:
        node.main()
    except rospy.ROSInterruptException:
        pass
