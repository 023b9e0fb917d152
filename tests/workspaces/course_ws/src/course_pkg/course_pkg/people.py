import rclpy
from course_interfaces.msg import Person
from rclpy.node import Node


class People(Node):
    def __init__(self):
        super().__init__("people")
        self.pub = self.create_publisher(Person, "people", 10)
        self.sub = self.create_subscription(Person, "people", self.heard, 10)
        self.timer = self.create_timer(0.5, self.tick)
        self.n = 0

    def tick(self):
        self.pub.publish(Person(name=f"p{self.n}", age=self.n))
        self.n += 1

    def heard(self, msg):
        self.get_logger().info(f"heard {msg.name} aged {msg.age} (max {Person.MAX_AGE})")


def main():
    rclpy.init()
    rclpy.spin(People())


if __name__ == "__main__":
    main()
