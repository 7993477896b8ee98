"""Launch-file arguments the integration tests share."""

# For a graph where a node takes every camera frame (the fruit detector) and the tests need its answers, not
# sharp or frequent pictures: 160 x 120 at 5 frames per sim second instead of 1920 x 1080 at 30. Rendering is
# then the simulator's biggest cost: in week4_demo at 10x real time, tb3_sim took 92 % of a core with the small
# camera at 30 Hz, 41 % at 5 Hz. The fruit detector still answers from an image at most 0.2 sim seconds old.
CHEAP_CAMERA = ("camera_width:=160", "camera_height:=120", "camera_rate:=5")
