"""tb3_sim: a Box2D TurtleBot3 Waffle simulator with Gazebo's topics, services and conventions.

Layers, each importing only the ones before it:
- `tb3_sim.core`: the simulation (world, bodies, robot and drive, sensors, world files, model XML); no rospy;
- `tb3_sim.ros`: the node (`gazebo`), the /gazebo/* API, message conversion and the periodic outputs;
- `tb3_sim.view`: what a person looks at: the scene, the top-down renderer, the Qt window and its box tool;
- `tb3_sim.tools`: command-line tools (spawn_box, spawn_model) and the core benchmark.
"""
