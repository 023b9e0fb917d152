from glob import glob

from setuptools import setup

package_name = "greeter_bringup"

setup(
    name=package_name,
    version="0.1.0",
    packages=[package_name],
    data_files=[
        ("share/ament_index/resource_index/packages", ["resource/" + package_name]),
        ("share/" + package_name, ["package.xml"]),
        ("share/" + package_name + "/launch", glob("launch/*")),
    ],
    entry_points={
        "console_scripts": ["counter = greeter_bringup.counter:main"],
    },
)
