"""ament_python package definition of ltl_instruct (works with colcon and with pip)."""
from glob import glob

from setuptools import find_packages, setup

package_name = 'ltl_instruct'

NODES = [
    'ltl_translator',
    'referent_grounder',
    'task_progression',
    'fmt_planner',
    'sim_world',
]

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test', 'test.*', 'bench', 'bench.*']),
    include_package_data=True,
    package_data={package_name: ['data/*', 'data/**/*']},
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/launch', glob('launch/*.py')),
        ('share/' + package_name + '/config', glob('config/*.yaml')),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='ltl_instruct developers',
    maintainer_email='ltl-instruct@example.com',
    description='Plain-English instructions with temporal and spatial constraints to verified '
                'robot paths (co-safe LTL, spatial grounding, FMT*).',
    license='Apache-2.0',
    tests_require=['pytest'],
    entry_points={
        'console_scripts': [
            'ltl-instruct = ltl_instruct.cli:main',
        ] + [f'{n} = ltl_instruct.nodes.{n}:main' for n in NODES],
    },
)
