"""A test-private ROS 2 domain for a module of graph tests: set while it runs, restored after it.

Every module that starts nodes talks on its own ``ROS_DOMAIN_ID`` (120-229, drawn per process
and start time, so two test runs on one machine rarely meet), discovers on localhost only,
and leaves ``os.environ`` as it found it for the modules after it.
"""
from __future__ import annotations

import contextlib
import os
import random
import time
from typing import Iterator, Optional

import pytest


def fresh_domain_id(salt: int = 0) -> str:
    """A domain id for this process, in 120-229 (``salt`` tells modules of one process apart)."""
    return str(random.Random(os.getpid() ^ int(time.time() * 1000) ^ salt).randint(120, 229))


@contextlib.contextmanager
def private_domain(domain: Optional[str] = None, transports: Optional[str] = None) -> Iterator[str]:
    """Set a private domain (and Fast DDS transports, e.g. ``UDPv4``) until the block ends; yield its id."""
    with pytest.MonkeyPatch.context() as env:
        env.setenv('ROS_DOMAIN_ID', domain or fresh_domain_id())
        env.setenv('ROS_AUTOMATIC_DISCOVERY_RANGE', 'LOCALHOST')
        env.delenv('ROS_LOCALHOST_ONLY', raising=False)
        if transports:
            env.setenv('FASTDDS_BUILTIN_TRANSPORTS', transports)
        yield os.environ['ROS_DOMAIN_ID']
