"""The ROS entities: names, time, QoS, logging, topics, timers, parameters, actions and the Node.

Each module is one concept, shaped like rclpy's module of the same name;
``actors`` re-exports what user code needs.  Modules whose names start with
``_`` are internal.
"""

__all__: list[str] = []
