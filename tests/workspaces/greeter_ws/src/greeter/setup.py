import os
from glob import glob

from setuptools import find_packages, setup

package_name = "greeter"
share = os.path.join("share", package_name)

setup(
    name=package_name,
    version="0.2.0",
    packages=find_packages(exclude=["test"]),
    data_files=[
        ("share/ament_index/resource_index/packages", ["resource/" + package_name]),
        (share, ["package.xml"]),
        (os.path.join(share, "launch"), glob(os.path.join("launch", "*launch.[pxy][yma]*"))),
        (f"{share}/config", glob("config/*.yaml")),
    ],
    install_requires=["setuptools"],
    zip_safe=True,
    entry_points={
        "console_scripts": [
            "greeter = greeter.greeter:main",
            "listener = greeter.listener:main",
        ],
    },
)
