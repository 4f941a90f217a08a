from setuptools import setup

package_name = "simple_robot"

setup(
    name=package_name,
    version="0.1.0",
    packages=[package_name],
    data_files=[
        ("share/ament_index/resource_index/packages", ["resource/" + package_name]),
        ("share/" + package_name, ["package.xml", "simple_robot/robot.urdf.xacro"]),
    ],
    install_requires=["setuptools"],
    zip_safe=True,
    maintainer="gazelle developers",
    maintainer_email="gazelle-dev@example.com",
    description="The seed's differential-drive robot that drives a square, ported to gazelle.",
    license="Apache-2.0",
    entry_points={"console_scripts": ["square_movement = simple_robot.square_movement:main"]},
)
