from setuptools import find_packages, setup

package_name = "param_demo"

setup(
    name=package_name,
    packages=find_packages(exclude=["test"]),
    data_files=[
        ("share/ament_index/resource_index/packages", ["resource/" + package_name]),
        # The parameter file sits beside the code and installs flat into share/, as demo_nodes_py's does.
        (
            "share/" + package_name,
            ["package.xml", "param_demo/parameters/params.yaml", "param_demo/parameters/other.yaml"],
        ),
    ],
    entry_points={
        "console_scripts": [
            "param_client = param_demo.parameters.param_client:main",
            "blackboard = param_demo.parameters.blackboard:main",
        ],
    },
)
