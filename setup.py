"""ament_python package definition of ltl_instruct (works with colcon and with pip)."""
import os
import sys
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


def ros2_run_wrappers() -> list:
    """``lib/ltl_instruct/<node>`` for a wheel install (``pip install .``), where ``ros2 run`` looks.

    colcon runs ``setup.py install``/``develop`` and setup.cfg's ``install_scripts`` puts
    the console scripts there itself. A wheel puts them in ``<prefix>/bin`` instead, so
    for wheels each node gets a small shell wrapper in ``lib/ltl_instruct`` that hands
    over to the console script of the same prefix (which has the right interpreter).
    """
    if not any(cmd in sys.argv for cmd in ('bdist_wheel', 'editable_wheel')):
        return []
    out_dir = os.path.join('build', 'ros2_run')
    os.makedirs(out_dir, exist_ok=True)
    files = []
    for name in NODES:
        path = os.path.join(out_dir, name)
        with open(path, 'w', encoding='utf-8') as f:
            f.write('#!/bin/sh\n'
                    '# ros2 run entry point: hands over to the console script installed with this prefix.\n'
                    'here=$(cd "$(dirname "$0")" && pwd)\n'
                    f'exec "$here/../../bin/{name}" "$@"\n')
        os.chmod(path, 0o755)
        files.append(path)
    return [('lib/' + package_name, files)]


setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test', 'test.*', 'bench', 'bench.*']),
    include_package_data=True,
    package_data={package_name: ['data/*', 'data/**/*', 'core/language/*.yaml', 'core/language/neural/*.yaml']},
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/launch', glob('launch/*.py')),
        ('share/' + package_name + '/config', glob('config/*.yaml')),
    ] + ros2_run_wrappers(),
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
