"""week5_actions: the COM2009 Week 5 CameraSweep action. Plain Python: goal checks and capture angles
(`sweep_plan`), the unwrapped heading (`heading`), the image folder and result texts (`image_folder`);
nodes/action_server.py and nodes/action_client.py wire them to ROS."""
