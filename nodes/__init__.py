"""The tutorial nodes of the ROS 2 course, ported to actors."""
